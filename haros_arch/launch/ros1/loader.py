"""The ROS 1 launch interpreter: roslaunch XML evaluated statically.

Tags are dispatched through a registry (``tags``) to one handler each; a tag that is
not in it is reported, as roslaunch warns about it. A ``Scope`` mirrors roslaunch's
``LoaderContext``: namespace, arguments, remappings, private parameters, environment
and the launch conditions that apply to what it contains. The rules (which scope sees
which argument, how ``~params`` reach nodes, how remaps override) follow roslaunch's
loader; where roslaunch refuses a file we report an error and go on.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Mapping
from dataclasses import replace
from typing import TYPE_CHECKING, Any

from lxml import etree

from ... import diagnostics as diag
from ...files import read_bytes
from ...manifest import as_expat_reads, start_lines, xml_parser
from ...model.conditions import Condition, exclusive, same_conditions
from ...model.launch_tree import ArgOrigin, LaunchArg, LaunchCondition, LaunchItem, PackageUse
from ...model.location import Location, is_upstream
from ...model.rosname import is_legal_name
from ...model.values import UNKNOWN_MARK, Unknown, Value, scalar_type
from ...rosrun import find_executable
from ...workspace import Workspace
from ..model import (
    LaunchModel,
    NodeDecl,
    RecordedEnvironment,
    UnreadInclude,
    found_nowhere,
    program_not_found,
    shell_words,
)
from ..paths import missing_argument_paths, written_absolute, written_argument_paths
from ..tree import MAX_SKIPPED, node_items, param_names, ros1_condition
from . import tags_params
from .child_launch import dropped_words, launched_file
from .scope import Scope, canonical, global_ns, same_unknowns, unknown_parts
from .substitution import ArgUndefined, Context, SubstitutionError, substitute, unclosed

if TYPE_CHECKING:
    from ...models.launch_files import ModelledFiles

Element = etree._Element
MAX_INCLUDE_DEPTH = 32
MIN_HINTED_DEFAULT = 3  # characters of an $(optenv) default a missing path is tested for
# an include's ``$(arg x)``, and what stands for any value of it (``include_pattern``)
_ARG_SUBSTITUTION = re.compile(r"\$\(arg\s+[^()\s]+\s*\)")
_ANY_MARK = "@haros-any-value@"
_LAUNCH_SUFFIXES = (".launch.xml", ".launch", ".xml")
MAX_INCLUDES = 2_000

COMMON = ("if", "unless")
NODE_ATTRS = ("pkg", "type", "machine", "name", "args", "output", "respawn",
              "respawn_delay", "cwd", "ns", "clear_params", "launch-prefix", "required")
ATTRIBUTES: dict[str, tuple[str, ...]] = {
    "launch": ("deprecated",),
    "node": NODE_ATTRS,
    "test": (*NODE_ATTRS, "test-name", "time-limit", "retry"),
    "param": ("name", "value", "type", "textfile", "binfile", "command"),
    "remap": ("from", "to"),
    "arg": ("name", "value", "default", "doc"),
    "group": ("ns", "clear_params"),
    "include": ("file", "ns", "clear_params", "pass_all_args"),
    "env": ("name", "value"),
    "machine": ("name", "address", "env-loader", "default", "user", "password",
                "timeout", "ssh-port"),
    "rosparam": ("command", "file", "param", "ns", "subst_value"),
    "master": ("auto",),
}
REQUIRED: dict[str, tuple[str, ...]] = {
    "node": ("pkg", "type", "name"), "test": ("pkg", "type", "test-name"),
    "param": ("name",), "remap": ("from", "to"), "arg": ("name",), "include": ("file",),
    "env": ("name", "value"), "machine": ("name", "address"),
}


class Ros1Loader:
    def __init__(self, workspace: Workspace, environment: Mapping[str, str],
                 models: ModelledFiles | None = None) -> None:
        self.workspace = workspace
        # the launch and parameter files of packages not here that their interface
        # models hold (``models.launch_files``): read as the real ones would be
        self.models = models
        self.model = LaunchModel()
        self.environment: Mapping[str, str] = RecordedEnvironment(environment,
                                                        self.model.environment_values)
        self.default_machine: str | None = None
        # each node's machine and where the node is: roslaunch looks them up once every
        # file is loaded (``check_machines``)
        self.machine_uses: list[tuple[str, Location]] = []
        # where an included file was not read (not in the workspace, outside it, in a
        # submodule not checked out): what it declares is not known
        self.unread_files: list[Location] = []
        # the nodes started so far by name, and the anonymous parts of the name: two
        # ``$(anon x)`` of one file are one name, those of two includes are not; each
        # with its place, conditions and the unknown parts of its name
        # and the include that reached its file (one file included twice starts its
        # nodes at one place: the includes tell them apart)
        self.node_names: dict[tuple[str, tuple[int, ...]], list[tuple[
            Location, tuple[Condition, ...], tuple[Unknown, ...], Location | None]]] = {}
        # each ``$(anon x)`` unknown met in a node name, by identity, with its number
        self.anon_parts: dict[int, tuple[Unknown, int]] = {}
        self.includes = 0
        # the programs that run roslaunch (``child_launch``): words dropped, None if not
        self.launchers: dict[tuple[str, str], int | None] = {}
        self.launcher: NodeDecl | None = None
        # $(optenv NAME default) of variables not set here, by the default they took
        # (``unset_hint``)
        self.optenv_defaults: dict[str, str] = {}
        # the first <param> tag of each name per parent element (LAUNCH_PARAM_SET_TWICE)
        self.param_tags: dict[tuple[int, str, str, tuple[str, ...]], Element] = {}
        # each <param> tag outside a node by parent element, full name and conditions,
        # for a later <rosparam> of that element that loads the name again
        # (LAUNCH_PARAM_LOADED_OVER)
        self.shared_param_tags: dict[tuple[int, str, tuple[str, ...]], Element] = {}
        # the if/unless of the element being handled, for the launch tree
        self.guard: LaunchCondition | None = None
        # paths of the workspace a node's command line names that are not there, each
        # with its node and place, and the paths nodes write (``xacro -o PATH``): said
        # once every file is loaded, but for a file another node writes
        # (``check_argument_paths``)
        self.missing_args: list[tuple[Location, str, str]] = []
        self.written_args: set[str] = set()
        # the files whose declared arguments were looked at (``unused_arguments``): a
        # file read twice is said once
        self.args_looked_at: set[str] = set()
        self.tags: dict[str, Callable[[Element, Scope], None]] = {
            "node": self.tag_node, "test": self.tag_node, "param": self.tag_param,
            "remap": self.tag_remap, "arg": self.tag_arg, "group": self.tag_group,
            "include": self.tag_include, "env": self.tag_env,
            "machine": self.tag_machine, "rosparam": self.tag_rosparam,
            "master": lambda element, scope: None,
        }

    # -- diagnostics and values ----------------------------------------------
    def anonymous_parts(self, value: Value) -> tuple[int, ...]:
        """The ``$(anon x)`` parts of a node's name, numbered by identity: roslaunch
        gives every use of ``$(anon x)`` in one file the same name, and an included file
        a fresh one (its context starts with a new substitution dictionary), so two
        nodes of ``$(anon cpu_monitor)`` in two includes of one file are two names, which
        both read ``cpu_monitor_?``."""
        numbers = []
        for part in value.parts:
            if isinstance(part, Unknown) and part.origin.startswith("anon "):
                # the unknown is kept, so its id is never another's while loading
                kept = self.anon_parts.setdefault(id(part), (part, len(self.anon_parts)))
                numbers.append(kept[1])
        return tuple(numbers)

    def where(self, scope: Scope | str, element: Element | None = None) -> Location:
        line = element.sourceline if element is not None else None
        path = scope if isinstance(scope, str) else scope.path
        return self.place(path, line if isinstance(line, int) else 0)

    def place(self, path: str, line: int = 0) -> Location:
        """A file's line: in the workspace, or upstream for a modelled file."""
        modelled = self.models.location(path, line) if self.models is not None else None
        return modelled or self.workspace.location(path, line)

    def relpath(self, path: str) -> str:
        """How a file is named: relative to the workspace, or upstream for a modelled
        file (``place``)."""
        modelled = self.models.location(path) if self.models is not None else None
        return modelled.file or path if modelled is not None else self.workspace.relpath(path)

    def unheld(self, path: str) -> str | None:
        """Why a file of a modelled package's folder (``$(find pkg)`` of a package not
        here) is not read: its model does not hold it; None for any other file."""
        owner = self.models.owner(path) if self.models is not None else None
        if owner is None or self.models is None or self.models.holds(path):
            return None
        return f"the interface model {owner[0].label} holds no file {owner[1]}; it is not read"

    def report(self, code: str, scope: Scope | str, element: Element | None,
               **params: object) -> None:
        """A diagnostic at ``element``; one in an installed package's own launch file
        (upstream, read from its model) also names the workspace's include that reached
        it (``Scope.reached_from``): mavros' node.launch fails on the ``config_yaml`` a
        workspace file gave it, and only that file can be changed."""
        said = diag.make(code, self.where(scope, element), **params)
        reached = scope.reached_from if isinstance(scope, Scope) else None
        if reached is not None and is_upstream(said.location.file or ""):
            said = replace(said, also=(reached,))
        self.model.diagnostics.append(said)

    @staticmethod
    def other_start(other: tuple[Location, Location | None], where: Location,
                    reached: Location | None) -> str:
        """Where the earlier of two nodes of one name starts; when both start at one
        place (one file included twice: hexapod_ros' rviz.launch by all_local_debug.launch
        and by a file it includes), with the include of each, which is what to change."""
        place, its_include = other
        text = f"{place.file}:{place.line}"
        if (place.file, place.line) != (where.file, where.line) or (
                its_include is None or reached is None):
            return text
        return (f"{text}, included at {its_include.file}:{its_include.line}; this one "
                f"included at {reached.file}:{reached.line}")

    def unset_hint(self, path: str) -> str:
        """Why a missing file's path may be as it is: it holds the default of an
        ``$(optenv NAME default)`` whose variable is not set here (cob_bringup's robot
        files under ``$(optenv ROBOT !!NO_ROBOT_SET!!)``: the launch wants ROBOT set)."""
        if not self.optenv_defaults:
            return ""
        # the first part of the path that is not there: the one that makes it missing
        parts = os.path.normpath(os.path.abspath(path)).split(os.sep)
        missing = next((part for at, part in enumerate(parts) if at and not os.path.exists(
            os.sep.join(parts[:at + 1]) or os.sep)), None)
        for default, name in self.optenv_defaults.items():
            if missing is not None and default in missing:
                return (f" (the path holds {default!r}, the default of $(optenv {name}): "
                        f"{name} is not set here)")
        return ""

    def fail(self, scope: Scope, element: Element, detail: str) -> None:
        """Something roslaunch refuses: an error, and the element is skipped."""
        self.report("LAUNCH_BAD_VALUE", scope, element, detail=detail)

    def resolve(self, raw: str, scope: Scope, element: Element, command: bool = False
                ) -> Value:
        """Substitute ``raw`` in ``scope``; problems become diagnostics, never raise.
        ``command``: ``raw`` is a command line that is never run (``<param command=>``),
        whose program's folder is not needed (``program_not_found``: the package of
        ``$(find xacro)/xacro`` not here is not said)."""
        def find(name: str) -> str | None:
            self.model.package_uses.append(PackageUse(name, self.where(scope, element)))
            found = self.workspace.find(name)
            if found is None and self.models is not None:
                found = self.models.root(name)  # installed on the robot, modelled here
            return found

        def declared(name: str) -> bool:
            # roslaunch makes every ``name:=value`` of its command line an argument of
            # the top-level file (load_sysargs_into_context), declared or not, and
            # pass_all_args hands them on: in a file that gets them (``command_line``)
            # ``$(arg bag_filename)`` with no <arg> (cartographer_ros' demo launches)
            # wants a value from the command line, unset as one declared without a
            # value (LAUNCH_ARG_UNSET), and the text around it stays (dvrk_video's
            # ``ns="$(arg rig_name)/left"`` is ``?/left``, not ``?``)
            return name in scope.arg_names or scope.command_line or (
                scope.include_args is not None and name in scope.outer_arg_names)

        ctx = Context(scope.args, self.environment, find, scope.filename,
                      scope.anon, declared, absence=self.workspace.absence,
                      misspelt=self.workspace.misspelt)
        try:
            result = substitute(raw, ctx)
        except ArgUndefined as err:
            if err.name in scope.arg_names or scope.in_include:
                self.report("LAUNCH_ARG_REQUIRED", scope, element,
                            path=self.relpath(scope.path), name=err.name)
            else:
                self.report("LAUNCH_ARG_UNDEFINED", scope, element, name=err.name)
            return Value.unknown(f"arg {err.name}")
        except SubstitutionError as err:
            self.fail(scope, element, f"\"{raw}\": {err}")
            return Value.unknown(raw)
        left_open = unclosed(raw)
        if left_open is not None:
            self.report("LAUNCH_SUBST_UNCLOSED", scope, element, text=left_open)
        for name in dict.fromkeys(ctx.unset):
            if scope.in_include and not scope.command_line:
                self.report("LAUNCH_ARG_REQUIRED", scope, element,
                            path=self.relpath(scope.path), name=name)
            else:
                self.report("LAUNCH_ARG_UNSET", scope, element, name=name)
        if command:  # never run: its program's folder is not needed (said by tag_param)
            _, program = program_not_found(result)
            ctx.unknown = [r for r in ctx.unknown if r.package not in program]
        for reason in dict.fromkeys(ctx.unknown):
            self.report("LAUNCH_UNKNOWN_VALUE", scope, element, detail=reason.detail)
        for name, default in ctx.defaults_taken:
            if len(default.strip()) >= MIN_HINTED_DEFAULT:
                self.optenv_defaults.setdefault(default.strip(), name)
        for name in dict.fromkeys(ctx.misspelt_packages):
            self.report("PACKAGE_NOT_FOUND", scope, element, name=name,
                        why=self.workspace.absence(name))
        return result

    def value(self, element: Element, attribute: str, scope: Scope, command: bool = False
              ) -> Value | None:
        raw = element.get(attribute)
        return None if raw is None else self.resolve(raw, scope, element, command)

    def text(self, element: Element, attribute: str, scope: Scope) -> str | None:
        value = self.value(element, attribute, scope)
        return None if value is None else value.text

    def flag(self, element: Element, attribute: str, scope: Scope, default: bool
             ) -> bool | None:
        """roslaunch's boolean attribute: true/false in any case; None if not a bool."""
        value = self.value(element, attribute, scope)
        if value is None:
            return default
        if value.literal is None:
            return None
        if value.literal.lower() in ("true", "false"):
            return value.literal.lower() == "true"
        self.fail(scope, element, f"invalid bool value for {attribute}: {value.literal!r}")
        return None

    def check(self, element: Element, scope: Scope) -> bool:
        """Report unknown and missing attributes; False if the element must be skipped.
        The attributes are those of the tag in lower case: roslaunch takes a node's or an
        include's children by their lower-cased name (``<Param name= value=>`` in a
        ``<node>`` sets the parameter, Lslidar's lslidar_ch.launch), and a tag of another
        case anywhere else is unknown before this is asked."""
        tag = str(element.tag)
        allowed = ATTRIBUTES.get(tag.lower(), ())
        for attribute in element.attrib:
            if attribute not in allowed and attribute not in COMMON:
                self.report("LAUNCH_UNKNOWN_ATTRIBUTE", scope, element,
                            attribute=attribute, tag=tag)
        for attribute in REQUIRED.get(tag.lower(), ()):
            if element.get(attribute) is None:
                self.report("LAUNCH_MISSING_ATTRIBUTE", scope, element,
                            tag=tag, attribute=attribute)
                return False
        return True

    def condition(self, element: Element, scope: Scope) -> Scope | None:
        """Apply if/unless: None drops the element, else the scope to use inside it."""
        self.guard = None
        if element.get("if") is not None and element.get("unless") is not None:
            self.report("LAUNCH_IF_AND_UNLESS", scope, element, tag=element.tag)
            return None
        for attribute in COMMON:
            value = self.value(element, attribute, scope)
            if value is None:
                continue
            raw = element.get(attribute, "")
            if value.literal is None:
                self.guard = ros1_condition(raw, attribute, scope.args, None,
                                            self.environment)
                return scope.conditional(raw, attribute, self.where(scope, element))
            truth = value.literal.strip().lower()
            if truth not in ("true", "1", "false", "0"):
                self.fail(scope, element, f"{attribute}=\"{value.literal}\" is not a boolean")
                return None
            holds = (truth in ("true", "1")) == (attribute == "if")
            self.guard = ros1_condition(raw, attribute, scope.args, holds, self.environment)
            if not holds:
                return None
        return scope

    def take_guard(self) -> LaunchCondition | None:
        guard, self.guard = self.guard, None
        return guard

    def skipped(self, element: Element, scope: Scope, guard: LaunchCondition) -> None:
        """A node, include or group a decided condition leaves out: named as written,
        with what it would have started."""
        item = scope.item.add(self.raw_item(element, scope))
        item.condition = guard
        if element.tag == "include":
            self.include_pattern(element, scope, reached=False)
        if element.tag == "group":
            for inner in element.iter("node", "test", "include"):
                if inner is not element and len(item.children) < MAX_SKIPPED:
                    item.add(self.raw_item(inner, scope))
                if inner.tag == "include":
                    self.include_pattern(inner, scope, reached=False)

    def raw_item(self, element: Element, scope: Scope) -> LaunchItem:
        where = self.where(scope, element)
        if element.tag == "include":
            return LaunchItem("include", element.get("file", ""), where, skipped=True)
        if element.tag == "group":
            return LaunchItem("group", element.get("ns", ""), where, skipped=True)
        return LaunchItem("node", element.get("name") or element.get("test-name") or "", where,
                          detail=f"{element.get('pkg', '')}/{element.get('type', '')}",
                          skipped=True)

    # -- traversal ------------------------------------------------------------
    def parse(self, path: str, location: Location) -> Element | None:
        modelled = self.models.launch(path) if self.models is not None else None
        if modelled is not None:  # a launch file of a package not here, as its model has it
            self.model.files.append(self.relpath(path))
            return modelled
        if not os.path.isfile(path):
            self.model.diagnostics.append(diag.make(
                "LAUNCH_FILE_MISSING", location,
                path=self.workspace.relpath(path) + self.unset_hint(path)))
            return None
        data, found = read_bytes(path, self.workspace.location(path))
        self.model.diagnostics.extend(found)
        if data is None:
            return None
        try:
            root = etree.fromstring(as_expat_reads(data), xml_parser())
            start_lines(root, data)
        except etree.XMLSyntaxError as err:
            line, col = err.position if err.position else (0, 0)
            self.model.diagnostics.append(diag.make(
                "LAUNCH_XML_SYNTAX", self.workspace.location(path, line, col), detail=err.msg))
            return None
        if any(isinstance(e, etree._Entity) for e in root.iter()):
            self.model.diagnostics.append(diag.make(
                "LAUNCH_XML_SYNTAX", self.workspace.location(path), detail=(
                    "entity references are not expanded (roslaunch's parser would); "
                    "text that uses them is incomplete")))
        if root.tag != "launch":
            self.model.diagnostics.append(diag.make(
                "LAUNCH_XML_SYNTAX", self.where(path, root),
                detail=f"root element is <{root.tag}>, not <launch>"))
            return None
        self.model.files.append(self.workspace.relpath(path))
        if root.get("deprecated"):
            self.model.diagnostics.append(diag.make(
                "LAUNCH_UNSUPPORTED", self.where(path, root),
                detail=f"deprecated launch file: {root.get('deprecated')}"))
        return root

    def children(self, element: Element, scope: Scope) -> None:
        for child in element:
            if not isinstance(child.tag, str):
                continue
            handler = self.tags.get(child.tag)
            if handler is None:
                self.report("LAUNCH_UNKNOWN_TAG", scope, child, tag=child.tag)
                continue
            inner = self.condition(child, scope)
            if inner is None:
                if self.guard is not None and child.tag in ("node", "test", "include",
                                                            "group"):
                    self.skipped(child, scope, self.guard)
                continue
            if self.check(child, inner):
                params_before = len(self.model.params)
                handler(child, inner)
                if child.tag in ("param", "rosparam"):
                    scope.item.params.extend(param_names(self.model, params_before))
            self.guard = None

    # -- tags -----------------------------------------------------------------
    def tag_param(self, element: Element, scope: Scope, local: bool = False) -> None:
        tags_params.tag_param(self, element, scope, local)

    def tag_rosparam(self, element: Element, scope: Scope, in_node: bool = False) -> None:
        tags_params.tag_rosparam(self, element, scope, in_node)

    def tag_arg(self, element: Element, scope: Scope) -> None:
        name = self.text(element, "name", scope) or ""
        value = self.value(element, "value", scope)
        default = self.value(element, "default", scope)
        self.value(element, "doc", scope)
        if value is not None and default is not None:
            self.fail(scope, element, "<arg> tag must have one and only one of value/default")
            return
        earlier = scope.arg_conditions.get(name, [()])
        # declared before only under conditions that cannot hold with this one's: roslaunch
        # declares one of them, so the argument is either's (one of two values)
        alternative = name in scope.arg_names and all(
            exclusive(conditions, scope.conditions) for conditions in earlier)
        if name in scope.arg_names and not scope.pass_all_args and not alternative:
            self.fail(scope, element, f"arg '{name}' has already been declared")
            return
        if name not in scope.arg_names:
            scope.arg_names.append(name)
            scope.arg_conditions.pop(name, None)
        if scope.conditions:
            scope.arg_conditions.setdefault(name, []).append(scope.conditions)
        target = scope.args if scope.include_args is None else scope.include_args
        if alternative:
            self.alternative_arg(name, scope, element, value, default, target)
            return
        given = name in target
        if value is not None:
            if name in target and not scope.pass_all_args:
                self.fail(scope, element,
                          f"cannot override arg '{name}', which has already been set")
                return
            target[name] = value
        elif default is not None and name not in target:
            target[name] = default
        self.record_arg(name, scope, element, given, value is not None, default is not None)

    def alternative_arg(self, name: str, scope: Scope, element: Element, value: Value | None,
                        default: Value | None, target: dict[str, Value]) -> None:
        """Another declaration of an argument under conditions that exclude the earlier
        ones' (not decided here): its value is the earlier one where they agree, else
        unknown. A default gives way to a value the include or command line passed."""
        written = value if value is not None else default
        recorded = scope.item.arg(name)
        passed = recorded is not None and recorded.origin not in ("value", "default")
        if written is not None and not (value is None and passed):
            before = target.get(name)
            target[name] = written if before == written else Value.unknown(
                f"arg {name}, declared again under {' and '.join(map(str, scope.conditions))}")
        if written is None or (value is None and passed):
            return
        if scope.include_args is not None:  # an <arg> inside an <include>: the one passed
            self.record_arg(name, scope, element, True, True, False)
        else:  # each declaration as written
            scope.item.args.append(LaunchArg(
                name, written.text, "value" if value is not None else "default",
                self.where(scope, element)))

    def record_arg(self, name: str, scope: Scope, element: Element, given: bool,
                   fixed: bool, has_default: bool) -> None:
        """The argument on the tree: passed by an ``<include>``, or declared here."""
        where = self.where(scope, element)
        if scope.include_args is not None:  # an <arg> inside an <include>
            final = scope.include_args.get(name)
            scope.item.args[:] = [a for a in scope.item.args if a.name != name]
            scope.item.args.append(LaunchArg(
                name, final.text if final is not None else None, "include", where))
            return
        if scope.item.arg(name) is not None and not fixed:
            return  # given by the including file or the command line
        final = scope.args.get(name)
        origin: ArgOrigin = "value" if fixed else "unset" if final is None else (
            "default" if has_default and not given else "include")
        scope.item.args.append(LaunchArg(
            name, final.text if final is not None else None, origin, where))

    def tag_group(self, element: Element, scope: Scope) -> None:
        guard = self.take_guard()
        inner = self.ns_clear_params(element, scope)
        if inner is not None:
            inner.private = list(inner.private)
            inner.item = scope.item.add(LaunchItem(
                "group", inner.ns if element.get("ns") else "", self.where(scope, element),
                namespace=inner.ns, condition=guard))
            self.children(element, inner)

    def ns_clear_params(self, element: Element, scope: Scope, node_name: str | None = None,
                        include: str | None = None) -> Scope | None:
        ns = None
        unknowns: tuple[Unknown, ...] = ()
        if element.get("ns") is not None:
            value = self.value(element, "ns", scope)
            ns = value.text if value is not None else None
            if not ns:
                self.fail(scope, element, f"<{element.tag}> tag has an empty 'ns' attribute")
                return None
            unknowns = unknown_parts(value)
        inner = (scope.include_child(ns, include, unknowns) if include is not None
                 else scope.child(ns, unknowns))
        clear = self.flag(element, "clear_params", scope, False)
        if clear:
            if element.tag in ("node", "test"):
                self.model.clear_params.append(global_ns(inner.ns + (node_name or "")))
            elif not ns:
                self.fail(scope, element, "'ns' attribute must be set in order to use "
                                          "'clear_params'")
                return None
            else:
                self.model.clear_params.append(inner.ns)
        return inner

    def tag_remap(self, element: Element, scope: Scope) -> None:
        """A <remap> outside <node> applies to the nodes after it in the same scope."""
        pair = self.remap_pair(element, scope)
        if pair is not None:
            scope.add_remap(pair, self.where(scope, element))
            scope.item.remaps.append(pair)

    def remap_pair(self, element: Element, scope: Scope) -> tuple[str, str] | None:
        source = canonical(self.text(element, "from", scope) or "")
        target = canonical(self.text(element, "to", scope) or "")
        for label, name in (("from", source), ("to", target)):
            if not name:
                self.fail(scope, element, "remap from/to attributes cannot be empty")
                return None
            if not is_legal_name(name):
                self.fail(scope, element, f"remap {label} '{name}' is not a valid ROS name")
                return None
        return source, target

    def tag_env(self, element: Element, scope: Scope) -> None:
        name = self.text(element, "name", scope) or ""
        if not name:
            self.fail(scope, element, "<env>: 'name' attribute must be non-empty")
            return
        scope.env.append((name, self.text(element, "value", scope) or ""))

    def tag_machine(self, element: Element, scope: Scope) -> None:
        name = self.text(element, "name", scope) or ""
        address = self.text(element, "address", scope) or ""
        for attribute in ("env-loader", "user", "password", "timeout", "ssh-port"):
            self.value(element, attribute, scope)
        default = (self.text(element, "default", scope) or "false").lower()
        if default not in ("true", "false", "never"):
            self.fail(scope, element, f"invalid value for 'default': {default}")
            return
        self.model.machines[name] = address
        if default == "true":
            self.default_machine = name

    def tag_node(self, element: Element, scope: Scope) -> None:
        guard = self.take_guard()
        nodes_before, params_before = len(self.model.nodes), len(self.model.params)
        self.launcher = None
        self.node(element, scope)
        for item in node_items(self.model, nodes_before, params_before, guard):
            scope.item.add(item)
        if self.launcher is not None:
            self.child_roslaunch(self.launcher, element, scope, guard)

    def node(self, element: Element, scope: Scope) -> None:
        is_test = element.tag == "test"
        if is_test:
            for attribute in ("respawn", "respawn_delay", "output"):
                if element.get(attribute) is not None:
                    self.fail(scope, element, f"<test> tags cannot have '{attribute}'")
                    return
            test_name = self.text(element, "test-name", scope) or ""
            given = self.value(element, "name", scope)
            name = (given.text if given is not None else "") or test_name
            anonymous: tuple[int, ...] = ()
        else:
            given = self.value(element, "name", scope)
            name = given.text if given is not None else ""
            anonymous = () if given is None else self.anonymous_parts(given)
        if "/" in name:
            self.fail(scope, element, f"node name {name!r} cannot contain a namespace")
            return
        if name and not is_legal_name(name):
            # roslaunch only warns (xmlloader: "illegal <node> name"); roscpp's init
            # refuses the name, rospy warns and runs
            self.report("LAUNCH_NODE_NAME_ILLEGAL", scope, element, name=name)
        inner = self.ns_clear_params(element, scope, node_name=name)
        if inner is None:
            return
        private = inner.child(name)
        private.private = []
        params_before = len(self.model.params)
        package = self.text(element, "pkg", scope) or ""
        executable = self.text(element, "type", scope) or ""
        machine = self.text(element, "machine", scope) or self.default_machine
        args = self.text(element, "args", scope) or ""
        output = self.text(element, "output", scope)
        cwd = self.text(element, "cwd", scope)
        prefix = self.text(element, "launch-prefix", scope)
        required = self.flag(element, "required", scope, False)
        respawn = self.flag(element, "respawn", scope, False)
        delay = self.text(element, "respawn_delay", scope)
        if required and respawn:
            self.fail(scope, element, "respawn and required cannot both be set to true")
            return
        if output not in (None, "log", "screen") and "?" not in output:
            self.fail(scope, element, "output must be one of 'log', 'screen'")
            return
        if cwd == "ros_home":
            cwd = "ROS_HOME"
        if cwd not in (None, "ROS_HOME", "node") and "?" not in cwd:
            self.fail(scope, element, "cwd must be one of 'ROS_HOME', 'node'")
            return
        if not package.strip() or not executable.strip():
            self.fail(scope, element, "package and type must be non-empty")
            return
        remaps = scope.child(None)
        env = scope.child(None)
        for child in element:
            if not isinstance(child.tag, str):
                continue
            tag = child.tag.lower()
            if tag not in ("remap", "param", "rosparam", "env"):
                self.report("LAUNCH_UNKNOWN_TAG", scope, child, tag=child.tag)
                continue
            target = {"remap": scope, "env": env}.get(tag, private)
            inner_child = self.condition(child, target)
            if inner_child is None or not self.check(child, inner_child):
                continue
            if tag == "remap":
                pair = self.remap_pair(child, inner_child)
                if pair is not None:
                    remaps.add_remap(pair, self.where(scope, child))
            elif tag == "param":
                self.tag_param(child, inner_child, local=True)
            elif tag == "rosparam":
                self.tag_rosparam(child, inner_child, in_node=True)
            else:
                self.tag_env(child, env)
        for param in (*scope.private, *private.private):
            tags_params.add_param(self, private.ns + param.name.lstrip("~"), param.value,
                                  param.kind, (*scope.conditions, *param.conditions),
                                  param.location, param.source, param.command)
        full = inner.ns + name
        location = self.where(scope, element)
        self.written_args.update(written_argument_paths(args.split()))
        for path in missing_argument_paths(args.split(), self.workspace):
            self.missing_args.append((location, path, name or executable))
        for key, value in argument_params(args):
            tags_params.add_param(self, private.ns + key, value, scalar_type(value),
                                  scope.conditions, location)
        if name and not is_test:
            # roslaunch refuses two nodes of one name that it starts: certainly so when
            # they are under the same conditions; under conditions that cannot both
            # hold (<group if="$(eval model == 'a')"> and 'b') never; in between the
            # duplicate-node-names query says it is not decided. A name with unknown
            # parts is one name only where they are the same unknowns (``same_unknowns``)
            unknowns = (*inner.ns_unknowns, *unknown_parts(given))
            earlier = self.node_names.setdefault((full, anonymous), [])
            other = next(((where, reached) for where, conditions, parts, reached in earlier
                          if same_conditions(conditions, scope.conditions)
                          and same_unknowns(parts, unknowns)), None)
            if other is not None:
                self.report("LAUNCH_NODE_DUPLICATE", scope, element, name=full,
                            other=self.other_start(other, location, scope.reached_from))
            else:
                earlier.append((location, scope.conditions, unknowns, scope.reached_from))
        if machine and "?" not in machine:
            self.machine_uses.append((machine, self.where(scope, element)))
        try:
            respawn_delay = float(delay) if delay else 0.0
        except ValueError:
            self.fail(scope, element, f"respawn_delay must be a number: {delay!r}")
            respawn_delay = 0.0
        # the parameters given in the <node> element are its own (``ParamDecl.owner``):
        # two instances of one name (``$(anon x)`` of two includes, both ``/x_?`` here)
        # each read theirs
        for given_param in self.model.params[params_before:]:
            if given_param.owner is None:
                given_param.owner = len(self.model.nodes)
        decl = NodeDecl(
            full, package, executable, inner.ns, args, list(remaps.remaps),
            scope.conditions, location, anonymous="$(anon" in element.get("name", ""),
            machine=machine, respawn=bool(respawn), required=bool(required),
            respawn_delay=respawn_delay, output=output, cwd=cwd, launch_prefix=prefix or None,
            env=list(env.env), is_test=is_test, remap_places=dict(remaps.remap_places))
        if not is_test and self.dropped(package, executable) is not None:
            self.launcher = decl  # a program that runs roslaunch: read as an include
            return
        self.model.nodes.append(decl)

    def dropped(self, package: str, executable: str) -> int | None:
        """``child_launch.dropped_words``, once per program."""
        key = (package, executable)
        if key not in self.launchers:
            self.launchers[key] = dropped_words(package, executable, self.workspace)
        return self.launchers[key]

    def child_roslaunch(self, decl: NodeDecl, element: Element, scope: Scope,
                        guard: LaunchCondition | None) -> None:
        """The launch file a node's program runs through roslaunch (``child_launch``):
        read as the top-level file of a roslaunch of its own, in the node's namespace,
        with the ``name:=value`` words of its command line (its remaps and ``__name``
        among them, as roslaunch passes them) as arguments, under the node's conditions.
        A file not known (a word not known, a package not found) stays unknown, said."""
        dropped = self.dropped(decl.package, decl.executable) or 0
        # the script's package is one the file uses, as a node's (a ROS 1 launch's
        # guard is never a package check)
        self.model.package_uses.append(PackageUse(decl.package, decl.location, "node"))
        words = shell_words(decl.args)[dropped:] + [
            f"{a}:={b}" for a, b in decl.remaps] + (
            [f"__name:={decl.name.rsplit('/', 1)[-1]}"] if decl.name else [])
        where = decl.location
        split = launched_file(words)
        if split is None:
            return
        target, mappings = split
        namespace = decl.namespace
        for word in mappings:
            if word.startswith("__ns:=") and UNKNOWN_MARK not in word:
                namespace = global_ns(word[len("__ns:="):])
        path = None
        if not any(UNKNOWN_MARK in word for word in target):
            if len(target) == 1:
                path = target[0] if os.path.isabs(target[0]) else None
            else:
                self.model.package_uses.append(PackageUse(target[0], where))
                root = self.workspace.find(target[0])
                path = find_executable(root, target[1], executable=False) if root else None
        if path is None:
            self.report("LAUNCH_UNKNOWN_VALUE", scope, element, detail=(
                f"the launch file {' '.join(target)!r} that {decl.package}/"
                f"{decl.executable} runs through roslaunch is not found; what it starts "
                "is not read"))
            scope.item.add(LaunchItem("include", " ".join(target), where,
                                      namespace=namespace, condition=guard))
            self.model.unread_includes.append(UnreadInclude(
                " ".join(target), namespace, [], scope.conditions, where))
            return
        args: dict[str, Value] = {}
        for word in mappings:
            key, _, text = word.partition(":=")
            if key.startswith("_") and not key.startswith("__"):
                continue  # a parameter assignment: roslaunch's load_mappings skips it
            args[key] = Value.unknown("roslaunch argument") if UNKNOWN_MARK in text \
                else Value.of(text)
        filename = os.path.abspath(path)
        child = Scope.root(filename, args, namespace)
        child.conditions = scope.conditions
        child.env = list(decl.env)
        child.stack = scope.stack
        child.item = scope.item.add(LaunchItem(
            "file", self.relpath(filename), where, namespace=child.ns,
            condition=guard, args=[LaunchArg(k, v.text,
                                             "command line") for k, v in args.items()]))
        self.load_file(filename, child, element, scope)

    def check_machines(self) -> None:
        """Each node's machine, once every file is loaded, as roslaunch looks it up
        (``assign_machines``): one declared anywhere, after the node too, is known; one
        declared nowhere is an error, unless a file not read (an include whose package
        is not here: PR2's ``$(find pr2_machine)/pr2.machine``; one missing, said once
        where it is included) or a machine whose name
        is not known may declare it: then it is undecided, said once per machine, at
        the first node on it."""
        unread = [u.location for u in self.model.unread_includes] + self.unread_files
        unnamed = any("?" in name for name in self.model.machines)
        undecided: dict[str, list[Location]] = {}
        for machine, where in self.machine_uses:
            if machine in self.model.machines:
                continue
            if not unread and not unnamed:
                self.model.diagnostics.append(diag.make(
                    "LAUNCH_BAD_VALUE", where, detail=f"unknown machine '{machine}'"))
                continue
            undecided.setdefault(machine, []).append(where)
        for machine, nodes in undecided.items():
            places = ", ".join(f"{u.file}:{u.line}" for u in unread[:3]) + (
                f" and {len(unread) - 3} more" if len(unread) > 3 else "")
            why = (f"an include not read ({places})" if unread else "") + (
                " or " if unread and unnamed else "") + (
                "a machine whose name is not known" if unnamed else "")
            others = f" (and {len(nodes) - 1} more nodes)" if len(nodes) > 1 else ""
            self.model.diagnostics.append(diag.make("LAUNCH_UNKNOWN_VALUE", nodes[0], detail=(
                f"machine '{machine}' of this node{others} is declared in no file read; "
                f"{why} may declare it")))

    def check_argument_paths(self) -> None:
        """LAUNCH_NODE_ARG_PATH_MISSING for each path a node's command line names that is
        not there and that no node of the launch writes: a file xacro's ``-o`` makes
        while the launch starts is there for the node given it."""
        for location, path, name in self.missing_args:
            if path not in self.written_args:
                self.model.diagnostics.append(diag.make(
                    "LAUNCH_NODE_ARG_PATH_MISSING", location,
                    path=self.workspace.relpath(path), name=name))

    def tag_include(self, element: Element, scope: Scope) -> None:
        guard = self.take_guard()
        path = self.value(element, "file", scope)
        where = self.where(scope, element)
        relative = None if path is None or path.literal is None or os.path.isabs(
            path.literal) else path.literal
        unheld = self.unheld(path.literal) if path is not None and path.literal else None
        if path is None or path.literal is None or relative is not None or unheld:
            if unheld:
                self.report("LAUNCH_UNKNOWN_VALUE", scope, element, detail=unheld)
            elif relative is not None:
                # roslaunch opens it from the folder it runs in, which no file says (not
                # the folder this tool runs in): what it would start stays unknown
                self.report("LAUNCH_UNKNOWN_VALUE", scope, element, detail=(
                    f"launch file {relative!r} is a relative path, opened from the "
                    "folder roslaunch runs in; it is not read"))
            elif path is None or not found_nowhere(path, environment=True):
                self.report("LAUNCH_UNSUPPORTED", scope, element, detail=(
                    f"include file \"{element.get('file')}\" is not known statically"))
            ns = self.text(element, "ns", scope)
            # what it would start is in that namespace and takes the remaps written
            # before it (``Configuration.remaps``: a remap it takes may be used there)
            scope.item.add(LaunchItem("include", element.get("file", ""), where,
                                      namespace=scope.child(ns).ns, condition=guard,
                                      remaps=list(scope.remaps)))
            self.model.unread_includes.append(UnreadInclude(
                element.get("file", ""), scope.child(ns).ns, list(scope.remaps),
                scope.conditions, where))
            self.unread_include_values(element, scope)
            return
        self.include_pattern(element, scope)
        pass_all = self.flag(element, "pass_all_args", scope, False)
        filename = os.path.abspath(path.literal)
        inner = self.ns_clear_params(element, scope, include=filename)
        if inner is None:
            return
        inner.item = scope.item.add(LaunchItem(
            "file", self.relpath(filename), where, namespace=inner.ns,
            condition=guard))
        inner.reached_from = scope.reached_from if is_upstream(where.file or "") else where
        if pass_all:
            assert inner.include_args is not None
            for name, value in scope.args.items():
                inner.include_args[name] = value
                if name not in inner.arg_names:
                    inner.arg_names.append(name)
                inner.item.args.append(LaunchArg(name, value.text if value is not None
                                                 else None, "include", where))
            inner.pass_all_args = True
        inner.filename = scope.filename  # the include's children substitute as the parent
        for child in element:
            if not isinstance(child.tag, str):
                continue
            tag = child.tag.lower()
            if tag not in ("arg", "env"):
                self.report("LAUNCH_UNKNOWN_TAG", scope, child, tag=child.tag)
                continue
            inner_child = self.condition(child, inner)
            self.guard = None
            if inner_child is not None and self.check(child, inner_child):
                (self.tag_arg if tag == "arg" else self.tag_env)(child, inner)
        inner.filename = filename
        for name in inner.arg_names:
            if inner.include_args is not None and name not in inner.include_args:
                self.fail(scope, element, f"include arg '{name}' must have a value")
                return
        passed = list(inner.enter_include())
        if not self.load_file(filename, inner, element, scope):
            return
        unused = [name for name in passed if name not in inner.arg_names]
        if unused and not inner.pass_all_args:
            self.fail(scope, element, f"unused args ({', '.join(unused)}) for include of "
                                      f"{self.relpath(filename)}")

    def unread_include_values(self, element: Element, scope: Scope) -> None:
        """The values an include not read passes: roslaunch substitutes its ``<arg>``
        and ``<env>`` children in the including file before it reads the file, so an
        ``$(arg x)`` there that nothing declares fails the launch whatever the file is
        (turtlebot3's d435i launch passing ``$(arg image_input)`` with only
        ``iamge_input`` declared, to raw2compressed's launch not in the workspace).
        Substituted for what they say; nothing is recorded of the file not read."""
        inner = scope.include_child(None, scope.filename)
        for child in element:
            if not isinstance(child.tag, str) or child.tag.lower() not in ("arg", "env"):
                continue
            inner_child = self.condition(child, inner)
            self.guard = None
            if inner_child is None or not self.check(child, inner_child):
                continue
            for attribute in ("name", "value", "default"):
                self.value(child, attribute, inner)

    def include_pattern(self, element: Element, scope: Scope, reached: bool = True) -> None:
        """What an include's file would be with any value of the arguments it names
        (each ``$(arg x)`` any text without a ``/``), kept when the file name keeps text
        of its own besides them and the launch suffix: a file it matches is one this
        include reaches for some value (an include of ``$(arg file)`` alone names none).
        An include a condition leaves out (not ``reached``) reaches its file with other
        values of the condition's arguments: kept even when its file names no argument
        (MoveIt's ``sensor_manager.launch.xml`` if ``allow_active_sensing``)."""
        raw = element.get("file", "")
        if reached and "$(arg" not in raw:
            return
        marked = _ARG_SUBSTITUTION.sub(_ANY_MARK, raw)
        before, uses = len(self.model.diagnostics), len(self.model.package_uses)
        value = self.resolve(marked, scope, element)
        del self.model.diagnostics[before:]  # said once, by the include itself
        # nor is a $(find pkg) of this look-up a use of pkg: an include the launch
        # reaches says its own, and one a decided condition leaves out uses nothing,
        # as roslaunch-deps skips it (dingo_bringup's wibotic_connector_can, included
        # only if $(optenv DINGO_WIBOTIC_CHARGER 0))
        del self.model.package_uses[uses:]
        if value.literal is None or (reached and _ANY_MARK not in value.literal):
            return
        path = os.path.abspath(value.literal)
        name = os.path.basename(path)
        for suffix in _LAUNCH_SUFFIXES:
            if name.endswith(suffix):
                name = name[:-len(suffix)]
                break
        if not name.replace(_ANY_MARK, ""):
            return
        self.model.include_patterns.append(
            "".join("[^/]*" if part == _ANY_MARK else re.escape(part)
                    for part in re.split(f"({re.escape(_ANY_MARK)})", path)))

    def load_file(self, path: str, scope: Scope, element: Element | None = None,
                  parent: Scope | None = None) -> bool:
        path = os.path.abspath(path)
        # a file being read again with the arguments it is being read with now recurses
        # for ever; with others, it may end (talos_controller_configuration's
        # send_joint_commands.launch includes itself with subtree "arms", which includes
        # it with "right_arm" and "left_arm", which include nothing): roslaunch keeps no
        # list of the files it reads, so only the depth bounds that
        key = (path, tuple(sorted((name, value.text if value is not None else None)
                                  for name, value in scope.args.items())))
        if key in scope.stack or len(scope.stack) > MAX_INCLUDE_DEPTH \
                or self.includes > MAX_INCLUDES:
            assert parent is not None and element is not None
            self.report("LAUNCH_INCLUDE_CYCLE", parent, element,
                        path=self.relpath(path))
            return False
        self.includes += 1
        modelled = self.models is not None and self.models.holds(path)
        if parent is not None and element is not None and not modelled and \
                not self.workspace.readable(path, self.environment):
            # an included file is read only from the workspace and the installed packages
            # (as <rosparam file>): what it would start stays unknown, not missing
            self.report("LAUNCH_UNKNOWN_VALUE", parent, element, detail=(
                f"launch file {path} is outside the workspace and installed packages; "
                "it is not read"))
            if written_absolute(path, parent.path):
                self.report("LAUNCH_INCLUDE_ABSOLUTE", parent, element, path=path)
            scope.item.kind = "include"  # the include that reached it, not read
            self.unread_files.append(self.where(parent, element))
            return False
        location = self.where(parent, element) if parent else self.workspace.location(path)
        if parent is not None and element is not None and not modelled and \
                not os.path.isfile(path) and (
                note := self.workspace.submodule_note(path)) is not None:
            # in a git submodule not checked out: what it would start stays unknown
            self.report("LAUNCH_UNKNOWN_VALUE", parent, element, detail=note)
            scope.item.kind = "include"  # the include that reached it, not read
            self.unread_files.append(self.where(parent, element))
            return False
        root = self.parse(path, location)
        if root is None:
            if parent is not None and element is not None:
                # a file missing (or not well-formed XML; said by ``parse``): what it
                # would declare, a machine, is not known (omniveyor's pcv_base includes
                # ``$(find omniveyor_mobility)/launch/local.machine``, not in the tree,
                # for its nodes' ``machine="AGV"``)
                self.unread_files.append(self.where(parent, element))
            return False
        scope.path = path
        scope.stack = (*scope.stack, key)
        self.children(root, scope)
        if not modelled:
            self.unused_arguments(path, root)
        return True

    def unused_arguments(self, path: str, root: Element) -> None:
        """Each ``<arg>`` a workspace file declares whose name nothing else in the file
        writes, said where it is declared: LAUNCH_ARG_UNUSED (an info). roslaunch's
        arguments are the file's own (an include gets only those passed to it), so one
        that no ``$(arg)``, ``$(eval)`` or include value of the file names changes
        nothing: Autoware's baumer.launch declared ``brightness`` and never gave it to the
        camera node, which read its own default. Read from the text as written, every
        element's attributes and text but comments, whatever conditions hold, so an
        argument used only where a condition skips is used; nothing is said for a file
        with an ``<include pass_all_args>`` (its arguments go on to the included file)
        or an ``arg()`` of a name made in ``$(eval)``."""
        if path in self.args_looked_at or self.workspace.package_of(path) is None or \
                is_upstream(self.workspace.location(path).file or ""):
            return  # an installed package's file is not the user's to mend
        self.args_looked_at.add(path)
        declared: list[tuple[str, Element]] = []
        written: list[str] = []
        for element in root.iter():
            if not isinstance(element.tag, str):
                continue  # a comment or processing instruction
            parent = element.getparent()
            own = element.tag == "arg" and (parent is None or parent.tag != "include")
            if element.tag == "include" and "pass_all_args" in element.attrib and \
                    element.get("pass_all_args", "").strip().lower() != "false":
                return
            for attribute, value in element.attrib.items():
                if own and attribute == "name":
                    declared.append((str(value), element))
                elif not (element.tag == "arg" and attribute == "name"):
                    written.append(str(value))
            if element.text:
                written.append(element.text)
        if any(re.search(r"\barg\(\s*[^\s'\"]", text) for text in written):
            return  # $(eval arg(name)) of a name made at run time: any may be read
        said: set[str] = set()
        for name, element in declared:
            if name in said or not name or "$(" in name:
                continue
            said.add(name)
            used = re.compile(rf"(?<!\w){re.escape(name)}(?!\w)")
            if not any(used.search(text) for text in written):
                self.report("LAUNCH_ARG_UNUSED", path, element, name=name)


def argument_params(args: str) -> list[tuple[str, Any]]:
    """The private parameters a node's command line sets: roscpp's ``ros::init`` and
    rospy's ``init_node`` take each ``_name:=value`` word (not ``__name:=``) as the
    parameter ``~name``, its value an integer, a real or a boolean when it reads as one
    (``true`` / ``false``, any case), else the text (sciurus17's republish ``args="...
    _image_transport:=compressed"``). A word with a part not known sets a value not
    known (None)."""
    found: list[tuple[str, Any]] = []
    for word in shell_words(args):
        key, sep, text = word.partition(":=")
        if not sep or not key.startswith("_") or key.startswith("__") or len(key) < 2:
            continue
        if UNKNOWN_MARK in key:
            continue
        found.append((key[1:], None if UNKNOWN_MARK in text else _argument_value(text)))
    return found


def _argument_value(text: str) -> Any:
    for convert in (int, float) if "_" not in text else ():  # (Python's ``1_000``)
        try:
            return convert(text)
        except ValueError:
            pass
    truth = {"true": True, "false": False}.get(text.lower())
    return text if truth is None else truth


def load(path: str, workspace: Workspace, args: Mapping[str, str] | None = None,
         environment: Mapping[str, str] | None = None,
         models: ModelledFiles | None = None) -> LaunchModel:
    """Interpret one ROS 1 launch file and what it includes (``models``: the launch
    files of packages not here that their interface models hold)."""
    env = workspace.environment if environment is None else environment
    loader = Ros1Loader(workspace, env, models)
    given = {k: Value.of(v) for k, v in (args or {}).items()}
    scope = Scope.root(os.path.abspath(path), given, env.get("ROS_NAMESPACE", "/"))
    scope.item = LaunchItem("file", workspace.relpath(os.path.abspath(path)),
                            workspace.location(os.path.abspath(path)), namespace=scope.ns,
                            args=[LaunchArg(k, v.text, "command line")
                                  for k, v in given.items()])
    loader.model.tree.append(scope.item)
    loader.load_file(path, scope)
    loader.check_machines()
    loader.check_argument_paths()
    loader.model.args = {k: (v.text if v is not None else None)
                         for k, v in scope.args.items()}
    for name in scope.arg_names:
        loader.model.args.setdefault(name, None)
    return loader.model
