"""A bt_navigator navigator of the workspace derived from nav2_core's
BehaviorTreeNavigator<ActionT>, navigation2 not in the workspace (opennav_coverage's
CoverageNavigator): the nav2_core stand-in declares the base with its members
(``bt_action_server_`` was an undeclared identifier), and bt_navigator, loading the
class, serves ActionT under the name the class's getName() returns, as the base's
on_configure does; the default trees of the navigators its list leaves out are not
run."""

from __future__ import annotations

from pathlib import Path

from haros_arch.api import analyse_path
from haros_arch.pipeline import Options

FIXTURE = Path(__file__).resolve().parent.parent / "fixtures" / "cpp" / "derived_navigator"


def test_a_navigator_derived_from_the_tree_navigator_serves_its_action() -> None:
    analysis = analyse_path(str(FIXTURE), Options(cache_dir=None, jobs=1))
    assert analysis.model is not None
    (config,) = analysis.model.configurations
    links = {(link.kind, link.resource.name, link.type) for link in config.links
             if link.node.name == "/bt_navigator"}
    assert ("action-server", "/cover_area", "my_navigator/action/CoverArea") in links
    names = {name for kind, name, _type in links if kind == "read"}
    # the tree server's settings the base reads, and the class's own under its name
    assert {"/bt_navigator/bt_loop_duration", "/bt_navigator/default_cover_bt_xml",
            "/bt_navigator/cover_area.area_blackboard_id"} <= names
    # NavigateToPose is not in the list: neither its server nor its tree's clients
    assert not any(kind == "action-client" for kind, _name, _type in links)
    assert ("action-server", "/navigate_to_pose", "nav2_msgs/action/NavigateToPose") \
        not in links
    codes = {d.code for d in analysis.model.diagnostics
             if d.location.file.startswith("my_navigator/")}
    assert not codes & {"CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NODE_PARTIAL"}
