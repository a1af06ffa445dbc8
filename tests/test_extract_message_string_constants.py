"""A string constant of a message the workspace defines, used as a topic name
(smarc2's ``string DVL_TOPIC = 'core/dvl'`` in sam_msgs' Topics.msg, read as
``sam_msgs::msg::Topics::DVL_TOPIC`` in C++ and ``Topics.DVL_TOPIC`` in Python).
rosidl takes the value without its outer quotes (rosidl_adapter's
``parse_primitive_value_string``: one pair of ``"`` or ``'`` off, ``\\'`` unescaped);
ROS 1's genmsg keeps everything after ``=`` as written, quotes included."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.extract.cpp.interfaces import constant_value
from haros_arch.workspace import scan

TOPICS = """\
# topics of the vehicle
string DVL_TOPIC = 'core/dvl'
string DEPTH_TOPIC="core/depth"  # Type: Float64
string PLAIN_TOPIC = core/plain
int32 RATE = 10
"""

CPP = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <vehicle_msgs/msg/topics.hpp>
class Listener : public rclcpp::Node {
 public:
  Listener() : Node("listener") {
    a_ = create_subscription<std_msgs::msg::String>(
        vehicle_msgs::msg::Topics::DVL_TOPIC, 10, [](std_msgs::msg::String::SharedPtr) {});
    b_ = create_publisher<std_msgs::msg::String>(vehicle_msgs::msg::Topics::DEPTH_TOPIC, 1);
    c_ = create_publisher<std_msgs::msg::String>(vehicle_msgs::msg::Topics::PLAIN_TOPIC, 1);
  }
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr a_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr b_, c_;
};
"""

def _workspace(tmp_path):
    msgs = tmp_path / "vehicle_msgs"
    (msgs / "msg").mkdir(parents=True)
    (msgs / "package.xml").write_text(package_xml("vehicle_msgs", "ament_cmake"))
    (msgs / "msg" / "Topics.msg").write_text(TOPICS)
    node = tmp_path / "listener"
    node.mkdir()
    (node / "package.xml").write_text(package_xml("listener", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>rclpy</depend>"
        "<depend>std_msgs</depend><depend>vehicle_msgs</depend></package>"))
    return node


def test_cpp_reads_a_ros2_string_constant_without_its_quotes(tmp_path) -> None:
    node = _workspace(tmp_path)
    source = node / "listener.cpp"
    source.write_text(CPP)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "core/depth"), ("publish", "core/plain"), ("subscribe", "core/dvl")]


def test_constant_values_per_ros_version() -> None:
    assert constant_value("string", "'core/dvl'", ros2=True) == "core/dvl"
    assert constant_value("string", '"a \\"b\\""', ros2=True) == 'a "b"'
    assert constant_value("string", "'core/dvl'", ros2=False) == "'core/dvl'"
    # rosidl reads a '#' as a comment on a constant's line too (smarc2's
    # ``string DR_ODOM_TOPIC = 'dr/odom'  # Type: Odometry``); genmsg keeps it
    assert constant_value("string", "'dr/odom'  # Type: Odometry", ros2=True) == "dr/odom"
    assert constant_value("string", "a # b", ros2=False) == "a # b"
    assert constant_value("string", "plain", ros2=True) == "plain"
    assert constant_value("int32", "10", ros2=True) == 10
    assert constant_value("float64", "0.5", ros2=False) == 0.5
    assert constant_value("int32", "x", ros2=True) is None
