"""The ROS calls of the BehaviorTree.CPP nodes a tree host (nav2's bt_navigator) runs.

A BT plugin library registers node classes under tree IDs (``BT_REGISTER_NODES(factory)
{ factory.registerBuilder<ns::ComputePathToPoseAction>("ComputePathToPose", builder); }``
with a builder lambda ``make_unique<ns::ComputePathToPoseAction>(name,
"compute_path_to_pose", config)`` that passes the default action name, or
``factory.registerNodeType<ns::Class>("ID")``). A class derived from nav2's
``BtActionNode<ActionT>`` / ``BtCancelActionNode<ActionT>`` is an action client of
``ActionT`` named by the tag's ``server_name`` port, else the builder's default; one
derived from ``BtServiceNode<ServiceT>`` is a service client named by ``service_name``,
else the name its constructor passes its base. Another class's own
``create_subscription<T>(topic, ...)`` (publisher, service, client) is named by the
literal it passes, or by the input port its variable is read from (``getInput("port",
topic)``): the tag's attribute, else the port's default in ``providedPorts()``. A port
given from the blackboard (``{name}``) is unknown (``?``).

The libraries are those of the CMake library targets whose sources hold
``BT_REGISTER_NODES``, in packages that depend on BehaviorTree.CPP; the trees are the
XML files the host's parameters name (or their defaults in a package's share folder).
A tag whose ID no library read registers, a library or tree that cannot be found or read
make the host instance partial (with a diagnostic), never silently empty.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

from lxml import etree

from .. import diagnostics as diag
from ..cmake import targets_of
from ..diagnostics import Diagnostic
from ..files import read_bytes, read_text
from ..launch.model import NodeDecl
from ..manifest import xml_parser
from ..model.location import Location
from ..model.runtime import Configuration, NodeInstance, Parameter
from ..model.source import PrimitiveCall
from ..model.values import UNKNOWN_MARK
from ..share import share_map, share_source
from ..workspace import Workspace
from .classes import code_only, remembered, with_headers
from .hosts import TREE_HOSTS, TreeHost, tree_host_of

BT_PACKAGES = ("behaviortree_cpp", "behaviortree_cpp_v3")
MAX_TREE_ELEMENTS = 20_000  # per tree file
MAX_LIBRARY_SOURCES = 2_000  # per package

# BehaviorTree.CPP's own nodes (v3 and v4): no ROS calls; and the structure of a file
_BUILTIN_IDS = frozenset((
    "Sequence", "SequenceStar", "SequenceWithMemory", "ReactiveSequence", "Fallback",
    "ReactiveFallback", "Parallel", "ParallelAll", "IfThenElse", "WhileDoElse",
    "ManualSelector", "Switch2", "Switch3", "Switch4", "Switch5", "Switch6", "Inverter",
    "RetryUntilSuccessful", "RetryUntilSuccesful", "Repeat", "ForceSuccess", "ForceFailure",
    "KeepRunningUntilFailure", "Delay", "Timeout", "Precondition", "RunOnce",
    "BlackboardCheckInt", "BlackboardCheckDouble", "BlackboardCheckString",
    "BlackboardCheckBool", "AlwaysSuccess", "AlwaysFailure", "SetBlackboard",
    "UnsetBlackboard", "Sleep", "Script", "ScriptCondition", "SkipUnlessUpdated",
    "WaitValueUpdate", "WasEntryUpdated", "LoopInt", "LoopDouble", "LoopString", "LoopBool",
    "TestNode", "SubTree", "SubTreePlus", "EntryUpdatedAction", "EntryUpdatedDecorator"))
_STRUCTURE = frozenset(("root", "BehaviorTree", "TreeNodesModel"))
_GENERIC_TAGS = frozenset(("Action", "Condition", "Decorator", "Control", "SubTree",
                           "SubTreePlus"))

_BUILDER = re.compile(r"registerBuilder\s*<\s*([\w:]+)\s*>\s*\(\s*\"([^\"]+)\"")
_NODE_TYPE = re.compile(r"registerNodeType\s*<\s*([\w:]+)\s*>\s*\(\s*\"([^\"]+)\"")
# a node made of a function, ``registerSimpleCondition("ID", callback, ports)`` (nav2's
# InitialPoseReceived: a library that registers nothing else)
_SIMPLE = re.compile(r"registerSimple(?:Action|Condition|Decorator)\s*\(\s*\"([^\"]+)\"")
_MADE = re.compile(r"make_(?:unique|shared)\s*<\s*([\w:]+)\s*>\s*\(\s*\w+\s*,\s*\"([^\"]*)\"")
_BASE = r"(?:[\w:]*::)?(BtActionNode|BtCancelActionNode|BtServiceNode)\s*<\s*([\w:]+)\s*>"
_MADE_CALL = re.compile(r"\bcreate_(subscription|publisher|service|client)\s*<\s*([\w:]+)\s*>"
                        r"\s*\(\s*(\"[^\"]*\"|[\w.>\-]+)")
# ``Class::member(`` from the first column, after its return type: a member defined
_MEMBER_DEF = re.compile(r"^(?![\s#/:,])(?:[\w:<>*&]+\s+)*(\w+)\s*::\s*~?\w+\s*\(",
                         re.MULTILINE)
_KIND = {"subscription": "subscribe", "publisher": "publish", "service": "server",
         "client": "client"}


@dataclass
class Registered:
    """A BT node class registered under a tree ID by a library."""

    id: str
    cls: str
    library: str
    location: Location
    default: str | None = None  # the action / service name the builder or base is given
    base: str | None = None  # BtActionNode, BtCancelActionNode, BtServiceNode
    type: str | None = None  # the base's template argument, as an interface name
    # its own calls: kind, type, and where the name comes from: ("literal", name),
    # ("port", port) or ("parameter", parameter of the node, its default); None: unknown
    calls: list[tuple[str, str | None, tuple[str, ...] | None]] = field(default_factory=list)
    ports: dict[str, str] = field(default_factory=dict)  # port defaults (strings)


@dataclass
class Libraries:
    """The BT libraries of the workspace: per library, the IDs it registers."""

    by_library: dict[str, dict[str, Registered]] = field(default_factory=dict)
    by_package: dict[str, list[str]] = field(default_factory=dict)  # package → libraries


# -- as interface model data (``models.format``: a package without source) -----------------


def registered_data(each: Registered) -> dict[str, Any]:
    """A registration as a model document holds it (its library is the key above it)."""
    return {"id": each.id, "class": each.cls,
            "location": {"file": each.location.file, "line": each.location.line},
            "default": each.default, "base": each.base, "type": each.type,
            "calls": [[kind, type_, list(source) if source is not None else None]
                      for kind, type_, source in each.calls],
            "ports": dict(each.ports)}


def registered_from_data(data: Any, library: str, package: str) -> Registered | None:
    """A registration of a model document; None for an entry that is not one."""
    if not isinstance(data, dict) or not isinstance(data.get("id"), str):
        return None
    calls: list[tuple[str, str | None, tuple[str, ...] | None]] = []
    for entry in _listed(data.get("calls")):
        if isinstance(entry, list) and len(entry) == 3 and isinstance(entry[0], str):
            source = tuple("" if p is None else str(p) for p in entry[2]) if isinstance(
                entry[2], list) else None
            calls.append((entry[0], entry[1] if isinstance(entry[1], str) else None, source))
    text = {key: value if isinstance(value := data.get(key), str) else None
            for key in ("class", "default", "base", "type")}
    return Registered(data["id"], text["class"] or "", library,
                      _located(data.get("location"), package), text["default"],
                      text["base"], text["type"], calls,
                      {str(k): str(v) for k, v in _mapping(data.get("ports")).items()})


def tree_data(tree: Tree) -> dict[str, Any]:
    """A tree file as a model document holds it: its tags, the trees it defines, the
    subtrees it runs and what was not read."""
    def tag(each: Tag) -> dict[str, Any]:
        return {"id": each.id, "attributes": dict(each.attributes),
                "location": {"file": each.location.file, "line": each.location.line}}
    return {"tags": [tag(t) for t in tree.tags], "defined": sorted(tree.defined),
            "subtrees": [tag(t) for t in tree.subtrees], "reasons": list(tree.reasons)}


def tree_from_data(data: Any, package: str) -> Tree | None:
    """A tree of a model document; None for an entry that is not one."""
    if not isinstance(data, dict):
        return None

    def tags(entries: Any) -> list[Tag]:
        return [Tag(entry["id"], {str(k): str(v) for k, v in _mapping(
                    entry.get("attributes")).items()},
                    _located(entry.get("location"), package))
                for entry in _listed(entries)
                if isinstance(entry, dict) and isinstance(entry.get("id"), str)]
    return Tree(tags(data.get("tags")), {str(d) for d in _listed(data.get("defined"))},
                tags(data.get("subtrees")), [str(r) for r in _listed(data.get("reasons"))])


def _mapping(value: Any) -> dict[Any, Any]:
    return value if isinstance(value, dict) else {}


def _listed(value: Any) -> list[Any]:
    return value if isinstance(value, list) else []


def _located(value: Any, package: str) -> Location:
    where = _mapping(value)
    line = where.get("line")
    return Location(package=package, file=str(where.get("file") or "") or None,
                    line=line if isinstance(line, int) and not isinstance(line, bool) else 0)


def package_model_data(package: str, workspace: Workspace) -> tuple[
        dict[str, list[dict[str, Any]]], dict[str, dict[str, Any]]]:
    """What an interface model of ``package`` holds of behavior trees: the BT libraries it
    builds (library -> registrations) and, for a tree host's package, the default trees
    in its share folder (share path -> tree), read as the graph reads them."""
    known = libraries(workspace)
    found_libraries = {name: [registered_data(each) for each in known.by_library[name].values()]
                       for name in known.by_package.get(package, [])}
    trees: dict[str, dict[str, Any]] = {}
    owner = workspace.packages.get(package)
    for host in TREE_HOSTS:
        for _parameter, share, relative in host.trees:
            if share != package or owner is None or relative in trees:
                continue
            path = share_map(owner, workspace).get(relative)
            read = read_tree(path, workspace, []) if path else None
            if read is not None:
                trees[relative] = tree_data(read)
    return found_libraries, trees


def interface_name(cpp: str) -> str | None:
    """``nav2_msgs::action::Spin`` → ``nav2_msgs/action/Spin``."""
    parts = [p for p in cpp.strip().lstrip(":").split("::") if p]
    return "/".join(parts) if len(parts) == 3 else None


def libraries(workspace: Workspace) -> Libraries:
    """Every BT library of the workspace's packages that depend on BehaviorTree.CPP (read
    once per run)."""
    return remembered("behavior tree libraries", "", workspace, lambda: _libraries(workspace))


def _libraries(workspace: Workspace) -> Libraries:
    found = Libraries()
    using = _using_bt(workspace)
    for package in workspace.packages.values():
        if package.name not in using:
            continue
        targets, _ = targets_of(package, workspace)
        for target in targets:
            if target.kind != "library":
                continue
            registered: dict[str, Registered] = {}
            for source in target.sources[:MAX_LIBRARY_SOURCES]:
                path = source if os.path.isabs(source) else os.path.join(package.root, source)
                if path.endswith((".cpp", ".cc", ".cxx")) and os.path.isfile(path):
                    for each in _registrations(path, target.output_name or target.name,
                                               workspace):
                        registered.setdefault(each.id, each)
            if registered:
                name = target.output_name or target.name
                found.by_library.setdefault(name, registered)
                found.by_package.setdefault(package.name, []).append(name)
    return found


def _using_bt(workspace: Workspace) -> set[str]:
    """The workspace packages that depend on BehaviorTree.CPP, directly or through other
    workspace packages (PlanSys2's plansys2_bt_example builds its tree nodes' libraries
    with plansys2_bt_actions, which depends on behaviortree_cpp)."""
    using: set[str] = set()
    changed = True
    while changed:
        changed = False
        for package in workspace.packages.values():
            if package.name not in using and any(
                    d.name in BT_PACKAGES or d.name in using for d in package.dependencies):
                using.add(package.name)
                changed = True
    return using


def _registrations(path: str, library: str, workspace: Workspace) -> list[Registered]:
    text, _ = read_text(path, workspace.location(path))
    if not text or "BT_REGISTER_NODES" not in text:
        return []
    code = code_only(text, literals=True)
    made = {cls.lstrip(":"): name for cls, name in _MADE.findall(code)}
    headers = with_headers(workspace.relpath(path), workspace)
    everything = "\n".join(code_only(t, literals=True) for t in headers)
    out: list[Registered] = []
    for pattern in (_BUILDER, _NODE_TYPE):
        for match in pattern.finditer(code):
            cls = match.group(1).lstrip(":")
            line = code.count("\n", 0, match.start()) + 1
            each = Registered(match.group(2), cls, library, workspace.location(path, line, 0),
                              made.get(cls) if pattern is _BUILDER else None)
            _read_class(each, code, everything)
            out.append(each)
    for match in _SIMPLE.finditer(code):
        # no class: its calls are those of the file that no registered class owns
        line = code.count("\n", 0, match.start()) + 1
        each = Registered(match.group(1), "", library, workspace.location(path, line, 0))
        _own_calls(each, code, everything, None)
        out.append(each)
    return out


def _read_class(each: Registered, code: str, everything: str) -> None:
    """The class's nav2 base and its own calls, from its file and the headers it includes."""
    short = each.cls.rsplit("::", 1)[-1]
    base = re.search(rf"\bclass\s+{short}\s*(?:final\s*)?:\s*(?:public\s+)?{_BASE}",
                     everything)
    if base is not None:
        each.base, each.type = base.group(1), interface_name(base.group(2))
        if each.base == "BtServiceNode" and each.default is None:
            passed = re.search(rf"{short}\s*::\s*{short}\s*\([^{{]*?BtServiceNode\s*<[^>]*>"
                               r"\s*\(\s*\w+\s*,\s*\w+\s*,\s*\"([^\"]*)\"", code)
            each.default = passed.group(1) if passed else None
        return
    # InputPort<std::string>(name, default, description): a default only where a
    # description follows it (with two arguments the second is the description)
    for port, default in re.findall(
            r"InputPort\s*<\s*std::string\s*>\s*\(\s*\"(\w+)\"\s*,\s*"
            r"(?:std::string\s*\(\s*)?\"([^\"]*)\"\s*(?:\)\s*)?,\s*\"", everything):
        each.ports.setdefault(port, default)
    _own_calls(each, code, everything, short)


def _own_calls(each: Registered, code: str, everything: str, short: str | None) -> None:
    """The ``create_*`` calls of the file that are the class ``short``'s (or, for a
    function's node, None, that no registered class owns)."""
    owners = [(m.start(), m.group(1)) for m in _MEMBER_DEF.finditer(code)]
    for made in _MADE_CALL.finditer(code):
        owner = next((name for start, name in reversed(owners) if start < made.start()), None)
        if owner is not None and owner != short and owner in _classes_of(code):
            continue  # another registered class's code in the same file
        kind, cpp, given = _KIND[made.group(1)], made.group(2), made.group(3)
        if "::" not in cpp:  # an alias: ``using Trigger = std_srvs::srv::Trigger;``
            alias = re.search(rf"\busing\s+{re.escape(cpp)}\s*=\s*([\w:]+)\s*;", everything)
            cpp = alias.group(1) if alias else cpp
        source = ("literal", given[1:-1]) if given.startswith('"') else _name_source(
            given.split(".")[-1].split(">")[-1], code)
        each.calls.append((kind, interface_name(cpp), source))


def _name_source(variable: str, code: str, depth: int = 3) -> tuple[str, ...] | None:
    """Where a variable's value comes from: the input port ``getInput("port", variable)``
    reads, or the node parameter ``get_parameter_or("name", variable, "default")`` reads
    (nav2's GoalUpdater), also through the variable it is assigned from
    (``topic_name_ = topic_new;``); None when not known."""
    for _ in range(depth):
        name = re.escape(variable)
        read = re.search(rf"getInput\s*(?:<[^>]*>)?\s*\(\s*\"(\w+)\"\s*,\s*{name}\s*\)",
                         code)
        if read is not None:
            return ("port", read.group(1))
        parameter = re.search(r"get_parameter_or\s*(?:<[^>]*>)?\s*\(\s*\"([\w.]+)\"\s*,\s*"
                              rf"{name}\s*,\s*(?:std::string\s*\(\s*)?\"([^\"]*)\"", code)
        if parameter is not None:
            return ("parameter", parameter.group(1), parameter.group(2))
        assigned = re.findall(rf"(?<![\w.>]){re.escape(variable)}\s*=\s*(\w+)\s*;", code)
        if len(set(assigned)) != 1:
            return None
        variable = assigned[0]
    return None


def _classes_of(code: str) -> set[str]:
    """The short names of the classes a file registers."""
    return {cls.rsplit("::", 1)[-1] for pattern in (_BUILDER, _NODE_TYPE)
            for cls, _ in pattern.findall(code)}


# -- trees --------------------------------------------------------------------------------


@dataclass(frozen=True)
class Tag:
    id: str
    attributes: Mapping[str, str]
    location: Location


@dataclass
class Tree:
    """What the files of one tree hold: node tags, the trees they define, the subtrees
    they run, and what could not be read (reasons)."""

    tags: list[Tag] = field(default_factory=list)
    defined: set[str] = field(default_factory=set)
    subtrees: list[Tag] = field(default_factory=list)
    reasons: list[str] = field(default_factory=list)


MAX_INCLUDES = 32  # files read for one tree (its includes, theirs, ...)


def read_tree(path: str, workspace: Workspace, found: list[Diagnostic]) -> Tree | None:
    """The tree of a file and of the files it includes (``<include path="..."/>``,
    relative to the including file as BehaviorTree.CPP reads it); None when the file
    itself cannot be read (a diagnostic says why)."""
    tree = Tree()
    waiting: list[str] = [path]
    seen: set[str] = set()
    while waiting and len(seen) < MAX_INCLUDES:
        each = os.path.realpath(waiting.pop(0))
        if each in seen:
            continue
        seen.add(each)
        includes = _read_file(each, workspace, found, tree)
        if includes is None:
            if each == os.path.realpath(path):
                return None
            tree.reasons.append(f"behavior tree {workspace.relpath(each)} cannot be read")
            continue
        for element, line in includes:
            given = element.get("path", "")
            target = os.path.normpath(os.path.join(os.path.dirname(each), given))
            if not given or element.get("ros_pkg") or not (
                    os.path.isfile(target) and workspace.readable(target)):
                tree.reasons.append(f"behavior tree include {given or '?'} not read "
                                    f"({workspace.relpath(each)}:{line})")
                continue
            waiting.append(target)
    if waiting:
        tree.reasons.append(f"behavior tree includes beyond {MAX_INCLUDES} files not read")
    return tree


def _read_file(path: str, workspace: Workspace, found: list[Diagnostic],
               tree: Tree) -> list[tuple[etree._Element, int]] | None:
    """Add one file's tags to ``tree``; its include elements, None when not read."""
    where = workspace.location(path)
    data, problems = read_bytes(path, where)
    found.extend(problems)
    if data is None:
        return None
    try:
        root = etree.fromstring(data, xml_parser())
    except etree.XMLSyntaxError as err:
        line, column = err.position if err.position else (0, 0)
        found.append(diag.make("BT_XML_SYNTAX", workspace.location(path, line, column),
                               detail=err.msg))
        return None
    includes: list[tuple[etree._Element, int]] = []
    for element in _elements(root):
        tag = element.tag
        if not isinstance(tag, str):
            continue
        line = element.sourceline if isinstance(element.sourceline, int) else 0
        if tag == "include":
            includes.append((element, line))
            continue
        if tag == "BehaviorTree":
            tree.defined.add(element.get("ID", ""))
        if tag in _STRUCTURE:
            continue
        ident = element.get("ID", "") if tag in _GENERIC_TAGS else tag
        attributes = {str(k): str(v) for k, v in element.attrib.items()}
        if tag in ("SubTree", "SubTreePlus"):
            tree.subtrees.append(Tag(ident, attributes, workspace.location(path, line, 0)))
            continue
        if not ident or ident in _BUILTIN_IDS:
            continue
        tree.tags.append(Tag(ident, attributes, workspace.location(path, line, 0)))
        if len(tree.tags) >= MAX_TREE_ELEMENTS:
            tree.reasons.append(f"behavior tree {workspace.relpath(path)}: more than "
                                f"{MAX_TREE_ELEMENTS} nodes, the rest not read")
            break
    return includes


def _elements(root: etree._Element) -> Iterator[etree._Element]:
    """Every element but those of ``TreeNodesModel`` (a description, not a tree)."""
    stack = [root]
    while stack:
        element = stack.pop()
        yield element
        if element.tag != "TreeNodesModel":
            stack.extend(reversed(list(element)))


# -- the host instances ---------------------------------------------------------------------


def attach(config: Configuration, started: Sequence[tuple[NodeDecl, NodeInstance]],
           params: Any, workspace: Workspace, partial: Any,
           models: Callable[[str], Any] | None = None,
           ) -> list[tuple[NodeInstance, list[PrimitiveCall]]]:
    """The calls of the tree nodes each tree host instance runs; ``partial(instance,
    reason)`` marks an instance whose trees are not wholly known. ``models``: a package
    without source to its interface model (``models.format.InterfaceModel``), whose BT
    libraries and default trees stand for its source (nav2_behavior_tree's nodes and
    nav2_bt_navigator's trees where navigation2 is installed, not in the workspace)."""
    out: list[tuple[NodeInstance, list[PrimitiveCall]]] = []
    for decl, instance in started:
        host = tree_host_of(decl.package, decl.executable, decl.ros_version)
        if host is None:
            continue
        calls, reasons = _host_calls(host, instance, params, workspace, config.diagnostics,
                                     models)
        for reason in reversed(reasons[:5]):  # each goes first: the first stays first
            partial(instance, reason)
        out.append((instance, calls))
    return out


def _param(params: Any, name: str) -> Parameter | None:
    found = params.by_name.get((Parameter, name))
    return found if isinstance(found, Parameter) and found.set_by_launch else None


def _host_calls(host: TreeHost, instance: NodeInstance, params: Any, workspace: Workspace,
                found: list[Diagnostic], models: Callable[[str], Any] | None = None,
                ) -> tuple[list[PrimitiveCall], list[str]]:
    base = instance.name.rstrip("/") + "/"
    reasons: list[str] = []
    known = libraries(workspace)
    registered: dict[str, Registered] = {}
    modelled: dict[str, dict[str, Registered]] = {}  # the builtin packages' models' libraries
    for package in host.builtin:
        if package not in workspace.packages:
            from_model = _model_libraries(package, models)
            if from_model is None:
                reasons.append(f"behavior tree nodes of {package}: no source in the "
                               "workspace, their calls are not known")
            modelled.update(from_model or {})
            for library_ids in (from_model or {}).values():
                for ident, each in library_ids.items():
                    registered.setdefault(ident, each)
        for built in known.by_library.keys() & set(known.by_package.get(package, [])):
            for ident, each in known.by_library[built].items():
                registered.setdefault(ident, each)
    listed = _param(params, base + host.libraries)
    if listed is not None:
        names = listed.value if isinstance(listed.value, list) else [listed.value]
        for entry in names[:200]:
            if not isinstance(entry, str) or UNKNOWN_MARK in entry:
                reasons.append(f"{host.libraries}: a library not known statically")
                continue
            library = known.by_library.get(entry) or modelled.get(entry)
            if library is None:
                found.append(diag.make("BT_LIBRARY_NOT_FOUND", listed.launch_location,
                                       library=entry, host=instance.name))
                where = listed.launch_location
                reasons.append(f"behavior tree library {entry} not found "
                               f"({where.file}:{where.line})")
                continue
            for ident, each in library.items():
                registered.setdefault(ident, each)
    reasons.extend(_other_navigators(host, base, params))
    running = _listed_navigators(host, base, params)
    calls: list[PrimitiveCall] = []
    seen: set[tuple[str, str, str | None, str | None]] = set()
    for index, (parameter, package, relative) in enumerate(host.trees):
        runner = host.tree_navigators[index] if index < len(host.tree_navigators) else ""
        if runner and running is not None and runner not in running:
            continue  # its navigator is not in the host's list: the tree is not run
        given = _param(params, base + parameter)
        path = _tree_path(given, package, relative, workspace)
        read: Tree | None = None
        if path is None and given is None and package not in workspace.packages:
            read = _model_tree(package, relative, models)  # the default, as modelled
        if path is None and read is None:
            what = given.value if given is not None else f"{package}/{relative}"
            reasons.append(f"behavior tree {parameter} ({what}) not found or not known"
                           if given is not None or package else
                           f"behavior tree {parameter} not set: the tree is not known")
            if given is not None and isinstance(given.value, str) \
                    and UNKNOWN_MARK not in given.value:
                found.append(diag.make("BT_TREE_NOT_FOUND", given.launch_location,
                                       path=given.value, host=instance.name))
            continue
        if read is None and path is not None:
            read = read_tree(path, workspace, found)
            if read is None:
                reasons.append(f"behavior tree {workspace.relpath(path)} cannot be read")
        if read is None:
            continue
        reasons.extend(read.reasons)
        for subtree in read.subtrees:
            if subtree.id not in read.defined:
                where = subtree.location
                reasons.append(f"behavior subtree {subtree.id or '?'} not defined in the "
                               f"files read ({where.file}:{where.line})")
        for tag in read.tags:
            chosen = registered.get(tag.id)
            if chosen is None:
                found.append(diag.make("BT_NODE_UNKNOWN", tag.location, id=tag.id,
                                       host=instance.name))
                reasons.append(f"behavior tree node {tag.id} has no registered class found "
                               f"({tag.location.file}:{tag.location.line})")
                continue
            for call in _tag_calls(tag, chosen):
                key = (call.kind, call.name, call.type, call.name_param)
                if key not in seen:
                    seen.add(key)
                    calls.append(call)
    return calls, list(dict.fromkeys(reasons))


def _model_libraries(package: str, models: Callable[[str], Any] | None
                     ) -> dict[str, dict[str, Registered]] | None:
    """The BT libraries of a package's interface model (library -> ID -> class); None
    when it has no model, or one without them."""
    model = models(package) if models is not None else None
    data = getattr(model, "bt_libraries", None)
    if not data:
        return None
    out: dict[str, dict[str, Registered]] = {}
    for library, entries in data.items():
        for entry in entries:
            each = registered_from_data(entry, library, package)
            if each is not None:
                out.setdefault(library, {}).setdefault(each.id, each)
    return out


def _model_tree(package: str, relative: str, models: Callable[[str], Any] | None
                ) -> Tree | None:
    """A tree host's default tree ``relative`` in the share folder of ``package``, as its
    interface model holds it; None when it holds none."""
    model = models(package) if models is not None else None
    data = getattr(model, "bt_trees", None) or {}
    return tree_from_data(data.get(relative), package) if relative in data else None


def _navigators(host: TreeHost, base: str, params: Any
                ) -> list[tuple[str | None, Any, Location]] | None:
    """The navigators the host's list names, each with its id (None when not known
    statically), its class (``<id>.plugin``, the default class for a default id; a
    lookup name ``pkg/Class`` as the class) and where the launch files give it; None
    when the list is not set (the host's defaults run)."""
    if host.navigators is None:
        return None
    parameter, known = host.navigators
    listed = _param(params, base + parameter)
    if listed is None:
        return None
    ids = listed.value if isinstance(listed.value, list) else [listed.value]
    out: list[tuple[str | None, Any, Location]] = []
    for ident in ids[:200]:
        if not isinstance(ident, str) or UNKNOWN_MARK in ident:
            out.append((None, None, listed.launch_location))
            continue
        typed = _param(params, f"{base}{ident}.plugin")
        cls = typed.value if typed is not None else dict(known).get(ident)
        if isinstance(cls, str):
            cls = cls.replace("/", "::")
        out.append((ident, cls, (typed or listed).launch_location))
    return out


def _listed_navigators(host: TreeHost, base: str, params: Any) -> set[str] | None:
    """The classes of the navigators the host's list names; None when the list is not
    set (the host's defaults run) or names one not known statically (any may)."""
    listed = _navigators(host, base, params)
    if listed is None:
        return None
    out: set[str] = set()
    for ident, cls, _where in listed:
        if ident is None or not isinstance(cls, str) or UNKNOWN_MARK in cls:
            return None
        out.add(cls)
    return out


def _other_navigators(host: TreeHost, base: str, params: Any) -> list[str]:
    """Why the host runs trees not read: a navigator of its list that is not one whose
    trees the row names."""
    listed = _navigators(host, base, params)
    if listed is None or host.navigators is None:
        return []
    parameter, known = host.navigators
    out = []
    for ident, cls, where in listed:
        if ident is None:
            out.append(f"{parameter}: a navigator not known statically")
        elif (ident, cls) not in known and cls not in dict(known).values():
            out.append(f"navigator {ident} ({cls or '?'}) runs behavior trees not read "
                       f"({where.file}:{where.line})")
    return out


def _tree_path(given: Parameter | None, package: str, relative: str,
               workspace: Workspace) -> str | None:
    if given is None:
        owner = workspace.packages.get(package) if package else None
        return share_map(owner, workspace).get(relative) if owner is not None else None
    value = given.value
    if not isinstance(value, str) or UNKNOWN_MARK in value or not os.path.isabs(value):
        return None
    path = value if os.path.isfile(value) else share_source(workspace, value)
    return path if os.path.isfile(path) and workspace.readable(path) else None


def _port(tag: Tag, port: str, default: str | None) -> str:
    """A string port's value: the tag's literal, ``?`` from the blackboard, else the
    default (``?`` when there is none)."""
    value = tag.attributes.get(port)
    if value is None:
        return default if default else UNKNOWN_MARK
    return UNKNOWN_MARK if "{" in value else value


def _tag_calls(tag: Tag, each: Registered) -> list[PrimitiveCall]:
    if each.base in ("BtActionNode", "BtCancelActionNode"):
        return [PrimitiveCall("action-client", _port(tag, "server_name", each.default),
                              each.type, location=tag.location, origin="plugin")]
    if each.base == "BtServiceNode":
        return [PrimitiveCall("client", _port(tag, "service_name", each.default), each.type,
                              location=tag.location, origin="plugin")]
    out = []
    for kind, type_, source in each.calls:
        if source is not None and source[0] == "parameter":
            # named by the node's parameter (the graph puts in its value, else the
            # default), which the node reads
            out.append(PrimitiveCall(kind, UNKNOWN_MARK, type_,  # type: ignore[arg-type]
                                     location=tag.location, origin="plugin",
                                     name_param=source[1], name_default=source[2]))
            out.append(PrimitiveCall("read", source[1], "string", location=tag.location,
                                     origin="plugin", has_default=True, default=source[2]))
            continue
        name = source[1] if source is not None and source[0] == "literal" else (
            _port(tag, source[1], each.ports.get(source[1])) if source else UNKNOWN_MARK)
        out.append(PrimitiveCall(kind, name, type_, location=tag.location,  # type: ignore[arg-type]
                                 origin="plugin"))
    return out
