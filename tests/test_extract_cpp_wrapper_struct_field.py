"""A wrapper whose name argument reaches the ROS call through a field of a local it fills
first: nav2_util's ``LifecycleNode::add_parameter(name, default_value, ...)`` (humble,
jazzy) writes ``descriptor.name = name`` and calls ``declare_parameter(descriptor.name,
default_value, descriptor)``. It was no wrapper: its declaration stayed in the helper,
named per call site, and the default each call site gives was lost (nav2_amcl declares
about fifty parameters so; ``robot_model_type``, the class its motion model loads, had
no default). Now each call site declares its parameter with its own default."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

BASE = """
#include <rclcpp/rclcpp.hpp>
#include <rcl_interfaces/msg/parameter_descriptor.hpp>
class Base : public rclcpp::Node {
public:
  explicit Base(const std::string & n) : rclcpp::Node(n) {}
  void add_parameter(const std::string & name, const rclcpp::ParameterValue & default_value,
                     const std::string & description = "", bool read_only = false)
  {
    auto descriptor = rcl_interfaces::msg::ParameterDescriptor();
    descriptor.name = name;
    descriptor.description = description;
    descriptor.read_only = read_only;
    declare_parameter(descriptor.name, default_value, descriptor);
  }
};
"""

AMCL = """
#include "base.hpp"
class Amcl : public Base {
public:
  Amcl() : Base("amcl") {
    add_parameter("robot_model_type",
                  rclcpp::ParameterValue("nav2_amcl::DifferentialMotionModel"));
    add_parameter("laser_model_type", rclcpp::ParameterValue(std::string("likelihood_field")));
    add_parameter("tf_broadcast", rclcpp::ParameterValue(true), "publish the transform");
    add_parameter("max_beams", rclcpp::ParameterValue(60));
  }
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Amcl>());
}
"""


def test_each_call_site_of_the_helper_declares_with_its_default(write_tree) -> None:
    root = write_tree({"amcl/package.xml": package_xml("amcl", "ament_cmake"),
                       "amcl/src/base.hpp": BASE, "amcl/src/amcl.cpp": AMCL})
    result = extract_cpp([str(root / "amcl" / "src" / "amcl.cpp")], scan([str(root)]),
                         cache_dir=None)
    declared = sorted((c.name, c.default, c.has_default, c.location.file.rsplit("/", 1)[-1],
                       c.location.line) for c in result.calls if c.kind == "declare")
    assert declared == [
        ("laser_model_type", "likelihood_field", True, "amcl.cpp", 7),
        ("max_beams", 60, True, "amcl.cpp", 9),
        ("robot_model_type", "nav2_amcl::DifferentialMotionModel", True, "amcl.cpp", 5),
        ("tf_broadcast", True, True, "amcl.cpp", 8),
    ]
