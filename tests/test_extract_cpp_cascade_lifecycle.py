"""rclcpp_cascade_lifecycle's ``CascadeLifecycleNode`` (PlanSys2's servers and action
performers derive from it) has a stand-in for a workspace that does not hold it: the
base was unknown, so every call of its members the derived class makes unqualified
(``get_parameter``, ``now``, ``get_logger``) was a parse error near the node's calls
(plansys2 b82cc6f: 64 clang errors -> 21), and what its constructor makes (a lifecycle
node's services and transition topic, the cascade's activations and states topics) was
missing. And a static method of a node class (``ActionExecutorClient::make_shared``) is
run by code near a parse error only where that code names its class too: ``std::
make_shared`` near an error made plansys2's compute_bt and executor_node build an
``ActionExecutorClient`` they never build (its lifecycle services counted twice)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

PERFORMER = """
#include <chrono>
#include <string>
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_cascade_lifecycle/rclcpp_cascade_lifecycle.hpp"

class Performer : public rclcpp_cascade_lifecycle::CascadeLifecycleNode {
public:
  explicit Performer(const std::string & node_name)
  : CascadeLifecycleNode(node_name) {
    declare_parameter<double>("rate", 1.0);
    double rate = get_parameter("rate").as_double();
    RCLCPP_INFO(get_logger(), "rate %f at %f", rate, now().seconds());
    add_activation("planner");
  }
};

int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<Performer>("move");
  rclcpp::spin(node->get_node_base_interface());
}
"""

LIBRARY = """
#include <memory>
#include <string>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"
namespace plan {
class Client : public rclcpp::Node {
public:
  using Ptr = std::shared_ptr<Client>;
  static Ptr make_shared(const std::string & name) { return std::make_shared<Client>(name); }
  explicit Client(const std::string & name) : Node(name) {
    pub_ = create_publisher<std_msgs::msg::String>("status", 10);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
class Server : public rclcpp::Node {
public:
  Server() : Node("server") {
    sub_ = create_subscription<std_msgs::msg::String>(
      "status", 10, [](std_msgs::msg::String::SharedPtr) {});
  }
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};
}  // namespace plan
"""
MAIN = """
#include "pkg/lib.hpp"
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto server = std::make_shared<plan::Server>();
  int wrong = std::make_shared<plan::Server>(1, 2, 3, 4);
  rclcpp::spin(server);
}
"""


def _package(name: str) -> str:
    return package_xml(name, "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend>"
        "<depend>rclcpp_cascade_lifecycle</depend></package>")


def test_a_cascade_lifecycle_node_parses_and_makes_what_its_base_makes(write_tree) -> None:
    root = write_tree({"perf/package.xml": _package("perf"),
                       "perf/src/perf.cpp": PERFORMER})
    result = extract_cpp([str(root / "perf" / "src" / "perf.cpp")], scan([str(root)]),
                         cache_dir=None)
    errors = [d.message for d in result.diagnostics
              if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED")]
    assert errors == []
    assert result.rosname == "move"
    calls = {(c.kind, c.name) for c in result.calls}
    assert {("declare", "rate"), ("read", "rate"), ("publish", "~transition_event"),
            ("server", "~change_state"),
            ("publish", "cascade_lifecycle_activations"),
            ("subscribe", "cascade_lifecycle_activations"),
            ("publish", "cascade_lifecycle_states"),
            ("subscribe", "cascade_lifecycle_states")} <= calls


def test_a_static_factory_runs_only_where_hidden_code_names_its_class(write_tree) -> None:
    root = write_tree({"pkg/package.xml": _package("pkg"),
                       "pkg/include/pkg/lib.hpp": LIBRARY,
                       "pkg/src/lib.cpp": '#include "pkg/lib.hpp"\n',
                       "pkg/src/main.cpp": MAIN})
    result = extract_cpp([str(root / "pkg" / "src" / "lib.cpp"),
                          str(root / "pkg" / "src" / "main.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert any(d.code == "CPP_PARSE_ERROR" or d.code == "CPP_ERROR_NEAR_CALL"
               for d in result.diagnostics)
    assert sorted((c.kind, c.name) for c in result.calls) == [("subscribe", "status")]
