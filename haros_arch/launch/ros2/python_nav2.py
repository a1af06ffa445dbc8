"""nav2_common's launch helpers, as the static Python interpreter knows them.

``RewrittenYaml`` (parameter, key and value rewrites under an optional root key),
``ReplaceString`` (text replacements, maybe under a condition), ``LaunchConfigAsBool``,
``HasNodeParams`` and Humble's ``ParseMultiRobotPose``: rows of ``python_api.API`` (and
of its methods), never nav2's own code.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import yaml

from ... import safe_yaml
from ...model.values import Unknown
from . import entities as e
from .python_methods import Args, Builder, Kwargs, Method, arg, cond, text_or_none
from .python_values import derived, to_text

if TYPE_CHECKING:
    from .python import Interpreter


def launch_config_as_bool(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    return e.Logic("asbool", ((e.Var(to_text(arg(a, k, 0, "name"))),),))


def has_node_params(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    node = arg(a, k, 1, "node_name")
    if not isinstance(node, str):
        return Unknown("HasNodeParams with a node name not known statically")
    return e.NodeParamsIn(to_text(arg(a, k, 0, "source_file")), node)


def rewritten_yaml(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    rewrites = k.get("param_rewrites") or {}
    pairs = [(to_text(key), to_text(val) if not isinstance(val, (bool, int, float))
              else val) for key, val in rewrites.items()] if isinstance(rewrites, dict) else []
    root = k.get("root_key")

    def text_pairs(given: Any) -> list[tuple[e.Text, e.Text]]:
        return [(to_text(key), to_text(val)) for key, val in given.items()] if isinstance(
            given, dict) else []

    return e.ParamFile(to_text(arg(a, k, 0, "source_file")), text_or_none(root), pairs,
                       i.where(n), key_rewrites=text_pairs(k.get("key_rewrites")),
                       value_rewrites=text_pairs(k.get("value_rewrites")))


def replace_string(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """nav2_common's ``ReplaceString``: the file with text replaced (if its condition)."""
    replacements = k.get("replacements") or {}
    pairs = [(to_text(key), to_text(val)) for key, val in replacements.items()] if isinstance(
        replacements, dict) else []
    return e.ParamFile(to_text(arg(a, k, 0, "source_file")), location=i.where(n),
                       replacements=pairs, condition=cond(i, k.get("condition"), n))


@dataclass(frozen=True)
class MultiRobotPoses:
    """Humble's ``ParseMultiRobotPose(target)``: the text of ``target:=...`` on the
    command line ``ros2 launch`` was started with (``sys.argv``, whatever file includes
    this one), ``''`` when it is not there."""

    text: str


# the pose fields ParseMultiRobotPose.value() sets to 0.0 when a robot's pose omits them
_POSE_FIELDS = ("x", "y", "z", "roll", "pitch", "yaw")


def parse_multirobot_pose(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    target = arg(a, k, 0, "target_argument")
    if not isinstance(target, str):
        return i.unsupported(n, "ParseMultiRobotPose of an argument name not known "
                                "statically")
    return MultiRobotPoses(i.command_line.get(target, ""))


def m_value(i: Interpreter, owner: Any, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``ParseMultiRobotPose(...).value()``: ``{name: pose}`` of ``name={x: .., ...}``
    entries separated by ``;`` (an entry without exactly one ``=`` skipped), each pose
    read as YAML with the fields it omits at 0.0; ``{}`` when the argument is not given."""
    if not isinstance(owner, MultiRobotPoses):
        if isinstance(owner, Unknown) and owner.kind == "unsupported":  # said where made
            return derived(owner, "method .value() of a value not known statically")
        return i.unsupported(n, "method .value() is not interpreted")
    poses: dict[str, Any] = {}
    for entry in owner.text.split(";") if owner.text else []:
        name_pose = entry.strip().split("=")
        if len(name_pose) != 2:
            continue
        try:
            pose = safe_yaml.load(name_pose[1].strip())
        except yaml.YAMLError as err:
            return i.failed(n, f"a robot's pose cannot be read: {err}", "ScannerError")
        if not isinstance(pose, dict):
            return i.failed(n, f"a robot's pose is not a mapping: {name_pose[1].strip()}",
                            "TypeError")
        pose = dict(pose)
        for field in _POSE_FIELDS:  # after the fields given, as setdefault() adds them
            pose.setdefault(field, 0.0)
        poses[name_pose[0].strip()] = pose
    return poses


NAV2_METHODS: dict[str, Method] = {"value": m_value}


NAV2_COMMON: dict[str, Builder] = {
    "RewrittenYaml": rewritten_yaml, "ReplaceString": replace_string,
    "LaunchConfigAsBool": launch_config_as_bool, "HasNodeParams": has_node_params,
    "ParseMultiRobotPose": parse_multirobot_pose,
}
