"""A Gazebo ROS 2 plugin's ``<ros><argument>`` words, read as gazebo_ros and rcl read them."""

from __future__ import annotations

import os

from conftest import FIXTURES

from haros_arch import pipeline
from haros_arch.model.runtime import Configuration
from haros_arch.project import ConfigurationSpec, Project

ROOT = str(FIXTURES / "robot" / "ros2_args")


def configuration() -> Configuration:
    project = Project("robot", os.path.join(ROOT, "project.yaml"), workspace=[ROOT],
                      configurations=[ConfigurationSpec(
                          "c", ["argbot_description/launch/model.launch.py"], {})])
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    return model.configurations[0]


def test_plugin_arguments_that_rcl_reads_as_remaps_rename_the_plugin_node_topics():
    config = configuration()
    made = sorted((link.node.name, link.resource.name)
                  for link in config.links if link.origin == "description")
    assert made == [
        # ``--ros-args --remap rule``, three words: a remap
        ("/imu_a", "/imu/a"),
        # one word with spaces: not a ROS argument, ignored by rcl
        ("/imu_b", "/imu_b/out"),
        # a rule after --ros-args without -r: rclcpp refuses it, nothing applied
        ("/imu_c", "/imu_c/out"),
        # __node / __ns rules (the deprecated form, outside --ros-args) rename the node;
        # node-specific rules match its new name; the first rule for ~/out wins over
        # the <remapping> after it; --log-level outside --ros-args takes no value
        ("/imu_e", "/imu_e/out"),
        ("/plain", "/odom"),
        ("/robot/imu_dee", "/robot/imu/d"),
        # the deprecated form outside --ros-args: a remap (champ's p3d)
        ("/truth", "/odom/ground_truth"),
    ]
    said = sorted((d.code, d.location.line) for d in config.diagnostics
                  if d.code.startswith("GAZEBO_PLUGIN_ARGUMENT"))
    assert said == [("GAZEBO_PLUGIN_ARGUMENT", 20), ("GAZEBO_PLUGIN_ARGUMENT", 27),
                    ("GAZEBO_PLUGIN_ARGUMENT_UNKNOWN", 45)]
    # a rostopic:// rule is not modelled: said, and the node is partial
    assert config.node("/imu_e").completeness == "partial"
    assert config.node("/truth").completeness == "complete"
