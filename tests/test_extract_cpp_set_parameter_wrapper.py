"""A wrapper that writes a parameter through ``set_parameter(rclcpp::Parameter(name,
value))`` names the parameter by the argument the call site gives as ``name``, never by
its value: sick_scan_xd's ``rosSetParam(nh, "hostname", "192.168.0.1")``
(sick_ros_wrapper.h) writes ``hostname``, not a parameter named ``192.168.0.1``."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = r"""
#include <rclcpp/rclcpp.hpp>
#include <string>

template <typename T> void setParam(rclcpp::Node::SharedPtr nh, const std::string& param_name,
                                    const T& param_value)
{
  try {
    nh->set_parameter(rclcpp::Parameter(param_name, param_value));
  } catch (const std::exception&) {
  }
}

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("writer");
  setParam(node, "hostname", "192.168.0.1");
  setParam(node, "imu_topic", std::string("imu"));
  setParam(node, "rate", 5);
  node->set_parameter(rclcpp::Parameter("direct", "value"));
  rclcpp::spin(node);
}
"""


def test_the_written_name_is_the_name_argument(write_tree) -> None:
    root = write_tree({
        "src/w/package.xml": package_xml("w", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend></package>"),
        "src/w/CMakeLists.txt": "project(w)\nadd_executable(writer src/writer.cpp)\n",
        "src/w/src/writer.cpp": NODE,
    })
    result = extract_cpp([str(root / "src/w/src/writer.cpp")], scan([str(root / "src")]),
                         cache_dir=None)
    writes = sorted((c.name, c.location.line) for c in result.calls if c.kind == "write")
    assert writes == [("direct", 19), ("hostname", 16), ("imu_topic", 17), ("rate", 18)]


DECLARE = r"""
#include <rclcpp/rclcpp.hpp>
#include <string>

template <typename T> void declareParam(rclcpp::Node::SharedPtr nh, const std::string& name,
                                        const T& value)
{
  if (!nh->has_parameter(name)) {
    nh->declare_parameter<T>(name, value);
  }
}

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("decl");
  declareParam(node, "hostname", "192.168.0.1");
  declareParam(node, "port", 2112);
  rclcpp::spin(node);
}
"""


def test_declare_parameter_of_a_character_array_parses(write_tree) -> None:
    """rclcpp's ``declare_parameter<T>(name, const T&)`` takes T = ``char[N]`` (the
    value converts to a string): sick_scan_xd's ``rosDeclareParam(nh, "hostname",
    "192.168.0.1")`` is no C++ error near the call, and its declarations are read."""
    root = write_tree({
        "src/d/package.xml": package_xml("d", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend></package>"),
        "src/d/CMakeLists.txt": "project(d)\nadd_executable(decl src/decl.cpp)\n",
        "src/d/src/decl.cpp": DECLARE,
    })
    result = extract_cpp([str(root / "src/d/src/decl.cpp")], scan([str(root / "src")]),
                         cache_dir=None)
    assert [d.message for d in result.diagnostics if d.code.startswith("CPP_ERROR")] == []
    declared = sorted((c.name, c.location.line) for c in result.calls if c.kind == "declare")
    assert declared == [("hostname", 15), ("port", 16)]
