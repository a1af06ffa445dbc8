"""A Python node's test of its command-line arguments is decided by the ``args`` the
launch file gives the instance, as main's ``argc`` / ``argv`` are in C++.
fetchit_challenge (fetch_gazebo 19c5ec4) serves its schunk_machine action only ``if
len(sys.argv) > 1:`` (schunk_machine_server.py:99) and its launch file starts it with
``args="simulated"``: the server and the four publishers its constructor makes were
"conditional", and every absence they could fill undecided. ``sys.argv`` is every word
as the program was started (roslaunch's remappings, ``__name:=`` and ``__log:=`` after
the user's: rospy takes none off it), ``rospy.myargv()`` what is left without them; a
ROS 2 instance's ``sys.argv`` holds the words launch_ros adds, not told here."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.graph.conditions import decide
from haros_arch.model.conditions import Condition
from haros_arch.model.values import Unknown
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

SERVER = """#!/usr/bin/env python
import sys
import rospy
from std_msgs.msg import String

if __name__ == "__main__":
    rospy.init_node("machine")
    if len(sys.argv) > 1:
        given = rospy.Publisher("given", String, queue_size=1)
    else:
        rospy.logerr("Use: machine.py simulated/real")
    if len(sys.argv) > 1 and sys.argv[1] == "simulated":
        simulated = rospy.Publisher("simulated", String, queue_size=1)
    if len(rospy.myargv()) < 2:
        usage = rospy.Publisher("usage", String, queue_size=1)
    rospy.spin()
"""

LAUNCH = """<launch>
  <arg name="version" default="simulated"/>
  <node pkg="sch" type="machine.py" name="sim" args="$(arg version)"/>
  <node pkg="sch" type="machine.py" name="real" args="real"/>
  <node pkg="sch" type="machine.py" name="bare"/>
  <node pkg="sch" type="machine.py" name="unknown" args="$(env MACHINE_VERSION)"/>
</launch>
"""


def test_the_launch_arguments_decide_a_python_node_s_tests(write_tree) -> None:
    root = write_tree({
        "src/sch/package.xml": package_xml("sch"),
        "src/sch/CMakeLists.txt": "project(sch)\n"
                                  "catkin_install_python(PROGRAMS scripts/machine.py)\n",
        "src/sch/scripts/machine.py": SERVER,
        "src/sch/launch/sch.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [sch/launch/sch.launch]\n",
    })
    env = {"PATH": os.environ.get("PATH", "")}
    config = analyse(load(str(root / "project.yaml")), env,
                     Options(cache_dir=None)).configuration("c")
    found = {(link.node.name, link.rosname.full): [c.text for c in link.conditions]
             for link in config.links if link.kind == "publish"
             and link.rosname.full in ("/given", "/simulated", "/usage")}
    assert found == {
        ("/sim", "/given"): [], ("/sim", "/simulated"): [],
        ("/real", "/given"): [],
        # roslaunch's __name:= and __log:= are in sys.argv: one word more than the
        # program's name even with no args
        ("/bare", "/given"): [], ("/bare", "/usage"): [],
        # not known: the tests stay
        ("/unknown", "/given"): ["len(sys.argv) > 1"],
        ("/unknown", "/simulated"): ['len(sys.argv) > 1 and sys.argv[1] == "simulated"'],
        ("/unknown", "/usage"): ["len(rospy.myargv()) < 2"],
    }


def test_a_ros2_instance_s_sys_argv_is_not_known() -> None:
    def nothing(name: str) -> object:
        return Unknown(name)
    ros2 = [(None, ["machine.py", "simulated"])]
    assert decide(Condition("len(sys.argv) > 1"), nothing, ros2) is None
    ros1 = [(["machine.py", "simulated", "__name:=sim", "__log:=x"],
             ["machine.py", "simulated"]),
            (["machine.py", "simulated"], ["machine.py", "simulated"])]
    assert decide(Condition("len(sys.argv) > 3"), nothing, ros1) is True
    assert decide(Condition("len(rospy.myargv()) > 2"), nothing, ros1) is False
    assert decide(Condition("sys.argv[1] == 'real'", statement="else"), nothing,
                  ros1) is True
    assert decide(Condition("len(sys.argv) > 1"), nothing, None) is None
