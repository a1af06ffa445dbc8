"""A ros_gz bridge whose program is neither in the workspace nor modelled (osrf/mbzirc's
launch files start ``ros_ign_bridge parameter_bridge`` with ``parameters=[{'lazy':
True}]``; no ros_ign_bridge model exists for the distributions shipped): its topics are
its arguments and its config file, but which of its own parameters it reads depends on
its release (humble's and jazzy's parameter_bridge read ``config_file``, ``lazy``,
``subscription_heartbeat``, ...; galactic's ros_ign_bridge reads none). Each parameter
the launch file gives it was "set but never read", ``config_file`` too, whose file the
bridge was read with; now they are undecided. A modelled bridge still decides them."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue

LAUNCH = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node
def generate_launch_description():
    cfg = os.path.join(get_package_share_directory('sim'), 'config', 'bridge.yaml')
    return LaunchDescription([
        Node(package='ros_ign_bridge', executable='parameter_bridge', name='ign',
             arguments=['/scan@sensor_msgs/msg/LaserScan[ignition.msgs.LaserScan'],
             parameters=[{'lazy': True}]),
        Node(package='ros_ign_bridge', executable='parameter_bridge', name='ign_file',
             parameters=[{'config_file': cfg}]),
        Node(package='ros_gz_bridge', executable='parameter_bridge', name='gz',
             parameters=[{'config_file': cfg, 'lazy': True, 'lazzy': True}]),
    ])
"""

CONFIG = """
- ros_topic_name: /clock
  gz_topic_name: /clock
  ros_type_name: rosgraph_msgs/msg/Clock
  gz_type_name: gz.msgs.Clock
  direction: GZ_TO_ROS
"""


def test_an_unknown_bridge_program_leaves_its_parameters_undecided(write_tree):
    root = write_tree({
        "src/sim/package.xml": package_xml("sim", "ament_cmake"),
        "src/sim/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(sim)\n"
                                  "find_package(ament_cmake REQUIRED)\nament_package()\n",
        "src/sim/config/bridge.yaml": CONFIG,
        "src/sim/launch/sim.launch.py": LAUNCH,
        "project.yaml": "project: p\ndistro: jazzy\n"
                        "configurations:\n  c: [sim/launch/sim.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    config = model.configurations[0]
    topics = sorted((link.kind, link.resource.name) for n in config.nodes
                    if n.name in ("/ign", "/ign_file") for link in n.links
                    if link.kind in ("publish", "subscribe"))
    assert topics == [("publish", "/clock"), ("publish", "/scan")]
    found = run_catalogue(model)
    unread = sorted(e for f in found if f.rule == "parameter-set-not-read"
                    for e in f.entities if e.startswith("parameter:"))
    # the modelled ros_gz_bridge reads lazy and config_file, not the misspelt one
    assert unread == ["parameter:/gz/lazzy"]
    undecided = [f for f in found if f.rule == "parameter-set-not-read-undecided"]
    assert [(f.message.split(" (")[0], sorted(f.entities)) for f in undecided] == [
        ("2 possible finding(s) not reported", ["node:/ign", "node:/ign_file"])]
