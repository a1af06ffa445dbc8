"""rclcpp's ``declare_parameter(name, rclcpp::PARAMETER_STRING)`` declares the parameter
uninitialised when no override sets it, and does not throw (rclcpp's
node_parameters.cpp); the templated ``declare_parameter<T>(name)`` does, as it returns
the value. phidgets_drivers declares ``server_name`` so and reads it only under
``if (get_parameter("server_name", server_name_))``: it is optional, and was 48 false
``parameter-read-not-set`` warnings over its ten nodes."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """
#include <rclcpp/rclcpp.hpp>
class Phidget : public rclcpp::Node {
 public:
  Phidget() : Node("phidget") {
    declare_parameter("server_name", rclcpp::ParameterType::PARAMETER_STRING);
    if (get_parameter("server_name", server_name_)) {
      RCLCPP_INFO(get_logger(), "%s", server_name_.c_str());
    }
    declare_parameter<double>("rate");
  }
  std::string server_name_;
};
"""


def test_a_declaration_of_a_type_alone_is_no_read_that_needs_the_value(write_tree) -> None:
    root = write_tree({"ph/package.xml": package_xml("ph", "ament_cmake"),
                       "ph/src/node.cpp": NODE})
    result = extract_cpp([str(root / "ph" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name, c.type, c.has_default, c.tested) for c in result.calls] == [
        ("declare", "server_name", "str", False, True),
        ("read", "server_name", "str", False, True),
        # the templated declaration returns the value: it throws when nothing sets it
        ("declare", "rate", "double", False, False)]


FOXY = """
#include <rclcpp/rclcpp.hpp>
class Base : public rclcpp::Node {
 public:
  Base() : Node("base") {
    declare_parameter("use_mcnamu");
    get_parameter_or<bool>("use_mcnamu", use_mcnamu_, false);
    declare_parameter("port_name");
    get_parameter("port_name", port_);
  }
  bool use_mcnamu_;
  std::string port_;
};
"""


def test_a_declaration_of_a_name_alone_is_no_read_that_needs_the_value(write_tree) -> None:
    # Foxy's declare_parameter(name) declares an uninitialised value and does not throw
    # (limo_ros2's limo_base, then get_parameter_or with a default): no read of its own;
    # a later read without default still needs the value
    root = write_tree({"lb/package.xml": package_xml("lb", "ament_cmake"),
                       "lb/src/node.cpp": FOXY})
    result = extract_cpp([str(root / "lb" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name, c.has_default, c.tested) for c in result.calls] == [
        ("declare", "use_mcnamu", False, True), ("read", "use_mcnamu", True, False),
        ("declare", "port_name", False, True), ("read", "port_name", False, False)]
