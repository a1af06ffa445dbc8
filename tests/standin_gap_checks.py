"""The check the stand-in gap tests share (``test_extract_cpp_standin_gaps_*``): a node
whose source uses a library the stand-ins declare parses without an error, and its ROS
call after that use (a publisher of ``out``) is found."""

from __future__ import annotations

from pathlib import Path

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

ROS1_HEAD = "#include <ros/ros.h>\n#include <std_msgs/String.h>\n"


def ros1_main(include: str, body: str) -> str:
    """A roscpp main whose ``body`` comes before its publisher of ``out``."""
    return (ROS1_HEAD + include + "int main(int argc, char** argv) {\n"
            "  ros::init(argc, argv, \"node\");\n  ros::NodeHandle nh;\n" + body +
            "  ros::Publisher pub = nh.advertise<std_msgs::String>(\"out\", 1);\n}\n")


ROS2_HEAD = "#include <rclcpp/rclcpp.hpp>\n#include <std_msgs/msg/string.hpp>\n"


def ros2_main(include: str, body: str) -> str:
    """An rclcpp main whose ``body`` comes before its publisher of ``out``."""
    return (ROS2_HEAD + include + "int main(int argc, char** argv) {\n"
            "  rclcpp::init(argc, argv);\n"
            "  auto node = std::make_shared<rclcpp::Node>(\"node\");\n" + body +
            "  auto pub = node->create_publisher<std_msgs::msg::String>(\"out\", 10);\n}\n")


def assert_call_found(tmp_path: Path, text: str, build: str | None = None,
                      distro: str = "noetic") -> None:
    """``text`` as the node's source parses without an error, and its publisher of
    ``out`` is found."""
    (tmp_path / "package.xml").write_text(package_xml("node", build))
    source = tmp_path / "node.cpp"
    source.write_text(text)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro=distro)
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED",
                          "CPP_INCLUDE_MISSING")] == []
    assert [(c.kind, c.name) for c in result.calls if c.name == "out"] == [("publish", "out")]
