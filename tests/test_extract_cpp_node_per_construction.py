"""A process of several ROS 2 nodes whose classes do not name one node each (PlanSys2's
plansys2_node): a class built twice with its node's name as a constructor argument
(``LifecycleServiceClient("domain_expert_lc_mngr", "domain_expert")``), a helper built
through its own static factory with ``shared_from_this()``, and one also built by code
whose node is not known. Each call is made on the node that makes it; where that cannot
be told, the graph says so with a node named ``?``, never the process's first node."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.graph.processes import own_calls, process_nodes
from haros_arch.launch.model import NodeDecl
from haros_arch.model.source import Node
from haros_arch.workspace import scan

PACKAGE = ('<?xml version="1.0"?>\n<package format="2"><name>pkg</name>'
           "<version>0.1.0</version><description>d</description>"
           '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
           "<depend>rclcpp</depend><depend>std_msgs</depend><depend>std_srvs</depend>"
           "<export><build_type>ament_cmake</build_type></export></package>\n")

LIBRARY = """
#include <memory>
#include <string>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"
#include "std_srvs/srv/trigger.hpp"

namespace plan {
class Hub {
public:
  using Ptr = std::shared_ptr<Hub>;
  static Ptr make_shared(rclcpp::Node::SharedPtr node) { return std::make_shared<Hub>(node); }
  explicit Hub(rclcpp::Node::SharedPtr node) {
    pub_ = node->create_publisher<std_msgs::msg::String>("hub", 10);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
class Executor : public rclcpp::Node {
public:
  Executor() : Node("executor") {}
  void start() { hub_ = Hub::make_shared(shared_from_this()); }
  Hub::Ptr hub_;
};
class Manager : public rclcpp::Node {
public:
  Manager(const std::string & node_name, const std::string & managed)
  : Node(node_name), managed_(managed) {}
  void init() {
    client_ = create_client<std_srvs::srv::Trigger>(managed_ + "/get_state");
  }
  std::string managed_;
  rclcpp::Client<std_srvs::srv::Trigger>::SharedPtr client_;
};
}  // namespace plan
"""

# a class no file constructs (a behaviour tree's node, made by a factory) hands the hub
# a node that is not known
TICKER = """
#include "pkg/lib.hpp"
namespace plan {
class Ticker {
public:
  void tick() { hub_ = Hub::make_shared(node_); }
  rclcpp::Node::SharedPtr node_;
  Hub::Ptr hub_;
};
}  // namespace plan
"""

MAIN = """
#include "pkg/lib.hpp"
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto executor = std::make_shared<plan::Executor>();
  executor->start();
  auto first = std::make_shared<plan::Manager>("executor_lc_mngr", "executor");
  auto second = std::make_shared<plan::Manager>("planner_lc_mngr", "planner");
  first->init();
  second->init();
  rclcpp::spin(executor);
}
"""


def _extract(root: Path, *files: str) -> CppResult:
    return extract_cpp([str(root / f"pkg/src/{name}") for name in files], scan([str(root)]),
                       cache_dir=None)


def rows(result: CppResult) -> set[tuple[str, str, str | None]]:
    return {(c.kind, c.name, c.node_name) for c in result.calls}


def test_each_construction_names_its_own_node(write_tree) -> None:
    root = write_tree({"pkg/package.xml": PACKAGE, "pkg/include/pkg/lib.hpp": LIBRARY,
                       "pkg/src/main.cpp": MAIN})
    result = _extract(root, "main.cpp")
    assert result.rosnames == ["executor", "executor_lc_mngr", "planner_lc_mngr"]
    assert rows(result) == {
        # each Manager on the node its construction names, its service as that
        # construction gives it (it was "?"'s, given to the first node: the executor)
        ("client", "executor/get_state", "executor_lc_mngr"),
        ("client", "planner/get_state", "planner_lc_mngr"),
        # built by its own static factory, handed shared_from_this(): the executor's
        ("publish", "hub", "executor"),
    }


def test_a_call_whose_node_is_not_known_is_no_node_s_as_a_fact(write_tree) -> None:
    root = write_tree({"pkg/package.xml": PACKAGE, "pkg/include/pkg/lib.hpp": LIBRARY,
                       "pkg/src/main.cpp": MAIN, "pkg/src/ticker.cpp": TICKER})
    result = _extract(root, "main.cpp", "ticker.cpp")
    assert ("publish", "hub", None) in rows(result)  # the executor's, or the ticker's
    node = Node("pkg", "plan", "executable", "cpp", [], calls=result.calls,
                rosnames=result.rosnames)
    assert node.unplaced
    unnamed = NodeDecl(package="pkg", executable="plan", name="/?", ros_version=2)
    made = list(process_nodes([unnamed], {"pkg/plan": node}))
    assert [(decl.name, own) for decl, own in made] == [
        ("/executor", "executor"), ("/executor_lc_mngr", "executor_lc_mngr"),
        ("/planner_lc_mngr", "planner_lc_mngr"), ("/?", "?")]
    named = {own: [(c.kind, c.name) for c in own_calls(decl, node, own)]
             for decl, own in made}
    assert named["executor"] == []  # not the first node's as a fact
    assert named["?"] == [("publish", "hub")]
    # launched with name=: every node of the process has that name, the first holds it
    renamed = NodeDecl(package="pkg", executable="plan", name="/planning", name_given=True,
                       ros_version=2)
    made = list(process_nodes([renamed], {"pkg/plan": node}))
    assert [own for _, own in made] == ["executor", "executor_lc_mngr", "planner_lc_mngr"]
    assert own_calls(made[0][0], node, "executor") == [
        c for c in result.calls if c.node_name is None]


DELEGATING = """
#include <memory>
#include <string>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

namespace plan {
class Router : public rclcpp::Node {
public:
  explicit Router(const std::string & node_name = "router")
  : Router(rclcpp::NodeOptions(), node_name) {}
  Router(const rclcpp::NodeOptions & options, const std::string & node_name = "router")
  : rclcpp::Node(node_name, options) {
    pub_ = create_publisher<std_msgs::msg::String>("routed", 10);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
}  // namespace plan
"""

DELEGATING_MAIN = """
#include "pkg/router.hpp"
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::NodeOptions options;
  auto node = std::make_shared<rclcpp::Node>("container", options);
  auto router = std::make_shared<plan::Router>(options, "mavros_like_router");
  rclcpp::spin(node);
}
"""

ROUTER_SOURCE = '#include "pkg/router.hpp"\nplan::Router * make() { return nullptr; }\n'


def test_a_delegating_constructor_nothing_calls_names_no_node(write_tree) -> None:
    """mavros' Router has ``Router(node_name) : Router(NodeOptions(), node_name)`` beside
    the ``Router(options, node_name)`` mavros_node's main builds: the file that holds the
    first's code named the class's node by its parameter, which no call fills ("?"),
    beside "mavros_router": two names, no node told, and the router's 23 calls went to
    the process's first node."""
    root = write_tree({"pkg/package.xml": PACKAGE, "pkg/include/pkg/router.hpp": DELEGATING,
                       "pkg/src/main.cpp": DELEGATING_MAIN,
                       "pkg/src/router.cpp": ROUTER_SOURCE})
    result = _extract(root, "main.cpp", "router.cpp")
    assert sorted(result.rosnames) == ["container", "mavros_like_router"]
    assert ("publish", "routed", "mavros_like_router") in rows(result)
