"""The XML and YAML front ends of ROS 2 launch (launch_xml, launch_yaml, launch_ros tags).

Both formats become ``Entity`` trees (tag, attributes, children, line); one registry of
tag handlers (``TAGS``) turns entities into actions. As in the ``launch`` package, an
attribute or child a handler did not read is reported, and an unknown tag is reported
and skipped.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import yaml
from lxml import etree

from ... import diagnostics as diag
from ... import safe_yaml
from ...diagnostics import Diagnostic
from ...manifest import start_lines, xml_parser
from ...model.location import Location
from ...workspace import Workspace
from . import entities as e
from .package_actions import BY_TAG, node_action
from .substitutions import SubstitutionSyntax, parse

COMMON = ("if", "unless")
_PARAM_ATTRS = ("name", "value", "from", "value-sep", "sep", "allow_substs")


@dataclass
class Entity:
    tag: str
    attrs: dict[str, Any]
    children: list[Entity] = field(default_factory=list)
    line: int = 0
    read: set[str] = field(default_factory=set)


class Frontend:
    def __init__(self, path: str, workspace: Workspace) -> None:
        self.path = path
        self.workspace = workspace
        self.diagnostics: list[Diagnostic] = []
        self.tags: dict[str, Callable[[Entity], e.Action | None]] = {
            "arg": self.arg, "let": self.let, "group": self.group, "include": self.include,
            "push-ros-namespace": self.push, "push_ros_namespace": self.push,
            "node": self.node, "node_container": self.node, "executable": self.executable,
            "set_parameter": self.set_parameter, "set_parameters_from_file": self.set_pfile,
            "set_remap": self.set_remap, "set_env": self.set_env, "unset_env": self.set_env,
            "load_composable_node": self.load_composable, "timer": self.timer,
            "log": self.ignored, "set_launch_configuration": self.let,
            "ros_timer": self.timer, "shutdown": self.ignored, "append_env": self.ignored,
            # the launch process's own ROS node and log folder: nothing in the graph
            "set_use_sim_time": self.ignored, "set_ros_log_dir": self.ignored,
            "reset": self.reset, "for_each": self.for_each, "for": self.for_loop,
            # actions installed packages expose (ros_gz's ``<ros_gz_bridge>``, ...)
            **{tag: self.package_action for tag in BY_TAG},
        }

    # -- helpers -------------------------------------------------------------------
    def where(self, ent: Entity) -> Location:
        return self.workspace.location(self.path, ent.line)

    def report(self, code: str, ent: Entity, **params: object) -> None:
        self.diagnostics.append(diag.make(code, self.where(ent), **params))

    def text(self, ent: Entity, name: str, required: bool = False) -> e.Text | None:
        ent.read.add(name)
        raw = ent.attrs.get(name)
        if raw is None:
            if required:
                self.report("LAUNCH_MISSING_ATTRIBUTE", ent, tag=ent.tag, attribute=name)
            return None
        if isinstance(raw, bool):
            return (str(raw).lower(),)
        if not isinstance(raw, str):
            return (str(raw),)
        try:
            return parse(raw)
        except SubstitutionSyntax as err:
            self.report("LAUNCH_BAD_VALUE", ent, detail=f"{name}=\"{raw}\": {err}")
            return (e.Opaque(f"{name}=\"{raw}\" cannot be parsed", report=False),)

    def flag(self, ent: Entity, name: str, default: bool) -> bool:
        raw = self.text(ent, name)
        if raw is None:
            return default
        literal = "".join(p for p in raw if isinstance(p, str)).strip().lower()
        return literal in ("true", "1") if literal in ("true", "1", "false", "0") else default

    def finish(self, ent: Entity, action: e.Action) -> e.Action:
        """Attach condition and location; report what the handler did not read."""
        for key in COMMON:
            raw = ent.attrs.get(key)
            if raw is not None:
                expr = self.text(ent, key)
                assert expr is not None
                action.condition = e.Cond(expr, negate=key == "unless", source=str(raw))
        action.location = self.where(ent)
        self.leftovers(ent, action=True)
        return action

    def leftovers(self, ent: Entity, action: bool = False) -> None:
        # launch's frontend checks an action's own attributes once its parse method
        # has run (expose_action, since foxy) and refuses the file with "Unexpected
        # attribute(s)": an action's attribute no distro reads fails the launch; one
        # on a nested entity (<param>, <remap>, <arg> of an include) is not checked
        code = "LAUNCH_UNEXPECTED_ATTRIBUTE" if action else "LAUNCH_UNKNOWN_ATTRIBUTE"
        for key in ent.attrs:
            if key not in ent.read and key not in COMMON:
                self.report(code, ent, attribute=key, tag=ent.tag)

    def cond_of(self, ent: Entity) -> e.Cond | None:
        for key in COMMON:
            if key in ent.attrs:
                expr = self.text(ent, key)
                assert expr is not None
                return e.Cond(expr, negate=key == "unless", source=str(ent.attrs[key]))
        return None

    def actions(self, children: list[Entity]) -> list[e.Action]:
        out: list[e.Action] = []
        for child in children:
            handler = self.tags.get(child.tag)
            if handler is None:
                self.report("LAUNCH_UNKNOWN_TAG", child, tag=child.tag)
                # ros2 launch takes an action tag from a launch extension an installed
                # package exposes (ros_gz_bridge's <ros_gz_bridge>, ros_gz_sim's
                # <gz_server>), else fails: what it starts is unknown, not nothing
                out.append(e.UnknownAction(f"<{child.tag}>", condition=self.cond_of(child),
                                           location=self.where(child)))
                continue
            action = handler(child)
            if action is not None:
                out.append(self.finish(child, action))
        return out

    # -- tags ----------------------------------------------------------------------
    def ignored(self, ent: Entity) -> e.Action | None:
        ent.read.update(ent.attrs)
        return None

    def arg(self, ent: Entity) -> e.Action | None:
        name = ent.attrs.get("name")
        # (not ROS 1's ``doc``: DeclareArgument.parse does not read it, launch refuses it)
        ent.read.update(("name", "description"))
        for child in ent.children:
            if child.tag != "choice":
                self.report("LAUNCH_UNKNOWN_TAG", child, tag=child.tag)
        if not isinstance(name, str):
            self.report("LAUNCH_MISSING_ATTRIBUTE", ent, tag="arg", attribute="name")
            return None
        default = self.text(ent, "default")
        return e.DeclareArg(name, default)

    def reset(self, ent: Entity) -> e.Action | None:
        keeps: list[tuple[e.Text, e.Text]] = []
        for child in ent.children:
            if child.tag != "keep":
                self.report("LAUNCH_UNKNOWN_TAG", child, tag=child.tag)
                continue
            name, value = self.text(child, "name", True), self.text(child, "value", True)
            self.leftovers(child)
            if name is not None and value is not None:
                keeps.append((name, value))
        return e.ResetConfigs(keeps if ent.children else None)

    def let(self, ent: Entity) -> e.Action | None:
        name, value = self.text(ent, "name", True), self.text(ent, "value", True)
        return None if name is None or value is None else e.SetConfig(name, value)

    def group(self, ent: Entity) -> e.Action | None:
        keeps: list[tuple[e.Text, e.Text]] = []
        others = []
        for child in ent.children:
            if child.tag == "keep":
                name, value = self.text(child, "name", True), self.text(child, "value", True)
                self.leftovers(child)
                if name is not None and value is not None:
                    keeps.append((name, value))
            else:
                others.append(child)
        # (no ``ns``: ROS 1's; GroupAction.parse does not read it, launch refuses it and
        # pushes no namespace, which is launch_ros' <push-ros-namespace>)
        actions = self.actions(others)
        return e.Group(actions, self.flag(ent, "scoped", True),
                       self.flag(ent, "forwarding", True), keeps)

    def for_each(self, ent: Entity) -> e.Action | None:
        """``<for_each values="...">``: its children once per iteration (launch reads
        ``values`` only; without it, ForEach is not built and the file fails)."""
        values = self.text(ent, "values", True)
        children = self.actions(ent.children)
        return None if values is None else e.ForEach(values, children=children)

    def for_loop(self, ent: Entity) -> e.Action | None:
        """``<for len="N" name="i">``: its children N times, ``$(index i)`` 0 to N-1."""
        length = self.text(ent, "len", True)
        ent.read.add("name")  # taken as written (launch reads no substitution there)
        raw = ent.attrs.get("name")
        index = None if raw is None else str(raw)
        children = self.actions(ent.children)
        return None if length is None else e.ForEach(length, length=True, index=index,
                                                     children=children)

    def include(self, ent: Entity) -> e.Action | None:
        path = self.text(ent, "file", True)
        args: list[tuple[e.Text, e.Text]] = []
        for child in ent.children:
            if child.tag != "arg":
                self.report("LAUNCH_UNKNOWN_TAG", child, tag=child.tag)
                continue
            name, value = self.text(child, "name", True), self.text(child, "value", True)
            self.leftovers(child)
            if name is not None and value is not None:
                args.append((name, value))
        return None if path is None else e.Include(path, args)

    def push(self, ent: Entity) -> e.Action | None:
        ns = self.text(ent, "namespace", True)
        return None if ns is None else e.PushNamespace(ns)

    def set_parameter(self, ent: Entity) -> e.Action | None:
        name, value = self.text(ent, "name", True), self.text(ent, "value", True)
        return None if name is None or value is None else e.SetParam(name, value)

    def set_pfile(self, ent: Entity) -> e.Action | None:
        path = self.text(ent, "filename", True)
        return None if path is None else e.SetParamFile(path)

    def set_remap(self, ent: Entity) -> e.Action | None:
        src, dst = self.text(ent, "from", True), self.text(ent, "to", True)
        return None if src is None or dst is None else e.SetRemap(src, dst)

    def set_env(self, ent: Entity) -> e.Action | None:
        name = self.text(ent, "name", True)
        value = self.text(ent, "value", ent.tag == "set_env")
        return None if name is None else e.SetEnv(name, value)

    def executable(self, ent: Entity) -> e.Action | None:
        cmd = self.text(ent, "cmd")
        ent.read.update(ent.attrs)  # the rest (cwd, output, env...) changes no name
        return None if cmd is None else e.Process(cmd)

    def timer(self, ent: Entity) -> e.Action | None:
        period = ent.attrs.get("period", "?")
        ent.read.add("period")
        return e.Delayed(self.actions(ent.children), f"after timer period={period}")

    def params(self, children: list[Entity], prefix: str = "") -> list[e.ParamEntry]:
        out: list[e.ParamEntry] = []
        for child in children:
            if child.tag != "param":
                continue
            ent = child
            if "from" in ent.attrs:
                path = self.text(ent, "from")
                substs = self.flag(ent, "allow_substs", False)
                if path is not None:
                    out.append(e.ParamFile(path, location=self.where(ent),
                                           allow_substs=substs))
                self.leftovers(ent)
                continue
            name = self.text(ent, "name", True)
            if name is None:
                continue
            full = e.text(prefix + "." if prefix else "", name) if prefix else name
            if ent.children:
                key = "".join(p for p in name if isinstance(p, str))
                out.extend(self.params(ent.children, f"{prefix}.{key}" if prefix else key))
            else:
                value = self.param_value(ent)
                if value is not None:
                    out.append((full, value))
            self.leftovers(ent)
        return out

    def param_value(self, ent: Entity) -> Any:
        raw = ent.attrs.get("value")
        ent.read.update(("value", "value-sep", "sep", "type"))
        if raw is None:
            self.report("LAUNCH_MISSING_ATTRIBUTE", ent, tag="param", attribute="value")
            return None
        yaml_file = self.path.lower().endswith((".yaml", ".yml"))
        if not isinstance(raw, str):  # YAML gives typed values
            if isinstance(raw, list):
                return [_plain(item) for item in raw]
            return raw
        sep = ent.attrs.get("value-sep") or ent.attrs.get("sep")
        value = self.text(ent, "value")
        if isinstance(sep, str) and sep and all(isinstance(p, str) for p in value or ()):
            return [item for item in raw.split(sep)]
        if yaml_file:  # launch_yaml: a string with no substitution is that string
            return _plain(raw)
        return value

    def remaps(self, children: list[Entity]) -> list[tuple[e.Text, e.Text]]:
        out = []
        for child in children:
            if child.tag == "remap":
                src, dst = self.text(child, "from", True), self.text(child, "to", True)
                self.leftovers(child)
                if src is not None and dst is not None:
                    out.append((src, dst))
        return out

    def node(self, ent: Entity) -> e.Action | None:
        def words(name: str) -> list[e.Text]:
            found = self.text(ent, name)
            return [] if found is None else [found]

        container = ent.tag == "node_container"
        # what launch's ExecuteProcess and launch_ros's Node read, in any distro
        for key in ("output", "respawn", "respawn_delay", "launch-prefix", "exec_name",
                    "emulate_tty", "cwd", "sigterm_timeout", "sigkill_timeout", "shell",
                    "respawn_max_retries", "node-name", "on_exit"):
            ent.read.add(key)
        executable = self.text(ent, "exec", True)
        if executable is None:
            # launch_ros' Node.parse asks for exec= and ros2 launch stops: the element
            # is skipped (as LAUNCH_MISSING_ATTRIBUTE says), no node of an unknown type;
            # the attributes launch refuses (ROS 1's type=) are still said
            ent.read.update(("pkg", "name", "namespace", "args", "ros_args"))
            self.leftovers(ent, action=True)
            return None
        action = e.NodeAction(
            self.text(ent, "pkg", True), executable,
            self.text(ent, "name", container), self.text(ent, "namespace"),
            self.params(ent.children), self.remaps(ent.children),
            words("args"), words("ros_args"), container=container, split=True)
        for child in ent.children:
            if child.tag == "composable_node" and container:
                component = self.composable(child)
                if component is not None:
                    action.composable.append(component)
            elif child.tag not in ("param", "remap", "env"):
                self.report("LAUNCH_UNKNOWN_TAG", child, tag=child.tag)
        return action

    def package_action(self, ent: Entity) -> e.Action | None:
        """A launch action of an installed package (``package_actions``): the node its
        launch file starts, named and given parameters by the tag's attributes."""
        row = BY_TAG[ent.tag]
        for key in row.others:
            ent.read.add(key)
        missing = [key for key in row.required if key not in ent.attrs]
        for key in missing:
            self.report("LAUNCH_MISSING_ATTRIBUTE", ent, tag=ent.tag, attribute=key)
        if missing:
            return None
        return node_action(row, lambda argument: self.text(ent, argument))

    def composable(self, ent: Entity) -> e.ComposableNode | None:
        node = e.ComposableNode(
            self.text(ent, "pkg", True), self.text(ent, "plugin", True),
            self.text(ent, "name"), self.text(ent, "namespace"),
            self.params(ent.children), self.remaps(ent.children),
            self.cond_of(ent), self.where(ent))
        for child in ent.children:
            if child.tag not in ("param", "remap", "extra_arg"):
                self.report("LAUNCH_UNKNOWN_TAG", child, tag=child.tag)
        self.leftovers(ent)
        return node

    def load_composable(self, ent: Entity) -> e.Action | None:
        target = self.text(ent, "target", True)
        nodes = [c for c in (self.composable(child) for child in ent.children
                             if child.tag == "composable_node") if c is not None]
        return None if target is None else e.LoadComposable(target, nodes)


def _plain(raw: Any) -> Any:
    """A YAML launch file's parameter value as launch_yaml gives it: a string with no
    substitution stays that string (``'false'`` is not ``false``, unlike XML's
    attribute text); one with substitutions is read as YAML once they are performed."""
    if not isinstance(raw, str):
        return raw
    try:
        parts = parse(raw)
    except SubstitutionSyntax:
        return raw
    if all(isinstance(p, str) for p in parts):
        return e.ParamValue("".join(p for p in parts if isinstance(p, str)), as_text=True)
    return parts


# -- reading the files ---------------------------------------------------------------
def xml_entities(data: bytes) -> Entity:
    root = etree.fromstring(data, xml_parser())
    start_lines(root, data)

    def convert(el: Any) -> Entity:
        children = [convert(c) for c in el if isinstance(c.tag, str)]
        line = el.sourceline if isinstance(el.sourceline, int) else 0
        return Entity(str(el.tag), dict(el.attrib), children, line)

    return convert(root)


def yaml_entities(text: str) -> Entity:
    node = safe_yaml.compose(text)
    if not isinstance(node, yaml.MappingNode) or len(node.value) != 1:
        raise ValueError("a YAML launch file is one mapping with the key 'launch'")
    key, body = node.value[0]
    return _yaml_entity(str(key.value), body, key.start_mark.line + 1)


def _scalar(node: Any) -> Any:
    if isinstance(node, yaml.ScalarNode):
        return yaml.safe_load(yaml.serialize(node)) if node.tag != "tag:yaml.org,2002:str" \
            else node.value
    return yaml.safe_load(yaml.serialize(node))


def _yaml_entity(tag: str, body: Any, line: int) -> Entity:
    ent = Entity(tag, {}, [], line)
    if isinstance(body, yaml.SequenceNode):  # launch: [ {node: ...}, ... ]
        ent.children = _yaml_list(body)
        return ent
    if not isinstance(body, yaml.MappingNode):
        return ent
    for key, value in body.value:
        name = str(key.value)
        if isinstance(value, yaml.SequenceNode) and name in (
                "children", "param", "remap", "arg", "composable_node", "keep", "choice",
                "extra_arg", "env"):
            if name == "children":
                ent.children.extend(_yaml_list(value))
            else:
                ent.children.extend(_yaml_entity(name, item, item.start_mark.line + 1)
                                    for item in value.value)
        else:
            ent.attrs[name] = _scalar(value)
    return ent


def _yaml_list(seq: Any) -> list[Entity]:
    out: list[Entity] = []
    for item in seq.value:
        if isinstance(item, yaml.MappingNode) and len(item.value) == 1:
            key, value = item.value[0]
            out.append(_yaml_entity(str(key.value), value, key.start_mark.line + 1))
    return out
