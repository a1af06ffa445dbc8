"""rosidl_generator_cpp gives every ROS 2 message struct, besides ``SharedPtr`` and
``ConstSharedPtr``, the pointer names ``Ptr`` / ``ConstPtr`` (deprecated, ROS 1's
names), ``ConstUniquePtr``, ``ConstWeakPtr``, ``RawPtr`` and ``ConstRawPtr``. Code
ported from ROS 1 writes its callbacks with them (``const sensor_msgs::msg::Imu::ConstPtr
msg``); the synthesised headers lacked them, so such a node's calls were reported
incomplete (``no type named 'ConstPtr'``) and its callbacks' message types unknown."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/imu.hpp>
#include <nav_msgs/msg/odometry.hpp>
#include <example_interfaces/srv/add_two_ints.hpp>

class Preintegration : public rclcpp::Node
{
public:
  Preintegration() : rclcpp::Node("preintegration")
  {
    auto imu_callback = [this](const sensor_msgs::msg::Imu::ConstPtr msg) -> void
      {
        sensor_msgs::msg::Imu::Ptr copy(new sensor_msgs::msg::Imu(*msg));
        last_ = copy;
      };
    sub_ = create_subscription<sensor_msgs::msg::Imu>("imu", 10, imu_callback);
    pub_ = create_publisher<nav_msgs::msg::Odometry>("odometry", 10);
    nav_msgs::msg::Odometry::ConstUniquePtr unique;
    nav_msgs::msg::Odometry::ConstWeakPtr weak;
    nav_msgs::msg::Odometry::ConstRawPtr raw = nullptr;
    example_interfaces::srv::AddTwoInts::Request::ConstPtr request;
  }

private:
  sensor_msgs::msg::Imu::ConstPtr last_;
  rclcpp::Subscription<sensor_msgs::msg::Imu>::SharedPtr sub_;
  rclcpp::Publisher<nav_msgs::msg::Odometry>::SharedPtr pub_;
};
"""


def test_ros1_style_pointer_names_of_a_ros2_message_parse(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("lio", "ament_cmake"))
    source = tmp_path / "preintegration.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="humble")
    errors = [d for d in result.diagnostics if d.code.startswith("CPP_")
              and d.code not in ("CPP_NAMES_DECLARED",)]
    assert [(d.code, d.message) for d in errors
            if "Ptr" in d.message] == []
    calls = sorted((c.kind, c.name, c.type) for c in result.calls)
    assert calls == [("publish", "odometry", "nav_msgs/msg/Odometry"),
                     ("subscribe", "imu", "sensor_msgs/msg/Imu")]
