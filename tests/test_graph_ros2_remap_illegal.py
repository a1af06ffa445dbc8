"""A ROS 2 remap rule whose source or target rcl refuses as a name: the node does not
start (rcl fails to parse its arguments; a container refuses the component).
clearpath_sensors' image_rectify.launch.py (fbfe872) declares ``output_ns`` with the
default ``'`rectif`y'`` and remaps ``rectify`` to ``PathJoinSubstitution([output_ns,
'image'])``: nothing said it. Substitutions, wildcards in a source, a ``node:`` prefix,
``~/`` and unknown parts are names rcl takes (or may)."""

from __future__ import annotations

from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl
from haros_arch.model import Configuration, Node
from haros_arch.model.rosname import ros2_name_problem
from haros_arch.model.source import PrimitiveCall
from haros_arch.workspace import Workspace


def _said(remaps: list[tuple[str, str]], version: int = 2) -> list[str]:
    node = Node("image_proc", "rectify", calls=[
        PrimitiveCall("publish", "rectify", "sensor_msgs/msg/Image")])
    config = build(Configuration("c"), LaunchModel(nodes=[NodeDecl(
        "/cam/rectify", "image_proc", "rectify", namespace="/cam", remaps=remaps,
        ros_version=version)]), Workspace(root="/nowhere"), {node.name: node})
    return [d.message for d in config.diagnostics if d.code == "LAUNCH_REMAP_ILLEGAL"]


def test_an_illegal_target_is_an_error() -> None:
    (said,) = _said([("rectify", "`rectif`y/image"), ("image", "color/image")])
    assert said.startswith("remap rectify:=`rectif`y/image given to /cam/rectify: its "
                           "target '`rectif`y/image' is not a legal ROS 2 name (it holds '`'")
    assert _said([("cmd-vel", "cmd_vel")]) and _said([("scan", "scan/")])
    # one error per node: the other rules that one bad value spoils are named in it
    (said,) = _said([("rectify", "`rectif`y/image"), ("rectify/compressed",
                                                      "`rectif`y/compressed"),
                     ("rectify/theora", "`rectif`y/theora"), ("image", "color/image")])
    assert "; so are 2 more of its rules (rectify/compressed:=`rectif`y/compressed, " \
        "rectify/theora:=`rectif`y/theora); rcl refuses" in said
    assert _said([("image", "2d/image")]) and _said([("image", "a//b")])


def test_names_rcl_takes_are_not() -> None:
    assert _said([("rectify", "/rect/image"), ("~/out", "{node}/out"), ("ns/*/cmd", "x"),
                  ("docking_server:cmd_vel", "cmd_vel_nav"), ("image", "?/image"),
                  ("__node", "cam-1"), ("__ns", "/a")]) == []
    # ROS 1 names are roslaunch's to refuse (its loader says so)
    assert _said([("cmd-vel", "cmd_vel")], version=1) == []


def test_the_rules_of_a_ros2_name() -> None:
    assert ros2_name_problem("~x") == "'~' must be followed by '/'"
    assert ros2_name_problem("") == "it is empty"
    assert ros2_name_problem("/") is None and ros2_name_problem("~/a_1/b2") is None
    assert ros2_name_problem("a/1b") == "its part '1b' starts with a digit or is not a name"


def _named(name: str, given: bool = True) -> list[str]:
    config = build(Configuration("c"), LaunchModel(nodes=[NodeDecl(
        f"/cam/{name}", "image_proc", "rectify", namespace="/cam", ros_version=2,
        name_given=given)]), Workspace(root="/nowhere"), {})
    return [d.message for d in config.diagnostics if d.code == "LAUNCH_NODE_NAME_REFUSED"]


def test_a_node_name_rmw_refuses_is_an_error() -> None:
    # a host name's dash, a dotted name, a leading digit: rcl_node_init fails
    assert _named("rectify-left") == [
        "node name rectify-left is not one rmw takes (letters, digits and '_', not "
        "starting with a digit): the node does not start"]
    assert _named("cam.rectify") and _named("2nd_rectify")
    assert _named("rectify_left") == [] and _named("rectify_?") == []
    assert _named("rectify-left", given=False) == []  # the code's name: its own reading


def test_names_are_ascii_to_rcl() -> None:
    # rcl's lexer and rmw's validators take ASCII letters and digits only, where
    # Python's \w takes any letter: one definition of a node name serves every reader
    from haros_arch.model.rosname import is_ros2_node_name
    from haros_arch.robot.attach import _PluginArguments

    assert ros2_name_problem("cámara/image") == "it holds 'á', which a ROS 2 name may not"
    assert ros2_name_problem("camera_2/image") is None
    assert _said([("image", "cámara/image")]) and _named("cámara")
    assert is_ros2_node_name("cam_2") and not is_ros2_node_name("cámara")
    assert not is_ros2_node_name("2cam") and not is_ros2_node_name("cam-2")
    rules = _PluginArguments("p", Workspace(root="/nowhere"), Configuration("c"))
    assert rules._rule("__node:=cámara") == "no" and rules._rule("cámara:a:=b") == "no"
    assert rules._rule("ímage:=b") == "no" and rules._rule("__node:=cam_2") == "rule"
    assert rules.rules == [(None, "__node", "cam_2")]
