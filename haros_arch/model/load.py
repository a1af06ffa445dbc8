"""Rebuild a read-only model from its JSON data (the inverse of ``serialise.to_data``).

Used by ``haros-arch query --model model.json`` and by test fixtures, which may leave
out any field: defaults fill it, and topics, services, actions and parameters that links
name are created when the document does not list them.
"""

from __future__ import annotations

from typing import Any

from ..collector import held_back
from .conditions import Condition
from .diagnostic import Diagnostic
from .launch_tree import item_from_data, use_from_data
from .location import NOWHERE, Location
from .model import Model
from .robot import description_from_data
from .rosname import RosName, namespace_of
from .runtime import (
    LAUNCH_WRITER,
    LINK_CLASSES,
    Action,
    Configuration,
    Link,
    NodeInstance,
    Parameter,
    Resource,
    Service,
    Topic,
)
from .source import (
    JOINED,
    Completeness,
    Dependency,
    Node,
    Package,
    Plugin,
    PrimitiveCall,
    wire_call,
)
from .values import UNKNOWN_MARK

_RESOURCE_OF_KIND: dict[str, type[Resource]] = {
    "publish": Topic, "subscribe": Topic, "server": Service, "client": Service,
    "action-server": Action, "action-client": Action, "read": Parameter,
    "write": Parameter, "declare": Parameter,
}


class ModelDataError(ValueError):
    """The document is not a model this reader understands."""


def location(data: Any) -> Location:
    if not isinstance(data, dict):
        return NOWHERE
    return Location(data.get("package"), data.get("file"), int(data.get("line") or 0),
                    int(data.get("column") or 0))


def conditions(data: Any) -> tuple[Condition, ...]:
    if not data:
        return ()
    found = []
    for item in data or ():
        if isinstance(item, str):
            found.append(Condition(item))
        elif isinstance(item, dict):
            found.append(Condition(str(item.get("text", "")), item.get("kind", "source"),
                                   item.get("statement", "if"), location(item.get("location")),
                                   bool(item.get("program_args", False)),
                                   left if isinstance(left := item.get("args_left"), str)
                                   else None, _held(item.get("parameters")),
                                   _compares(item.get("compares")),
                                   tuple(n for n in item.get("runs") or ()
                                         if isinstance(n, int)),
                                   _constants(item.get("constants")),
                                   _elements(item.get("elements")),
                                   after if isinstance(after := item.get("after_init"), bool)
                                   else None))
    return tuple(found)


def _compares(data: Any) -> tuple[str, tuple[str, ...], bool] | None:
    """A launch condition's (argument, strings, holds when it is one of them) as the
    JSON model writes it."""
    if isinstance(data, list) and len(data) == 3 and isinstance(data[0], str) and (
            isinstance(data[1], list) and all(isinstance(s, str) for s in data[1])
            and isinstance(data[2], bool)):
        return data[0], tuple(data[1]), data[2]
    return None


def _held(data: Any) -> tuple[tuple[str, str], ...] | None:
    """A condition's (local, parameter) pairs as the JSON model lists them."""
    if not isinstance(data, list):
        return None
    found = tuple((str(pair[0]), str(pair[1])) for pair in data
                  if isinstance(pair, list | tuple) and len(pair) == 2)
    return found or None


def _constants(data: Any) -> tuple[tuple[str, int | bool | float | str], ...] | None:
    """A condition's (constant, value) pairs as the JSON model lists them: plain
    values only (integers and bools of the code; an element's value in a graph)."""
    if not isinstance(data, list):
        return None
    found = tuple((str(pair[0]), pair[1]) for pair in data
                  if isinstance(pair, list | tuple) and len(pair) == 2
                  and isinstance(pair[1], int | float | str))
    return found or None


def _elements(data: Any) -> tuple[tuple[str, str, str], ...] | None:
    """A condition's (name, list parameter, field) triples as the JSON model lists
    them."""
    if not isinstance(data, list):
        return None
    found = tuple((item[0], item[1], item[2]) for item in data
                  if isinstance(item, list | tuple) and len(item) == 3
                  and all(isinstance(part, str) for part in item))
    return found or None


def diagnostic_from_data(data: dict[str, Any]) -> Diagnostic:
    also = data.get("also")
    return Diagnostic(str(data.get("code", "")), data.get("severity", "warning"),
                      str(data.get("message", "")), location(data.get("location")),
                      tuple(location(where) for where in also)
                      if isinstance(also, list) else ())


def _program_arg(value: Any) -> int | None:
    """A program argument's index: K > 0 from the front, -K from the end."""
    return value if isinstance(value, int) and not isinstance(value, bool) and (
        0 < abs(value) < 1000) else None


def _name_more(value: Any) -> list[list[str | None]] | None:
    """``PrimitiveCall.name_more``: [parameter, default or None] pairs, each maybe with
    JOINED after (its value continues the ``?`` before), else None."""
    if not isinstance(value, list) or not value or not all(
        isinstance(v, list) and len(v) in (2, 3) and isinstance(v[0], str)
        and (v[1] is None or isinstance(v[1], str)) and v[2:] in ([], [JOINED])
        for v in value
    ):
        return None
    return [list(v) for v in value]


def call_from_data(c: dict[str, Any]) -> PrimitiveCall:
    """A call (a node's ``calls`` entry, or a link's own ``call``) from its data."""
    return PrimitiveCall(c.get("kind", "publish"), str(c.get("name", "")), c.get("type"),
                         c.get("queue_size"), c.get("qos"), bool(c.get("latch", False)),
                         c.get("callback"), conditions(c.get("conditions")),
                         location(c.get("location")),
                         name_param=c.get("name_param"), name_default=c.get("name_default"),
                         default_param=c.get("default_param") if isinstance(
                             c.get("default_param"), str) else None,
                         origin=str(c.get("origin", "source")),
                         has_default=bool(c.get("has_default", False)),
                         default=c.get("default"), searched=bool(c.get("searched", False)),
                         tested=bool(c.get("tested", False)),
                         under=c.get("under") is True,
                         keys_only=c.get("keys_only") is True,
                         struct_member=c.get("struct_member") is True,
                         handle_namespace=c.get("handle_namespace"),
                         root_handle=c.get("root_handle") is True,
                         handle_origin=c.get("handle_origin") if isinstance(
                             c.get("handle_origin"), str) else None,
                         deletes=bool(c.get("deletes", False)),
                         node_name=c.get("node_name"), name_each=c.get("name_each"),
                         program_arg=_program_arg(c.get("program_arg")),
                         name_arg=_program_arg(c.get("name_arg")),
                         name_self=c.get("name_self") is True,
                         name_full=c.get("name_full") is True,
                         name_below=c.get("name_below") if isinstance(
                             c.get("name_below"), str) else None,
                         name_option=c.get("name_option") if isinstance(
                             c.get("name_option"), str) else None,
                         name_option_default=c.get("name_option_default") if isinstance(
                             c.get("name_option_default"), str) else None,
                         name_getopt=c.get("name_getopt") if isinstance(
                             c.get("name_getopt"), str) else None,
                         name_option_null=c.get("name_option_null") is True,
                         name_more=_name_more(c.get("name_more")),
                         transport=c.get("transport"),
                         transport_param=c.get("transport_param") if isinstance(
                             c.get("transport_param"), str) else None,
                         transport_arg=_program_arg(c.get("transport_arg")),
                         transport_default=c.get("transport_default") if isinstance(
                             c.get("transport_default"), str) else None,
                         transport_fixed=c.get("transport_fixed") is True,
                         variable=c.get("variable"),
                         also=c.get("also") if isinstance(c.get("also"), list) else None,
                         queue_size_missing=bool(c.get("queue_size_missing", False)),
                         camera_of=c.get("camera_of"),
                         host_named=c.get("host_named") if isinstance(
                             c.get("host_named"), str) else None,
                         loads=c.get("loads") if isinstance(c.get("loads"), str) else None,
                         argument=c.get("argument") is True,
                         resolved=c.get("resolved") is True,
                         **{name: c[name] for name in _OPTIONAL_TEXTS
                            if isinstance(c.get(name), str)})


# the calls' optional text fields (written only when set): read back as written, so that
# a model reads back whole (``runcache.store`` keeps only such a model)
_OPTIONAL_TEXTS = ("made_in", "built_in", "called_in", "name_member", "stores",
                   "loads_given", "namespace_param", "name_built", "host_handle")


def node_from_data(data: dict[str, Any], package: str) -> Node:
    """A node model (a package's node entry) from its data; also reads interface models."""
    name = str(data.get("name", ""))
    executable = data.get("executable") or name.partition("/")[2] or name
    calls = [call_from_data(c) for c in data.get("calls", ())]
    return Node(data.get("package", package), executable, data.get("kind", "executable"),
                data.get("language", "cpp"), list(data.get("sources", ())), calls,
                data.get("rosname"), conditions(data.get("conditions")),
                location(data.get("location")),
                [str(n) for n in data.get("rosnames", ()) if isinstance(n, str)],
                _completeness(data.get("completeness")),
                [str(r) for r in data.get("completeness_reasons", ()) if isinstance(r, str)],
                data.get("model") if isinstance(data.get("model"), str) else None,
                plugin_class=data.get("plugin_class") if isinstance(
                    data.get("plugin_class"), str) else None,
                plugin_base=data.get("plugin_base") if isinstance(
                    data.get("plugin_base"), str) else None,
                deferred=data.get("deferred") is True,
                aliases=[str(a) for a in data.get("aliases", ()) or () if isinstance(a, str)],
                plugin_loads=[str(a) for a in data.get("plugin_loads", ()) or ()
                              if isinstance(a, str)],
                nodelets=[str(a) for a in data.get("nodelets", ()) or ()
                          if isinstance(a, str)],
                handles_given=_handles_given(data.get("handles_given")),
                local_rules=_handles_given(data.get("local_rules")),
                entry=data.get("entry") if isinstance(data.get("entry"), str) else None)


def _handles_given(value: Any) -> dict[str, list[str]]:
    """A saved node's ``handles_given`` (or ``local_rules``); anything else than text
    lists is none."""
    if not isinstance(value, dict):
        return {}
    return {str(key): [str(v) for v in values if isinstance(v, str)]
            for key, values in value.items() if isinstance(values, list)}


def _completeness(value: Any) -> Completeness:
    """A saved node's completeness; documents without it (older ones) mean complete."""
    if value in ("complete", "partial", "model", "unknown"):
        return value
    return "complete"


def _package(data: dict[str, Any]) -> Package:
    name = str(data.get("name", ""))
    deps = [Dependency(d.get("name", ""), d.get("kind", "depend"), d.get("condition"),
                       d.get("active", True) is not False)
            for d in data.get("dependencies", ()) if isinstance(d, dict)]
    plugins = [Plugin(str(p.get("kind", "")), str(p.get("file", "")))
               for p in data.get("plugins", ()) if isinstance(p, dict)]
    return Package(name, data.get("path", name), data.get("build_type", "unknown"),
                   data.get("version", ""), int(data.get("format", 1)), deps, plugins,
                   [node_from_data(n, name) for n in data.get("nodes", ())],
                   location(data.get("location")))


class _Resources:
    def __init__(self, config: Configuration) -> None:
        self.config = config
        self.by_key: dict[tuple[type[Resource], str], Resource] = {}
        self.by_id: dict[str, Resource] = {}
        # how many resources of a kind carry a name (``/?`` may be many): kept as they
        # are added, so naming the next one costs nothing (counting them each time made
        # loading quadratic in the links that name unlisted or unknown resources)
        self.count: dict[tuple[type[Resource], str], int] = {}
        self.collections: dict[type[Resource], list[Any]] = {
            Topic: config.topics, Service: config.services, Action: config.actions,
            Parameter: config.parameters}

    def add(self, cls: type[Resource], data: dict[str, Any]) -> Resource:
        name = str(data.get("name", ""))
        resource = cls(name, id=data.get("id") or f"{cls.__name__.lower()}:{name}")
        if isinstance(resource, Parameter):
            writers = data.get("writers", ())
            resource.value = data.get("value")
            resource.set_by_launch = LAUNCH_WRITER in writers or bool(data.get("set_by_launch"))
            if resource.set_by_launch:
                resource.launch_type = data.get("type")
                resource.launch_location = location(data.get("location"))
                resource.launch_conditions = conditions(data.get("conditions"))
                setting = data.get("setting")
                resource.setting = setting if isinstance(setting, str) else None
        self.by_key.setdefault((cls, name), resource)
        self.by_id.setdefault(resource.id, resource)
        self.count[(cls, name)] = self.count.get((cls, name), 0) + 1
        self.collections[cls].append(resource)
        return resource

    def get(self, cls: type[Resource], name: str) -> Resource:
        found = self.by_key.get((cls, name))
        if found is not None and (UNKNOWN_MARK not in name or not found.links):
            return found
        same = 1 if (cls, name) in self.by_key else 0
        repeats = self.count.get((cls, name), 0) + same - 1
        suffix = f"#{repeats + 1}" if found is not None else ""
        return self.add(cls, {"name": name, "id": f"{cls.__name__.lower()}:{name}{suffix}"})


def _configuration(data: dict[str, Any], nodes: dict[str, Node],
                   hinted: dict[str, Node]) -> Configuration:
    config = Configuration(str(data.get("name", "")), list(data.get("launch", ())),
                           dict(data.get("args", {})))
    # the node types instances run that no package lists (interface models, hints,
    # commands' arguments), written whole: instances name theirs by ``node_type``
    types = [node_from_data(d, str(d.get("package", "")))
             for d in data.get("node_types") or () if isinstance(d, dict)]
    by_name: dict[str, NodeInstance] = {}
    by_id: dict[str, NodeInstance] = {}
    for item in data.get("nodes", ()):
        name = str(item.get("name", ""))
        own = item.get("node_type")
        instance = NodeInstance(
            name, types[own] if type(own) is int and 0 <= own < len(types) else
            _node_type(nodes, hinted, item.get("node"), item.get("completeness")),
            item.get("id") or f"node:{name}",
            item.get("namespace") or namespace_of(name),
            [tuple(pair) for pair in item.get("remaps", ())], item.get("args", ""),
            conditions(item.get("conditions")), location(item.get("location")),
            origin=str(item.get("origin", "launch")),
            ros_version=int(item.get("ros_version", 1) or 1),
            test=bool(item.get("test", False)),
            hosted=bool(item.get("hosted", False)),
            host_unseen=bool(item.get("host_unseen", False)),
            remaps_applied=[str(n) for n in item.get("remaps_applied") or ()
                            if isinstance(n, str)],
            code_name=code if isinstance(code := item.get("code_name"), str) else None,
            remap_places={str(k): location(v) for k, v in written.items()} if isinstance(
                written := item.get("remap_places"), dict) else {})
        config.nodes.append(instance)
        by_name.setdefault(name, instance)
        by_id.setdefault(instance.id, instance)
    resources = _Resources(config)
    for key, cls in (("topics", Topic), ("services", Service), ("actions", Action),
                     ("parameters", Parameter)):
        for item in data.get(key, ()):
            resources.add(cls, item)
    call_index: dict[int, dict[tuple[str, Location], PrimitiveCall]] = {}
    # names and places repeat over links (instances of one node type): made once each
    names: dict[tuple[str, str], RosName] = {}
    places: dict[tuple[Any, ...], Location] = {}
    for item in data.get("links", ()):
        kind = item.get("kind", "")
        if kind not in LINK_CLASSES:
            raise ModelDataError(f"unknown link kind {kind!r}")
        node_name = str(item.get("node", ""))
        found = by_id.get(str(item.get("node_id", ""))) or by_name.get(node_name)
        if found is not None:
            instance = found
        else:
            instance = NodeInstance(node_name, None, f"node:{node_name}",
                                    namespace_of(node_name))
            config.nodes.append(instance)
            by_name[node_name] = instance
        full = str(item.get("name", ""))
        named = resources.by_id.get(str(item.get("resource", "")))
        resource = named if isinstance(named, _RESOURCE_OF_KIND[kind]) else resources.get(
            _RESOURCE_OF_KIND[kind], full)
        given = str(item.get("given", full))
        rosname = names.get((given, full))
        if rosname is None:
            rosname = names[(given, full)] = RosName(given, full, namespace_of(full))
        link = LINK_CLASSES[kind](
            node=instance, resource=resource, rosname=rosname, type=item.get("type"),
            queue_size=item.get("queue_size"), qos=item.get("qos"),
            latch=bool(item.get("latch", False)),
            conditions=conditions(item.get("conditions")),
            location=_place(item.get("location"), places),
            origin=str(item.get("origin", "source")))
        link.call = _written_call(link, item) or default_call(link, item, call_index)
        instance.links.append(link)
        resource.links.append(link)
        config.links.append(link)
    for key in ("topics", "services", "actions", "parameters"):
        for item in data.get(key, ()):
            owner = resources.by_id.get(str(item.get("id", "")))
            if owner is None:
                continue
            owner.candidates = [resources.by_id[i] for i in item.get("candidates") or ()
                                   if i in resources.by_id]
            whole = resources.by_id.get(str(item.get("read_as_part_of") or ""))
            if isinstance(owner, Parameter) and isinstance(whole, Parameter):
                owner.read_as_part_of = whole
    _wire_calls(config)
    config.package_paths = [str(p) for p in data.get("package_paths", ())]
    config.launch_tree = [item for item in map(item_from_data, data.get("launch_tree") or ())
                          if item is not None]
    config.package_uses = [use for use in map(use_from_data, data.get("package_uses") or ())
                           if use is not None]
    config.robot_descriptions = [
        made for made in map(description_from_data, data.get("robot_descriptions") or ())
        if made is not None]
    for instance in config.nodes:  # a hint-made node type lists what its instances use
        if instance.node is not None and hinted.get(instance.node.name) is instance.node:
            calls = instance.node.calls
            calls.extend(link.call for link in instance.links if link.call is not None
                         and link.origin != "action" and link.call not in calls)
    config.diagnostics = [diagnostic_from_data(d) for d in data.get("diagnostics", ())]
    return config


def _node_type(nodes: dict[str, Node], hinted: dict[str, Node], name: Any,
               completeness: Any = None) -> Node | None:
    """The node type an instance runs. One that no package of the document lists (made
    by a project-file ``nodes:`` hint, an interface model, a container's loader) is made
    again, with the completeness its instance was written with, and its calls are its
    instances' links."""
    if not name:
        return None
    found = nodes.get(str(name)) or hinted.get(str(name))
    if found is None:
        package, _, executable = str(name).partition("/")
        found = hinted[str(name)] = Node(package, executable,
                                         completeness=_completeness(completeness))
    return found


def _place(data: Any, places: dict[tuple[Any, ...], Location]) -> Location:
    """``location(data)``, one object for equal places."""
    if not isinstance(data, dict):
        return NOWHERE
    key = (data.get("package"), data.get("file"), data.get("line"), data.get("column"))
    found = places.get(key)
    if found is None:
        found = places[key] = location(data)
    return found


def default_call(link: Link, data: dict[str, Any],
                 index: dict[int, dict[tuple[str, Location], PrimitiveCall]]
                 ) -> PrimitiveCall | None:
    """The call a link written without its own ``call`` reads back with: its node type's
    first call of its kind and place, else one made from the link (None for an action's
    wire link: ``_wire_calls`` gives it)."""
    return _call_of(link.node, link.kind, link.location, index) or _call_from(
        link, data, link.kind)


def _written_call(link: Link, data: dict[str, Any]) -> PrimitiveCall | None:
    """The call a link's ``call`` names: an index in its node type's calls, or the call
    itself (written when ``default_call`` would not give it back)."""
    own = data.get("call")
    if isinstance(own, dict):
        return call_from_data(own)
    node = link.node.node
    if type(own) is int and node is not None and 0 <= own < len(node.calls):
        return node.calls[own]
    return None


def _call_of(instance: NodeInstance, kind: str, where: Location,
             index: dict[int, dict[tuple[str, Location], PrimitiveCall]]
             ) -> PrimitiveCall | None:
    """The source call a link was made from: same node type, kind and place (the first
    such call; ``index`` holds each node type's calls by kind and place, made once)."""
    node = instance.node
    if node is None:
        return None
    calls = index.get(id(node))
    if calls is None:
        calls = index[id(node)] = {}
        for call in node.calls:
            calls.setdefault((call.kind, call.location), call)
    if kind == "read":
        return calls.get(("read", where)) or calls.get(("declare", where))
    return calls.get((kind, where))


def _call_from(link: Link, data: dict[str, Any], kind: str) -> PrimitiveCall | None:
    """The call of a link that its node type does not list (a configuration hint's, a
    node instance's without a known type), rebuilt from the link as the graph made it.
    Action wire links get theirs from their action's call afterwards (``_wire_calls``)."""
    if link.origin == "action":
        return None
    own = tuple(c for c in link.conditions if c not in link.node.conditions
                ) if link.conditions else ()
    return PrimitiveCall(kind, link.rosname.given, link.type,  # type: ignore[arg-type]
                         link.queue_size, link.qos, link.latch, None, own, link.location,
                         origin=link.origin, deletes=bool(data.get("deletes", False)))


def action_links(config: Configuration) -> dict[tuple[int, Location], list[Link]]:
    """The action links with a call, by node instance and place (for ``wire_call_of``)."""
    actions: dict[tuple[int, Location], list[Link]] = {}
    for link in config.links:
        if link.kind in ("action-server", "action-client") and link.call is not None:
            actions.setdefault((id(link.node), link.location), []).append(link)
    return actions


def wire_call_of(link: Link, actions: dict[tuple[int, Location], list[Link]]
                 ) -> PrimitiveCall | None:
    """The call the graph gives a topic or service link that an action stands for: its
    action call's, under the wire's kind, name and type."""
    action = next((a for a in actions.get((id(link.node), link.location), ())
                   if link.name.startswith(a.name.rstrip("/") + "/")), None)
    if action is None or action.call is None:
        return None
    return wire_call(action.call, link.kind,  # type: ignore[arg-type]
                     link.name, link.type,
                     tuple(c for c in action.conditions if c not in action.node.conditions))


def _wire_calls(config: Configuration) -> None:
    """A wire link of an action read without its call gets it (``wire_call_of``)."""
    actions = action_links(config)
    for link in config.links:
        if link.origin == "action" and link.call is None:
            link.call = wire_call_of(link, actions)


def from_data(data: Any) -> Model:
    """A model from the JSON document ``extract`` writes (schema ``haros-arch/1``)."""
    if not isinstance(data, dict):
        raise ModelDataError("a model document is a JSON object")
    schema = data.get("schema")
    if schema is not None and not str(schema).startswith("haros-arch/"):
        raise ModelDataError(f"unknown schema {schema!r}")
    # the collector would walk every object made so far again and again while hundreds of
    # thousands are made (half the load time of a 300,000-link model): held back
    try:
        with held_back():
            model = Model(str(data.get("project", "")))
            model.packages = [_package(p) for p in data.get("packages", ())]
            nodes = {node.name: node for package in model.packages for node in package.nodes}
            hinted: dict[str, Node] = {}
            model.configurations = [_configuration(c, nodes, hinted)
                                    for c in data.get("configurations", ())]
            model.diagnostics = [diagnostic_from_data(d) for d in data.get("diagnostics", ())]
    except (AttributeError, TypeError, KeyError, ValueError, OverflowError,
            RecursionError) as err:
        # a field of the wrong type (a list where an object belongs, ...): the document is
        # not one extract writes; say so instead of failing inside the reader
        raise ModelDataError(f"not a haros-arch model: a field has the wrong type or shape "
                             f"({type(err).__name__}: {err})") from None
    return model
