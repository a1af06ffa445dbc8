"""joystick_drivers' ROS 1 joy_node reads the Linux joystick and event interfaces
(``<linux/joystick.h>``'s ``js_event``, ``<linux/input.h>``'s ``input_event`` /
``ff_effect`` / ``EVIOCSFF``), lists ``/dev/input`` with ``<dirent.h>``, ``S_ISCHR`` and
``realpath``, and tests ``errno != EAGAIN``: with those headers empty, errors in ``main``
beside its ROS calls made the node partial (f1tenth_system's vendored joy)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <unistd.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <dirent.h>
#include <linux/joystick.h>
#include <linux/input.h>
#include <ros/ros.h>
#include <sensor_msgs/Joy.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "joy_node");
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<sensor_msgs::Joy>("joy", 1);
  DIR* dev = opendir("/dev/input");
  struct dirent* entry = readdir(dev);
  char resolved[256];
  realpath(entry->d_name, resolved);
  struct stat st;
  if (stat(entry->d_name, &st) == 0 && S_ISCHR(st.st_mode)) { closedir(dev); }
  int fd = open("/dev/input/js0", O_RDONLY);
  js_event event;
  read(fd, &event, sizeof(js_event));
  if (event.type == (JS_EVENT_BUTTON | JS_EVENT_INIT)) { event.number = 0; }
  struct input_event ie;
  ie.type = EV_FF; ie.code = 0; ie.value = 1;
  struct ff_effect effect;
  effect.type = FF_RUMBLE;
  effect.u.rumble.strong_magnitude = 0;
  effect.replay.length = 1000;
  if (ioctl(fd, EVIOCSFF, &effect) == -1 && errno != EAGAIN) { return 1; }
  ros::spin();
}
"""


def test_the_linux_joystick_interfaces_are_known(write_tree) -> None:
    root = write_tree({
        "joy/package.xml": package_xml("joy", "catkin"),
        "joy/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(joy)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp)\ncatkin_package()\n"
            "add_executable(joy_node src/joy_node.cpp)\n"),
        "joy/src/joy_node.cpp": SOURCE})
    result = extract_cpp([str(root / "joy" / "src" / "joy_node.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "joy")]
    codes = [d.code for d in result.diagnostics]
    assert not {"CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_INCLUDE_MISSING"} & set(
        codes), [d.message for d in result.diagnostics]
