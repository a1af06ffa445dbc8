"""Python's counting loop up to a parameter's value whose name holds the variable plus a
constant (``'~joint_%d' % (i + 1)``, ``'~axis_' + str(1 + k)``, ``f'~stage{j - 1}'``):
one call per turn, named by the shifted value, as the C++ reader's
(test_graph_counting_loop_shifted_name.py); they were ``~joint_?``, every joint setting
undecided. A run that is no such value (``2 * i``) keeps its ``?``."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue

SCRIPT = """#!/usr/bin/env python
import rospy
rospy.init_node('hw')
n = rospy.get_param('~robot_joints', 0)
for i in range(n):
    rospy.get_param('~joint_%d' % (i + 1))
for k in range(n):
    rospy.get_param('~axis_' + str(1 + k))
for j in range(1, n):
    rospy.get_param(f'~stage{j - 1}', 0)
for m in range(n):
    rospy.get_param('~even_%d' % (2 * m), 0)
rospy.spin()
"""

LAUNCH = """
<launch>
  <node pkg="wp" type="hw.py" name="hw">
    <param name="robot_joints" value="2"/>
    <param name="joint_1" value="1"/>
    <param name="joint_2" value="1"/>
    <param name="axis_1" value="1"/>
    <param name="axis_2" value="1"/>
    <param name="axis_3" value="1"/>
  </node>
</launch>
"""


def test_each_turn_reads_the_name_its_shifted_value_makes(write_tree) -> None:
    root = write_tree({
        "src/wp/package.xml": package_xml("wp"),
        "src/wp/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0.2)\nproject(wp)\n"
                                 "find_package(catkin REQUIRED COMPONENTS rospy)\n"
                                 "catkin_package()\n",
        "src/wp/scripts/hw.py": SCRIPT,
        "src/wp/launch/hw.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [wp/launch/hw.launch]\n",
    })
    os.chmod(root / "src/wp/scripts/hw.py", 0o755)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    reads = sorted(link.resource.name for link in model.configurations[0].links
                   if link.node.name == "/hw" and link.kind == "read")
    assert "/hw/joint_1" in reads and "/hw/joint_2" in reads and "/hw/axis_1" in reads
    assert "/hw/joint_?" not in reads and "/hw/joint_0" not in reads
    assert "/hw/stage0" in reads and "/hw/even_?" in reads
    found = sorted((f.rule, e) for f in run_catalogue(model)
                   if f.rule in ("parameter-set-not-read", "parameter-read-not-set")
                   for e in f.entities if e.startswith("parameter:"))
    assert found == [("parameter-set-not-read", "parameter:/hw/axis_3")]
