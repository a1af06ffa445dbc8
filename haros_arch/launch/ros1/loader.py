"""The ROS 1 launch interpreter: roslaunch XML evaluated statically.

Tags are dispatched through a registry (``TAGS``) to one handler each; a tag that is
not in it is reported, as roslaunch warns about it. A scope carries the namespace,
the remappings and the launch conditions that apply to what it contains.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace

from lxml import etree

from ... import diagnostics as diag
from ...files import read_bytes
from ...manifest import xml_parser
from ...model.conditions import Condition
from ...model.location import Location
from ...model.rosname import as_namespace, resolve
from ...model.values import Value
from ...workspace import Workspace
from ..model import LaunchModel, NodeDecl, ParamDecl
from .substitution import Context, SubstitutionError, substitute

Element = etree._Element
MAX_INCLUDE_DEPTH = 32

COMMON = ("if", "unless")
ATTRIBUTES: dict[str, tuple[str, ...]] = {
    "launch": ("deprecated",),
    "node": ("name", "pkg", "type", "args", "ns", "machine", "respawn", "respawn_delay",
             "required", "clear_params", "output", "cwd", "launch-prefix"),
    "test": ("name", "pkg", "type", "args", "ns", "test-name", "clear_params", "cwd",
             "launch-prefix", "retry", "time-limit"),
    "param": ("name", "value", "type", "textfile", "binfile", "command"),
    "remap": ("from", "to"),
    "arg": ("name", "value", "default", "doc"),
    "group": ("ns", "clear_params"),
    "include": ("file", "ns", "clear_params", "pass_all_args"),
    "env": ("name", "value"),
    "machine": ("name", "address", "env-loader", "default", "user", "password",
                "timeout", "ssh-port"),
    "rosparam": ("command", "file", "param", "ns", "subst_value"),
}
REQUIRED: dict[str, tuple[str, ...]] = {
    "node": ("pkg", "type"), "test": ("pkg", "type", "test-name"), "param": ("name",),
    "remap": ("from", "to"), "arg": ("name",), "include": ("file",),
    "env": ("name", "value"), "machine": ("name", "address"),
}


@dataclass
class Scope:
    """What the enclosing elements give to the ones inside them."""

    namespace: str = "/"
    remaps: tuple[tuple[str, str], ...] = ()
    conditions: tuple[Condition, ...] = ()
    node: str | None = None  # inside <node>: its full name (for private params)


@dataclass
class FileState:
    """Per launch file: its path, arguments and substitution context."""

    path: str
    ctx: Context
    args: dict[str, Value | None] = field(default_factory=dict)
    given: Mapping[str, Value | None] = field(default_factory=dict)
    stack: tuple[str, ...] = ()


class Ros1Loader:
    def __init__(self, workspace: Workspace, environment: Mapping[str, str]) -> None:
        self.workspace = workspace
        self.environment = environment
        self.model = LaunchModel()
        self.tags: dict[str, Callable[[Element, Scope, FileState], None]] = {
            "node": self.tag_node, "test": self.tag_node, "param": self.tag_param,
            "remap": self.tag_remap_outside, "arg": self.tag_arg, "group": self.tag_group,
            "include": self.tag_include, "env": self.tag_ignored,
            "machine": self.tag_ignored, "rosparam": self.tag_rosparam,
        }

    # -- diagnostics and values ----------------------------------------------
    def where(self, state: FileState, element: Element | None = None) -> Location:
        line = element.sourceline if element is not None else None
        return self.workspace.location(state.path, line if isinstance(line, int) else 0)

    def report(self, code: str, state: FileState, element: Element | None,
               **params: object) -> None:
        self.model.diagnostics.append(diag.make(code, self.where(state, element), **params))

    def value(self, element: Element, attribute: str, state: FileState) -> Value | None:
        raw = element.get(attribute)
        if raw is None:
            return None
        ctx = state.ctx
        ctx.unset.clear()
        ctx.unsupported.clear()
        try:
            result = substitute(raw, ctx)
        except SubstitutionError as err:
            self.report("LAUNCH_BAD_VALUE", state, element,
                        detail=f"{attribute}=\"{raw}\": {err}")
            return Value.unknown(raw)
        for name in dict.fromkeys(ctx.unset):
            self.report("LAUNCH_ARG_UNSET", state, element, name=name)
        for text in ctx.unsupported:
            self.report("LAUNCH_UNSUPPORTED", state, element,
                        detail=f"{text} is not evaluated; its value is unknown")
        return result

    def text(self, element: Element, attribute: str, state: FileState,
             default: str | None = None) -> str | None:
        value = self.value(element, attribute, state)
        return default if value is None else value.text

    def check(self, element: Element, state: FileState) -> bool:
        """Report unknown and missing attributes; False if the element must be skipped."""
        tag = str(element.tag)
        allowed = ATTRIBUTES.get(tag, ())
        for attribute in element.attrib:
            if attribute not in allowed and attribute not in COMMON:
                self.report("LAUNCH_UNKNOWN_ATTRIBUTE", state, element,
                            attribute=attribute, tag=tag)
        for attribute in REQUIRED.get(tag, ()):
            if element.get(attribute) is None:
                self.report("LAUNCH_MISSING_ATTRIBUTE", state, element,
                            tag=tag, attribute=attribute)
                return False
        return True

    def condition(self, element: Element, scope: Scope, state: FileState) -> Scope | None:
        """Apply if/unless: None drops the element, else the scope to use inside it."""
        for attribute in COMMON:
            if element.get(attribute) is None:
                continue
            value = self.value(element, attribute, state)
            assert value is not None
            literal = value.literal
            if literal is None:
                where = self.where(state, element)
                cond = Condition(element.get(attribute, ""), "launch", attribute, where)
                scope = replace(scope, conditions=(*scope.conditions, cond))
                continue
            truth = literal.strip().lower()
            if truth not in ("true", "1", "false", "0"):
                self.report("LAUNCH_BAD_VALUE", state, element,
                            detail=f"{attribute}=\"{literal}\" is not a boolean")
                return None
            if (truth in ("true", "1")) != (attribute == "if"):
                return None
        return scope

    # -- traversal ------------------------------------------------------------
    def load_file(self, path: str, scope: Scope, given: Mapping[str, Value | None],
                  stack: tuple[str, ...], element: Element | None = None,
                  parent: FileState | None = None) -> None:
        path = os.path.abspath(path)
        if path in stack or len(stack) > MAX_INCLUDE_DEPTH:
            assert parent is not None
            self.report("LAUNCH_BAD_VALUE", parent, element,
                        detail=f"include cycle: {self.workspace.relpath(path)} includes itself")
            return
        if not os.path.isfile(path):
            location = self.where(parent, element) if parent else self.workspace.location(path)
            self.model.diagnostics.append(diag.make(
                "LAUNCH_FILE_MISSING", location, path=self.workspace.relpath(path)))
            return
        data, found = read_bytes(path, self.workspace.location(path))
        self.model.diagnostics.extend(found)
        if data is None:
            return
        try:
            root = etree.fromstring(data, xml_parser())
        except etree.XMLSyntaxError as err:
            line, col = err.position if err.position else (0, 0)
            self.model.diagnostics.append(diag.make(
                "LAUNCH_XML_SYNTAX", self.workspace.location(path, line, col), detail=err.msg))
            return
        self.model.files.append(self.workspace.relpath(path))
        ctx = Context({}, self.environment, self.workspace.find, path)
        state = FileState(path, ctx, given=given, stack=(*stack, path))
        ctx.args = state.args
        if root.tag != "launch":
            self.report("LAUNCH_BAD_VALUE", state, root,
                        detail=f"root element is <{root.tag}>, not <launch>")
            return
        self.check(root, state)
        self.children(root, scope, state)
        if not stack:
            self.model.args = {k: (v.text if v is not None else None)
                               for k, v in state.args.items()}

    def children(self, element: Element, scope: Scope, state: FileState) -> None:
        for child in element:
            if not isinstance(child.tag, str):
                continue
            handler = self.tags.get(child.tag)
            if handler is None:
                self.report("LAUNCH_UNKNOWN_TAG", state, child, tag=child.tag)
                continue
            if not self.check(child, state):
                continue
            inner = self.condition(child, scope, state)
            if inner is not None:
                handler(child, inner, state)

    # -- tags -----------------------------------------------------------------
    def tag_ignored(self, element: Element, scope: Scope, state: FileState) -> None:
        """Tags that do not change the Computation Graph (env, machine)."""

    def tag_arg(self, element: Element, scope: Scope, state: FileState) -> None:
        name = element.get("name", "")
        if "value" in element.attrib and "default" in element.attrib:
            self.report("LAUNCH_BAD_VALUE", state, element,
                        detail=f"arg {name} has both value= and default=")
        if "value" in element.attrib:
            state.args[name] = self.value(element, "value", state)
        elif name in state.given:
            state.args[name] = state.given[name]
        elif "default" in element.attrib:
            state.args[name] = self.value(element, "default", state)
        else:
            state.args[name] = None

    def tag_group(self, element: Element, scope: Scope, state: FileState) -> None:
        ns = self.text(element, "ns", state)
        scope = replace(scope)  # remaps inside the group stay inside it
        if ns:
            scope.namespace = as_namespace(resolve(ns, scope.namespace))
        self.children(element, scope, state)

    def tag_remap_outside(self, element: Element, scope: Scope, state: FileState) -> None:
        """A <remap> outside <node> applies to the nodes after it in the same scope."""
        pair = (self.text(element, "from", state) or "", self.text(element, "to", state) or "")
        scope.remaps = (*scope.remaps, pair)

    def tag_node(self, element: Element, scope: Scope, state: FileState) -> None:
        ns = self.text(element, "ns", state)
        namespace = scope.namespace
        if ns:
            namespace = as_namespace(resolve(ns, namespace))
        package = self.text(element, "pkg", state) or "?"
        executable = self.text(element, "type", state) or "?"
        given = self.text(element, "name", state)
        if given is None:
            if element.tag == "node":
                self.report("LAUNCH_MISSING_ATTRIBUTE", state, element, tag="node",
                            attribute="name")
                return
            given = self.text(element, "test-name", state) or executable
        name = resolve(given, namespace)
        decl = NodeDecl(name, package, executable, namespace,
                        self.text(element, "args", state, "") or "",
                        list(scope.remaps), scope.conditions, self.where(state, element))
        inner = Scope(namespace, (), scope.conditions, name)
        for child in element:
            if not isinstance(child.tag, str):
                continue
            if child.tag not in ("remap", "param", "rosparam", "env"):
                self.report("LAUNCH_UNKNOWN_TAG", state, child, tag=child.tag)
                continue
            if not self.check(child, state):
                continue
            child_scope = self.condition(child, inner, state)
            if child_scope is None:
                continue
            if child.tag == "remap":
                decl.remaps.append((self.text(child, "from", state) or "",
                                    self.text(child, "to", state) or ""))
            elif child.tag == "param":
                self.tag_param(child, child_scope, state)
            elif child.tag == "rosparam":
                self.tag_rosparam(child, child_scope, state)
        self.model.nodes.append(decl)

    def tag_param(self, element: Element, scope: Scope, state: FileState) -> None:
        given = self.text(element, "name", state) or ""
        base = (scope.node + "/") if scope.node else scope.namespace
        name = resolve(given, base, scope.node)
        declared = element.get("type")
        if "value" in element.attrib:
            raw = self.value(element, "value", state)
            assert raw is not None
            value, kind = typed_value(raw, declared)
            if kind is None and declared:
                self.report("LAUNCH_BAD_VALUE", state, element,
                            detail=f"value \"{raw.text}\" is not of type {declared}")
        else:
            value, kind = None, declared  # textfile, binfile, command: not read here
        self.model.params.append(
            ParamDecl(name, value, kind, scope.conditions, self.where(state, element)))

    def tag_rosparam(self, element: Element, scope: Scope, state: FileState) -> None:
        self.report("LAUNCH_UNSUPPORTED", state, element,
                    detail="<rosparam> is not evaluated yet; its parameters are unknown")

    def tag_include(self, element: Element, scope: Scope, state: FileState) -> None:
        path = self.value(element, "file", state)
        if path is None or path.literal is None:
            self.report("LAUNCH_UNSUPPORTED", state, element,
                        detail=f"include file \"{element.get('file')}\" is not known statically")
            return
        ns = self.text(element, "ns", state)
        scope = replace(scope)
        if ns:
            scope.namespace = as_namespace(resolve(ns, scope.namespace))
        given: dict[str, Value | None] = {}
        if (self.text(element, "pass_all_args", state) or "").lower() in ("true", "1"):
            given.update(state.args)
        for child in element:
            if not isinstance(child.tag, str):
                continue
            if child.tag == "arg" and self.check(child, state):
                if self.condition(child, scope, state) is None:
                    continue
                key = "value" if "value" in child.attrib else "default"
                given[child.get("name", "")] = self.value(child, key, state)
            elif child.tag != "env":
                self.report("LAUNCH_UNKNOWN_TAG", state, child, tag=child.tag)
        self.load_file(path.literal, scope, given, state.stack, element, state)


def typed_value(raw: Value, declared: str | None) -> tuple[object, str | None]:
    """A parameter's value and type as roslaunch would give them (None if unknown)."""
    text = raw.literal
    if text is None:
        return None, declared
    if declared in (None, "auto"):
        stripped = text.strip()
        lowered = stripped.lower()
        if lowered in ("true", "false"):
            return lowered == "true", "bool"
        for cast, kind in ((int, "int"), (float, "double")):
            try:
                return cast(stripped), kind
            except ValueError:
                pass
        return text, "str"
    try:
        if declared == "int":
            return int(text.strip()), "int"
        if declared in ("double", "float"):
            return float(text.strip()), "double"
        if declared in ("bool", "boolean"):
            lowered = text.strip().lower()
            if lowered not in ("true", "false", "1", "0"):
                return None, None
            return lowered in ("true", "1"), "bool"
        if declared in ("str", "string"):
            return text, "str"
        if declared == "yaml":
            return text, "yaml"
    except ValueError:
        return None, None
    return text, declared


def load(path: str, workspace: Workspace, args: Mapping[str, str] | None = None,
         environment: Mapping[str, str] | None = None) -> LaunchModel:
    """Interpret one ROS 1 launch file and what it includes."""
    loader = Ros1Loader(workspace, workspace.environment if environment is None
                        else environment)
    given = {k: Value.of(v) for k, v in (args or {}).items()}
    loader.load_file(path, Scope(), given, ())
    return loader.model
