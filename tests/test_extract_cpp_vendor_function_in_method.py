"""An unqualified call of a vendor's C function, its header missing, in a method of a
class whose every base the parse reads: ros_phoenix's PhoenixManager (2023Rover's
phoenix_manager.cpp:47) calls ``c_SetPhoenixDiagnosticsStartTime(1);`` in its constructor,
the function of CTRE's ``ctre/phoenix/cci/Unmanaged_CCI.h``, whose prefix ``c_`` no
missing header's name gives. The permissive declarations left an unqualified name in a
class alone (it could be a member of a base the parse does not know) unless the class has
no base; here the one base, rclcpp_components' ComponentManager, is read whole, so the
name is no member: declared free. A class with a base the parse does not know keeps the
error (the name may be that base's)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/int32.hpp>
#include "vendor/cci/Unmanaged_CCI.h"

class Base : public rclcpp::Node {
public:
  Base() : Node("manager") {}
};

class Manager : public BASE {
public:
  Manager() {
    pub_ = create_publisher<std_msgs::msg::Int32>("status", 10);
    c_SetDiagnosticsStartTime(1);
  }
private:
  rclcpp::Publisher<std_msgs::msg::Int32>::SharedPtr pub_;
};
"""


def _extract(write_tree, base: str):
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "ament_cmake"),
        "pkg/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(pkg)\n"
                              "add_executable(manager src/manager.cpp)\n",
        "pkg/src/manager.cpp": SOURCE.replace("BASE", base)})
    return extract_cpp([str(root / "pkg" / "src" / "manager.cpp")], scan([str(root)]),
                       cache_dir=None)


def test_a_vendor_function_called_in_a_method_of_a_class_whose_bases_are_read(
        write_tree) -> None:
    result = _extract(write_tree, "Base")
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "status")]


def test_a_class_with_an_unknown_base_keeps_the_error(write_tree) -> None:
    result = _extract(write_tree, "vendor::Device")
    assert "C++ error: use of undeclared identifier 'c_SetDiagnosticsStartTime'" in [
        d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"]
