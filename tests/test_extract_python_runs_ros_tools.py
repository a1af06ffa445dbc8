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


PLAYER = """#!/usr/bin/env python
import subprocess, sys
import rospy

rospy.init_node('player')
bag = rospy.get_param('~bag')
remaps = [a for a in sys.argv[1:] if ':=' in a]
subprocess.call(['rosbag', 'info', '--yaml', bag])
subprocess.call(['rosbag', 'record', '-a'])
subprocess.call(' '.join(['rosbag play', '--clock', bag] + remaps), shell=True)
subprocess.Popen(['ros2', 'bag', 'play', bag])
subprocess.Popen(['ros2', 'bag', 'info', bag])
subprocess.Popen(['ros2', 'run', 'demo_nodes_cpp', 'talker'])
subprocess.Popen(['rqt_bag', bag])
"""


def test_a_command_that_plays_a_bag_is_said_and_one_that_reads_it_is_not(tmp_path) -> None:
    # spencer_bagfile_tools' play.py runs ``rosbag play`` with the remaps it is given:
    # what it publishes is the bag's; ``rosbag info`` and ``record`` publish nothing
    source = tmp_path / "player.py"
    source.write_text(PLAYER)
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    said = [d.location.line for d in result.diagnostics if d.code == "PY_RUNS_ROS_TOOL"]
    assert said == [10, 11, 13, 14]


PROCESSES = """#!/usr/bin/env python3
import subprocess
import time

commands = [
    "MicroXRCEAgent udp4 -p 8888",
    "cd ~/PX4-Autopilot && make px4_sitl gz_x500",
]

for command in commands:
    subprocess.run(["gnome-terminal", "--tab", "--", "bash", "-c", command + "; exec bash"])
    time.sleep(1)
subprocess.run(["xterm", "-e", "ros2 run demo_nodes_cpp talker"])
subprocess.Popen("sh -c 'cd /tmp && micro-ros-agent serial --dev /dev/ttyACM0'", shell=True)
subprocess.run(["gnome-terminal", "--", "bash", "-c", "make; exec bash"])
subprocess.run(["konsole", "-e", "htop"])
"""


def test_a_command_a_terminal_or_a_shell_runs_is_read(tmp_path) -> None:
    """The PX4 offboard example's processes.py opens a terminal tab per command, each a
    bash that runs it: the micro XRCE-DDS agent, which puts PX4's topics (``/fmu/out/
    ...``) on the graph, and the simulator. The agent starts ROS entities as rosrun
    does; the terminal, the shell and ``make`` do not."""
    source = tmp_path / "processes.py"
    source.write_text(PROCESSES)
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    said = [d.location.line for d in result.diagnostics if d.code == "PY_RUNS_ROS_TOOL"]
    assert said == [11, 13, 14]
