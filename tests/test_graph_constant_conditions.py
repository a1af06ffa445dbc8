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


SWITCHES = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>
bool PUB_EACH_LINE = false;
bool VERBOSE = false;
int N_SCANS = 16;
static int STEPPED = 0;
void set_verbose();
int main(int argc, char** argv)
{
  ros::init(argc, argv, "scans");
  ros::NodeHandle nh;
  nh.param<int>("scan_line", N_SCANS, 16);
  std::vector<ros::Publisher> lines;
  ros::Publisher verbose, stepped, scans;
  if (PUB_EACH_LINE)
  {
    for (int i = 0; i < 4; i++)
      lines.push_back(nh.advertise<std_msgs::String>("/laser_scanid_" + std::to_string(i), 1));
  }
  set_verbose();
  if (VERBOSE)
    verbose = nh.advertise<std_msgs::String>("verbose", 1);
  STEPPED++;
  if (STEPPED == 0)
    stepped = nh.advertise<std_msgs::String>("stepped", 1);
  if (N_SCANS == 16)
    scans = nh.advertise<std_msgs::String>("scans", 1);
  ros::spin();
}
"""

SETTER = r"""
extern bool VERBOSE;
void set_verbose() { VERBOSE = true; }
"""


def test_a_global_no_source_writes_after_its_literal_is_a_constant(write_tree) -> None:
    """A-LOAM's ``bool PUB_EACH_LINE = false;``, a switch no code writes, kept its per-line
    publishers as ``/laser_scanid_?`` under an undecided ``if (PUB_EACH_LINE)``; a global
    of a number or bool that no source of the package writes after its literal is now a
    constant of the condition. One another file assigns, one stepped, one read into by
    a call (``nh.param(..., N_SCANS, ...)``) is none."""
    root = write_tree({
        "src/ex/package.xml": package_xml("ex"),
        "src/ex/CMakeLists.txt": "project(ex)\n"
                                 "add_executable(scans src/scans.cpp src/setter.cpp)\n",
        "src/ex/src/scans.cpp": SWITCHES,
        "src/ex/src/setter.cpp": SETTER,
    })
    found = extract_cpp([str(root / "src/ex/src/scans.cpp")], scan([str(root / "src")]),
                        cache_dir=None)
    held = {c.name: [k.constants for k in c.conditions]
            for c in found.calls if c.kind == "publish"}
    # (a counting loop over literal bounds: one publisher per turn, the loop no condition)
    for line in range(4):
        assert held[f"/laser_scanid_{line}"] == [(("PUB_EACH_LINE", False),)]
    assert held["verbose"] == [None]
    assert held["stepped"] == [None]
    assert held["scans"] == [None]


def test_a_cached_unit_is_read_again_when_another_file_writes_the_global(
        write_tree, tmp_path) -> None:
    """The unit's cache entry lists the package's sources looked through: once another
    file assigns the switch, the condition is undecided again, not the cached constant."""
    root = write_tree({
        "src/ex/package.xml": package_xml("ex"),
        "src/ex/CMakeLists.txt": "project(ex)\n"
                                 "add_executable(scans src/scans.cpp src/setter.cpp)\n",
        "src/ex/src/scans.cpp": SWITCHES,
        "src/ex/src/setter.cpp": "void set_verbose() {}\n",
    })
    cache = str(tmp_path / "cache")

    def held():
        found = extract_cpp([str(root / "src/ex/src/scans.cpp")],
                            scan([str(root / "src")]), cache_dir=cache)
        return {c.name: [k.constants for k in c.conditions]
                for c in found.calls if c.kind == "publish"}["verbose"]
    assert held() == [(("VERBOSE", False),)]
    (root / "src/ex/src/setter.cpp").write_text(SETTER)
    assert held() == [None]
