"""A ROS 1 controller is an object its controller manager loads in the manager's
process, not a node: the master never hears its name, so a node of the same name (in
the controller's namespace) does not collide with it. squirrel_robotino (12e4ed9)
robotino_controller_configuration_gazebo/launch/shell_controller.launch:14 starts
door_controller.py as ``door_controller`` in ``shell_controller``, beside the position
controller of that name its shell_controller.yaml:21 defines for Gazebo's manager: the
node publishes the controller's ``door_controller/command`` and was reported as a
duplicate node name (an error). ROS 2 controllers are nodes: they still collide."""

from __future__ import annotations

import os
from typing import Any

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

DOOR = """#!/usr/bin/env python
import rospy
from std_msgs.msg import Float64

rospy.init_node('door_controller_server')
pub = rospy.Publisher('door_controller/command', Float64, queue_size=10)
rospy.spin()
"""

LAUNCH = """<launch>
  <group ns="shell_controller">
    <rosparam>
      door_controller:
        type: position_controllers/JointPositionController
        joint: door_joint
    </rosparam>
    <node name="spawner" pkg="controller_manager" type="spawner" args="door_controller" />
    <node name="door_controller" pkg="shell" type="door_controller.py" />
  </group>
</launch>
"""


def test_a_node_named_as_a_ros1_controller_is_no_duplicate(write_tree: Any) -> None:
    xml = package_xml("shell", None).replace("</package>", "".join(
        f"<depend>{d}</depend>" for d in ("rospy", "controller_manager")) + "</package>")
    root = write_tree({
        "src/shell/package.xml": xml,
        "src/shell/CMakeLists.txt": "project(shell)\n",
        "src/shell/scripts/door_controller.py": DOOR,
        "src/shell/launch/shell.launch": LAUNCH,
        "src/shell/launch/other.launch": (
            '<launch>\n  <node name="door_controller" ns="shell_controller" pkg="shell"'
            ' type="door_controller.py" />\n</launch>\n'),
        "project.yaml": ("project: p\nconfigurations:\n  c: [shell/launch/shell.launch]\n"
                         "  both: [shell/launch/shell.launch, shell/launch/other.launch]\n")})
    os.chmod(root / "src/shell/scripts/door_controller.py", 0o755)
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    config = model.configuration("c")
    # the controller (no manager of the configuration is known: an instance of its own,
    # as Gazebo's unknown hwi_switch_gazebo_ros_control left squirrel's) beside the node
    assert sorted((n.name, n.origin) for n in config.nodes
                  if n.name == "/shell_controller/door_controller") == [
        ("/shell_controller/door_controller", "launch"),
        ("/shell_controller/door_controller", "plugin")]
    findings = run_catalogue(model, project)
    assert not [f for f in findings if f.configuration == "c"
                and f.rule.startswith("duplicate-node-names")]
    # two nodes of that name (two launch files of one configuration) still collide, and
    # the controller is not counted with them
    assert [f.message.split(" (")[0] for f in findings if f.configuration == "both"
            and f.rule == "duplicate-node-names"] == [
        "2 nodes are named /shell_controller/door_controller"]
