"""A parameter helper that declares each parameter with a default computed from one of
its own parameters (``declare_parameter<int>(name + ".can_id", defaults.can_id)``, a field
of a struct its callers pass; ``declare_parameter(name, scale * 2.0)``; a local's field,
``parameter.inverted``): rclcpp's
``declare_parameter(name, value)`` always gives the parameter that value, whatever it is,
so each call site declares it with a default, whose value the call site alone knows (EduArt's
edu_robot: ``MotorControllerHardware::get_parameter(name, {}, node)``). The default was
dropped, as if the helper declared the parameter without one, and every read that
followed was a parameter-read-not-set warning. A typed declaration the helper is handed
(``declare_parameter(name, type)`` of an ``rclcpp::ParameterType``) stays without one."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HELPER = """
#include <rclcpp/rclcpp.hpp>
class MotorHardware {
public:
  struct Parameter { int can_id = 3; float gear_ratio = 1.0f; bool inverted = false; };
  static Parameter get_parameter(const std::string & name, const Parameter & defaults,
                                 rclcpp::Node & node)
  {
    Parameter parameter;
    node.declare_parameter<int>(name + ".can_id", defaults.can_id);
    node.declare_parameter<float>(name + ".gear_ratio", defaults.gear_ratio * 2.0f);
    node.declare_parameter<bool>(name + ".inverted", parameter.inverted);
    node.declare_parameter(name + ".label", rclcpp::ParameterValue(std::string("m")));
    parameter.can_id = node.get_parameter(name + ".can_id").as_int();
    parameter.gear_ratio = node.get_parameter(name + ".gear_ratio").as_double();
    parameter.inverted = node.get_parameter(name + ".inverted").as_bool();
    return parameter;
  }
};
inline void typed(const std::string & name, rclcpp::ParameterType type, rclcpp::Node & node)
{
  node.declare_parameter(name, type);
}
"""

NODE = """
#include "helper.hpp"
class Bot : public rclcpp::Node {
public:
  Bot() : rclcpp::Node("bot") {
    for (int i = 0; i < 2; ++i) {
      MotorHardware::get_parameter("motor_" + std::to_string(i), {}, *this);
    }
    MotorHardware::get_parameter("spare", MotorHardware::Parameter{}, *this);
    typed("mode", rclcpp::PARAMETER_STRING, *this);
  }
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Bot>());
}
"""


def test_a_default_computed_from_the_helper_s_parameter_is_a_default(write_tree) -> None:
    root = write_tree({"bot/package.xml": package_xml("bot", "ament_cmake"),
                       "bot/src/helper.hpp": HELPER, "bot/src/bot.cpp": NODE})
    result = extract_cpp([str(root / "bot" / "src" / "bot.cpp")], scan([str(root)]),
                         cache_dir=None)
    declared = sorted({(c.name, c.has_default) for c in result.calls
                       if c.kind == "declare"})
    assert declared == [
        ("mode", False),
        ("motor_0.can_id", True), ("motor_0.gear_ratio", True), ("motor_0.inverted", True),
        ("motor_0.label", True),
        ("motor_1.can_id", True), ("motor_1.gear_ratio", True), ("motor_1.inverted", True),
        ("motor_1.label", True),
        ("spare.can_id", True), ("spare.gear_ratio", True), ("spare.inverted", True),
        ("spare.label", True),
    ]
