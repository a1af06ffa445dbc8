"""A name that a constructor takes as an argument holding a parameter's value: nav2's
servers read ``costmap_topic`` into a local and build ``CostmapSubscriber(node,
costmap_topic)``, whose constructor template keeps it in ``topic_name_`` and subscribes
to it. The subscription's name is that parameter's (the graph fills in its value); it was
'?' with no parameter, for a constructor template (whose member values were not read) and
for a plain constructor (a function's parameter was not followed to its callers)."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp_nodes
from haros_arch.workspace import scan

SOURCE = """#include <memory>
#include <string>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"
class Templated {
public:
  template<typename NodeT>
  Templated(const NodeT & parent, const std::string & topic) : topic_(topic) {
    rclcpp::Node::SharedPtr node = parent;
    sub_ = node->create_subscription<std_msgs::msg::String>(topic_, 1, nullptr);
  }
  std::string topic_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};
class Plain {
public:
  Plain(rclcpp::Node::SharedPtr parent, const std::string & topic) {
    sub_ = parent->create_subscription<std_msgs::msg::String>(topic, 1, nullptr);
  }
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};
class Server : public rclcpp::Node {
public:
  Server() : rclcpp::Node("server") {}
  void configure() {
    std::string costmap = declare_parameter("costmap_topic", std::string("costmap_raw"));
    std::string odom = declare_parameter("odom_topic", std::string("odom"));
    templated_ = std::make_unique<Templated>(shared_from_this(), costmap);
    plain_ = std::make_unique<Plain>(shared_from_this(), odom);
  }
  std::unique_ptr<Templated> templated_;
  std::unique_ptr<Plain> plain_;
};
int main() {auto server = std::make_shared<Server>(); server->configure();}
"""


def test_a_parameter_passed_to_a_constructor_names_its_subscription(tmp_path: Path) -> None:
    package = tmp_path / "server"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="3"><name>server</name><version>1.0.0</version>'
        "<description>x</description><maintainer email='a@b.c'>a</maintainer>"
        "<license>x</license><buildtool_depend>ament_cmake</buildtool_depend>"
        "<depend>rclcpp</depend><depend>std_msgs</depend>"
        "<export><build_type>ament_cmake</build_type></export></package>")
    (package / "src" / "server.cpp").write_text(SOURCE)
    batch = extract_cpp_nodes([[str(package / "src" / "server.cpp")]],
                              scan([str(tmp_path)]), cache_dir=None, jobs=1)
    found = sorted((c.location.line, c.name, c.name_param, c.name_default)
                   for c in batch.results[0].calls if c.kind == "subscribe")
    assert found == [(10, "?", "costmap_topic", "costmap_raw"),
                     (18, "?", "odom_topic", "odom")]


HEADER = """#include <memory>
#include <string>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"
class Watcher {
public:
  template<typename NodeT>
  Watcher(const NodeT & parent, const std::string & topic) : topic_(topic) {
    rclcpp::Node::SharedPtr node = parent;
    sub_ = node->create_subscription<std_msgs::msg::String>(topic_, 1, nullptr);
  }
  std::string topic_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};
"""

UNIT = """#include "server/watcher.hpp"
void make_{which}(rclcpp::Node::SharedPtr node, std::unique_ptr<Watcher> & out) {{
  std::string topic = node->declare_parameter("{which}_topic", std::string("{which}"));
  out = std::make_unique<Watcher>(node, topic);
}}
"""


def test_two_files_building_a_header_class_with_two_parameters(tmp_path: Path) -> None:
    """The node's two files each build the header's class with a parameter of their own
    (nav2's behavior server: the local and the global costmap's topic): two
    subscriptions at the header's line, one per parameter; the node kept the first only,
    as its calls were told apart by kind, name and place, not by the parameter."""
    package = tmp_path / "server"
    (package / "src").mkdir(parents=True)
    (package / "include" / "server").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="3"><name>server</name><version>1.0.0</version>'
        "<description>x</description><maintainer email='a@b.c'>a</maintainer>"
        "<license>x</license><buildtool_depend>ament_cmake</buildtool_depend>"
        "<depend>rclcpp</depend><depend>std_msgs</depend>"
        "<export><build_type>ament_cmake</build_type></export></package>")
    (package / "include" / "server" / "watcher.hpp").write_text(HEADER)
    units = []
    for which in ("local", "global"):
        (package / "src" / f"{which}.cpp").write_text(UNIT.format(which=which))
        units.append(str(package / "src" / f"{which}.cpp"))
    batch = extract_cpp_nodes([units], scan([str(tmp_path)]), cache_dir=None, jobs=1)
    assert sorted((c.name, c.name_param, c.name_default, c.location.line)
                  for c in batch.results[0].calls if c.kind == "subscribe") == [
        ("?", "global_topic", "global", 10), ("?", "local_topic", "local", 10)]


DOCKS = """#include <string>
#include <vector>
#include "rclcpp/rclcpp.hpp"
inline void read_docks(rclcpp::Node::SharedPtr node, const std::vector<std::string> & docks)
{
  for (const auto & dock : docks) {
    node->declare_parameter(dock + ".frame", std::string("map"));
  }
}
"""

CALLER = """#include "server/docks.hpp"
void load(rclcpp::Node::SharedPtr node) {
  auto docks = node->declare_parameter("docks", std::vector<std::string>());
  read_docks(node, docks);
}
"""

BYSTANDER = """#include "server/docks.hpp"
void other(rclcpp::Node::SharedPtr node) {node->declare_parameter("rate", 1.0);}
"""


def test_a_header_functions_unnamed_copy_beside_its_named_one(tmp_path: Path) -> None:
    """opennav_docking's ``parseDockParams(docks_param, ...)``, inline in utils.hpp: the
    unit that calls it with the ``docks`` list reads ``<dock>.frame`` per element; a unit
    that only includes the header reads ``?.frame`` of a list it cannot know. The node
    keeps the one named by ``docks``: two calls at one place are one when only one of them
    knows its parameter."""
    package = tmp_path / "server"
    (package / "src").mkdir(parents=True)
    (package / "include" / "server").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="3"><name>server</name><version>1.0.0</version>'
        "<description>x</description><maintainer email='a@b.c'>a</maintainer>"
        "<license>x</license><buildtool_depend>ament_cmake</buildtool_depend>"
        "<depend>rclcpp</depend><export><build_type>ament_cmake</build_type></export>"
        "</package>")
    (package / "include" / "server" / "docks.hpp").write_text(DOCKS)
    units = []
    for name, text in (("bystander", BYSTANDER), ("caller", CALLER)):
        (package / "src" / f"{name}.cpp").write_text(text)
        units.append(str(package / "src" / f"{name}.cpp"))
    batch = extract_cpp_nodes([units], scan([str(tmp_path)]), cache_dir=None, jobs=1)
    assert [(c.name, c.name_param) for c in batch.results[0].calls
            if c.kind == "declare" and c.location.line == 7] == [("?.frame", "docks")]
