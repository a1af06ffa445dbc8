"""Source conditions over constants of the code and over a function that returns a
parameter it reads by a fixed name: neonavigation_common's compatibility.h makes every
topic of the neonavigation nodes one of two names, ``if (getCompat() != current_level)``
the old one, else the new one, where ``const int current_level = 1;`` and ``getCompat()``
returns the global parameter ``neonavigation_compatible`` (default 0), which the launch
files set to 1. Both names stayed, each under the undecided condition. The constant is
now held in the condition with its value (``Condition.constants``) and the call stands
for the parameter (``Condition.parameters``), so the graph decides it. A variable that
is not const, or a function that returns no parameter, is not taken."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import scan

COMPAT_H = r"""
#include <ros/ros.h>
#include <string>
namespace ex
{
namespace compat
{
const int current_level = 1;
const int default_level = 0;
int moving_level = 1;
int getCompat()
{
  int compat(default_level);
  ros::NodeHandle("/").param("ex_compatible", compat, compat);
  return compat;
}
int fixedLevel()
{
  return 1;
}
template <class M>
ros::Publisher advertise(ros::NodeHandle& nh_new, const std::string& topic_new,
                         ros::NodeHandle& nh_old, const std::string& topic_old, uint32_t size)
{
  if (getCompat() != current_level)
  {
    return nh_old.advertise<M>(topic_old, size);
  }
  else
  {
    return nh_new.advertise<M>(topic_new, size);
  }
}
}  // namespace compat
}  // namespace ex
"""

NODE = r"""
#include <ex/compat.h>
#include <std_msgs/String.h>
using namespace ex::compat;
int main(int argc, char** argv)
{
  ros::init(argc, argv, "node");
  ros::NodeHandle nh, pnh("~");
  ros::Publisher map = advertise<std_msgs::String>(nh, "map", pnh, "map", 1);
  moving_level = argc;
  ros::Publisher moving, fixed;
  if (getCompat() == moving_level)
    moving = nh.advertise<std_msgs::String>("moving", 1);
  if (fixedLevel() == current_level)
    fixed = nh.advertise<std_msgs::String>("fixed", 1);
  ros::spin();
}
"""

LAUNCH = """
<launch>
  <arg name="level" default="1"/>
  <param name="ex_compatible" value="$(arg level)" if="$(eval level != 'unset')"/>
  <node pkg="ex" type="node" name="node"/>
</launch>
"""


def _workspace(write_tree):
    return write_tree({
        "src/ex/package.xml": package_xml("ex"),
        "src/ex/CMakeLists.txt": "project(ex)\ninclude_directories(include)\n"
                                 "add_executable(node src/node.cpp)\n",
        "src/ex/include/ex/compat.h": COMPAT_H,
        "src/ex/src/node.cpp": NODE,
        "src/ex/launch/ex.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n"
                        "  new: [ex/launch/ex.launch]\n"
                        "  old:\n    launch: [ex/launch/ex.launch]\n    args: {level: '0'}\n"
                        "  unset:\n    launch: [ex/launch/ex.launch]\n"
                        "    args: {level: unset}\n"})


def test_a_constant_and_a_fixed_parameter_function_are_held(write_tree) -> None:
    root = _workspace(write_tree)
    found = extract_cpp([str(root / "src/ex/src/node.cpp")], scan([str(root / "src")]),
                        cache_dir=None)
    held = {c.name: [(k.statement, k.parameters, k.constants) for k in c.conditions]
            for c in found.calls if c.kind == "publish"}
    compat = (("getCompat()", "/ex_compatible"),)
    assert held["~map"] == [("if", compat, (("current_level", 1),))]
    assert held["map"] == [("else", compat, (("current_level", 1),))]
    # moving_level is written: no constant; fixedLevel returns no parameter
    assert held["moving"] == [("if", compat, None)]
    assert held["fixed"] == [("if", None, (("current_level", 1),))]


def test_the_compatibility_level_decides_the_names(write_tree) -> None:
    root = _workspace(write_tree)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None, jobs=1))

    def published(name):
        config = model.configuration(name)
        return sorted((link.rosname.full, tuple(c.text for c in link.conditions))
                      for link in config.links if link.kind == "publish"
                      and "rosout" not in link.rosname.full)
    moving = ("/moving", ("getCompat() == moving_level",))
    fixed = ("/fixed", ("fixedLevel() == current_level",))
    assert published("new") == [fixed, ("/map", ()), moving]
    # the launch file sets 0, or nothing (getCompat's default, default_level: 0)
    assert published("old") == published("unset") == [fixed, moving, ("/node/map", ())]
