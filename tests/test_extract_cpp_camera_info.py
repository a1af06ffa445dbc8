"""camera_info_manager without its package in the workspace: a camera driver that builds a
CameraInfoManager serves the calibration service (set_camera_info) and is not partial for
handing itself to a class the parse does not know."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

ROS1_PACKAGE = """<package format="2"><name>cam</name><version>0.0.0</version>
<description>d</description><maintainer email="a@b.c">m</maintainer><license>BSD</license>
<buildtool_depend>catkin</buildtool_depend><depend>roscpp</depend>
<depend>camera_info_manager</depend></package>
"""
ROS2_PACKAGE = """<package format="3"><name>cam</name><version>0.0.0</version>
<description>d</description><maintainer email="a@b.c">m</maintainer><license>BSD</license>
<depend>rclcpp</depend><depend>camera_info_manager</depend>
<export><build_type>ament_cmake</build_type></export></package>
"""

ROS1_NODE = """
#include <ros/ros.h>
#include <camera_info_manager/camera_info_manager.h>
#include <sensor_msgs/CameraInfo.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "cam");
  ros::NodeHandle camera("camera");
  camera_info_manager::CameraInfoManager info(camera, "narrow", "file:///tmp/c.yaml");
  sensor_msgs::CameraInfo ci = info.getCameraInfo();
  ros::Publisher pub = camera.advertise<sensor_msgs::CameraInfo>("camera_info", 1);
  ros::spin();
}
"""

ROS2_NODE = """
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <camera_info_manager/camera_info_manager.hpp>
#include <sensor_msgs/msg/camera_info.hpp>
class Camera : public rclcpp::Node {
public:
  Camera() : rclcpp::Node("cam") {
    info_ = std::make_shared<camera_info_manager::CameraInfoManager>(this, "narrow");
    sensor_msgs::msg::CameraInfo ci = info_->getCameraInfo();
    pub_ = create_publisher<sensor_msgs::msg::CameraInfo>("camera_info", 1);
  }
private:
  std::shared_ptr<camera_info_manager::CameraInfoManager> info_;
  rclcpp::Publisher<sensor_msgs::msg::CameraInfo>::SharedPtr pub_;
};
"""


def _extract(tmp_path, manifest: str, source: str):
    (tmp_path / "package.xml").write_text(manifest)
    (tmp_path / "cam.cpp").write_text(source)
    return extract_cpp([str(tmp_path / "cam.cpp")], scan([str(tmp_path)]), cache_dir=None)


def test_ros1_serves_set_camera_info_on_the_handle_given(tmp_path) -> None:
    result = _extract(tmp_path, ROS1_PACKAGE, ROS1_NODE)
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("publish", "camera/camera_info", "sensor_msgs/CameraInfo"),
        ("server", "camera/set_camera_info", "sensor_msgs/SetCameraInfo")]
    assert not [d for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_NODE_TO_UNKNOWN", "CPP_INCLUDE_MISSING")]


def test_ros2_serves_its_own_set_camera_info(tmp_path) -> None:
    """From Jazzy on (the rclcpp of the stand-ins) the service is the node's private
    ``~/set_camera_info``."""
    result = _extract(tmp_path, ROS2_PACKAGE, ROS2_NODE)
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("publish", "camera_info", "sensor_msgs/msg/CameraInfo"),
        ("server", "~set_camera_info", "sensor_msgs/srv/SetCameraInfo")]
    assert not [d for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_NODE_TO_UNKNOWN", "CPP_INCLUDE_MISSING")]
