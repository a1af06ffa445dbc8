"""A name made of text and a value of a library the parse does not have
(open_manipulator_controller.cpp:139 and :157, robotis_manipulator not installed:
``for (auto const& name : om_tools_name) advertise<...>(name + "/kinematics_pose", 10)``
over a list ``getAllToolComponentName()`` returns): the parse reads ``name + "..."`` as
the permissive class's ``operator+``, turned into the ``std::string`` the call takes by
the class's conversion; the name was kept as a bare ``?``, though the code writes its
text. It is now ``?/kinematics_pose``: the unknown part is the library's value, the
rest what the source says."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <vendor/manip.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  ros::NodeHandle nh;
  vendor::Manipulator m;
  auto names = m.getToolNames();
  for (auto const& name : names) {
    ros::Publisher p = nh.advertise<std_msgs::String>(name + "/kinematics_pose", 10);
    ros::Publisher q = nh.advertise<std_msgs::String>("tool/" + name, 10);
  }
  ros::Publisher r = nh.advertise<std_msgs::String>(m.prefix() + "_state", 10);
  ros::Publisher s = nh.advertise<std_msgs::String>(m.topic(), 10);
  return 0;
}
"""


def test_text_joined_to_an_unknown_library_value_is_kept(write_tree) -> None:
    root = write_tree({"p/package.xml": package_xml("p", "catkin"),
                       "p/src/n.cpp": NODE})
    result = extract_cpp([str(root / "p" / "src" / "n.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert sorted(c.name for c in result.calls) == [
        "?", "?/kinematics_pose", "?_state", "tool/?"]
