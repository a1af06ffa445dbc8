"""A message type a unit names without including its header, which a missing library
header would have brought (kinova's pick_place names ``geometry_msgs::PoseStampedConstPtr``
and includes only MoveIt's headers): the message's header is synthesised and included, so
the type is the message, not a name declared permissively that makes
``subscribe<geometry_msgs::PoseStamped>(topic, 1, &C::cb, this)`` an error in the
constructor that makes the node's calls (the node was partial)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """#include <ros/ros.h>
#include <moveit/move_group_interface/move_group_interface.h>
class Pick {
public:
  explicit Pick(ros::NodeHandle& nh);
  void onPose(const geometry_msgs::PoseStampedConstPtr& msg);
  void onJoints(const sensor_msgs::JointStateConstPtr& msg);
private:
  ros::NodeHandle nh_;
  ros::Subscriber pose_sub_, joint_sub_;
  moveit::planning_interface::MoveGroupInterface* group_;
};
"""

SOURCE = """#include <pick.h>
Pick::Pick(ros::NodeHandle& nh) : nh_(nh) {
  pose_sub_ = nh_.subscribe<geometry_msgs::PoseStamped>("tool_pose", 1, &Pick::onPose, this);
  joint_sub_ = nh_.subscribe("joint_states", 1, &Pick::onJoints, this);
  group_ = new moveit::planning_interface::MoveGroupInterface("arm");
}
void Pick::onPose(const geometry_msgs::PoseStampedConstPtr& msg) {
  double x = msg->pose.position.x;
}
void Pick::onJoints(const sensor_msgs::JointStateConstPtr& msg) {}
int main(int argc, char** argv) {
  ros::init(argc, argv, "pick");
  ros::NodeHandle nh;
  Pick pick(nh);
  ros::spin();
}
"""


def test_a_message_type_used_without_its_header_is_the_message(write_tree) -> None:
    root = write_tree({
        "demo/package.xml": package_xml("demo", "catkin"),
        "demo/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(demo)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp moveit_ros_planning_interface)\n"
            "catkin_package()\ninclude_directories(include)\n"
            "add_executable(pick src/pick.cpp)\n"),
        "demo/include/pick.h": HEADER,
        "demo/src/pick.cpp": SOURCE})
    result = extract_cpp([str(root / "demo" / "src" / "pick.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    calls = [(c.kind, c.name, c.type) for c in result.calls]
    assert calls == [("subscribe", "tool_pose", "geometry_msgs/PoseStamped"),
                     ("subscribe", "joint_states", "sensor_msgs/JointState")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_PARSE_ERROR" not in codes and "CPP_ERROR_NEAR_CALL" not in codes
    assert "CPP_CALL_UNRESOLVED" not in codes


ROS2_SOURCE = """#include <rclcpp/rclcpp.hpp>
#include <geometry_msgs/msg/twist.hpp>
#include <tf2_ros/transform_broadcaster.h>
class Base : public rclcpp::Node {
public:
  Base() : Node("base") {
    cmd_sub_ = create_subscription<geometry_msgs::msg::Twist>(
        "cmd_vel", 10, [this](geometry_msgs::msg::Twist::SharedPtr) {});
    odom_pub_ = create_publisher<geometry_msgs::msg::Twist>("cmd_vel_out", 10);
  }
  void fill() {  // no ROS call here: the error did not make the node partial
    geometry_msgs::msg::TransformStamped t;
    t.header.frame_id = "odom";
    t.child_frame_id = "base_link";
  }
private:
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr cmd_sub_;
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr odom_pub_;
};
"""


def test_a_ros2_message_of_a_known_package_used_without_its_header(write_tree) -> None:
    # limo_ros2's limo_driver.cpp:475 names geometry_msgs::msg::TransformStamped, which
    # tf2_ros' headers bring in a real build; it includes only geometry_msgs' twist.hpp:
    # clang's "no type named 'TransformStamped' in namespace 'geometry_msgs::msg'"
    root = write_tree({"base/package.xml": package_xml("base", "ament_cmake"),
                       "base/src/base.cpp": ROS2_SOURCE})
    result = extract_cpp([str(root / "base" / "src" / "base.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("subscribe", "cmd_vel", "geometry_msgs/msg/Twist"),
        ("publish", "cmd_vel_out", "geometry_msgs/msg/Twist")]
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []
