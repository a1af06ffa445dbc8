"""realtime_tools' AsyncFunctionHandlerParams::initialize(node, prefix) (jazzy) reads the
async handler's settings from the node's parameters under the prefix, each only when the
node has it: ros2_control's controller base calls it with "async_parameters."
(controller_interface_base.cpp:260 at ros2_control 9ffbf97f). With no stand-in the class
was unknown and the node given to it made the node partial."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_lifecycle/lifecycle_node.hpp"
#include "realtime_tools/async_function_handler.hpp"
class Worker {
public:
  void configure()
  {
    node_ = std::make_shared<rclcpp_lifecycle::LifecycleNode>("worker");
    realtime_tools::AsyncFunctionHandlerParams params;
    params.initialize(node_, "async_parameters.");
    if (params.scheduling_policy == realtime_tools::AsyncSchedulingPolicy::DETACHED) {
      RCLCPP_ERROR(node_->get_logger(), "detached");
    }
    handler_.init(
      [](const rclcpp::Time &, const rclcpp::Duration &) { return 0; }, params);
    pub_ = node_->create_publisher<std_msgs::msg::String>("state", 1);
  }
private:
  rclcpp_lifecycle::LifecycleNode::SharedPtr node_;
  realtime_tools::AsyncFunctionHandler<int> handler_;
  std::shared_ptr<rclcpp::Publisher<std_msgs::msg::String>> pub_;
};
"""


def test_async_parameters_are_read_under_the_prefix_with_defaults(write_tree) -> None:
    root = write_tree({"pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "pkg/src/node.cpp": '#include "std_msgs/msg/string.hpp"\n' + SOURCE})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NODE_TO_UNKNOWN")] == []
    reads = {(c.name, c.type, c.has_default) for c in result.calls if c.kind == "read"}
    assert reads == {
        ("async_parameters.thread_priority", "int", True),
        ("async_parameters.cpu_affinity", "int[]", True),
        ("async_parameters.scheduling_policy", "str", True),
        ("async_parameters.execution_rate", "int", True),
        ("async_parameters.wait_until_initial_trigger", "bool", True),
        ("async_parameters.print_warnings", "bool", True)}
    assert ("publish", "state") in [(c.kind, c.name) for c in result.calls]


def test_a_method_named_initialize_is_no_ros_call_site() -> None:
    # ros2_control's resource manager: ``hardware.initialize(component_params)`` (the
    # row's name is too common to mark a line as a place a ROS call may be missing)
    from haros_arch.extract.cpp.recall import call_sites
    text = "void f() {\n  auto state = hardware.initialize(component_params);\n}\n"
    assert call_sites(text) == []


def test_an_unknown_class_s_initialize_is_still_declared_permissively(write_tree) -> None:
    # the form of ros2_controllers' admittance_rule_impl.hpp:62, kinematics_->initialize
    # (...) on a class of a library with no stand-in: the node given to it makes the node
    # partial. (A guard: on admittance_controller itself the row's ``initialize`` kept
    # out of the permissive declarations lost this; this small unit declares the member
    # from clang's error either way.)
    source = """
#include "rclcpp/rclcpp.hpp"
#include "kinematics_interface/kinematics_interface.hpp"
class Rule {
public:
  void configure(const std::shared_ptr<rclcpp::Node> & node)
  {
    kinematics_->calculate_link_transform(joints_, "tip", transform_);
    if (!kinematics_->initialize(description_, node->get_node_parameters_interface(), "tip")) {
      return;
    }
    pub_ = node->create_publisher<std_msgs::msg::String>("state", 1);
  }
private:
  std::unique_ptr<kinematics_interface::KinematicsInterface> kinematics_;
  std::vector<double> joints_;
  std::vector<double> transform_;
  std::string description_;
  std::shared_ptr<rclcpp::Publisher<std_msgs::msg::String>> pub_;
};
"""
    root = write_tree({"pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "pkg/src/node.cpp": '#include "std_msgs/msg/string.hpp"\n' + source})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [d.code for d in result.diagnostics if d.code == "CPP_NODE_TO_UNKNOWN"] == [
        "CPP_NODE_TO_UNKNOWN"]
