"""``rospy.resolve_name(name)`` gives the name resolved and remapped at run time; text put
after it is in that name. jsk_robot_startup's mux_selector.py calls
``rospy.ServiceProxy(rospy.resolve_name('mux') + '/select', MuxSelect)`` and is launched
with ``<remap from="mux" to="input_vel_mux"/>`` beside a topic_tools mux remapped alike:
it calls ``/input_vel_mux/select``, which the mux serves, not ``/mux/select``."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

SELECTOR = """#!/usr/bin/env python
import rospy
from std_msgs.msg import String
from topic_tools.srv import MuxSelect

rospy.init_node('mux_selector')
name = rospy.resolve_name('mux')
client = rospy.ServiceProxy(name + '/select', MuxSelect)
pub = rospy.Publisher(rospy.resolve_name('chosen'), String, queue_size=1)
rospy.spin()
"""

LAUNCH = """
    <launch>
      <node pkg="topic_tools" type="mux" name="input_vel_mux" args="cmd_vel nav_vel joy_vel">
        <remap from="mux" to="input_vel_mux"/>
      </node>
      <node pkg="robot" type="selector.py" name="selector">
        <remap from="mux" to="input_vel_mux"/>
        <remap from="chosen" to="selected_input"/>
      </node>
    </launch>
    """


def test_a_name_after_resolve_name_is_in_the_remapped_name(write_tree):
    root = write_tree({
        "src/robot/package.xml": package_xml("robot"),
        "src/robot/CMakeLists.txt": "project(robot)\n",
        "src/robot/scripts/selector.py": SELECTOR,
        "src/robot/launch/a.launch": LAUNCH,
        "project.yaml": "project: p\ndistro: noetic\nconfigurations:\n"
                        "  c: [robot/launch/a.launch]\n",
    })
    (root / "src/robot/scripts/selector.py").chmod(0o755)
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    selector = next(n for n in config.nodes if n.name == "/selector")
    links = sorted((link.kind, link.name) for link in selector.links
                   if link.kind in ("client", "publish"))
    assert links == [("client", "/input_vel_mux/select"), ("publish", "/selected_input")]
    service = next(s for s in config.services if s.name == "/input_vel_mux/select")
    assert [link.node.name for link in service.servers] == ["/input_vel_mux"]
