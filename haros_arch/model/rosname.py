"""ROS graph resource names: resolution, remapping and wildcard patterns.

Implements the ROS 1 naming rules (http://wiki.ros.org/Names): a name is global
(``/a/b``), relative (``a/b``, resolved against the node's namespace) or private
(``~a``, resolved against the node's own name). A ``?`` in a name stands for a part that
cannot be known statically; ``RosName.pattern`` turns it into a regular expression that
can be matched against known names.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass

from .values import UNKNOWN_MARK

SEP = "/"
PRIVATE = "~"
# a legal ROS 1 name (rosgraph's is_legal_name, roscpp's names::validate): a letter, "/"
# or "~" first, then letters, digits, "_" and "/"; "?" stands for an unknown part
_LEGAL = re.compile(r"^[~/A-Za-z?][\w/?]*$")


def node_name_joined(name: str) -> str:
    """A node name the code builds as ``/<ns>/<name>`` once a namespace given as a value
    is known, as a namespace written there is taken: ``""`` adds nothing (``name``),
    ``"/robot"`` one slash (``/robot/name``). nav2's ``LifecycleNode(name, ns = "")``;
    the jazzy interface models were written with ``//controller_server``."""
    if name.startswith("//"):
        rest = name.lstrip("/")
        name = rest if "/" not in rest else "/" + rest
    return re.sub(r"/{2,}", "/", name)


def is_legal_name(name: str) -> bool:
    """Whether roscpp and rospy accept ``name`` (the empty name too: the namespace)."""
    return not name or (_LEGAL.match(name) is not None and "//" not in name)


# a token of a ROS 2 name (rcl's rmw_validate_full_topic_name / rcl_validate_topic_name):
# letters, digits and "_", not starting with a digit; a "{substitution}" of such
# characters; in a remap rule's source, a wildcard "*" or "**" (rcl_remap); "?" stands
# for an unknown part
_ROS2_TOKEN = re.compile(r"(?:[A-Za-z_?][\w?]*|\{[\w?]+\}|\?[\w?]*)+", re.ASCII)
# a ROS 2 node name's own part (rmw_validate_node_name): ASCII letters, digits and "_",
# not starting with a digit
_ROS2_NODE_NAME = re.compile(r"[A-Za-z_]\w*", re.ASCII)


def is_ros2_node_name(name: str) -> bool:
    """Whether rcl takes ``name`` as a node's own name (no namespace, no unknown)."""
    return _ROS2_NODE_NAME.fullmatch(name) is not None


def ros2_name_problem(name: str, source: bool = False) -> str | None:
    """Why rcl refuses ``name`` as a topic or service name in a remap rule (``source``:
    the rule's left side, which may be written ``node:name`` and hold ``*`` / ``**``
    tokens), or None when it takes it: not empty; ``~`` only first, then ``/``; tokens of
    letters, digits and ``_`` not starting with a digit, or ``{substitutions}``; no
    ``//`` and no ``/`` at the end."""
    if source and ":" in name:
        node, _, name = name.partition(":")
        if not _ROS2_TOKEN.fullmatch(node):
            return f"the node name {node!r} before ':' is not a legal ROS 2 name"
    if not name:
        return "it is empty"
    rest = name
    if rest.startswith("~"):
        rest = rest[1:]
        if rest and not rest.startswith(SEP):
            return "'~' must be followed by '/'"
    if rest.startswith(SEP):
        rest = rest[1:]
    if not rest:
        return None if name in ("/", "~") else "it ends with '/'"
    if rest.endswith(SEP):
        return "it ends with '/'"
    for token in rest.split(SEP):
        if not token:
            return "it holds '//'"
        if source and token in ("*", "**"):
            continue
        if not _ROS2_TOKEN.fullmatch(token):
            bad = next((c for c in token if not ((c.isascii() and c.isalnum()) or c in "_{}?")),
                       None)
            if bad is not None:
                return f"it holds {bad!r}, which a ROS 2 name may not"
            return f"its part {token!r} starts with a digit or is not a name"
    return None


def clean(name: str) -> str:
    """Collapse repeated slashes and drop a trailing one (except for the root)."""
    name = re.sub(r"/+", "/", name)
    if len(name) > 1 and name.endswith(SEP):
        name = name[:-1]
    return name


def namespace_of(full: str) -> str:
    """The namespace of a full name, with its trailing slash: ``/a/b`` -> ``/a/``."""
    head = full.rsplit(SEP, 1)[0]
    return head + SEP if head else SEP


def as_namespace(ns: str) -> str:
    """Normalise a namespace to the form ``/a/b/`` (the root is ``/``)."""
    ns = clean(SEP + ns.strip() + SEP) if ns.strip() not in ("", SEP) else SEP
    return ns if ns.endswith(SEP) else ns + SEP


def resolve(name: str, namespace: str = SEP, node: str | None = None) -> str:
    """Resolve ``name`` as ROS 1 does for a node named ``node`` in ``namespace``.

    A name that begins with an unknown part stays as written: wholly unknown (``?``: a
    runtime string, VINS-Mono's image topic read from its own YAML file) or a text
    before a known rest (``?/cmd_vel``: C++ ``prefix + "/cmd_vel"``, the prefix not
    known), its value may be global (``/cam0/image_raw``, ``/robot1/cmd_vel``), which
    roscpp, rospy and rcl take as it is on any handle, relative or private, so no
    namespace is known to hold it (its pattern, ``.*/cmd_vel``, matches the names in
    every namespace). A name whose unknown parts come later keeps what is known
    (``scan_?``, ``a/?``: relative, in ``namespace``). The rest after an unknown head is
    cleaned as roscpp cleans what it resolves: ``prefix + "/" + "/ctrl"`` (``?//ctrl``)
    is ``?/ctrl``, which ``/robot_0/ctrl`` matches."""
    if name.startswith(UNKNOWN_MARK):
        return clean(name)
    namespace = as_namespace(namespace)
    if not name:
        return clean(namespace)
    if name.startswith(SEP):
        return clean(name)
    if name.startswith(PRIVATE):
        owner = node if node is not None else namespace
        return clean(owner + SEP + name[1:])
    return clean(namespace + name)


def remap(full: str, remaps: Mapping[str, str]) -> str:
    """Apply resolved remappings (``{from: to}``, both full names) to a full name."""
    return remaps.get(full, full)


def resolve_remaps(
    pairs: list[tuple[str, str]], namespace: str, node: str | None = None,
    first_wins: bool = False,
) -> dict[str, str]:
    """Resolve remapping rules as the node does: both sides in the node's namespace.
    Where two rules name the same source, ROS 1 (roscpp's and rospy's map of them) keeps
    the last; rcl (``first_wins``, ROS 2) applies the first rule that matches a name,
    ``pairs`` being in the order the node is given them."""
    out: dict[str, str] = {}
    for a, b in pairs:
        source = resolve(a, namespace, node)
        if first_wins and source in out:
            continue
        out[source] = resolve(b, namespace, node)
    return out


def pattern_for(full: str) -> str:
    """A regular expression matching the names that a name with ``?`` parts could be.
    A ``?`` may stand for nothing at all: a prefix a parameter or a condition chooses
    is often empty (ros2_controllers' joint_state_broadcaster publishes
    ``prefix + "joint_states"``, its prefix ``"~/"`` or ``""``: ``/joint_states`` by
    default). A ``?`` that is a whole segment, ``/a/?/b``, may also stand for no
    segment: roscpp cleans the ``//`` an empty text leaves (autorally's serial ports
    read ``nodeName + (handle.empty() ? "" : "/" + handle) + "/serialBaud"``, which is
    ``~?/serialBaud``, ``/node/?/serialBaud`` resolved, and ``/node/serialBaud`` when the
    handle is empty). A last segment that is all ``?``, ``/a/?``, is ``/a`` too: an
    image_transport subscriber whose transport is not known subscribes ``<base>/?``,
    which ``raw`` makes the base itself."""
    parts = full.split(UNKNOWN_MARK)
    out = ["^", re.escape(parts[0])]
    after_slash = parts[0].endswith(SEP)
    for at, part in enumerate(parts[1:], 1):
        if after_slash and part.startswith(SEP):
            out.append("(?:.*/)?")  # the segment, and its slash, or nothing
            part = part[1:]
        elif not part and at == len(parts) - 1 and out[-1].endswith(SEP) and (
                "".join(out[1:]) != SEP):
            out[-1] = out[-1][:-1]  # the text before, without its slash
            out.append("(?:/.*)?")  # the last segment and its slash, or nothing
        else:
            out.append(".*")
            after_slash = False
        out.append(re.escape(part))
        if part:
            after_slash = part.endswith(SEP)
    return "".join(out) + "$"


def own_unknown(owner: str, name: str) -> bool:
    """Whether the only unknown parts of a parameter's name are in the name of the node
    ``owner`` whose private parameter it is (``/?/fla_ukf/enable_cam`` of a node in a
    launch ``<group ns="$(arg robot)">`` whose value is not known statically): what the
    launch sets under that node is what the node reads. Not for a node whose own name
    is not known (``/?``, ``/ns/?``): several nodes may have that name in the graph."""
    own = owner.rstrip("/") + "/"
    return UNKNOWN_MARK in own and UNKNOWN_MARK not in own.rstrip("/").rsplit("/", 1)[-1] and (
        name.startswith(own) and UNKNOWN_MARK not in name[len(own):])


@dataclass(frozen=True)
class RosName:
    """A name as written in a call (``given``) and as resolved (``full``)."""

    given: str
    full: str
    namespace: str = SEP

    @classmethod
    def make(
        cls,
        given: str,
        namespace: str = SEP,
        node: str | None = None,
        remaps: Mapping[str, str] | None = None,
    ) -> RosName:
        full = resolve(given, namespace, node)
        if remaps:
            full = remap(full, remaps)
        return cls(given, full, namespace_of(full))

    @property
    def own(self) -> str:
        return self.full.rsplit(SEP, 1)[-1]

    @property
    def is_global(self) -> bool:
        return self.given.startswith(SEP)

    @property
    def is_private(self) -> bool:
        return self.given.startswith(PRIVATE)

    @property
    def is_relative(self) -> bool:
        return not (self.is_global or self.is_private)

    @property
    def is_unresolved(self) -> bool:
        return UNKNOWN_MARK in self.full

    @property
    def pattern(self) -> str:
        return pattern_for(self.full)

    def matches(self, other: str) -> bool:
        """True when the known name ``other`` is one this name could stand for."""
        return re.match(self.pattern, other) is not None

    def __str__(self) -> str:
        return self.full
