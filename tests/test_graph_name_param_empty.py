"""NAME_PARAM_UNSET says why a name taken from a parameter stays unknown. Where the
launch file sets the parameter to the empty string (aau_multi_robot's launch files
default ``robot_prefix`` to ""), or to a value not known statically, it must not say
that the configuration does not set it."""

from __future__ import annotations

from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Node, PrimitiveCall
from haros_arch.model.values import Unknown
from haros_arch.workspace import Workspace


def _messages(value: object, name: str, ros_version: int = 1) -> list[str]:
    node = Node("pkg", "exe", calls=[
        PrimitiveCall("publish", name, "std_msgs/String", name_param="~topic",
                      handle_namespace="~" if name.startswith("~") else None)])
    decl = NodeDecl("/n", "pkg", "exe", "/", ros_version=ros_version)
    params = [] if value is None else [ParamDecl(
        "/n/topic", value, node="/n" if ros_version == 2 else None,
        key="topic" if ros_version == 2 else None)]
    config = build(Configuration("c"), LaunchModel(nodes=[decl], params=params),
                   Workspace(root="/x"), {"pkg/exe": node})
    return [d.message for d in config.diagnostics if d.code == "NAME_PARAM_UNSET"]


def test_a_parameter_the_launch_does_not_set() -> None:
    (message,) = _messages(None, "?")
    assert "which the configuration does not set" in message


def test_a_parameter_set_to_the_empty_string_is_said_so() -> None:
    for name in ("?", "~?", "robot/?"):
        (message,) = _messages("", name)
        assert "does not set" not in message, message
        assert "sets to the empty string" in message, message
        assert "it stays unknown" in message
    (message,) = _messages("", "/?/ctrl", ros_version=2)
    assert "sets to the empty string" in message and "/ctrl" in message, message


def test_a_parameter_set_to_a_value_not_known() -> None:
    (message,) = _messages(Unknown(), "?")
    assert "does not set" not in message, message
    assert "a value not known" in message, message
