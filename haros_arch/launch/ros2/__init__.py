"""ROS 2 launch files (XML, YAML, Python) interpreted statically.

Entry point: ``load(path, workspace, args, environment) -> LaunchModel``. Each format is
turned into the same action tree (``entities``) by its front end (``frontend`` for XML
and YAML, ``python`` for ``.launch.py``, never imported nor executed), and ``runner``
performs it. ``is_ros2(path)`` tells a ROS 2 launch file from a roslaunch one.
"""

from __future__ import annotations

import ast
import os
from collections.abc import Mapping
from typing import Any

import yaml
from lxml import etree

from ...files import read_bytes, read_text
from ...model.launch_tree import LaunchItem
from ...model.location import Location
from ...model.values import Value
from ...share import install_prefix, share_source
from ...workspace import Workspace
from ..dialect import ros_version
from ..model import LaunchModel
from . import entities as e
from .frontend import Frontend, xml_entities, yaml_entities
from .nodes import sections_for_no_node
from .python_values import Lazy
from .runner import Runner, Scope

__all__ = ["is_ros2", "load"]

def is_ros2(path: str, head: bytes | None = None, workspace: Workspace | None = None) -> bool:
    """True for a ROS 2 launch file (``dialect.ros_version``: content, package, name)."""
    return ros_version(path, workspace, head) == 2


def parse_file(path: str, runner: Runner, where: Location) -> list[e.Action] | None:
    """The actions of one launch file, by its format; None if it cannot be read."""
    workspace = runner.workspace
    here = workspace.location(path)
    lower = path.lower()
    if lower.endswith(".py"):
        text, found = read_text(path, here)
        runner.model.diagnostics.extend(found)
        if text is None:
            return None
        return _parse_python(text, path, runner)
    front = Frontend(path, workspace)
    try:
        if lower.endswith((".yaml", ".yml")):
            text, found = read_text(path, here)
            runner.model.diagnostics.extend(found)
            if text is None:
                return None
            root = yaml_entities(text)
        else:
            data, found = read_bytes(path, here)
            runner.model.diagnostics.extend(found)
            if data is None:
                return None
            root = xml_entities(data)
    except etree.XMLSyntaxError as err:
        text = _python_launch_text(path)
        if text is not None:
            # launch loads a file of another extension with its front ends first, then
            # as Python (``get_launch_description_from_any_launch_file``): a Python
            # launch file named ``*.launch`` is one (CMU's autonomy stacks)
            return _parse_python(text, path, runner)
        line, col = err.position if err.position else (0, 0)
        runner.report("LAUNCH_XML_SYNTAX", workspace.location(path, line, col),
                      detail=err.msg)
        return None
    except (yaml.YAMLError, ValueError) as err:
        mark = getattr(err, "problem_mark", None)
        runner.report("LAUNCH_YAML_SYNTAX", workspace.location(
            path, mark.line + 1 if mark else 0, mark.column + 1 if mark else 0),
            detail=str(getattr(err, "problem", None) or err))
        return None
    if root.tag != "launch":
        runner.report("LAUNCH_BAD_VALUE", workspace.location(path, root.line),
                      detail=f"root element is <{root.tag}>, not <launch>")
        return None
    root.read.add("version")
    front.leftovers(root)
    actions = front.actions(root.children)
    runner.model.diagnostics.extend(front.diagnostics)
    return actions


def _parse_python(text: str, path: str, runner: Runner) -> list[e.Action] | None:
    """The actions of a Python launch file's text."""
    from .python import parse_python

    written: dict[str, str] = {}
    unsure = set(runner.environment_unsure)
    actions, problems = parse_python(text, path, runner.workspace, runner.loaded_environment(),
                                     uses=runner.model.package_uses,
                                     command_line=runner.command_line,
                                     written=written, unsure=unsure,
                                     made=runner.model.environment_values,
                                     argv=runner.argv)
    runner.wrote(written, unsure)
    runner.model.diagnostics.extend(problems)
    return actions


def _python_launch_text(path: str) -> str | None:
    """The text of a file that is no XML when it is a Python launch file: Python that
    defines ``generate_launch_description``, which launch's Python loader then calls."""
    try:
        with open(path, encoding="utf-8") as handle:
            text = handle.read()
        tree = ast.parse(text, filename=path)
    except (OSError, UnicodeDecodeError, SyntaxError, ValueError):
        return None
    return text if any(isinstance(node, ast.FunctionDef)
                       and node.name == "generate_launch_description"
                       for node in tree.body) else None


def command_argv(workspace: Workspace, path: str, args: Mapping[str, str]
                 ) -> list[Any] | None:
    """``sys.argv`` of the ``ros2 launch`` process that runs the configuration, as a user
    starts an installed launch file: ``[<ros2>, 'launch', <package>, <file name>,
    'name:=value', ...]`` (the launch files that read it take ``sys.argv[4:]`` as the
    launch arguments: tmr_ros2's, wheeltec's usb_cam); the path of the ros2 script,
    under the install prefix of ros2cli, when that is installed here, else not known.
    None when the file is in no package of the workspace (started by its path, whose
    spelling is the user's)."""
    package = workspace.package_of(path)
    if package is None:
        return None
    prefix = install_prefix(workspace, "ros2cli")
    # (a text not known, not an unknown item: the list's length is known)
    ros2: Any = os.path.join(prefix, "bin", "ros2") if prefix else Lazy((
        e.Opaque("the path of the ros2 command", report=False),))
    return [ros2, "launch", package.name, os.path.basename(path),
            *(f"{name}:={value}" for name, value in args.items())]


def load(path: str, workspace: Workspace, args: Mapping[str, str] | None = None,
         environment: Mapping[str, str] | None = None) -> LaunchModel:
    """Interpret one ROS 2 launch file and what it includes."""
    env = workspace.environment if environment is None else environment
    runner = Runner(workspace, env, parse_file)
    runner.command_line = dict(args or {})
    scope = Scope({k: Value.of(v) for k, v in (args or {}).items()})
    path = os.path.abspath(path)
    runner.argv = command_argv(workspace, path, runner.command_line)
    scope.item = LaunchItem("file", workspace.relpath(share_source(workspace, path)),
                            workspace.location(path), namespace="/")
    runner.model.tree.append(scope.item)
    runner.run_file(path, scope, workspace.location(path))
    runner.unused_arguments()
    sections_for_no_node(runner)
    model = runner.model
    for name, value in (args or {}).items():
        model.args.setdefault(name, value)
    model.diagnostics[:] = list(dict.fromkeys(model.diagnostics))
    return model
