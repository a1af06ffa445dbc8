"""A constant of a message known only by name, given as a template's argument through a
cast or a product (nao_lola's ``std::array<float, 3 *
static_cast<int>(nao_command_msgs::msg::LeftEyeLeds::NUM_LEDS)> l_eye;``, the message
package not in the workspace), is a constant as one written bare is
(test_extract_cpp_unknown_template_size): it was a static member, no constant
expression, the member an error, the class holding it invalid and so the node's class
that holds one: every publisher of its constructor unresolved and the node partial."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <array>
#include "rclcpp/rclcpp.hpp"
#include "vendor_msgs/msg/left_eye_leds.hpp"
#include "vendor_msgs/msg/head_leds.hpp"
#include "vendor_msgs/msg/sonar.hpp"

class Packer
{
public:
  Packer() {}
private:
  std::array<float, static_cast<int>(vendor_msgs::msg::HeadLeds::NUM_LEDS)> skull;
  std::array<float, 3 * static_cast<int>(vendor_msgs::msg::LeftEyeLeds::NUM_LEDS)> l_eye;
};

class Bridge : public rclcpp::Node
{
public:
  Bridge() : rclcpp::Node("bridge")
  {
    sonar_pub = create_publisher<vendor_msgs::msg::Sonar>("sensors/sonar", 10);
  }
private:
  rclcpp::Publisher<vendor_msgs::msg::Sonar>::SharedPtr sonar_pub;
  Packer packer;
};
"""


def test_a_cast_constant_of_an_unknown_message_as_a_template_argument(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("bridge", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>vendor_msgs</depend></package>"))
    source = tmp_path / "bridge.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="humble")
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("publish", "sensors/sonar", "vendor_msgs/msg/Sonar")]
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL",
                          "CPP_CALL_UNRESOLVED")] == []
