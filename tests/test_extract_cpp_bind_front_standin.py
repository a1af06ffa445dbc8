"""C++20's ``std::bind_front``: ateam's (RoboCup SSL A-Team, Jazzy) joystick and radio
bridge components, built with ``set_target_properties(... CXX_STANDARD 20)``, hand
``std::bind_front(&Node::method, this)`` to ``rclcpp::on_shutdown`` and to their
subscriptions; the std stand-ins had no bind_front, so each constructor was a C++ error
near the ROS calls and four nodes partial. In C++17 it stays an error, as the compiler
says."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
#include <functional>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

namespace team
{
class Radio : public rclcpp::Node
{
public:
  explicit Radio(const rclcpp::NodeOptions & options)
  : Node("radio", options)
  {
    rclcpp::on_shutdown(std::bind_front(&Radio::stop, this));
    sub_ = create_subscription<std_msgs::msg::String>(
      "team_color", 1, std::bind_front(&Radio::on_color, this));
    pub_ = create_publisher<std_msgs::msg::String>("status", 10);
  }

private:
  void stop() {}
  void on_color(const std_msgs::msg::String::SharedPtr msg) { (void)msg; }
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
}  // namespace team
"""

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(pkg)
find_package(rclcpp REQUIRED)
add_library(${{PROJECT_NAME}} SHARED src/radio.cpp)
set_target_properties(${{PROJECT_NAME}} PROPERTIES CXX_STANDARD {std})
"""


def _run(write_tree, std: str):
    root = write_tree({"pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "pkg/CMakeLists.txt": CMAKE.format(std=std),
                       "pkg/src/radio.cpp": SOURCE})
    return extract_cpp([str(root / "pkg" / "src" / "radio.cpp")], scan([str(root)]),
                       cache_dir=None)


def test_bind_front_in_a_cpp20_component(write_tree) -> None:
    result = _run(write_tree, "20")
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("subscribe", "team_color"), ("publish", "status")]


def test_bind_front_is_an_error_in_cpp17(write_tree) -> None:
    result = _run(write_tree, "17")
    assert any("bind_front" in d.message for d in result.diagnostics
               if d.code == "CPP_PARSE_ERROR")
