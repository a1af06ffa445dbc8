"""A ros_gz bridge whose package is not here still has the topics of its arguments
(survey Z49: dolly's ignition launch file starts ``ros_ign_bridge parameter_bridge``,
a package neither in the workspace nor installed, nor modelled). The warning said
its interface was unknown while the graph held its three bridged topics."""

from __future__ import annotations

import os

from conftest import FIXTURES

from haros_arch import pipeline
from haros_arch.project import ConfigurationSpec, Project

ROS2 = str(FIXTURES / "robot" / "ros2")


def test_a_bridge_package_not_here_is_said_with_the_topics_of_its_arguments():
    config = pipeline.analyse(
        Project("robot", os.path.join(ROS2, "project.yaml"), workspace=[ROS2],
                configurations=[ConfigurationSpec(
                    "c", ["bot2_description/launch/gz.launch.py"], {})]),
        {}, pipeline.Options(cache_dir=None, jobs=1, models=False)).configurations[0]
    bridge = [n for n in config.nodes if n.node is not None
              and n.node.executable == "parameter_bridge"]
    # its five topics, and a read of a parameter of its own not known (which ones its
    # release reads is not known: test_robot_bridge_unknown_parameters)
    assert [(n.completeness, sorted(c.kind for c in n.node.calls)) for n in bridge] == [
        ("complete", ["publish", "publish", "publish", "read", "subscribe", "subscribe"])]
    said = [d.message for d in config.diagnostics if d.code == "NODE_PACKAGE_UNKNOWN"
            and "parameter_bridge" in d.message]
    assert said == ["package ros_gz_bridge of node ros_gz_bridge/parameter_bridge is "
                    "not in the workspace nor installed here; its topics are read from "
                    "its arguments"]
