"""A ROS 1 handle whose namespace is a parameter's value: the calls on it name that
parameter (``name_param``, with the read's default), so that the graph puts the value in
the place of the ``?``, as for a name that holds one. pointgrey_camera_driver's stereo
nodelet reads ``first_namespace`` (default "left") into ``firstcam``, builds
``ros::NodeHandle lnh(getMTNodeHandle(), firstcam)`` and advertises its camera, and its
camera_info_manager's ``set_camera_info``, on it: all of them were ``?/...``."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <image_transport/image_transport.h>
#include <camera_info_manager/camera_info_manager.h>
int main(int argc, char **argv) {
  ros::init(argc, argv, "stereo");
  ros::NodeHandle nh, pnh("~");
  std::string firstcam, other;
  pnh.param<std::string>("first_namespace", firstcam, "left");
  ros::NodeHandle lnh(nh, firstcam);
  image_transport::ImageTransport it(lnh);
  image_transport::CameraPublisher pub = it.advertiseCamera("image_raw", 5);
  camera_info_manager::CameraInfoManager info(lnh, "cam", "");
  ros::NodeHandle unknown(nh, other + firstcam);
  ros::Publisher temp = unknown.advertise<std_msgs::String>("temp", 5);
  ros::spin();
}
"""


def test_calls_on_a_handle_named_by_a_parameter_name_it(write_tree) -> None:
    root = write_tree({"cam/package.xml": package_xml("cam", "catkin").replace(
                           "</package>", "<depend>roscpp</depend></package>"),
                       "cam/src/stereo.cpp": SOURCE})
    result = extract_cpp([str(root / "cam" / "src" / "stereo.cpp")], scan([str(root)]),
                         cache_dir=None)
    named = sorted((c.kind, c.name, c.handle_namespace, c.name_param, c.name_default)
                   for c in result.calls if "?" in c.name)
    assert named == [
        ("publish", "?/camera_info", "?", "~first_namespace", "left"),
        ("publish", "?/image_raw", "?", "~first_namespace", "left"),
        # a namespace that holds more than the value (``other + firstcam``): unnamed
        ("publish", "?/temp", "?", None, None),
        ("server", "?/set_camera_info", "?", "~first_namespace", "left"),
    ]
