"""A ROS 1 message package's config sets ``<pkg>_MESSAGE_FILES`` / ``<pkg>_SERVICE_FILES``
for the packages that find it (genmsg's ``<pkg>-msg-extras.cmake``: ``msg/Name.msg``).
mavros 1.x tests ``list(FIND sensor_msgs_MESSAGE_FILES "msg/BatteryState.msg" IDX)`` and
defines ``HAVE_SENSOR_MSGS_BATTERYSTATE_MSG`` when it is there: its ``battery`` is then
sensor_msgs/BatteryState. The lists were unset, the test failed, and the noetic model
published mavros_msgs/BatteryStatus: a false topic-type-mismatch against every node
subscribing to ``/mavros/battery`` as sensor_msgs/BatteryState (bluerov_ros_playground)."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

CMAKE = """cmake_minimum_required(VERSION 3.0.2)
project(batt)
find_package(catkin REQUIRED COMPONENTS roscpp sensor_msgs {extra})
list(FIND sensor_msgs_MESSAGE_FILES "msg/BatteryState.msg" BATTERY_IDX)
if(${{BATTERY_IDX}} GREATER -1)
  add_definitions(-DHAVE_BATTERY_STATE)
endif()
list(FIND sensor_msgs_SERVICE_FILES "srv/SetCameraInfo.srv" CAMERA_IDX)
if(${{CAMERA_IDX}} GREATER -1)
  add_definitions(-DHAVE_SET_CAMERA_INFO)
endif()
{own}
catkin_package()
add_executable(batt src/batt.cpp)
"""

NODE = r"""
#include <ros/ros.h>
#include <std_msgs/Float32.h>
#ifdef HAVE_BATTERY_STATE
#include <sensor_msgs/BatteryState.h>
using Battery = sensor_msgs::BatteryState;
#else
using Battery = std_msgs::Float32;
#endif
int main(int argc, char ** argv) {
  ros::init(argc, argv, "batt");
  ros::NodeHandle nh("~");
  ros::Publisher pub = nh.advertise<Battery>("battery", 10);
#ifdef HAVE_SET_CAMERA_INFO
  ros::Publisher camera = nh.advertise<std_msgs::Float32>("camera", 1);
#endif
#ifdef HAVE_OWN_STATUS
  ros::Publisher own = nh.advertise<std_msgs::Float32>("own", 1);
#endif
  ros::spin();
}
"""

OWN = """list(FIND batt_msgs_MESSAGE_FILES "msg/Status.msg" OWN_IDX)
if(${OWN_IDX} GREATER -1)
  add_definitions(-DHAVE_OWN_STATUS)
endif()"""


def _publishes(write_tree, distro: str = "noetic", own: bool = False) -> dict[str, str]:
    files = {
        "src/batt/package.xml": package_xml("batt", "catkin").replace(
            "</package>", "<depend>roscpp</depend><depend>sensor_msgs</depend>"
            + ("<depend>batt_msgs</depend>" if own else "") + "</package>"),
        "src/batt/CMakeLists.txt": CMAKE.format(extra="batt_msgs" if own else "",
                                                own=OWN if own else ""),
        "src/batt/src/batt.cpp": NODE,
        "project.yaml": "project: p\n" + (f"distro: {distro}\n" if distro else "")
                        + "configurations: {}\n",
    }
    if own:
        files.update({
            "src/batt_msgs/package.xml": package_xml("batt_msgs", "catkin"),
            "src/batt_msgs/CMakeLists.txt": "project(batt_msgs)\n",
            "src/batt_msgs/msg/Status.msg": "float32 level\n",
        })
    root = write_tree(files)
    model = analyse(load(str(root / "project.yaml")),
                    {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    node = next(n for p in model.packages for n in p.nodes if n.executable == "batt")
    return {c.name: c.type for c in node.calls if c.kind == "publish"}


def test_an_installed_message_package_s_files_are_its_catalogue_definitions(write_tree):
    published = _publishes(write_tree)
    assert published["~battery"] == "sensor_msgs/BatteryState"
    assert "~camera" in published  # srv/SetCameraInfo.srv is in SERVICE_FILES


def test_a_workspace_message_package_s_files_are_its_own(write_tree):
    published = _publishes(write_tree, own=True)
    assert "~own" in published
    assert published["~battery"] == "sensor_msgs/BatteryState"
