"""A ROS 1 Python node that calls into a module whose code is not read and that no list
knows as a library was 'complete': mobiman's training node calls openai_ros'
``StartOpenAI_ROS_Environment(name)`` (openai_ros neither in the workspace nor in
package.xml), whose gym environment reads the 80 parameters the launch file sets, and
each was a false parameter-set-not-read. rospy's node is the process's, so such code
can read parameters without being given anything: ``PY_MODULE_UNSEEN`` names the module
at its first call, the node is partial, and the parameters are undecided. Not for the
standard library, a client library, a library rosdep installs (by pip, or by a Python
key of its own: ``python3-requests``, ``python3-smbus``), a package known to make no ROS
call, a module of the workspace, roslaunch, nor in ROS 2, whose node a function must be
given."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue
from haros_arch.workspace import scan

TRAINING = """#!/usr/bin/env python3
import os
import numpy as np
import requests
import smbus
import rospy
import roslaunch
from openai_ros.openai_ros_common import StartOpenAI_ROS_Environment
from stable_baselines3.ppo.ppo import PPO
from helpers.tools import scale
import openai_ros.robot_envs

rospy.init_node('training')
name = rospy.get_param('~task_and_robot_environment_name', '')
uuid = roslaunch.rlutil.get_or_generate_uuid(None, False)
env = StartOpenAI_ROS_Environment(name)
robot = openai_ros.robot_envs.Robot(env)
model = PPO('MlpPolicy', env)
scale(np.array([1.0]))
os.path.join('a', 'b')
bus = smbus.SMBus(1)
requests.get('http://localhost')
rospy.spin()
"""

HELPERS = "def scale(x):\n    return x\n"


def _tree(write_tree, body: str):
    return write_tree({
        "src/trainer/package.xml": package_xml("trainer"),
        "src/trainer/CMakeLists.txt": "project(trainer)\n",
        "src/trainer/scripts/training.py": body,
        "src/trainer/scripts/helpers/__init__.py": "",
        "src/trainer/scripts/helpers/tools.py": HELPERS,
        "src/trainer/launch/training.launch": (
            '<launch>\n  <node name="training" pkg="trainer" type="training.py">\n'
            '    <rosparam>\n      task_and_robot_environment_name: Mobiman-v0\n'
            '      world_range_x_min: -5.0\n    </rosparam>\n  </node>\n</launch>\n'),
        "project.yaml": "project: p\nconfigurations:\n  c: [trainer/launch/training.launch]\n",
    })


def _said(root) -> list[tuple[int, str]]:
    source = root / "src/trainer/scripts/training.py"
    result = extract_python([str(source)], scan([str(root / "src")]), package="trainer")
    return [(d.location.line, d.message) for d in result.diagnostics
            if d.code == "PY_MODULE_UNSEEN"]


def test_a_call_into_an_unread_module_is_said_once(write_tree) -> None:
    assert _said(_tree(write_tree, TRAINING)) == [
        (16, "openai_ros.openai_ros_common.StartOpenAI_ROS_Environment of openai_ros, a "
             "Python module the workspace does not hold and no list knows as a library, "
             "is called here in a ROS 1 node's process; its code is not read")]


def test_the_node_is_partial_and_its_parameters_undecided(write_tree) -> None:
    root = _tree(write_tree, TRAINING)
    os.chmod(root / "src/trainer/scripts/training.py", 0o755)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    (node,) = model.configuration("c").nodes
    assert node.completeness == "partial"
    findings = run_catalogue(model)
    assert [f for f in findings if f.rule == "parameter-set-not-read"] == []
    assert any(f.rule == "parameter-set-not-read-undecided"
               and "world_range_x_min" in f.message for f in findings)


def test_known_libraries_and_workspace_modules_are_not(write_tree) -> None:
    body = "\n".join(line for line in TRAINING.splitlines()
                     if "openai_ros" not in line and "Robot(" not in line) + "\n"
    assert _said(_tree(write_tree, body)) == []


def test_a_ros2_node_calling_such_a_module_without_the_node_is_not(write_tree) -> None:
    body = ("import rclpy\nfrom openai_ros.openai_ros_common import StartOpenAI_ROS_Environment\n"
            "rclpy.init()\nnode = rclpy.create_node('training')\n"
            "env = StartOpenAI_ROS_Environment('Mobiman-v0')\nrclpy.spin(node)\n")
    assert _said(_tree(write_tree, body)) == []


PYTHON2_CONSOLE = """#!/usr/bin/env python
import Queue
import tkFont
import Tkinter as tk
import urllib2
import rospy
from crc8 import crc8

rospy.init_node('console')
font = tkFont.Font(size=24)
root = tk.Tk()
pending = Queue.Queue()
urllib2.urlopen('http://localhost')
rospy.spin()
"""


def test_python2_standard_library_modules_are_not(write_tree) -> None:
    # cusub (848e8a0) console.py:36 builds ``tkFont.Font(size=24)`` in a Python 2 node:
    # tkFont is Python 2's standard library (Python 3's tkinter.font), which makes no
    # ROS call, and the node was partial for it; a module no list knows (crc8, of
    # PyPI, ActuatorService.py:38) is still said
    body = PYTHON2_CONSOLE + "crc8(b'x')\n"
    assert _said(_tree(write_tree, body)) == [
        (15, "crc8.crc8 of crc8, a Python module the workspace does not hold and no list "
             "knows as a library, is called here in a ROS 1 node's process; its code is "
             "not read")]


HISTOGRAM = """#!/usr/bin/env python
import rospy
import rostopic
import rosnode
import rosservice

rospy.init_node('histogram')
cls, real, _ = rostopic.get_topic_class('/depth', blocking=True)
rospy.Subscriber(real, cls, lambda m: None)
names = rosnode.get_node_names()
rosservice.call_service('/drop_marker', [])
rospy.spin()
"""


def test_master_queries_of_ros_comm_tools_are_not(write_tree) -> None:
    # the Palouse RoboSub (40e79ed) scripts/histogram.py:20 asks rostopic for a topic's
    # class and subscribes itself: no unseen module; rosservice's call_service calls a
    # service of the node's process: still said
    assert _said(_tree(write_tree, HISTOGRAM)) == [
        (11, "rosservice.call_service of rosservice, a Python module the workspace does "
             "not hold and no list knows as a library, is called here in a ROS 1 node's "
             "process; its code is not read")]


POINTS = """#!/usr/bin/env python
import rospy
from sensor_msgs.msg import PointCloud2
import sensor_msgs.point_cloud2 as pc2
from velodyne_msgs import helpers
from lab_filters import decoder

def callback(msg):
    for p in pc2.read_points(msg, skip_nans=True, field_names=("x", "y", "z")):
        rospy.loginfo("%f", p[0])
    helpers.stamp(msg)
    decoder.decode(msg)

rospy.init_node('pointcloud_data')
rospy.Subscriber('/kinect2/sd/points', PointCloud2, callback)
rospy.spin()
"""


def test_helpers_of_interface_packages_are_not(write_tree) -> None:
    # wpb_home (0917443) wpb_home_python/scripts/pointcloud_data.py:11 reads a cloud with
    # ROS 1 sensor_msgs' point_cloud2.read_points: an interface package's helper, no ROS
    # call, and the node was partial; a module of another package is still said
    assert _said(_tree(write_tree, POINTS)) == [
        (12, "lab_filters.decoder.decode of lab_filters, a Python module the "
             "workspace does not hold and no list knows as a library, is called here in a "
             "ROS 1 node's process; its code is not read")]
