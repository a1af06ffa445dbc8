"""The project file: which workspace, packages, configurations, hints and queries.

A YAML file compatible with HAROS project files (``project``, ``packages``,
``configurations``, ``nodes``, ``rules``) plus our keys (``workspace``, per-configuration
``args`` and ``environment``, ``queries``, interface ``models`` and ``distro``). Every
problem is a ``ProjectError`` that names the file and line, and the CLI exits with code 2.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import yaml
from yaml.nodes import MappingNode, Node, ScalarNode, SequenceNode

from . import safe_yaml
from .files import read_text
from .model.diagnostic import SEVERITY_RANK
from .model.location import Location


class ProjectError(Exception):
    """The project file cannot be used; ``str()`` gives ``file:line:col: message``."""

    def __init__(self, path: str, line: int, column: int, message: str) -> None:
        self.path, self.line, self.column, self.message = path, line, column, message
        where = f"{path}:{line}:{column}" if line else path
        super().__init__(f"{where}: {message}")


@dataclass
class ConfigurationSpec:
    """A configuration as the project file gives it (before anything is analysed)."""

    name: str
    launch: list[str] = field(default_factory=list)
    args: dict[str, str] = field(default_factory=dict)
    environment: dict[str, str] = field(default_factory=dict)
    launch_lines: list[int] = field(default_factory=list)  # where each launch entry is
    hints: dict[str, Any] = field(default_factory=dict)
    user_data: dict[str, Any] = field(default_factory=dict)
    # run by rostest: its <test> nodes are started too; None: when a launch file is a .test
    rostest: bool | None = None
    line: int = 0


@dataclass
class Project:
    name: str
    path: str
    workspace: list[str] = field(default_factory=list)
    packages: list[str] = field(default_factory=list)
    configurations: list[ConfigurationSpec] = field(default_factory=list)
    nodes: dict[str, Any] = field(default_factory=dict)
    rules: dict[str, Any] = field(default_factory=dict)
    queries: list[Any] = field(default_factory=list)
    environment: dict[str, str] = field(default_factory=dict)
    # a compile_commands.json (or its folder) for the C++ flags; None: looked for
    compile_commands: str | None = None
    # interface models: the user's model files or folders (win over the shipped ones),
    # and the ROS distribution whose models to use (None: from the environment or the
    # launch files; see haros_arch.models)
    models: list[str] = field(default_factory=list)
    distro: str | None = None

    @property
    def folder(self) -> str:
        return os.path.dirname(os.path.abspath(self.path))


class _Reader:
    """Validates YAML nodes (which keep their line numbers) into plain values."""

    def __init__(self, path: str) -> None:
        self.path = path

    def fail(self, node: Node, message: str) -> ProjectError:
        mark = node.start_mark
        return ProjectError(self.path, mark.line + 1, mark.column + 1, message)

    def plain(self, node: Node) -> Any:
        loader = yaml.SafeLoader("")
        try:
            return loader.construct_object(node, deep=True)
        except RecursionError:
            raise self.fail(node, "value nested too deeply") from None
        except (yaml.YAMLError, ValueError) as err:  # ValueError: an int of 5,000 digits
            raise self.fail(node, f"invalid value: {getattr(err, 'problem', err)}") from None

    def mapping(self, node: Node, what: str) -> list[tuple[str, Node, Node]]:
        if not isinstance(node, MappingNode):
            raise self.fail(node, f"{what} must be a mapping")
        items: list[tuple[str, Node, Node]] = []
        for key, value in node.value:
            if not isinstance(key, ScalarNode):
                raise self.fail(key, f"keys of {what} must be strings")
            items.append((str(key.value), key, value))
        return items

    def string(self, node: Node, what: str) -> str:
        if not isinstance(node, ScalarNode) or node.tag.endswith(":null"):
            raise self.fail(node, f"{what} must be a string")
        return str(node.value)

    def boolean(self, node: Node, what: str) -> bool:
        value = self.plain(node) if isinstance(node, ScalarNode) else None
        if not isinstance(value, bool):
            raise self.fail(node, f"{what} must be true or false")
        return value

    def strings(self, node: Node, what: str) -> list[str]:
        return [text for text, _line in self.strings_at(node, what)]

    def strings_at(self, node: Node, what: str) -> list[tuple[str, int]]:
        """A string or a list of strings, each with its line."""
        if isinstance(node, ScalarNode) and not node.tag.endswith(":null"):
            return [(str(node.value), node.start_mark.line + 1)]
        if not isinstance(node, SequenceNode):
            raise self.fail(node, f"{what} must be a list of strings")
        return [(self.string(item, f"each item of {what}"), item.start_mark.line + 1)
                for item in node.value]

    def string_map(self, node: Node, what: str) -> dict[str, str]:
        result = {}
        for key, _key_node, value in self.mapping(node, what):
            if not isinstance(value, ScalarNode):
                raise self.fail(value, f"{what}.{key} must be a string, number or boolean")
            result[key] = _scalar_text(self.plain(value))
        return result

    def any_map(self, node: Node, what: str) -> dict[str, Any]:
        self.mapping(node, what)
        value = self.plain(node)
        return value if isinstance(value, dict) else {}


def _scalar_text(value: Any) -> str:
    """Launch arguments are strings; write YAML booleans the way roslaunch spells them."""
    if isinstance(value, bool):
        return "true" if value else "false"
    return "" if value is None else str(value)


TOP_KEYS = ("project", "packages", "configurations", "nodes", "rules", "queries",
            "workspace", "environment", "analysis", "repositories", "compile_commands",
            "models", "distro")
CONFIG_KEYS = ("launch", "hints", "user_data", "args", "environment", "description",
               "rostest")


def load(path: str) -> Project:
    """Read and validate a project file. Raises ``ProjectError`` with file:line."""
    text, problems = read_text(path, Location(file=path))
    if text is None:
        raise ProjectError(path, 0, 0, problems[0].message if problems else "cannot read")
    try:
        document = safe_yaml.compose(text)  # bounded: nesting, aliases, flow brackets
    except yaml.MarkedYAMLError as err:
        mark = err.problem_mark or err.context_mark
        line, col = (mark.line + 1, mark.column + 1) if mark else (0, 0)
        raise ProjectError(path, line, col, f"invalid YAML: {err.problem or err}") from None
    except safe_yaml.YAMLLimit as err:
        raise ProjectError(path, 0, 0, f"the YAML is nested too deeply or too large to be a "
                                       f"project file ({err})") from None
    except (yaml.YAMLError, ValueError) as err:  # ValueError: "%YAML 99999...9"
        raise ProjectError(path, 0, 0, f"invalid YAML: {err}") from None
    except RecursionError:
        raise ProjectError(path, 0, 0, "the YAML is nested too deeply to be a project "
                                       "file") from None
    reader = _Reader(path)
    if document is None:
        raise ProjectError(path, 1, 1, "the project file is empty")
    project = Project(name=os.path.splitext(os.path.basename(path))[0], path=path)
    handlers: dict[str, Callable[[Node], None]] = {
        "project": lambda n: setattr(project, "name", reader.string(n, "project")),
        "packages": lambda n: setattr(project, "packages", reader.strings(n, "packages")),
        "workspace": lambda n: setattr(project, "workspace", reader.strings(n, "workspace")),
        "environment": lambda n: setattr(
            project, "environment", reader.string_map(n, "environment")),
        "configurations": lambda n: setattr(
            project, "configurations", _configurations(reader, n)),
        "nodes": lambda n: setattr(project, "nodes", reader.any_map(n, "nodes")),
        "rules": lambda n: setattr(project, "rules", _rules(reader, n)),
        "queries": lambda n: setattr(project, "queries", _queries(reader, n)),
        "compile_commands": lambda n: setattr(
            project, "compile_commands", reader.string(n, "compile_commands")),
        "models": lambda n: setattr(project, "models", reader.strings(n, "models")),
        "distro": lambda n: setattr(project, "distro", reader.string(n, "distro")),
        "analysis": lambda n: None,
        "repositories": lambda n: None,  # HAROS fetched these; we analyse what is on disk
    }
    for key, key_node, value in reader.mapping(document, "the project file"):
        if key not in handlers:
            raise reader.fail(key_node, f"unknown key '{key}' (expected one of: "
                                        f"{', '.join(TOP_KEYS)})")
        handlers[key](value)
    folder = project.folder
    if project.workspace:
        project.workspace = [os.path.normpath(os.path.join(folder, w))
                             for w in project.workspace]
    else:
        src = os.path.join(folder, "src")
        project.workspace = [src if os.path.isdir(src) else folder]
    if project.compile_commands is not None:
        project.compile_commands = os.path.normpath(os.path.join(folder,
                                                                 project.compile_commands))
    project.models = [os.path.normpath(os.path.join(folder, m)) for m in project.models]
    names = [c.name for c in project.configurations]
    for config in project.configurations:
        if names.count(config.name) > 1:
            raise ProjectError(path, config.line, 1,
                               f"configuration '{config.name}' is defined twice")
    return project


def _configurations(reader: _Reader, node: Node) -> list[ConfigurationSpec]:
    """``{name: {launch: [...]}}`` as in HAROS, or a list of ``{name: ..., launch: ...}``."""
    specs: list[ConfigurationSpec] = []
    if isinstance(node, SequenceNode):
        for item in node.value:
            entries = {k: (kn, v) for k, kn, v in reader.mapping(item, "a configuration")}
            if "name" not in entries:
                raise reader.fail(item, "a configuration in a list needs a 'name'")
            name = reader.string(entries["name"][1], "configuration name")
            rest = [(k, kn, v) for k, (kn, v) in entries.items() if k != "name"]
            specs.append(_configuration(reader, name, item, rest))
        return specs
    for name, key_node, value in reader.mapping(node, "configurations"):
        if isinstance(value, SequenceNode):  # HAROS short form: name: [launch files]
            spec = ConfigurationSpec(name, line=key_node.start_mark.line + 1)
            _set_launch(spec, reader.strings_at(value, f"configuration '{name}'"))
            specs.append(spec)
            continue
        specs.append(_configuration(reader, name, key_node,
                                    reader.mapping(value, f"configuration '{name}'")))
    return specs


def _configuration(
    reader: _Reader, name: str, where: Node, entries: list[tuple[str, Node, Node]]
) -> ConfigurationSpec:
    spec = ConfigurationSpec(name, line=where.start_mark.line + 1)
    for key, key_node, value in entries:
        what = f"configurations.{name}.{key}"
        if key == "launch":
            _set_launch(spec, reader.strings_at(value, what))
        elif key == "args":
            spec.args = reader.string_map(value, what)
        elif key == "environment":
            spec.environment = reader.string_map(value, what)
        elif key == "hints":
            spec.hints = reader.any_map(value, what)
        elif key == "user_data":
            spec.user_data = reader.any_map(value, what)
        elif key == "description":
            reader.string(value, what)
        elif key == "rostest":
            spec.rostest = reader.boolean(value, what)
        else:
            raise reader.fail(key_node, f"unknown key '{key}' in configuration '{name}' "
                                        f"(expected one of: {', '.join(CONFIG_KEYS)})")
    if not spec.launch:
        raise reader.fail(where, f"configuration '{name}' names no launch files")
    return spec


def _set_launch(spec: ConfigurationSpec, entries: list[tuple[str, int]]) -> None:
    spec.launch = [text for text, _line in entries]
    spec.launch_lines = [line for _text, line in entries]


def _check_severities(reader: _Reader, node: Node) -> None:
    """Each query or rule's ``severity`` is one the findings know (said here, with its
    line, instead of when the queries run)."""
    items = node.value if isinstance(node, SequenceNode) else [
        value for _key, value in node.value] if isinstance(node, MappingNode) else []
    for item in items:
        if not isinstance(item, MappingNode):
            continue
        for key, value in item.value:
            if isinstance(key, ScalarNode) and key.value == "severity" and not (
                    isinstance(value, ScalarNode) and value.value in SEVERITY_RANK):
                raise reader.fail(value, "severity must be one of "
                                         + ", ".join(SEVERITY_RANK))


def _rules(reader: _Reader, node: Node) -> dict[str, Any]:
    rules = reader.any_map(node, "rules")
    _check_severities(reader, node)
    return rules


def _queries(reader: _Reader, node: Node) -> list[Any]:
    if not isinstance(node, SequenceNode):
        raise reader.fail(node, "queries must be a list")
    _check_severities(reader, node)
    result = reader.plain(node)
    return result if isinstance(result, list) else []
