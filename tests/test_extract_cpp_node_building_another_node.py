"""A server node that builds another node class of its own (navigation2's controller and
planner servers each make a ``Costmap2DROS``, a ``nav2::LifecycleNode`` of another
package's library) keeps its own name. Both were named ``?``: the costmap's constructor,
whose code the server's files have not, counted as code that may build the base class
unseen (its declaration's words: the base ``LifecycleNode`` and a comment's
"child-LifecycleNode"), so the base's delegating ``LifecycleNode(name, options)``, which no
file calls, counted as possibly run; and a unit that sees only that delegating
constructor (main.cpp, without the server's) gave its parameter as the node's name. So
the launch's ``controller_server`` parameters never reached the node, which ran as
``/?``."""

from __future__ import annotations

from pathlib import Path

from conftest import package_xml

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.workspace import scan

BASE = """\
#pragma once
#include <string>
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_lifecycle/lifecycle_node.hpp"
namespace common {
class LifecycleNode : public rclcpp_lifecycle::LifecycleNode {
public:
  LifecycleNode(const std::string & node_name, const std::string & ns,
                const rclcpp::NodeOptions & options = rclcpp::NodeOptions())
  : rclcpp_lifecycle::LifecycleNode(node_name, ns, options) {}
  LifecycleNode(const std::string & node_name,
                const rclcpp::NodeOptions & options = rclcpp::NodeOptions())
  : common::LifecycleNode(node_name, "", options) {}
};
}  // namespace common
"""

COSTMAP = """\
#pragma once
#include <string>
#include "common/lifecycle_node.hpp"
namespace costmap {
/** A costmap: a child-LifecycleNode of the server that makes it. */
class Costmap : public common::LifecycleNode {
public:
  explicit Costmap(const std::string & name);
};
}  // namespace costmap
"""

SERVER_H = """\
#pragma once
#include <memory>
#include "common/lifecycle_node.hpp"
#include "costmap/costmap.hpp"
#include "std_msgs/msg/string.hpp"
namespace server {
class Server : public common::LifecycleNode {
public:
  explicit Server(const rclcpp::NodeOptions & options = rclcpp::NodeOptions());
private:
  std::shared_ptr<costmap::Costmap> costmap_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
}  // namespace server
"""

SERVER = """\
#include "server/server.hpp"
namespace server {
Server::Server(const rclcpp::NodeOptions & options)
: common::LifecycleNode("controller_server", "", options)
{
  costmap_ = std::make_shared<costmap::Costmap>("local_costmap");
  pub_ = create_publisher<std_msgs::msg::String>("status", 1);
}
}  // namespace server
"""

MAIN = """\
#include "server/server.hpp"
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<server::Server>();
  rclcpp::spin(node->get_node_base_interface());
}
"""


def _extract(write_tree) -> CppResult:
    root: Path = write_tree({
        "common/package.xml": package_xml("common", "ament_cmake"),
        "common/include/common/lifecycle_node.hpp": BASE,
        "costmap/package.xml": package_xml("costmap", "ament_cmake"),
        "costmap/include/costmap/costmap.hpp": COSTMAP,
        "server/package.xml": package_xml("server", "ament_cmake"),
        "server/include/server/server.hpp": SERVER_H,
        "server/src/server.cpp": SERVER,
        "server/src/main.cpp": MAIN,
    })
    return extract_cpp([str(root / "server/src" / name) for name in ("main.cpp", "server.cpp")],
                       scan([str(root)]), cache_dir=None)


def test_the_server_keeps_its_own_name(write_tree) -> None:
    result = _extract(write_tree)
    assert result.rosname == "controller_server"
    assert ("publish", "status") in [(c.kind, c.name) for c in result.calls]
