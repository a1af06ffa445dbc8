"""Several ROS 2 nodes in one process: one node instance each.

A ROS 2 launch ``Node`` without ``name=`` runs its executable's node under the name the
code gives it (``rclcpp::Node("talker")``, ``rclpy.create_node("talker")``): the
instance takes that name, in the launch namespace, and the parameters the launch file
gave the unnamed node (``/ns/?``) go to it. Without its code (nor an interface model)
the executable's name stands in, as packages usually name the two alike; that is a
guess, and ``guessed_names`` says so for each.

An rclpy executable that creates two nodes (two ``Node`` subclasses added to one
executor, ``create_node`` called twice) has them in ``Node.rosnames``, and each of its
calls names the node it is made on (``PrimitiveCall.node_name``); the calls made on a node
the code does not tell (a class built by two of its nodes) are those of a node of its
own, named ``?``, never the first's as a fact. A launch ``Node`` that
starts it gives one node instance per ROS node, named as ROS 2 names them: without
``name=`` each keeps the name its code gives it, in the launch namespace; with
``name=`` (``__node:=``) every node of the process takes that name, as rcl renames them
all. Namespace, remaps and arguments apply to all of them. Parameters the launch file
gives the unnamed node (``/ns/?``) are given to each, as launch_ros passes them to the
whole process; each node takes a value only if it declares it, so such a copy is a
setting for several nodes (``ParamDecl.setting``), unread only when no node of the
process reads it.
"""

from __future__ import annotations

from collections.abc import Collection, Iterator, Mapping, Sequence
from dataclasses import replace

from .. import diagnostics as diag
from ..diagnostics import Diagnostic
from ..launch.model import LaunchModel, NodeDecl, ParamDecl
from ..launch.ros2.naming import pattern_matches
from ..model.rosname import namespace_of
from ..model.source import Node, PrimitiveCall
from ..model.values import UNKNOWN_MARK
from ..models.commands import by_arguments, command_node


def node_key(decl: NodeDecl) -> str:
    return f"{decl.package}/{decl.executable}"


def code_node(decl: NodeDecl, nodes: Mapping[str, Node], key: str | None = None
              ) -> Node | None:
    """The node a declaration runs: the one its arguments make when they say all (a
    ROS 2 controller spawner, ``commands.by_arguments``), else the code's or interface
    model's (``nodes[key]``, by default ``pkg/exec``), else the one its arguments make
    (``rostopic pub``), if any."""
    made = command_node(decl) if by_arguments(decl) else None
    return made or nodes.get(key or node_key(decl)) or command_node(decl)


def process_nodes(decls: Sequence[NodeDecl], nodes: Mapping[str, Node]
                  ) -> Iterator[tuple[NodeDecl, str | None]]:
    """Each declaration, or one per ROS node of its process, with the name the code
    gives that node (None: the executable's only node)."""
    for decl in decls:
        owns = _own_names(decl, nodes)
        if not owns:
            yield decl, None
            continue
        node = code_node(decl, nodes)
        guessed = node is None  # named after its executable
        for own in owns:
            local = _local(node, own)
            name = _renamed(decl, own, local)
            if name == decl.name:
                yield decl, own
                continue
            named = replace(decl, name=name, name_guessed=guessed)
            if _code_namespace(decl, own) or "__ns" in local:
                # the namespace the code gives holds where the launch gives none
                # (jetbot_ros' ``Node('nav_model', namespace='jetbot')``): the node's
                # relative names resolve in it, as its own name does
                named = replace(named, namespace=namespace_of(name))
            yield named, own


def process_params(launch: LaunchModel, nodes: Mapping[str, Node]) -> list[ParamDecl]:
    """The launch parameters, those given to an unnamed node moved to the name(s) its
    code gives it (each node of a several-node process gets a copy).

    A ROS 2 parameter knows the declaration it was given to (``owner``), so two unnamed
    nodes in one namespace (both ``/?`` until named) keep their own parameters. A
    parameter file's entry for particular nodes (``ParamDecl.pattern``) goes to a node
    named here only when the name matches, as rcl matches it; to a node never named,
    to none."""
    by_owner: dict[int, list[str]] = {}
    for index, decl in enumerate(launch.nodes):
        node = code_node(decl, nodes)
        names = [_renamed(decl, own, _local(node, own)) for own in _own_names(decl, nodes)]
        if names and names[0] != decl.name:
            by_owner[index] = names
    params: list[ParamDecl] = []
    for param in launch.params:
        targets = by_owner.get(param.owner) if param.owner is not None else None
        if not targets or param.node is None:
            if param.pattern is None:  # a file's entry for a node never named: not given
                params.append(param)
            continue
        rest = param.name[len(param.node):]
        chosen = [target for target in dict.fromkeys(targets)
                  if param.pattern is None or pattern_matches(param.pattern, target)]
        setting = param.setting
        if setting is None and len(chosen) > 1:
            # a value for the process: each of its nodes gets it and takes it only if it
            # declares it (``ParamDecl.setting``), so it is unread only when none does
            where = param.location
            setting = f"{where.file}:{where.line}:{where.column} (node {param.owner})"
        params.extend(replace(param, name=target + rest, node=target, pattern=None,
                              setting=setting) for target in chosen)
    return params


def guessed_names(launch: LaunchModel, nodes: Mapping[str, Node]) -> list[Diagnostic]:
    """One note for each unnamed node named after its executable (``_own_names``)."""
    return [diag.make("NODE_NAME_GUESSED", decl.location, name=_renamed(decl, names[0]),
                      executable=decl.executable)
            for decl in launch.nodes
            if code_node(decl, nodes) is None and (names := _own_names(decl, nodes))]


def unnamed_param_files(launch: LaunchModel, nodes: Mapping[str, Node]) -> list[Diagnostic]:
    """LAUNCH_PARAM_FILE for each parameter file with entries for particular nodes given
    to a node launched without a name, unless its code names it (then ``process_params``
    gives it the entries for that name, as the running node takes them): TurtleBot 4's
    ``Node(package='turtlebot4_node', executable='turtlebot4_node', parameters=[file])``
    is ``/turtlebot4_node`` and gets the file's ``turtlebot4_node:`` section. A name
    guessed from the executable (no code) keeps the warning."""
    return [diag.make("LAUNCH_PARAM_FILE", where,
                      detail=f"parameter file applied to {decl.name}, whose name is not "
                             "known here: only its /** entries are used")
            for decl in launch.nodes if decl.unnamed_param_files
            and (code_node(decl, nodes) is None or not [
                own for own in _own_names(decl, nodes) if UNKNOWN_MARK not in own])
            for where in decl.unnamed_param_files]


def _own_names(decl: NodeDecl, nodes: Mapping[str, Node]) -> list[str]:
    node = code_node(decl, nodes)
    if node is None and decl.ros_version == 2 and _unnamed(decl) and not decl.composable \
            and decl.executable and UNKNOWN_MARK not in decl.executable:
        # no code: rcl would use the name the code gives; the executable's name is the
        # usual one (a guess, said in NODE_NAME_GUESSED)
        return [decl.executable]
    if node is None or decl.ros_version != 2:
        return []
    if len(node.rosnames) >= 2:
        # the calls made on a node the code does not tell (``Node.unplaced``): a node
        # of its own, named ``?``, when each node keeps its code's name; under a name
        # the launch gives every node, the first's (they all have that name)
        return [*node.rosnames, *([UNKNOWN_MARK] if _apart(decl, node) else [])]
    # one node: a launch Node without name= runs it under the name its code gives it,
    # also one the code makes at run time around text it writes (tf2_ros'
    # static_transform_publisher, ``static_transform_publisher_`` and 16 random
    # characters: ``static_transform_publisher_?``, as an anonymous name is)
    if _unnamed(decl) and node.rosname and node.rosname.rsplit("/", 1)[-1].strip(
            UNKNOWN_MARK):
        return [node.rosname]
    if not _unnamed(decl) and node.rosname and (
            _code_namespace(decl, node.rosname) or _local(node, node.rosname)):
        # named by the launch, in the namespace its code gives (``__node:=`` alone), or
        # named or placed by its own arguments
        return [node.rosname]
    return []


def _unnamed(decl: NodeDecl) -> bool:
    """Launched without a name: its code's name (or a guess) names it. A name the launch
    gives but that is not known statically (``name=camera.name``) stays unknown."""
    return decl.name.rsplit("/", 1)[-1] == UNKNOWN_MARK and not decl.name_given


def own_calls(decl: NodeDecl, node: Node, own: str | None) -> list[PrimitiveCall]:
    """The calls of the process's node ``own`` (None: its only node), those no node
    could be told for apart (``?``) when ``_own_names`` gives them a node."""
    return node.calls_of(own, apart=_apart(decl, node))


def _apart(decl: NodeDecl, node: Node) -> bool:
    """Whether the calls of ``node`` (its code's) made on a node not told are a node
    ``?``'s: when the launch gives no name (``name=`` names every node alike)."""
    return node.unplaced and not decl.name_given


def _local(node: Node | None, own: str | None) -> set[str]:
    """What the node ``own``'s own arguments set (``Node.local_rules``): ``__ns``,
    ``__node``."""
    if node is None or own is None:
        return set()
    return {rule.partition(":=")[0] for rule in node.local_rules.get(own, ())}


def _renamed(decl: NodeDecl, own: str, local: Collection[str] = ()) -> str:
    """A node of the process: the launch name when one is given, else its own name.

    The code may give a namespace too (``rclcpp::Node("talker", "ns")``): it holds
    unless the launch file gives one (``namespace=``, ``PushRosNamespace``), which
    replaces it, as ``__ns:=`` does. A namespace or name its own arguments set
    (``local``: ``__ns``, ``__node``, ``Node.local_rules``) holds whatever the launch
    gives, as rcl reads a node's own rules first."""
    unnamed = _unnamed(decl)
    if local:
        name = own.rsplit("/", 1)[-1] if unnamed or "__node" in local else (
            decl.name.rsplit("/", 1)[-1])
        if "__ns" in local or _code_namespace(decl, own):
            return namespace_of(own) + name
        return decl.namespace.rstrip("/") + "/" + name
    if _code_namespace(decl, own):  # the code's namespace holds: its name, or the launch's
        return own if unnamed else namespace_of(own) + decl.name.rsplit("/", 1)[-1]
    if not unnamed:
        return decl.name
    return decl.namespace.rstrip("/") + "/" + own.rsplit("/", 1)[-1]


def _code_namespace(decl: NodeDecl, own: str) -> bool:
    """Whether the namespace the code gives its node ``own`` (``rclcpp::Node("x",
    "ns")``: ``/ns/x``) is the node's: the launch gives none (no ``namespace=``, no
    ``PushRosNamespace``, no ``__ns:=``), so launch_ros passes no ``__ns`` to replace
    it, whatever name it passes."""
    return (not decl.namespace_given and not decl.namespace.rstrip("/")
            and own.startswith("/") and bool(namespace_of(own).strip("/")))
