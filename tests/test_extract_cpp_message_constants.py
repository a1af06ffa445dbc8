"""A constant of a message known only by name, read in a case label (``case
Action::Goal::TOOL_CONTACT:``, the Universal Robots driver's trajectory_until_node with
ur_msgs not in the workspace): declared a constant of the synthesised message, so the
switch parses and the function that calls the ROS API there is not partial."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <rclcpp/rclcpp.hpp>
#include <vendor_msgs/action/move_until.hpp>
#include <std_msgs/msg/string.hpp>
using MoveUntil = vendor_msgs::action::MoveUntil;
class Mover : public rclcpp::Node {
 public:
  Mover() : Node("mover") {}
  void pick(std::shared_ptr<const MoveUntil::Goal> goal) {
    vendor::init();
    switch (goal->until_type) {
      case MoveUntil::Goal::TOOL_CONTACT:
        contact_ = create_publisher<std_msgs::msg::String>("contact", 1);
        break;
      case MoveUntil::Goal::FORCE:
      case 1:
        force_ = create_publisher<std_msgs::msg::String>("force", 1);
        break;
      default:
        break;
    }
    if (goal->until_type == MoveUntil::Goal::TOOL_CONTACT) {
      goal->speed;
    }
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr contact_, force_;
};
"""


def test_a_message_constant_in_a_case_label(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("mover", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"))
    source = tmp_path / "mover.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [
        ("publish", "contact"), ("publish", "force")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_NAMES_DECLARED" in codes
    assert "CPP_PARSE_ERROR" not in codes and "CPP_ERROR_NEAR_CALL" not in codes
