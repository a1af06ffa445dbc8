"""``std::put_time`` / ``std::get_time`` (``<iomanip>``): PlanSys2's BT action node
writes the time it started with ``std::put_time(std::localtime(&t), "%F %T")`` beside
its ROS calls (survey Z40); the stand-in standard library had no such manipulator, an
error in a function that calls the ROS API, so the node was partial."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = """\
#include <ctime>
#include <iomanip>
#include <sstream>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
class Logger : public rclcpp::Node {
public:
  Logger() : Node("logger") {
    std::time_t now = std::time(nullptr);
    std::stringstream text;
    text << std::put_time(std::localtime(&now), "%Y-%m-%d %H:%M:%S");
    std::tm parsed{};
    std::istringstream("2024-01-01") >> std::get_time(&parsed, "%Y-%m-%d");
    pub_ = create_publisher<std_msgs::msg::String>("started", 10);
  }
private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
"""


def test_time_manipulators_leave_no_error_near_the_calls(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("logger"))
    source = tmp_path / "logger.cpp"
    source.write_text(NODE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="jazzy")
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "started")]
