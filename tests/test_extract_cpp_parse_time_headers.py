"""A header only a parse finds missing (its include written through a macro, which the
scan before parsing does not read) is stood in for by the first unit that parses it;
every unit that includes it says it missing where it includes it, whichever unit of
its process was parsed first. With two workers a unit's result depended on the units
its worker had parsed before (two cold runs of six fetched trees: 3 of 560 units
differed); here, one process, the two orders of the same two units."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp_nodes
from haros_arch.workspace import scan

UNIT = """
#include <ros/ros.h>
#define VENDOR_HEADER <vendor_lib/device.h>
#include VENDOR_HEADER

int main(int argc, char** argv) {{
  ros::init(argc, argv, "{name}");
  ros::NodeHandle node;
  ros::Publisher pub = node.advertise<std_msgs::String>("{name}_out", 1);
  return 0;
}}
"""


def _sources(tmp_path: Path, manifest: str = "", first_text: str = "",
             second_text: str = "") -> tuple[Path, Path]:
    """Package ``demo`` with two units (by default the ROS 1 ones of ``UNIT``)."""
    package = tmp_path / "src" / "demo"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(manifest or (
        '<package format="2"><name>demo</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        "<license>BSD</license><depend>roscpp</depend><depend>std_msgs</depend>"
        "</package>\n"))
    first, second = package / "src" / "first.cpp", package / "src" / "second.cpp"
    first.write_text(first_text or "#include <std_msgs/String.h>\n" + UNIT.format(name="first"))
    second.write_text(second_text
                      or "#include <std_msgs/String.h>\n" + UNIT.format(name="second"))
    return first, second


def _said(result: object) -> list[tuple[str, str, int]]:
    return sorted((d.code, d.message, d.location.line)
                  for d in result.diagnostics)  # type: ignore[attr-defined]


def test_each_unit_says_a_header_a_parse_stood_in_for_whatever_the_order(
        tmp_path: Path) -> None:
    first, second = _sources(tmp_path)
    workspace = scan([str(tmp_path)])
    ahead = extract_cpp_nodes([[str(first)], [str(second)]], workspace, cache_dir=None,
                              jobs=1)
    behind = extract_cpp_nodes([[str(second)], [str(first)]], scan([str(tmp_path)]),
                               cache_dir=None, jobs=1)
    one, two = ahead.results
    two_first, one_second = behind.results
    assert _said(one) == _said(one_second) and _said(two) == _said(two_first)
    for result in (one, two):
        missing = [d for d in result.diagnostics if d.code == "CPP_INCLUDE_MISSING"]
        assert [d.message for d in missing] == [
            "header vendor_lib/device.h not found; an empty stand-in was used"], missing
        assert missing[0].location.line == 5  # the unit's own include
    assert [(c.kind, c.name) for c in two.calls] == [("publish", "second_out")]


ROS2_UNIT = """
#include <rclcpp/rclcpp.hpp>
#define MESSAGE_HEADER <geometry_msgs/msg/twist.hpp>
#include MESSAGE_HEADER
class {name} : public rclcpp::Node {{
 public:
  {name}() : rclcpp::Node("{name}") {{
    pub_ = create_publisher<geometry_msgs::msg::Twist>("{name}_out", 3);
  }}
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr pub_;
}};
"""


def test_a_ros2_message_header_only_a_parse_finds_is_the_message(tmp_path: Path) -> None:
    """A parse's missing ``pkg/msg/name.hpp`` of a known interface is made as the message
    (it was an empty stand-in, while a unit that named the type unincluded had the same
    header made as the message: which one a worker's file held depended on the order
    its units came in)."""
    first, second = _sources(
        tmp_path,
        '<package format="3"><name>demo</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        "<license>BSD</license><depend>rclcpp</depend><depend>geometry_msgs</depend>"
        "<export><build_type>ament_cmake</build_type></export></package>\n",
        ROS2_UNIT.format(name="First"), ROS2_UNIT.format(name="Second"))
    ahead = extract_cpp_nodes([[str(first)], [str(second)]], scan([str(tmp_path)]),
                              cache_dir=None, jobs=1)
    behind = extract_cpp_nodes([[str(second)], [str(first)]], scan([str(tmp_path)]),
                               cache_dir=None, jobs=1)
    one, two = ahead.results
    two_first, one_second = behind.results
    assert _said(one) == _said(one_second) == [] and _said(two) == _said(two_first) == []
    assert [(c.kind, c.name, c.type, c.queue_size) for c in one.calls] == [
        ("publish", "First_out", "geometry_msgs/msg/Twist", 3)]
