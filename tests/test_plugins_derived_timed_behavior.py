"""Behaviours of the workspace derived from navigation2's TimedBehavior<ActionT>, whose
package is not in the workspace (navigation2_tutorials' SendSms): the stand-in of
nav2_behaviors declares the base with its members (``node_``, ``behavior_name_``, ...),
so the derived class parses (``node_`` was an undeclared identifier and its calls were
kept by name only), and the behavior server that loads the class serves the class's
action under the plugin's name, with the type the class gives the base, and publishes
cmd_vel, as the base's configure(), which the class runs, does."""

from __future__ import annotations

from pathlib import Path

from haros_arch.api import analyse_path
from haros_arch.pipeline import Options

FIXTURE = Path(__file__).resolve().parent.parent / "fixtures" / "cpp" / "derived_behavior"


def test_a_behavior_derived_from_timed_behavior_serves_its_action_as_the_base_does() -> None:
    analysis = analyse_path(str(FIXTURE), Options(cache_dir=None, jobs=1))
    assert analysis.model is not None
    (config,) = analysis.model.configurations
    links = {(link.kind, link.resource.name, link.type) for link in config.links
             if link.node.name == "/behavior_server"}
    # the base's action server, named after the plugin, typed by the template argument
    # (through the class's alias, and written in place)
    assert ("action-server", "/announce", "my_behaviors/action/Announce") in links
    assert ("action-server", "/pause", "nav2_msgs/action/Wait") in links
    # the base's velocity publisher and the frames it reads from the server
    assert ("publish", "/cmd_vel", "geometry_msgs/msg/Twist") in links
    names = {name for kind, name, _type in links if kind == "read"}
    assert {"/behavior_server/robot_base_frame", "/behavior_server/cycle_frequency"} <= names
    # the class's own code, on the node the base keeps, under the plugin's name
    assert ("publish", "/speech", "std_msgs/msg/String") in links
    assert ("read", "/behavior_server/announce.volume", "double") in links
    codes = {d.code for d in analysis.model.diagnostics
             if d.location.file.startswith("my_behaviors/")}
    assert not codes & {"CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_UNRESOLVED",
                        "CPP_NODE_PARTIAL"}
