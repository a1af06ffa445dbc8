"""A test of ``argc`` / ``argv`` in ROS 1 ``main`` is decided by the arguments the code
sees where it tests them: after ``ros::init(argc, argv, ..)``, which takes roslaunch's
``:=`` words (remappings, ``__name:=``, ``__log:=``) off, the launch file's ``args``
alone; before it, those words too. Else (no such statement in main's body) only an
answer both views give decides it. image_transport's republish tests ``argc < 3`` after
``ros::init``: with one word of ``args`` (the input transport) it publishes ``out``
itself, which stayed undecided."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import scan

PROGRAM = """#include <ros/ros.h>
#include <std_msgs/String.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "republish");
  ros::NodeHandle n;
  ros::Publisher p;
  if (argc < 3) {
    p = n.advertise<std_msgs::String>("out", 1);
  } else {
    p = n.advertise<std_msgs::String>("out_other", 1);
  }
  ros::spin();
  return 0;
}
"""

# ros::init inside a branch: where the tests run against it is not told
INSIDE = """#include <ros/ros.h>
#include <std_msgs/String.h>

int main(int argc, char** argv) {
  if (argv[0]) {
    ros::init(argc, argv, "inside");
  }
  ros::NodeHandle n;
  if (argc < 3) {
    ros::Publisher p = n.advertise<std_msgs::String>("short", 1);
  }
  ros::spin();
  return 0;
}
"""

LAUNCH = """<launch>
  <node pkg="rep" type="program" name="one" args="raw">
    <remap from="in" to="/cam/image"/>
  </node>
  <node pkg="rep" type="program" name="two" args="raw compressed"/>
  <node pkg="rep" type="inside" name="inside" args="raw"/>
</launch>
"""


def _tree(write_tree):
    return write_tree({
        "src/rep/package.xml": package_xml("rep"),
        "src/rep/CMakeLists.txt": "project(rep)\nadd_executable(program src/program.cpp)\n"
                                  "add_executable(inside src/inside.cpp)\n",
        "src/rep/src/program.cpp": PROGRAM,
        "src/rep/src/inside.cpp": INSIDE,
        "src/rep/launch/rep.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [rep/launch/rep.launch]\n",
    })


def test_the_extractor_says_which_side_of_ros_init_a_test_is_on(write_tree) -> None:
    root = _tree(write_tree)
    ws = scan([str(root)])
    result = extract_cpp([str(root / "src/rep/src/program.cpp")], ws, cache_dir=None)
    sides = {(c.name, tuple((d.text, d.after_init) for d in c.conditions if d.program_args))
             for c in result.calls}
    assert sides == {("out", (("argc < 3", True),)), ("out_other", (("argc < 3", True),))}
    inside = extract_cpp([str(root / "src/rep/src/inside.cpp")], ws, cache_dir=None)
    assert [(d.text, d.after_init) for c in inside.calls for d in c.conditions
            if d.program_args] == [("argc < 3", None)]


def test_the_graph_decides_it_with_the_arguments_that_side_sees(write_tree) -> None:
    root = _tree(write_tree)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    config = model.configuration("c")
    links = {(link.node.name, link.rosname.full, tuple(c.text for c in link.conditions))
             for link in config.links if link.kind == "publish"}
    assert links == {
        # one word: argc 2 after ros::init (before it, 2 + a remap + __name + __log)
        ("/one", "/out", ()),
        # two words: 3 after it
        ("/two", "/out_other", ()),
        # ros::init in a branch: both views, which disagree for one word
        ("/inside", "/short", ("argc < 3",)),
    }
