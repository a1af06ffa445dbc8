"""A Gazebo ROS 2 plugin's ``<ros><argument>`` words, read as gazebo_ros and rcl read them."""

from __future__ import annotations

import os

from conftest import FIXTURES
from lxml import etree

from haros_arch import pipeline
from haros_arch.model.runtime import Configuration
from haros_arch.project import ConfigurationSpec, Project
from haros_arch.robot.attach import _PluginArguments
from haros_arch.workspace import Workspace

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
    # ROS 1's __log_level:= is no rule to rcl (ignored), then imu_b's and imu_c's words
    assert said == [("GAZEBO_PLUGIN_ARGUMENT", 6), ("GAZEBO_PLUGIN_ARGUMENT", 23),
                    ("GAZEBO_PLUGIN_ARGUMENT", 30), ("GAZEBO_PLUGIN_ARGUMENT_UNKNOWN", 48)]
    # a rostopic:// rule is not modelled: said, and the node is partial
    assert config.node("/imu_e").completeness == "partial"
    assert config.node("/truth").completeness == "complete"


def read(*words: str, name: str = "p") -> tuple[_PluginArguments, list[str]]:
    config = Configuration("c")
    said = _PluginArguments(name, Workspace("/nowhere"), config)
    for word in words:
        element = etree.Element("argument")
        element.text = word
        said.word(element)
    said.end()
    return said, [d.code for d in config.diagnostics]


def test_an_argument_with_unknown_parts_is_said_and_not_applied():
    said, codes = read("~/out:=?/scan", "odom:=odom/truth")
    assert codes == ["GAZEBO_PLUGIN_ARGUMENT_UNKNOWN"] and said.partial
    assert said.remaps_for("p") == [("odom", "odom/truth")]


def test_rcl_flags_and_their_values():
    # a parameter's value is no rule; --enable-*-logs takes no value; -- ends --ros-args
    said, codes = read("--ros-args", "-p", "a:=?", "--disable-stdout-logs", "-r", "x:=y",
                       "--", "u:=v", "--ros-args", "-r")
    assert said.remaps_for("p") == [("x", "y"), ("u", "v")]
    assert codes == ["GAZEBO_PLUGIN_ARGUMENT"]  # the -r no rule follows
    # a relative __ns is no rule to rcl; a rule for another node is not this one's
    said, codes = read("__ns:=relative", "q:a:=b", "p:c:=d")
    assert said.remaps_for("p") == [("c", "d")] and said.namespace is None
