"""A Python name built from an option that argparse parses (intera_interface's joint
trajectory action server: ``parser.add_argument("-l", "--limb", dest="limb",
default=valid_limbs[0])``, ``args = parser.parse_args(rospy.myargv()[1:])``, then
``"/robot/limb/" + limb + "/joint_command"`` in the classes it builds) carries the option's
flags (``PrimitiveCall.name_option``), and the graph names it with the value the launch
file's ``args`` give the instance (``--limb right``, ``-l left``, ``--limb=right``); with
none, its ``default=`` when that is a literal string; with arguments not known statically
the ``?`` stays."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import scan

SERVER = """import argparse
import rospy
from std_msgs.msg import String

class Server(object):
    def __init__(self, limb, mode):
        ns = "robot/limb/" + limb
        self._pub = rospy.Publisher(ns + "/joint_command", String, queue_size=1)
        self._sub = rospy.Subscriber("/robot/" + mode + "/state", String, self.cb)
    def cb(self, msg):
        pass

def start(limb, mode, valid):
    if limb == "all":  # a server per limb the parameter names, else the one asked for
        for each in valid:
            Server(each, mode)
    else:
        Server(limb, mode)

def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("-l", "--limb", dest="limb", default=rospy.get_param("~limb"))
    parser.add_argument("-m", "--control-mode", default="position")
    parser.add_argument("rate")
    args, unknown = parser.parse_known_args(rospy.myargv()[1:])
    rospy.init_node("server")
    start(args.limb, args.control_mode, rospy.get_param("~limbs"))
    rospy.spin()

if __name__ == "__main__":
    main()
"""

LAUNCH = """<launch>
  <node pkg="arm" type="server.py" name="a" args="--limb right --control-mode velocity 100"/>
  <node pkg="arm" type="server.py" name="b" args="-lleft --control-mode=position 100"/>
  <node pkg="arm" type="server.py" name="c" args="100"/>
</launch>
"""


def test_names_from_argparse_options(write_tree) -> None:
    root = write_tree({
        "src/arm/package.xml": package_xml("arm"),
        "src/arm/CMakeLists.txt": "project(arm)\n"
                                  "catkin_install_python(PROGRAMS scripts/server.py)\n",
        "src/arm/scripts/server.py": SERVER,
        "src/arm/launch/arm.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [arm/launch/arm.launch]\n",
    })
    ws = scan([str(root / "src")], {})
    result = extract_python([str(root / "src" / "arm" / "scripts" / "server.py")], ws,
                            package="arm")
    assert sorted((c.name, c.name_option or "") for c in result.calls if c.kind != "read") == [
        ("/robot/?/state", "-m --control-mode"),
        ("robot/limb/?/joint_command", ""), ("robot/limb/?/joint_command", "-l --limb")]
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    config = model.configuration("c")
    names = {(link.node.name, link.kind, link.rosname.full) for link in config.links
             if link.kind in ("publish", "subscribe")}
    assert names == {
        # a server per element of ~limbs, or the one of --limb: nothing sets ~limbs, and
        # rospy.get_param("~limbs") with no default raises, so no server per element
        # (graph.conditions._list_unset); /c's "?" is its --limb default, ~limb unset
        ("/a", "publish", "/robot/limb/right/joint_command"),
        ("/a", "subscribe", "/robot/velocity/state"),
        ("/b", "publish", "/robot/limb/left/joint_command"),
        ("/b", "subscribe", "/robot/position/state"),
        ("/c", "publish", "/robot/limb/?/joint_command"),
        # no --control-mode: argparse's default, "position"
        ("/c", "subscribe", "/robot/position/state"),
    }


SPAWN = """import argparse
import sys
import rospy
from std_msgs.msg import String
from std_srvs.srv import Empty

def main():
    parser = argparse.ArgumentParser()
    source = parser.add_mutually_exclusive_group(required=True)
    source.add_argument('-file', type=str)
    source.add_argument('-topic', type=str)
    parser.add_argument('-gazebo_namespace', type=str, default='')
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node('spawn')
    if args.topic:
        rospy.Subscriber(args.topic, String, lambda msg: None)
    rospy.ServiceProxy('%s/spawn' % args.gazebo_namespace, Empty)

if __name__ == "__main__":
    main()
"""


def test_options_of_a_group_and_literal_defaults(write_tree) -> None:
    """gazebo_ros' spawn_entity.py: ``-topic`` is an option of a mutually exclusive
    group of the parser (it was no option at all, the subscription's name ``?``), and
    ``-gazebo_namespace`` defaults to ``''`` (its client's name stayed ``?/spawn_entity``
    when the launch file does not give it)."""
    root = write_tree({
        "src/sim/package.xml": package_xml("sim"),
        "src/sim/CMakeLists.txt": "project(sim)\n"
                                  "catkin_install_python(PROGRAMS scripts/spawn.py)\n",
        "src/sim/scripts/spawn.py": SPAWN,
        "src/sim/launch/sim.launch": (
            '<launch>\n  <node pkg="sim" type="spawn.py" name="a" '
            'args="-topic /robot_description"/>\n'
            '  <node pkg="sim" type="spawn.py" name="b" '
            'args="-file x.sdf -gazebo_namespace /sim"/>\n</launch>\n'),
        "project.yaml": "project: p\nconfigurations:\n  c: [sim/launch/sim.launch]\n",
    })
    ws = scan([str(root / "src")], {})
    result = extract_python([str(root / "src" / "sim" / "scripts" / "spawn.py")], ws,
                            package="sim")
    assert sorted((c.name, c.name_option, c.name_option_default) for c in result.calls) == [
        ("?", "-topic", None), ("?/spawn", "-gazebo_namespace", "")]
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    names = {(link.node.name, link.kind, link.rosname.full)
             for link in model.configuration("c").links}
    assert names == {("/a", "subscribe", "/robot_description"), ("/a", "client", "/spawn"),
                     ("/b", "subscribe", "?"), ("/b", "client", "/sim/spawn")}
