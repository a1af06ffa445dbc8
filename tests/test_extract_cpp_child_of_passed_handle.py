"""A handle made in the namespace of a handle that another file of the node passes
(``ros::NodeHandle stereo(nh, "stereo")`` in a constructor that main.cpp calls with its
public ``nh``): the names on it are relative, ``stereo/status``, as roscpp resolves
them in the node's namespace. The namespace was the placeholder of the passed handle,
``/`` and the child's name, and the public handle's ``""`` filled in left ``/stereo``,
a global name (realsense-ros's ``registerDynamicOption(nh, ...)`` read its options as
``/?/?``, any global parameter, where they are ``<camera namespace>/<module>/<option>``)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HEADER = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
class Driver {
 public:
  Driver(ros::NodeHandle& nh, ros::NodeHandle& pnh);
 private:
  ros::Publisher status_;
  int exposure_ = 0;
  int gain_ = 0;
};
"""
DRIVER = """\
#include "cam/driver.h"
Driver::Driver(ros::NodeHandle& nh, ros::NodeHandle& pnh) {
  ros::NodeHandle stereo(nh, "stereo");
  status_ = stereo.advertise<std_msgs::String>("status", 1);
  stereo.param("exposure", exposure_, 0);
  ros::NodeHandle left(pnh, "left");
  left.param("gain", gain_, 0);
  ros::NodeHandle root(nh, "/robot");
  root.param("mass", gain_, 0);
}
"""
MAIN = """\
#include "cam/driver.h"
int main(int argc, char** argv) {
  ros::init(argc, argv, "driver");
  ros::NodeHandle nh, pnh("~");
  Driver driver(nh, pnh);
  ros::spin();
}
"""
CMAKE = """\
cmake_minimum_required(VERSION 3.0)
project(cam)
find_package(catkin REQUIRED roscpp std_msgs)
include_directories(include)
add_executable(driver src/main.cpp src/driver.cpp)
"""


def test_a_child_of_the_public_handle_another_file_passes_is_relative(write_tree) -> None:
    root = write_tree({"cam/package.xml": package_xml("cam", "catkin").replace(
                           "</package>", "<depend>roscpp</depend></package>"),
                       "cam/CMakeLists.txt": CMAKE,
                       "cam/include/cam/driver.h": HEADER,
                       "cam/src/driver.cpp": DRIVER, "cam/src/main.cpp": MAIN})
    files = [str(root / "cam" / "src" / name) for name in ("driver.cpp", "main.cpp")]
    result = extract_cpp(files, scan([str(root)]), cache_dir=None)
    calls = sorted((c.kind, c.name, c.handle_namespace) for c in result.calls)
    assert calls == [("publish", "stereo/status", "stereo"),
                     ("read", "/robot/mass", "/robot"),
                     ("read", "stereo/exposure", "stereo"),
                     ("read", "~left/gain", "~left")]
