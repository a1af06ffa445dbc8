"""A Python program that starts nodes with a command (Doosan's dmodel.py writes an
rviz configuration and runs ``subprocess.call(['rosrun', 'rviz', 'rviz', '-d',
path])``) starts nodes not read: ``PY_RUNS_ROS_TOOL`` at the call, and the node is
partial, not one with no interface. And roslib's legacy ``from ros import rosparam``
is rosparam (dmodel.py's ``rosparam.get_param(p)`` of each parameter it lists)."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import Workspace

MODEL = """#!/usr/bin/env python
from ros import rosparam
import os
import subprocess

if __name__ == "__main__":
    for p in rosparam.list_params(''):
        v = rosparam.get_param(p)
    rosparam.set_param('/model/ready', 'true')
    args = ['rosrun', 'rviz', 'rviz', '-d', '/tmp/model.rviz']
    subprocess.call(args)
    subprocess.call(['ls', '-l'])
    subprocess.Popen('/opt/ros/noetic/bin/roslaunch demo demo.launch', shell=True)
    os.system('echo roslaunch')
"""


def test_a_command_that_starts_nodes_is_said(tmp_path) -> None:
    source = tmp_path / "dmodel.py"
    source.write_text(MODEL)
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    said = [(d.code, d.location.line) for d in result.diagnostics
            if d.code == "PY_RUNS_ROS_TOOL"]
    assert said == [("PY_RUNS_ROS_TOOL", 11), ("PY_RUNS_ROS_TOOL", 13)]


def test_rosparam_imported_from_ros_is_rosparam(tmp_path) -> None:
    source = tmp_path / "dmodel.py"
    source.write_text(MODEL)
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    assert [(c.kind, c.name) for c in result.calls] == [
        ("read", "?"), ("write", "/model/ready")]
