"""An installed ROS 1 mavros offers its node's own raw MAVLink bridge (mavros.cpp:
``mavlink/to`` subscribed, ``mavlink/from`` and the latched ``mavlink/gcs_ip``
published, for a gcs_bridge or the user's tools) as it offers its plugins' topics: no
subscriber-without-publisher on ``mavlink/to`` where nothing of the configuration
writes raw MAVLink (bluerov_ros_playground's user_mav.launch had that warning and two
publisher-without-subscriber infos). A node of the workspace that publishes there is
still a partner, and the rest of the configuration is checked as before."""

from __future__ import annotations

import os

from conftest import FIXTURES

from haros_arch import pipeline
from haros_arch.project import ConfigurationSpec, Project
from haros_arch.query import run_catalogue

ROOT = str(FIXTURES / "build" / "plugins")
RULES = ("subscriber-without-publisher", "publisher-without-subscriber",
         "similar-disconnected-topics")


def test_ros1_mavros_s_own_mavlink_topics_are_offered():
    project = Project("plugins", os.path.join(ROOT, "project.yaml"), workspace=[ROOT],
                      configurations=[ConfigurationSpec(
                          "c", ["bringup/launch/mavros.launch"], {})])
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    mavros = config.node("/drone1/mavros")
    assert mavros is not None and mavros.offered
    made = {(link.kind, link.resource.name) for link in config.links if link.node is mavros}
    assert {("subscribe", "/drone1/mavlink/to"), ("publish", "/drone1/mavlink/from"),
            ("publish", "/drone1/mavlink/gcs_ip")} <= made
    found = [f for f in run_catalogue(model, project) if f.rule in RULES]
    assert not any("/drone1/mavlink/" in f.message for f in found), [
        f.message for f in found]
