"""Python's counting loops up to a parameter's value (``for i in range(n)``, ``n`` a
parameter read): a call named by the loop's variable (``'~waypoint%d_x' % i``,
``'~waypoint{}_y'.format(i)``, ``f'~gain{i}'``) is one call per turn of the value the
configuration gives the parameter, as the C++ reader's (test_graph_counting_loop_parameter);
they were ``~waypoint?_x``, every waypoint setting undecided."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue

SCRIPT = """#!/usr/bin/env python
import rospy
rospy.init_node('wp')
n = rospy.get_param('~waypoint_num', 0)
points = []
for i in range(n):
    points.append(rospy.get_param('~waypoint%d_x' % i))
    points.append(rospy.get_param('~waypoint{}_y'.format(i)))
gains = [rospy.get_param(f'~gain{k}', 1.0) for k in range(3)]
for k in range(1, rospy.get_param('~stages', 1)):
    rospy.Publisher(f'stage{k}/cmd', rospy.AnyMsg, queue_size=1)
rospy.spin()
"""

LAUNCH = """
<launch>
  <node pkg="wp" type="wp.py" name="wp">
    <param name="waypoint_num" value="1"/>
    <param name="waypoint0_x" value="1.0"/>
    <param name="waypoint0_y" value="1.0"/>
    <param name="waypoint1_x" value="2.0"/>
    <param name="stages" value="3"/>
  </node>
</launch>
"""


def test_each_turn_of_a_python_loop_up_to_a_parameter(write_tree) -> None:
    root = write_tree({
        "src/wp/package.xml": package_xml("wp"),
        "src/wp/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0.2)\nproject(wp)\n"
                                 "find_package(catkin REQUIRED COMPONENTS rospy)\n"
                                 "catkin_package()\n",
        "src/wp/scripts/wp.py": SCRIPT,
        "src/wp/launch/wp.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [wp/launch/wp.launch]\n",
    })
    os.chmod(root / "src/wp/scripts/wp.py", 0o755)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    config = model.configurations[0]
    named = sorted((link.kind, link.resource.name) for link in config.links
                   if link.node.name == "/wp" and link.kind in ("read", "publish"))
    assert ("read", "/wp/waypoint0_x") in named and ("read", "/wp/waypoint0_y") in named
    assert ("publish", "/stage1/cmd") in named and ("publish", "/stage2/cmd") in named
    assert not [name for _, name in named if "?" in name]
    unread = sorted(e for f in run_catalogue(model) if f.rule == "parameter-set-not-read"
                    for e in f.entities if e.startswith("parameter:"))
    assert unread == ["parameter:/wp/waypoint1_x"]
