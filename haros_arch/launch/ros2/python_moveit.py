"""moveit_configs_utils (MoveIt 2's launch helpers), as the static Python interpreter knows
them: rows of ``python_api.API`` and of its methods, never moveit_configs_utils' code
(read in moveit2 humble, jazzy and main: ``moveit_configs_builder.py``, ``launches.py``,
``launch_utils.py``; the three agree on what is read here).

``MoveItConfigsBuilder(robot_name, robot_description='robot_description', package_name=
None)`` reads the config package (``<robot_name>_moveit_config`` unless named): its
``.setup_assistant`` (the URDF's package and path, xacro arguments, the SRDF's path),
``config/<robot_name>.urdf.xacro`` when it is there. Each chained method loads one
section from the config package (a file path given is relative to it): the robot
description and its semantic (a ``xacro`` command line, never run here), kinematics.yaml
(``<description>_kinematics``), joint_limits.yaml and pilz_cartesian_limits.yaml
(``<description>_planning``), moveit_cpp.yaml, the one ``config/*_controllers.yaml``
(``moveit``, ``moveit2`` or the robot's name among several) with
``moveit_manage_controllers``, the planning scene monitor's flags, sensors_3d.yaml when it
lists a sensor, and the planning pipelines (``config/<name>_planning.yaml`` and, unless
``load_all=False``, moveit_configs_utils' ``default_configs``, or when it is not in the
workspace the names its release for the configuration's ROS_DISTRO has there; ``ompl``
the default when it is one, its ``planner_configs`` from ``ompl_defaults.yaml`` when it
has none).
``to_moveit_configs()`` loads each section not loaded yet (the Pilz limits only with the
Pilz pipeline) into a ``MoveItConfigs``, whose attributes are those dicts and whose
``to_dict()`` merges them. What cannot be read (a package or file not in the workspace,
a path not known statically) is said where the launch file asks for it and stays
unknown: a parameter ``<section>.?`` (or ``?``) rather than none.

launch_param_builder's ``ParameterBuilder(package)`` (``yaml``, ``parameter``,
``file_parameter``, ``xacro_parameter``, ``to_dict``), ``load_yaml`` and ``load_xacro``
read the same way; ``load_yaml`` renders a file as a Jinja2 template before reading it as
YAML, so a file with Jinja2 marks is not known (said).

``moveit_configs_utils.launches.generate_*_launch(moveit_config)`` make the launch
descriptions launches.py makes (the nodes, arguments, conditions and parameters it
gives), with the interpreter's own rows; ``DeclareBooleanLaunchArg`` and
``add_debuggable_node`` are launch_utils'.
"""

from __future__ import annotations

import ast
import os
import posixpath
from dataclasses import dataclass, field
from pathlib import PurePosixPath
from typing import TYPE_CHECKING, Any

import yaml

from ... import diagnostics as diag
from ... import safe_yaml
from ...model.values import Unknown
from ...share import share_source
from . import entities as e
from .python_methods import (
    XACRO_NOT_RUN,
    Args,
    Builder,
    Kwargs,
    Method,
    arg,
    xacro_command,
)
from .python_values import LaunchDescription, Lazy, Record, derived, to_text

if TYPE_CHECKING:
    from .python import Interpreter

CONFIG = "config"
# the sections of a MoveItConfigs, in the order its to_dict() merges them
_MERGED = ("robot_description", "robot_description_semantic",
           "robot_description_kinematics", "planning_pipelines", "trajectory_execution",
           "planning_scene_monitor", "sensors_3d", "joint_limits", "moveit_cpp")
_SECTIONS = (*_MERGED, "pilz_cartesian_limits")
_PSM_FLAGS = ("publish_planning_scene", "publish_geometry_updates", "publish_state_updates",
              "publish_transforms_updates", "publish_robot_description",
              "publish_robot_description_semantic")
_PSM_DEFAULTS = (True, True, True, True, False, False)


_JINJA = ("{{", "{%", "{#")


def unknown_tree(reason: Unknown) -> dict[Any, Any]:
    """Parameters whose names and values are not known: one entry whose key is unknown
    (the node gets the parameter ``...?``, which any name there may be)."""
    return {reason: reason}


@dataclass(eq=False)
class ParamsBuilder:
    """launch_param_builder's ``ParameterBuilder(package_name)``: the package's share
    folder (None when not known here, ``package`` saying why) and the parameters its
    ``yaml`` / ``parameter`` / ``file_parameter`` / ``xacro_parameter`` gave:
    ``_parameters``, a class attribute, so one dict that every builder of the process
    fills and ``to_dict()`` returns (``shared``; here, of the launch file being read)."""

    share: str | None
    package: Unknown | None
    extra: dict[Any, Any] = field(default_factory=dict)


@dataclass(eq=False)
class ConfigsBuilder(ParamsBuilder):
    """A ``MoveItConfigsBuilder``: where its files are and the sections loaded so far."""

    robot: str = ""
    prefix: str = "robot_description"
    urdf: Any = None  # the URDF's path (text or str), its xacro arguments
    xacro_args: dict[str, str] | None = None
    srdf: str = ""
    sections: dict[str, Any] = field(default_factory=dict)
    srdf_file: str | None = None  # the SRDF loaded, when read with no xacro arguments


def shared(i: Interpreter) -> dict[Any, Any]:
    """``ParameterBuilder._parameters``: the class's one dict."""
    found: dict[Any, Any] = i.library_state.setdefault("ParameterBuilder._parameters", {})
    return found


def _exists(i: Interpreter, path: str) -> bool:
    return os.path.exists(share_source(i.workspace, path))


def _load_yaml(i: Interpreter, path: Any, n: ast.AST) -> Any:
    """launch_param_builder's ``load_yaml(path)``: the file's content; unknown (said here)
    when it cannot be read."""
    if isinstance(path, PurePosixPath):
        path = str(path)
    if not isinstance(path, str):
        return unknown_tree(i.unsupported(n, "a MoveIt configuration file whose path is not "
                                             "known statically; its parameters are not known"))
    text = i.read(path, n)
    if text is None:  # said by read()
        return unknown_tree(Unknown(f"{path} not read", "unsupported", where=i.where(n)))
    if any(mark in text for mark in _JINJA):
        # load_yaml renders the file as a Jinja2 template first: never run here
        file = i.workspace.relpath(share_source(i.workspace, path))
        return unknown_tree(i.unsupported(n, f"{file} is a Jinja2 template, which "
                                             "launch_param_builder renders before reading "
                                             "it (never run here); its parameters are not "
                                             "known"))
    try:
        return safe_yaml.load(text)
    except yaml.YAMLError as err:
        file = i.workspace.relpath(share_source(i.workspace, path))
        return unknown_tree(i.unsupported(n, f"{file} cannot be read as YAML: {err}"))


def _join(base: str, given: Any) -> Any:
    """``Path(base) / given``: a path given absolute replaces the base."""
    if isinstance(given, PurePosixPath):
        given = str(given)
    if isinstance(given, str):
        return posixpath.join(base, given)
    return None


def _matches(i: Interpreter, folder: str | None, suffix: str) -> list[str] | None:
    """The names ``X`` of the files ``X<suffix>`` in a package folder (sorted: the order of
    ``Path.iterdir`` is the file system's); None when the folder is not known."""
    if folder is None:
        return None
    real = share_source(i.workspace, folder)
    if not os.path.isdir(real):
        return []
    return sorted(name[: -len(suffix)] for name in os.listdir(real)
                  if name.endswith(suffix) and len(name) > len(suffix)
                  and os.path.isfile(os.path.join(real, name)))


def _package(i: Interpreter, name: Any, n: ast.AST) -> Any:
    return i.api["get_package_share_directory"](i, [name], {}, n)


# -- MoveItConfigsBuilder ----------------------------------------------------------------
def configs_builder(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    robot = arg(a, k, 0, "robot_name")
    prefix = arg(a, k, 1, "robot_description", default="robot_description")
    package = arg(a, k, 2, "package_name")
    if not isinstance(robot, str) or not isinstance(prefix, str) or not (
            package is None or isinstance(package, str)):
        return i.unsupported(n, "MoveItConfigsBuilder of a robot, package or description "
                                "name not known statically")
    package = package or f"{robot}_moveit_config"
    share = _package(i, package, n)
    if not isinstance(share, str):
        missing = i.unsupported(n, f"MoveIt configuration package {package} is not in the "
                                   "workspace; the parameters it gives are not known")
        return ConfigsBuilder(None, missing, shared(i), robot=robot, prefix=prefix)
    urdf: Any = None
    xacro_args: dict[str, str] | None = None
    srdf: str | None = None
    modified = posixpath.join(CONFIG, f"{robot}.urdf.xacro")
    if _exists(i, posixpath.join(share, modified)):
        urdf = posixpath.join(share, modified)
    assistant = posixpath.join(share, ".setup_assistant")
    if _exists(i, assistant):
        loaded = _load_yaml(i, assistant, n)
        config = loaded.get("moveit_setup_assistant_config", {}) if isinstance(
            loaded, dict) else {}
        config = config if isinstance(config, dict) else {}
        described = config.get("urdf", config.get("URDF"))
        if isinstance(described, dict):
            if urdf is None:
                where = _package(i, described.get("package"), n)
                relative = described.get("relative_path")
                urdf = _join(where, relative) if isinstance(where, str) else to_text(
                    [where, "/", relative if isinstance(relative, str) else "?"])
            given = described.get("xacro_args")
            if isinstance(given, str) and given:
                xacro_args = dict(word.split(":=", 1) for word in given.split(" ")
                                  if ":=" in word)
        semantic = config.get("srdf", config.get("SRDF"))
        if isinstance(semantic, dict) and isinstance(semantic.get("relative_path"), str):
            srdf = semantic["relative_path"]
    if urdf is None:
        urdf = posixpath.join(share, CONFIG, f"{robot}.urdf")
    return ConfigsBuilder(share, None, shared(i), robot=robot, prefix=prefix, urdf=urdf,
                          xacro_args=xacro_args,
                          srdf=srdf or posixpath.join(CONFIG, f"{robot}.srdf"))


def _unreadable(b: ConfigsBuilder, n: ast.AST) -> Unknown:
    assert b.package is not None
    return b.package


def _xacro(i: Interpreter, path: Any, mappings: Any, n: ast.AST) -> Any:
    """``load_xacro(path, mappings)`` (or ``Xacro(path, mappings)`` for mappings with
    substitutions): the document a ``xacro`` command makes, kept as text; unknown when
    the file is not in the workspace."""
    if isinstance(path, str) and not _exists(i, path):
        return i.unsupported(n, f"{i.workspace.relpath(share_source(i.workspace, path))} does "
                                "not exist in the workspace; the description made from it "
                                "is not known")
    command = e.Command(xacro_command(path, mappings), XACRO_NOT_RUN)
    return e.ParamValue(Lazy((command,)).text, as_text=True)


def m_robot_description(i: Interpreter, b: ConfigsBuilder, a: Args, k: Kwargs,
                        n: ast.AST) -> Any:
    if b.share is None:
        b.sections["robot_description"] = {b.prefix: _unreadable(b, n)}
        return b
    given = arg(a, k, 0, "file_path")
    mappings = arg(a, k, 1, "mappings")
    path = b.urdf if given is None else _join(b.share, given)
    if isinstance(path, str) and not _exists(i, path) and (mappings is None or (
            isinstance(mappings, dict) and all(
                isinstance(key, str) and isinstance(value, str)
                for key, value in mappings.items()))):
        # load_xacro raises ParameterBuilderFileNotFoundError, which robot_description()
        # catches: a warning, and no description in the configs (MoveIt reads the topic)
        found = diag.make("LAUNCH_MOVEIT_DESCRIPTION_TOPIC", i.where(n), detail=(
            f"{i.workspace.relpath(share_source(i.workspace, path))} does not exist: "
            "moveit_configs_utils warns and leaves the robot description out of the "
            "configs (MoveIt reads /robot_description)"))
        if found not in i.diagnostics:
            i.diagnostics.append(found)
        b.sections["robot_description"] = {}
        return b
    if path is None:
        value: Any = i.unsupported(n, "robot description file path not known statically")
    else:
        value = _xacro(i, path, mappings if mappings is not None else b.xacro_args, n)
    b.sections["robot_description"] = {b.prefix: value}
    return b


def m_semantic(i: Interpreter, b: ConfigsBuilder, a: Args, k: Kwargs, n: ast.AST) -> Any:
    key = b.prefix + "_semantic"
    if b.share is None:
        b.sections["robot_description_semantic"] = {key: _unreadable(b, n)}
        return b
    path = _join(b.share, arg(a, k, 0, "file_path") or b.srdf)
    mappings = arg(a, k, 1, "mappings")
    value = _xacro(i, path, mappings, n) if path is not None else \
        i.unsupported(n, "semantic description file path not known statically")
    b.srdf_file = path if isinstance(path, str) and not mappings else None
    b.sections["robot_description_semantic"] = {key: value}
    return b


def _yaml_section(section: str, default: str, key_suffix: str | None) -> Method:
    """A method loading one YAML file of the config package (``file_path`` or the default
    under ``config/``), under ``<description><key_suffix>`` or at the top."""
    def call(i: Interpreter, b: ConfigsBuilder, a: Args, k: Kwargs, n: ast.AST) -> Any:
        if b.share is None:
            content: Any = unknown_tree(_unreadable(b, n))
        else:
            path = _join(b.share, arg(a, k, 0, "file_path") or posixpath.join(CONFIG, default))
            content = _load_yaml(i, path, n)
        b.sections[section] = content if key_suffix is None else {
            b.prefix + key_suffix: content}
        return b
    return call


def m_trajectory_execution(i: Interpreter, b: ConfigsBuilder, a: Args, k: Kwargs,
                           n: ast.AST) -> Any:
    section: dict[Any, Any] = {
        "moveit_manage_controllers": arg(a, k, 1, "moveit_manage_controllers", default=True)}
    b.sections["trajectory_execution"] = section
    if b.share is None:
        section.update(unknown_tree(_unreadable(b, n)))
        return b
    given = arg(a, k, 0, "file_path")
    path: Any
    if given is None:
        folder = posixpath.join(b.share, CONFIG)
        names = _matches(i, folder, "_controllers.yaml") or []
        if not names:  # moveit_configs_utils warns and loads none
            return b
        chosen = names[0] if len(names) == 1 else next(
            (name for name in ("moveit", "moveit2", b.robot) if name in names), None)
        if chosen is None:
            section.update(unknown_tree(i.failed(
                n, "trajectory_execution: no file given and several config/*_controllers.yaml"
                   f" ({', '.join(names)}): moveit_configs_utils cannot choose one",
                "RuntimeError")))
            return b
        path = posixpath.join(folder, f"{chosen}_controllers.yaml")
    else:
        path = _join(b.share, given)
    loaded = _load_yaml(i, path, n)
    if isinstance(loaded, dict):
        section.update(loaded)
    return b


def m_planning_scene_monitor(i: Interpreter, b: ConfigsBuilder, a: Args, k: Kwargs,
                             n: ast.AST) -> Any:
    b.sections["planning_scene_monitor"] = {
        flag: arg(a, k, index, flag, default=default)
        for index, (flag, default) in enumerate(zip(_PSM_FLAGS, _PSM_DEFAULTS, strict=True))}
    return b


def m_sensors_3d(i: Interpreter, b: ConfigsBuilder, a: Args, k: Kwargs, n: ast.AST) -> Any:
    if b.share is None:
        b.sections["sensors_3d"] = unknown_tree(_unreadable(b, n))
        return b
    path = _join(b.share, arg(a, k, 0, "file_path") or posixpath.join(CONFIG, "sensors_3d.yaml"))
    if not isinstance(path, str) or not _exists(i, path):  # none: no sensors
        if not isinstance(path, str):
            b.sections["sensors_3d"] = unknown_tree(i.unsupported(
                n, "sensors_3d file path not known statically"))
        return b
    data = _load_yaml(i, path, n)
    sensors = data.get("sensors") if isinstance(data, dict) else None
    unread = not isinstance(data, dict) or any(isinstance(key, Unknown) for key in data)
    if unread or (isinstance(sensors, list) and sensors and sensors[0]):
        b.sections["sensors_3d"] = data
    return b


def _defaults_folder(i: Interpreter, n: ast.AST) -> str | None:
    """moveit_configs_utils' own ``default_configs`` (its code finds its share folder: not
    a use of the package by the launch file's, which imports it)."""
    found = i.workspace.find("moveit_configs_utils")
    return posixpath.join(found, "default_configs") if found is not None else None


# moveit_configs_utils' default_configs/*_planning.yaml by distribution (moveit2 humble
# 2b2030dd; iron, jazzy 4d841063, kilted and main 8fcb5d23 add stomp): the names it adds
# when it is not in the workspace, their files not known
_DEFAULT_PIPELINES = {"humble": ("chomp", "ompl", "pilz_industrial_motion_planner")}
_STOMP_ON = ("iron", "jazzy", "kilted", "rolling")


def _shipped_by_distro(i: Interpreter) -> list[str] | None:
    distro = i.environment.get("ROS_DISTRO", "").strip().lower()
    if distro in _STOMP_ON:
        return [*_DEFAULT_PIPELINES["humble"], "stomp"]
    found = _DEFAULT_PIPELINES.get(distro)
    return list(found) if found is not None else None


def m_planning_pipelines(i: Interpreter, b: ConfigsBuilder, a: Args, k: Kwargs,
                         n: ast.AST) -> Any:
    default = arg(a, k, 0, "default_planning_pipeline")
    pipelines = arg(a, k, 1, "pipelines")
    load_all = arg(a, k, 2, "load_all", default=True)
    if b.share is None:
        b.sections["planning_pipelines"] = unknown_tree(_unreadable(b, n))
        return b
    folder = posixpath.join(b.share, CONFIG)
    defaults = _defaults_folder(i, n)
    others: Unknown | None = None  # pipelines that may be there, not known which
    if pipelines is None:
        names = list(_matches(i, folder, "_planning.yaml") or [])
        if load_all is not False:
            shipped = _matches(i, defaults, "_planning.yaml")
            if shipped is None and isinstance(load_all, bool):
                shipped = _shipped_by_distro(i)
            if shipped is None or not isinstance(load_all, bool):
                # said here once; the values made of it say no more
                i.unknown_value(n, "moveit_configs_utils is not in the workspace: the "
                                   "default planning pipelines it adds are not known")
                others = Unknown("moveit_configs_utils' default planning pipelines",
                                 "unsupported", where=i.where(n))
            names += [name for name in shipped or [] if name not in names]
    elif isinstance(pipelines, (list, tuple)) and all(isinstance(p, str) for p in pipelines):
        names = list(pipelines)
    else:
        b.sections["planning_pipelines"] = unknown_tree(i.unsupported(
            n, "planning pipelines not known statically"))
        return b
    if not default and "ompl" in names:
        default = "ompl"
    elif not default and names and others is None and (pipelines is not None
                                                         or len(names) == 1):
        default = names[0]
    elif not default:
        # the first of the files found: their order is the file system's
        i.unknown_value(n, "the default planning pipeline is the first *_planning.yaml the "
                           "file system lists, not known here")
        default = Unknown("the default planning pipeline", "unsupported", where=i.where(n))
    if isinstance(default, str) and default not in names and others is None:
        b.sections["planning_pipelines"] = unknown_tree(i.failed(
            n, f"default_planning_pipeline {default} is none of the pipelines "
               f"({', '.join(names)})", "RuntimeError"))
        return b
    section: dict[Any, Any] = {
        "planning_pipelines": names if others is None else others,
        "default_planning_pipeline": default}
    unread: list[str] = []
    for name in names:
        path = posixpath.join(folder, f"{name}_planning.yaml")
        if not _exists(i, path) and defaults is None:
            unread.append(name)  # moveit_configs_utils' own file, if it has one
            continue
        if not _exists(i, path) and defaults is not None:
            path = posixpath.join(defaults, f"{name}_planning.yaml")
        section[name] = _load_yaml(i, path, n)
    if unread:
        files = ", ".join(f"{name}_planning.yaml" for name in unread)
        i.unknown_value(n, f"moveit_configs_utils is not in the workspace: the pipelines' "
                           f"files it would give ({files}) are not known")
        made = Unknown("moveit_configs_utils' default pipeline", "unsupported",
                       where=i.where(n))
        section.update((name, unknown_tree(made)) for name in unread)
    if others is not None:
        section.update(unknown_tree(others))
    ompl = section.get("ompl")
    if isinstance(ompl, dict) and "planner_configs" not in ompl and not any(
            isinstance(key, Unknown) for key in ompl):
        if defaults is None:
            i.unknown_value(n, "moveit_configs_utils is not in the workspace: the "
                               "OMPL planner configurations it adds are not known")
            ompl["planner_configs"] = unknown_tree(Unknown(
                "moveit_configs_utils' ompl_defaults.yaml", "unsupported", where=i.where(n)))
        else:
            extra = _load_yaml(i, posixpath.join(defaults, "ompl_defaults.yaml"), n)
            if isinstance(extra, dict):
                ompl.update(extra)
    b.sections["planning_pipelines"] = section
    return b


def m_to_moveit_configs(i: Interpreter, b: ConfigsBuilder, a: Args, k: Kwargs,
                        n: ast.AST) -> Any:
    for section in _MERGED[:-1]:  # moveit_cpp only when asked for
        if not b.sections.get(section):
            METHODS[section](i, b, [], {}, n)
    if "pilz_industrial_motion_planner" in b.sections.get("planning_pipelines", {}) \
            and not b.sections.get("pilz_cartesian_limits"):
        METHODS["pilz_cartesian_limits"](i, b, [], {}, n)
    attributes: dict[str, Any] = {
        "package_path": PurePosixPath(b.share) if b.share is not None else Unknown(
            "the MoveIt configuration package's path", "unsupported"),
        "move_group_capabilities": {"capabilities": "", "disable_capabilities": ""}}
    attributes.update((section, b.sections.get(section, {})) for section in _SECTIONS)
    return Record("MoveItConfigs", attributes, {"srdf_file": b.srdf_file})


def configs_dict(configs: Record) -> dict[Any, Any]:
    """``MoveItConfigs.to_dict()``: its sections merged, the Pilz limits into
    ``robot_description_planning``."""
    parameters: dict[Any, Any] = {}
    for section in _MERGED:
        value = configs.attributes.get(section)
        if isinstance(value, dict):
            parameters.update(value)
    limits = configs.attributes.get("pilz_cartesian_limits")
    if isinstance(limits, dict) and limits:
        for key, value in limits.items():
            below = parameters.get(key)
            if isinstance(below, dict) and isinstance(value, dict):
                below.update(value)
    return parameters


def _other(i: Interpreter, owner: Any, name: str, n: ast.AST) -> Unknown:
    """A method of these names on another value: not interpreted, as any method not
    listed (said once: not again for a value already said unknown where it was made)."""
    if isinstance(owner, Unknown) and owner.kind == "unsupported":
        return derived(owner, f"method .{name}() of a value not known statically")
    return i.unsupported(n, f"method .{name}() is not interpreted")


def m_to_dict(i: Interpreter, owner: Any, a: Args, k: Kwargs, n: ast.AST) -> Any:
    if isinstance(owner, Record) and owner.cls == "MoveItConfigs":
        return configs_dict(owner)
    if isinstance(owner, ConfigsBuilder):
        # the class's dict itself, updated with the configs (every builder's from then on)
        if arg(a, k, 0, "include_moveit_configs", default=True) is not False:
            owner.extra.update(configs_dict(m_to_moveit_configs(i, owner, [], {}, n)))
        return owner.extra
    if isinstance(owner, ParamsBuilder):
        return owner.extra
    return _other(i, owner, "to_dict", n)


def params_builder(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``ParameterBuilder(package_name)``."""
    package = arg(a, k, 0, "package_name")
    if not isinstance(package, str):
        return i.unsupported(n, "ParameterBuilder of a package not known statically")
    share = _package(i, package, n)
    if not isinstance(share, str):
        return ParamsBuilder(None, i.unsupported(
            n, f"package {package} is not in the workspace; the parameters read from its "
               "files are not known"), shared(i))
    return ParamsBuilder(share, None, shared(i))


def m_parameter(i: Interpreter, b: ParamsBuilder, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``parameter(name, value)``."""
    b.extra[arg(a, k, 0, "parameter_name")] = arg(a, k, 1, "parameter_value")
    return b


def _file_of(i: Interpreter, b: ParamsBuilder, given: Any, n: ast.AST) -> Any:
    """``package path / file_path``, or why it is not known."""
    if b.package is not None:
        return b.package
    assert b.share is not None
    path = _join(b.share, given)
    return path if path is not None else i.unsupported(
        n, "a parameter file path not known statically")


def m_yaml(i: Interpreter, b: ParamsBuilder, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``yaml(file_path, parameter_namespace=None)``: the file's content, under that name
    (merged into what it holds) or at the top."""
    path = _file_of(i, b, arg(a, k, 0, "file_path"), n)
    content = _load_yaml(i, path, n) if isinstance(path, str) else unknown_tree(path)
    under = arg(a, k, 1, "parameter_namespace")
    target = b.extra.setdefault(under, {}) if under else b.extra
    if isinstance(target, dict) and isinstance(content, dict):
        target.update(content)
    else:
        b.extra[under] = content
    return b


def m_file_parameter(i: Interpreter, b: ParamsBuilder, a: Args, k: Kwargs,
                     n: ast.AST) -> Any:
    """``file_parameter(name, file_path)``: the file's text."""
    path = _file_of(i, b, arg(a, k, 1, "file_path"), n)
    text = i.read(path, n) if isinstance(path, str) else None
    b.extra[arg(a, k, 0, "parameter_name")] = text if text is not None else Unknown(
        "a parameter file's text", "unsupported", where=i.where(n))
    return b


def m_xacro_parameter(i: Interpreter, b: ParamsBuilder, a: Args, k: Kwargs,
                      n: ast.AST) -> Any:
    """``xacro_parameter(name, file_path, mappings=None)``: the document it makes."""
    path = _file_of(i, b, arg(a, k, 1, "file_path"), n)
    b.extra[arg(a, k, 0, "parameter_name")] = _xacro(
        i, path, arg(a, k, 2, "mappings"), n) if isinstance(path, str) else path
    return b


def _of_builder(name: str, method: Any, cls: type = ConfigsBuilder) -> Method:
    def call(i: Interpreter, owner: Any, a: Args, k: Kwargs, n: ast.AST) -> Any:
        if not isinstance(owner, cls):
            return _other(i, owner, name, n)
        return method(i, owner, a, k, n)
    return call


METHODS: dict[str, Method] = {
    **{name: _of_builder(name, method) for name, method in (
        ("robot_description", m_robot_description),
        ("robot_description_semantic", m_semantic),
        ("robot_description_kinematics", _yaml_section(
            "robot_description_kinematics", "kinematics.yaml", "_kinematics")),
        ("joint_limits", _yaml_section("joint_limits", "joint_limits.yaml", "_planning")),
        ("moveit_cpp", _yaml_section("moveit_cpp", "moveit_cpp.yaml", None)),
        ("pilz_cartesian_limits", _yaml_section(
            "pilz_cartesian_limits", "pilz_cartesian_limits.yaml", "_planning")),
        ("trajectory_execution", m_trajectory_execution),
        ("planning_scene_monitor", m_planning_scene_monitor),
        ("sensors_3d", m_sensors_3d),
        ("planning_pipelines", m_planning_pipelines),
        ("to_moveit_configs", m_to_moveit_configs))},
    **{name: _of_builder(name, method, ParamsBuilder) for name, method in (
        ("parameter", m_parameter), ("yaml", m_yaml), ("file_parameter", m_file_parameter),
        ("xacro_parameter", m_xacro_parameter))},
    "to_dict": m_to_dict,
}


# -- launch_utils and launches ------------------------------------------------------------
def _config(i: Interpreter, name: str, n: ast.AST) -> Any:
    return i.api["LaunchConfiguration"](i, [name], {}, n)


def _declare(i: Interpreter, name: str, default: Any, n: ast.AST) -> Any:
    return i.api["DeclareLaunchArgument"](i, [name], {"default_value": default}, n)


def declare_boolean(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``DeclareBooleanLaunchArg(name, default_value=False, ...)``: the argument with
    ``str(default_value)`` as its default."""
    default = k.get("default_value", False)
    text = str(default) if isinstance(default, (bool, int, float, str)) else default
    return i.api["DeclareLaunchArgument"](
        i, [arg(a, k, 0, "name")], {**{key: v for key, v in k.items()
                                       if key not in ("name", "default_value")},
                                    "default_value": text}, n)


def add_debuggable_node(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``add_debuggable_node(ld, package, executable, condition_name='debug',
    commands_file=None, extra_debug_args=None, **kwargs)``: the node unless that argument
    is true, and the same node run in gdb if it is."""
    ld = arg(a, k, 0, "ld")
    if not isinstance(ld, LaunchDescription):
        return i.unsupported(n, "add_debuggable_node of a launch description not known "
                                "statically")
    package, executable = arg(a, k, 1, "package"), arg(a, k, 2, "executable")
    flag = arg(a, k, 3, "condition_name", default="debug")
    extra = arg(a, k, 5, "extra_debug_args")
    rest = {key: v for key, v in k.items() if key not in (
        "ld", "package", "executable", "condition_name", "commands_file",
        "extra_debug_args")}
    node = i.api["Node"]
    ld.actions.append(node(i, [], {**rest, "package": package, "executable": executable,
                                   "condition": i.api["UnlessCondition"](
                                       i, [_config(i, flag, n)], {}, n)}, n))
    arguments = rest.pop("arguments", None)
    if arguments is not None and isinstance(arguments, list) and isinstance(extra, list):
        arguments = [*arguments, *extra]
    ld.actions.append(node(i, [], {**rest, "package": package, "executable": executable,
                                   "arguments": arguments,
                                   "condition": i.api["IfCondition"](
                                       i, [_config(i, flag, n)], {}, n)}, n))
    return None


def _configs(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Record | None:
    given = arg(a, k, 0, "moveit_config")
    return given if isinstance(given, Record) and given.cls == "MoveItConfigs" else None


def _in_package(configs: Record, relative: str) -> Any:
    path = configs.attributes.get("package_path")
    return str(path / relative) if isinstance(path, PurePosixPath) else to_text(
        [Unknown("the MoveIt configuration package's path", "unsupported"), "/", relative])


def _launch(name: str, body: Any) -> Builder:
    def build(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
        configs = _configs(i, a, k, n)
        if configs is None:
            return i.unsupported(n, f"{name} of a MoveIt configuration not known statically")
        ld = i.api["LaunchDescription"](i, [], {}, n)
        body(i, configs, ld, a, k, n)
        return ld
    return build


def _rsp(i: Interpreter, c: Record, ld: LaunchDescription, a: Args, k: Kwargs,
         n: ast.AST) -> None:
    ld.actions.append(_declare(i, "publish_frequency", "15.0", n))
    ld.actions.append(i.api["Node"](i, [], {
        "package": "robot_state_publisher", "executable": "robot_state_publisher",
        "parameters": [c.attributes["robot_description"],
                       {"publish_frequency": _config(i, "publish_frequency", n)}]}, n))


def _rviz(i: Interpreter, c: Record, ld: LaunchDescription, a: Args, k: Kwargs,
          n: ast.AST) -> None:
    ld.actions.append(declare_boolean(i, ["debug"], {"default_value": False}, n))
    ld.actions.append(_declare(i, "rviz_config", _in_package(c, "config/moveit.rviz"), n))
    add_debuggable_node(i, [ld], {
        "package": "rviz2", "executable": "rviz2",
        "arguments": ["-d", _config(i, "rviz_config", n)],
        "parameters": [c.attributes[s] for s in (
            "planning_pipelines", "robot_description_kinematics", "joint_limits")]}, n)


def _setup_assistant(i: Interpreter, c: Record, ld: LaunchDescription, a: Args, k: Kwargs,
                     n: ast.AST) -> None:
    ld.actions.append(declare_boolean(i, ["debug"], {"default_value": False}, n))
    path = c.attributes.get("package_path")
    add_debuggable_node(i, [ld], {
        "package": "moveit_setup_assistant", "executable": "moveit_setup_assistant",
        "arguments": [["--config_pkg=", str(path) if isinstance(path, PurePosixPath)
                       else Unknown("the MoveIt configuration package's path")]]}, n)


def _virtual_joints(i: Interpreter, c: Record, ld: LaunchDescription, a: Args, k: Kwargs,
                    n: ast.AST) -> None:
    """A ``static_transform_publisher`` per virtual joint of the SRDF, read from its file
    when that is plain XML (a xacro one, or one not read: unknown, said)."""
    from lxml import etree

    from ...manifest import xml_parser

    path = c.facts.get("srdf_file")
    text = i.read(path, n) if isinstance(path, str) else None
    root = None
    if text is not None and "xacro" not in text:
        try:
            root = etree.fromstring(text.encode(), xml_parser())
        except (etree.XMLSyntaxError, ValueError):
            root = None
    if root is None:
        ld.actions.append(i.unsupported(n, "the SRDF's virtual joints are not known "
                                           "statically (a static_transform_publisher each)"))
        return
    for count, joint in enumerate(root.iter("virtual_joint")):
        parent, child = joint.get("parent_frame"), joint.get("child_link")
        ld.actions.append(i.api["Node"](i, [], {
            "package": "tf2_ros", "executable": "static_transform_publisher",
            "name": f"static_transform_publisher{count}",
            "arguments": ["--frame-id", parent or "", "--child-frame-id", child or ""]}, n))


def _spawners(i: Interpreter, c: Record, ld: LaunchDescription, a: Args, k: Kwargs,
              n: ast.AST) -> None:
    execution = c.attributes.get("trajectory_execution")
    manager = execution.get("moveit_simple_controller_manager", {}) if isinstance(
        execution, dict) else None
    names = manager.get("controller_names", []) if isinstance(manager, dict) else None
    if not isinstance(names, list) or (isinstance(execution, dict) and any(
            isinstance(key, Unknown) for key in execution)):
        i.unsupported(n, "the controllers of the MoveIt configuration are not known "
                         "statically (a spawner each)")
        names = [Unknown("a controller of the MoveIt configuration")]
    for name in [*names, "joint_state_broadcaster"]:
        ld.actions.append(i.api["Node"](i, [], {
            "package": "controller_manager", "executable": "spawner", "arguments": [name]},
            n))


def _warehouse(i: Interpreter, c: Record, ld: LaunchDescription, a: Args, k: Kwargs,
               n: ast.AST) -> None:
    ld.actions.append(_declare(i, "moveit_warehouse_database_path",
                               _in_package(c, "default_warehouse_mongo_db"), n))
    ld.actions.append(declare_boolean(i, ["reset"], {"default_value": False}, n))
    ld.actions.append(_declare(i, "moveit_warehouse_port", "33829", n))
    ld.actions.append(_declare(i, "moveit_warehouse_host", "localhost", n))
    ld.actions.append(i.api["Node"](i, [], {
        "package": "warehouse_ros_mongo", "executable": "mongo_wrapper_ros.py",
        "parameters": [{
            "overwrite": False,
            "database_path": _config(i, "moveit_warehouse_database_path", n),
            "warehouse_port": _config(i, "moveit_warehouse_port", n),
            "warehouse_host": _config(i, "moveit_warehouse_host", n),
            "warehouse_exec": "mongod",
            "warehouse_plugin": "warehouse_ros_mongo::MongoDatabaseConnection"}]}, n))
    ld.actions.append(i.api["Node"](i, [], {
        "package": "moveit_ros_warehouse", "executable": "moveit_init_demo_warehouse",
        "condition": i.api["IfCondition"](i, [_config(i, "reset", n)], {}, n)}, n))


def _move_group(i: Interpreter, c: Record, ld: LaunchDescription, a: Args, k: Kwargs,
                n: ast.AST) -> None:
    capabilities = c.attributes.get("move_group_capabilities") or {}
    for name, default in (("debug", False), ("allow_trajectory_execution", True),
                          ("publish_monitored_planning_scene", True)):
        ld.actions.append(declare_boolean(i, [name], {"default_value": default}, n))
    for name in ("capabilities", "disable_capabilities"):
        ld.actions.append(_declare(i, name, capabilities.get(name, ""), n))
    ld.actions.append(declare_boolean(i, ["monitor_dynamics"], {"default_value": False}, n))
    publish = _config(i, "publish_monitored_planning_scene", n)
    settings = {
        "publish_robot_description_semantic": True,
        "allow_trajectory_execution": _config(i, "allow_trajectory_execution", n),
        "capabilities": e.ParamValue(to_text(_config(i, "capabilities", n)), True),
        "disable_capabilities": e.ParamValue(to_text(_config(i, "disable_capabilities", n)),
                                             True),
        "publish_planning_scene": publish, "publish_geometry_updates": publish,
        "publish_state_updates": publish, "publish_transforms_updates": publish,
        "monitor_dynamics": False}
    add_debuggable_node(i, [ld], {
        "package": "moveit_ros_move_group", "executable": "move_group",
        "parameters": [configs_dict(c), settings], "extra_debug_args": ["--debug"]}, n)


def _demo(i: Interpreter, c: Record, ld: LaunchDescription, a: Args, k: Kwargs,
          n: ast.AST) -> None:
    base = arg(a, k, 1, "launch_package_path")
    if base is None:
        base = c.attributes.get("package_path")
    if isinstance(base, str):
        base = PurePosixPath(base)
    for name, default in (("db", False), ("debug", False), ("use_rviz", True)):
        ld.actions.append(declare_boolean(i, [name], {"default_value": default}, n))

    def include(relative: str, flag: str | None = None) -> None:
        path = str(base / relative) if isinstance(base, PurePosixPath) else to_text(
            [Unknown("the launch package's path", "unsupported"), "/", relative])
        source = i.api["PythonLaunchDescriptionSource"](i, [path], {}, n)
        extra = {"condition": i.api["IfCondition"](i, [_config(i, flag, n)], {}, n)} if (
            flag) else {}
        ld.actions.append(i.api["IncludeLaunchDescription"](i, [source], extra, n))

    virtual = "launch/static_virtual_joint_tfs.launch.py"
    if not isinstance(base, PurePosixPath):
        i.unsupported(n, "the MoveIt demo's launch package is not known statically")
    elif _exists(i, str(base / virtual)):
        include(virtual)
    include("launch/rsp.launch.py")
    include("launch/move_group.launch.py")
    include("launch/moveit_rviz.launch.py", "use_rviz")
    include("launch/warehouse_db.launch.py", "db")
    controllers = _in_package(c, "config/ros2_controllers.yaml")
    if _remaps_description(i, n):  # 2.9 on: the description from rsp's topic
        control = {"parameters": [controllers], "remappings": [
            ("/controller_manager/robot_description", "/robot_description")]}
    else:
        control = {"parameters": [c.attributes["robot_description"], controllers]}
    ld.actions.append(i.api["Node"](i, [], {
        "package": "controller_manager", "executable": "ros2_control_node", **control}, n))
    include("launch/spawn_controllers.launch.py")


# the distributions whose moveit_configs_utils is older than 2.9.0 (humble 2.5, iron 2.7)
_BEFORE_2_9 = ("foxy", "galactic", "humble", "iron")


def _remaps_description(i: Interpreter, n: ast.AST) -> bool:
    """Whether the demo's ros2_control_node reads the description from the topic (2.9.0
    on) rather than being given it: by moveit_configs_utils' version when the workspace
    has it, else by the configuration's ROS_DISTRO; not known, said, the newer way."""
    package = i.workspace.packages.get("moveit_configs_utils")
    numbers = [int(p) for p in package.version.split(".")[:2] if p.isdigit()] if (
        package is not None) else []
    if len(numbers) == 2:
        return tuple(numbers) >= (2, 9)
    distro = i.environment.get("ROS_DISTRO", "").strip().lower()
    if distro:
        return distro not in _BEFORE_2_9
    i.unknown_value(n, "moveit_configs_utils' version is not known (no ROS_DISTRO): the "
                       "demo's ros2_control_node is taken as 2.9.0 and later start it")
    return True


def load_yaml(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """launch_param_builder's ``load_yaml(file_path)``."""
    return _load_yaml(i, arg(a, k, 0, "file_path"), n)


def load_xacro(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """launch_param_builder's ``load_xacro(file_path, mappings=None)``."""
    path = arg(a, k, 0, "file_path")
    return _xacro(i, str(path) if isinstance(path, PurePosixPath) else path,
                  arg(a, k, 1, "mappings"), n)


MOVEIT_CONFIGS_UTILS: dict[str, Builder] = {
    "load_yaml": load_yaml, "load_xacro": load_xacro,
    "MoveItConfigsBuilder": configs_builder, "ParameterBuilder": params_builder,
    "DeclareBooleanLaunchArg": declare_boolean,
    "add_debuggable_node": add_debuggable_node,
    "generate_rsp_launch": _launch("generate_rsp_launch", _rsp),
    "generate_moveit_rviz_launch": _launch("generate_moveit_rviz_launch", _rviz),
    "generate_setup_assistant_launch": _launch("generate_setup_assistant_launch",
                                               _setup_assistant),
    "generate_static_virtual_joint_tfs_launch": _launch(
        "generate_static_virtual_joint_tfs_launch", _virtual_joints),
    "generate_spawn_controllers_launch": _launch("generate_spawn_controllers_launch",
                                                 _spawners),
    "generate_warehouse_db_launch": _launch("generate_warehouse_db_launch", _warehouse),
    "generate_move_group_launch": _launch("generate_move_group_launch", _move_group),
    "generate_demo_launch": _launch("generate_demo_launch", _demo),
}
