"""C++20's <numbers>: a ROS 2 node that converts its angle parameters with
``std::numbers::pi`` (kyubic_ros' localization components, their CMakeLists asking for
C++20) had no such header among the std stand-ins: the include was an empty stand-in
(CPP_INCLUDE_MISSING) and the constructor that makes the publishers a C++ error, so
the node was partial."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
#include <numbers>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>

class Turner : public rclcpp::Node
{
public:
  Turner() : Node("turner")
  {
    double degrees = declare_parameter("yaw_offset_deg", 90.0);
    offset_ = degrees * std::numbers::pi / 180.0;
    float half = std::numbers::pi_v<float> / 2.0f + static_cast<float>(std::numbers::sqrt2);
    (void)half;
    pub_ = create_publisher<std_msgs::msg::Float64>("yaw", 10);
  }

private:
  double offset_;
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Turner>());
}
"""


def test_std_numbers_constants_parse(write_tree) -> None:
    root = write_tree({"pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "pkg/src/node.cpp": SOURCE})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    codes = [d.code for d in result.diagnostics]
    assert "CPP_INCLUDE_MISSING" not in codes
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("declare", "yaw_offset_deg"), ("publish", "yaw")]


def test_std_numbers_reached_without_its_include_in_cpp20(write_tree) -> None:
    """libstdc++ includes <numbers> from its ranges support, which <string> and the
    other headers use in C++20: a source built as C++20 that writes std::numbers::pi
    after <rclcpp/rclcpp.hpp> alone compiles; in C++17 it is an error."""
    source = SOURCE.replace("#include <numbers>\n", "")
    cmake = ("cmake_minimum_required(VERSION 3.8)\nproject(pkg)\n"
             "set(CMAKE_CXX_STANDARD {std})\nfind_package(rclcpp REQUIRED)\n"
             "add_executable(turner src/node.cpp)\n")
    for std in ("20", "17"):
        root = write_tree({"pkg/package.xml": package_xml("pkg", "ament_cmake"),
                           "pkg/CMakeLists.txt": cmake.format(std=std),
                           "pkg/src/node.cpp": source})
        result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                             cache_dir=None)
        found = [d.message for d in result.diagnostics
                 if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")]
        if std == "20":
            assert found == []
        else:
            assert found and "numbers" in found[0]
