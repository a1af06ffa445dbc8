"""ROS 2 names as launch_ros and rcl compute them, and parameters in ROS 2 form.

- A node's namespace: an absolute ``namespace`` is used as it is; a relative one is put
  under the pushed namespace (``PushRosNamespace`` / ``<push-ros-namespace>``); none
  means the pushed namespace, else ``/``. The full name is ``namespace + name``.
- ``--ros-args`` are read as rcl reads them: ``-r``/``--remap from:=to`` (a
  ``node:from:=to`` rule applies only to the node called ``node``; ``__ns`` and
  ``__node``/``__name`` rename the node), ``-p name:=value``, ``--params-file FILE``.
- Parameters are flat, dotted names (``FollowPath.max_vel_x``); nested dicts are
  flattened with ``.``. A parameter file is a YAML document whose keys down to
  ``ros__parameters`` spell a node name pattern (``/**``, ``/**/amcl``, ``amcl``,
  ``robot1: amcl:``); ``*`` matches one name token and ``**`` any number of them, as in
  rcl. A pattern without a leading ``/`` is taken from the root, as rcl does.
- ``ParamDecl.name`` of a ROS 2 parameter is the node's full name, ``/``, and the
  dotted parameter name (``/robot1/controller_server/FollowPath.max_vel_x``); the owner
  node and the dotted name are also kept apart in ``ParamDecl.node`` / ``ParamDecl.key``.
"""

from __future__ import annotations

import copy
import functools
import re
from collections.abc import Hashable, Iterator
from dataclasses import dataclass, field
from typing import Any

import yaml

from ... import safe_yaml
from ...model.values import UNKNOWN_MARK, scalar_type

PARAMS_KEY = "ros__parameters"
MAX_PARAM_DEPTH = 32


def clean_namespace(ns: str) -> str:
    """``a//b/`` -> ``/a/b``; the root is ``/``."""
    ns = re.sub(r"/+", "/", "/" + ns.strip())
    return ns.rstrip("/") or "/"


def node_namespace(pushed: str | None, given: str | None) -> str:
    """The namespace launch_ros gives a node: ``given`` under ``pushed`` unless absolute."""
    if given:
        if given.startswith("/") or not pushed:
            return clean_namespace(given)
        return clean_namespace(pushed + "/" + given)
    return clean_namespace(pushed or "/")


def push_namespace(pushed: str | None, ns: str) -> str:
    """The namespace after ``PushRosNamespace(ns)``."""
    return node_namespace(pushed, ns)


def full_name(namespace: str, name: str) -> str:
    return clean_namespace(namespace + "/" + name)


def with_slash(namespace: str) -> str:
    """The ``/a/b/`` form that ``NodeDecl.namespace`` uses."""
    return namespace if namespace.endswith("/") else namespace + "/"


@dataclass
class RosArgs:
    """What a node's ``--ros-args`` say, as rcl reads them."""

    remaps: list[tuple[str, str]] = field(default_factory=list)
    params: list[tuple[str, str]] = field(default_factory=list)
    params_files: list[str] = field(default_factory=list)
    node_name: str | None = None
    namespace: str | None = None
    ignored: list[str] = field(default_factory=list)


def split_rule(rule: str) -> tuple[str | None, str, str] | None:
    """``[node:]from:=to`` -> (node or None, from, to); None if it is not a rule."""
    if ":=" not in rule:
        return None
    left, right = rule.split(":=", 1)
    node: str | None = None
    # a node prefix is the part before a single ':' (names cannot hold ':')
    if ":" in left:
        node, left = left.split(":", 1)
    return node, left, right


def rules_for(pairs: list[tuple[str, str]], node_name: str | None) -> list[tuple[str, str]]:
    """A node's remapping rules (``remappings``, ``SetRemap``: launch_ros passes each as
    ``-r from:=to``) as rcl takes them for the node called ``node_name``: a rule with a
    node prefix (``docking_server:cmd_vel``) applies to that node alone, without its
    prefix, and to no other; kept as written when the node's name is not known."""
    out: list[tuple[str, str]] = []
    for source, target in pairs:
        node, sep, rest = source.partition(":")
        if not sep or node_name is None or UNKNOWN_MARK in node_name:
            out.append((source, target))
        elif node == node_name:
            out.append((rest, target))
    return out


def parse_ros_args(tokens: list[str], node_name: str | None) -> RosArgs:
    """Read ``tokens`` (after ``--ros-args``) for the node called ``node_name``."""
    out = RosArgs()
    i = 0
    while i < len(tokens):
        token = tokens[i]
        nxt = tokens[i + 1] if i + 1 < len(tokens) else None
        if token in ("-r", "--remap") and nxt is not None:
            rule = split_rule(nxt)
            i += 2
            if rule is None:
                out.ignored.append(nxt)
                continue
            target, src, dst = rule
            if target is not None and node_name is not None and target != node_name:
                continue
            # rcl applies the first rule that matches: a later one renames nothing
            if src == "__ns":
                out.namespace = out.namespace if out.namespace is not None else dst
            elif src in ("__node", "__name"):
                out.node_name = out.node_name if out.node_name is not None else dst
            else:
                out.remaps.append((src, dst))
            continue
        if token in ("-p", "--param") and nxt is not None:
            rule = split_rule(nxt)
            i += 2
            if rule is None:
                out.ignored.append(nxt)
                continue
            target, src, dst = rule
            if target is None or node_name is None or target == node_name:
                out.params.append((src, dst))
            continue
        if token == "--params-file" and nxt is not None:
            out.params_files.append(nxt)
            i += 2
            continue
        if token == "--":
            break
        out.ignored.append(token)
        i += 1
    return out


def split_arguments(args: list[str]) -> tuple[list[str], list[str]]:
    """Split a command line into plain arguments and the ``--ros-args`` part."""
    plain: list[str] = []
    ros: list[str] = []
    inside = False
    for token in args:
        if token == "--ros-args":
            inside = True
        elif inside and token == "--":
            inside = False
        elif inside:
            ros.append(token)
        else:
            plain.append(token)
    return plain, ros


def flatten(values: Any, prefix: str = "", depth: int = 0) -> Iterator[tuple[str, Any]]:
    """``{"a": {"b": 1}}`` -> ``("a.b", 1)``; non-dict values are leaves."""
    if isinstance(values, dict) and depth < MAX_PARAM_DEPTH:
        for key, value in values.items():
            name = f"{prefix}.{key}" if prefix else str(key)
            yield from flatten(value, name, depth + 1)
    elif prefix:
        yield prefix, values


def param_type(value: Any) -> str | None:
    """The ROS 2 parameter type of a value as YAML gives it (None if unknown)."""
    scalar = scalar_type(value)
    if scalar is not None:
        return scalar
    if isinstance(value, (list, tuple)) and value:
        kinds = {param_type(item) for item in value}
        if kinds == {"int", "double"}:
            return "double[]"
        only = next(iter(kinds))
        if len(kinds) == 1 and only is not None and "[]" not in only:
            return f"{only}[]"
    if isinstance(value, (list, tuple)):
        return "str[]" if not value else None
    return None


class ParamFileLoader(yaml.SafeLoader):
    """The safe loader, reading a key given twice in one mapping as rcl reads a parameter
    file (event by event): two mappings merge, key by key (``/**:`` written twice, once
    for ``turtlebot3_node`` and once for ``diff_drive_controller``, gives both); any
    other value given again replaces the first."""

    def construct_mapping(self, node: yaml.MappingNode, deep: bool = False
                          ) -> dict[Any, Any]:
        if not isinstance(node, yaml.MappingNode):
            return super().construct_mapping(node, deep)  # says what is wrong
        self.flatten_mapping(node)
        mapping: dict[Any, Any] = {}
        for key_node, value_node in node.value:
            key = self.construct_object(key_node, deep=True)
            if not isinstance(key, Hashable):
                raise yaml.constructor.ConstructorError(
                    "while constructing a mapping", node.start_mark,
                    "found an unhashable key", key_node.start_mark)
            value = self.construct_object(value_node, deep=True)
            before = mapping.get(key)
            mapping[key] = safe_yaml.merged(before, value) if isinstance(
                before, dict) and isinstance(value, dict) else value
        return mapping


# How rcl_yaml_param_parser types a plain scalar of a parameter file: a bool word, else
# what strtol (base 0) reads whole, else what strtod reads whole (or .inf / .nan), else a
# string. YAML 1.1's resolvers (the safe loader's) differ: ``1e-3``, ``10e9`` and
# ``1.0e5`` (no dot, or an exponent without a sign) are strings there and doubles here
# (bitbots_robot_filter's ``robot_storage_time: 10e9``, read as a double); ``1_000`` and
# ``1:30`` (underscores, sexagesimal) are ints there and strings here; ``08`` is 8.0.
_RCL_INT = re.compile(r"^[-+]?(?:0x[0-9a-fA-F]+|0[0-7]*|[1-9][0-9]*)$")
_RCL_FLOAT = re.compile(r"^(?:[-+]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][-+]?[0-9]+)?"
                        r"|[-+]?\.(?:inf|Inf|INF)|\.(?:nan|NaN|NAN))$")
_YAML_INT = "tag:yaml.org,2002:int"
_YAML_FLOAT = "tag:yaml.org,2002:float"
ParamFileLoader.yaml_implicit_resolvers = {
    first: [(tag, regexp) for tag, regexp in resolvers if tag not in (_YAML_INT, _YAML_FLOAT)]
    for first, resolvers in yaml.SafeLoader.yaml_implicit_resolvers.items()}
ParamFileLoader.add_implicit_resolver(_YAML_INT, _RCL_INT, list("-+0123456789"))
ParamFileLoader.add_implicit_resolver(_YAML_FLOAT, _RCL_FLOAT, list("-+0123456789."))


class RclParamFileLoader(ParamFileLoader):
    """A parameter file as rcl reads it when the node is given its path
    (``--params-file``): its parse_file_events passes over the YAML document start and
    end events, so a file of several documents (``---``) is read as one, their entries
    merged as a key written twice is (ros2-rover's robot_localization.yaml gives its
    local and global EKFs in two documents). launch_ros reads a file itself with
    ``yaml.safe_load``, one document only, when it substitutes in it (allow_substs), when
    the file is a composable node's, and so does a rewrite (nav2's RewrittenYaml):
    ``ParamFileLoader`` there."""

    documents_merged = True


def load_param_file(text: str, loader: type[ParamFileLoader] = ParamFileLoader) -> Any:
    """A ROS 2 parameter file's document (bounded, as ``safe_yaml.load``)."""
    return safe_yaml.load(text, loader)


def yaml_value(text: str) -> Any:
    """A parameter given as text (``-p``, a substitution) is read as YAML, like launch_ros
    (the same text, given to many nodes, is read once; a list comes as a fresh copy)."""
    value = _short_yaml_value(text) if len(text) <= 256 else _yaml_value(text)
    return copy.deepcopy(value) if isinstance(value, list) else value


def _yaml_value(text: str) -> Any:
    try:
        value = safe_yaml.load(text)
    except yaml.YAMLError:
        return text
    if value is None or isinstance(value, dict):
        return text
    return value


_short_yaml_value = functools.lru_cache(maxsize=4096)(_yaml_value)


def node_patterns(document: Any, depth: int = 0,
                  path: tuple[str, ...] = ()) -> Iterator[tuple[str, dict[str, Any]]]:
    """(node name pattern, ros__parameters) pairs of a parameter file."""
    if not isinstance(document, dict) or depth > MAX_PARAM_DEPTH:
        return
    for key, value in document.items():
        if key == PARAMS_KEY:
            if isinstance(value, dict):
                yield clean_namespace("/".join(path)), value
            continue
        yield from node_patterns(value, depth + 1, (*path, str(key)))


def values_outside(document: Any, depth: int = 0, path: tuple[str, ...] = ()) -> list[str]:
    """The keys of a parameter file that hold a value (no mapping) above any
    ``ros__parameters``, as ``a/b/key``: rcl refuses such a file ("Cannot have a value
    before ros__parameters"), and none of those values is a node's parameter."""
    if not isinstance(document, dict) or depth > MAX_PARAM_DEPTH:
        return []
    found: list[str] = []
    for key, value in document.items():
        if key == PARAMS_KEY:
            continue
        if isinstance(value, dict):
            found.extend(values_outside(value, depth + 1, (*path, str(key))))
        else:
            found.append("/".join((*path, str(key))))
    return found


_RCL_INTEGER = re.compile(r"[-+]?(?:0|[1-9][0-9]*)")
_RCL_DOUBLE = re.compile(r"[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?"
                         r"|[-+]?\.(?:inf|Inf|INF)|\.(?:nan|NaN|NAN)")


_RCL_TYPE_NAMES = {"int": "integer", "str": "string"}  # rcl's words for scalar_type's


def _rcl_scalar(value: Any) -> str | None:
    """The type rcl's YAML parser gives a sequence element (bool, integer, double,
    string); None for what it is not sure of (a text our YAML reader kept that rcl may
    read as a number, ``1e3``; a nested value)."""
    kind = scalar_type(value)
    if kind == "str" and (_RCL_INTEGER.fullmatch(value) or _RCL_DOUBLE.fullmatch(value)):
        return None  # a number to rcl, a text to the YAML reader here
    return _RCL_TYPE_NAMES.get(kind, kind) if kind is not None else None


def mixed_sequences(document: Any, depth: int = 0,
                    path: tuple[str, ...] = ()) -> list[tuple[str, str]]:
    """The values of a parameter file that are sequences of elements of more than one
    type to rcl (``[0.01, 0, 0]``: a double, then integers), as ``(key path, the types
    in order of appearance)``: rcl refuses the whole file ("Sequence should be of same
    type"); launch_ros promotes such a list to doubles only in a launch file's own
    dictionaries, not in a file it hands rcl."""
    if not isinstance(document, dict) or depth > MAX_PARAM_DEPTH:
        return []
    found: list[tuple[str, str]] = []
    for key, value in document.items():
        where = (*path, str(key))
        if isinstance(value, dict):
            found.extend(mixed_sequences(value, depth + 1, where))
        elif isinstance(value, list) and len(value) > 1:
            kinds = [_rcl_scalar(item) for item in value]
            seen = [k for k in dict.fromkeys(kinds) if k is not None]
            if len(seen) < len(dict.fromkeys(kinds)):
                continue
            if len(seen) > 1:
                found.append(("/".join(where), " then ".join(seen)))
    return found


def as_component_file(document: Any) -> Any:
    """A parameter file as launch_ros gives it to a composable node: one with no
    ``ros__parameters`` anywhere is the node's parameters whole, its mappings joined by
    dots (``serial: {baudrate: 1}`` is ``serial.baudrate``), where rcl, for a node of its
    own process, refuses it (septentrio_gnss_driver's rover.yaml, loaded into a
    container). Written as the ``/**`` section it stands for; any other file as it is."""
    if isinstance(document, dict) and document and next(
            node_patterns(document), None) is None and not _holds_params_key(document):
        return {"/**": {PARAMS_KEY: document}}
    return document


def _holds_params_key(document: Any, depth: int = 0) -> bool:
    """Whether ``ros__parameters`` is a key at any level (with a value that is no
    mapping, which ``node_patterns`` skips, launch_ros still takes the file as sections)."""
    if not isinstance(document, dict) or depth > MAX_PARAM_DEPTH:
        return False
    return any(key == PARAMS_KEY or _holds_params_key(value, depth + 1)
               for key, value in document.items())


def pattern_matches(pattern: str, node: str) -> bool:
    """rcl's node name matching: ``*`` one token, ``**`` zero or more tokens."""
    if UNKNOWN_MARK in node:
        return False
    regex = ""
    for index, token in enumerate(pattern.strip("/").split("/")):
        if token == "**":
            regex += "(/[^/]+)*"
        elif token == "*":
            regex += "/[^/]+"
        else:
            regex += "/" + re.escape(token) if index or token else ""
    return re.fullmatch(regex or "/", node) is not None


def names_a_node(document: Any) -> bool:
    """True when a parameter file has entries for particular nodes (not only ``/**``)."""
    return any(pattern != "/**" for pattern, _ in node_patterns(document))


def for_every_node(document: Any, node: str) -> set[str]:
    """The names a parameter file's ``/**`` entries give ``node`` that no entry for
    this node's own name sets too: a setting for every node the file is given to."""
    every: set[str] = set()
    own: set[str] = set()
    for pattern, params in node_patterns(document):
        names = {name for name, _ in flatten(params)}
        if pattern == "/**":
            every |= names
        elif pattern_matches(pattern, node):
            own |= names
    return every - own


def params_for_node(document: Any, node: str) -> list[tuple[str, Any]]:
    """The parameters a parameter file gives the node ``node``, in file order.

    Later entries override earlier ones, as rcl applies them in order. For a node whose
    name has unknown parts only the ``/**`` entries are certain to apply.
    """
    found: dict[str, Any] = {}
    for pattern, params in node_patterns(document):
        if pattern == "/**" or pattern_matches(pattern, node):
            for name, value in flatten(params):
                found[name] = value
    return list(found.items())
