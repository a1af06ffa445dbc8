"""A vendor factory's result assigned to a ``std::unique_ptr`` with the vendor's headers
missing: hebi_ros2_examples' arm_node.cpp:1375 ``arm_ = arm::Arm::create(*arm_config);``
in the function that makes the node's publishers. The permissive parse takes ``create``
for a class whose value converts to anything; unique_ptr's ``operator=(unique_ptr&&)`` and
``operator=(nullptr_t)`` took it alike, the assignment was ambiguous, an error near the ROS
calls, and the node partial. Assigning ``nullptr`` or another unique_ptr stays as it was."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
#include <memory>
#include <utility>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <vendor_api/arm.hpp>

struct Gripper {};

class ArmNode : public rclcpp::Node {
public:
  ArmNode() : Node("arm_node") {}
  bool init() {
    auto config = vendor::arm::ArmConfig::load("arm.cfg.yaml");
    arm_ = vendor::arm::Arm::create(*config);
    if (!arm_) {
      return false;
    }
    std::unique_ptr<Gripper> gripper(new Gripper());
    gripper_ = std::move(gripper);
    gripper_ = nullptr;
    pub_ = create_publisher<std_msgs::msg::String>("arm_state", 10);
    return true;
  }
private:
  std::unique_ptr<vendor::arm::Arm> arm_;
  std::unique_ptr<Gripper> gripper_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
"""


def test_a_permissive_factory_result_assigned_to_a_unique_ptr(write_tree) -> None:
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "ament_cmake"),
        "pkg/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(pkg)\n"
                              "add_executable(arm src/arm.cpp)\n",
        "pkg/src/arm.cpp": SOURCE})
    result = extract_cpp([str(root / "pkg" / "src" / "arm.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "arm_state")]
