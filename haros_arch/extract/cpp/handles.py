"""Namespaces of node handles and nodes, and the callbacks calls are given.

A ROS 1 ``NodeHandle`` is followed back to its construction (``NodeHandle("~")``,
``NodeHandle("ns")``, ``NodeHandle(parent, "ns")``, a nodelet's ``getPrivateNodeHandle()``,
a member set in a constructor); an ``image_transport::ImageTransport`` has its handle's
namespace. A ROS 2 node (``rclcpp::Node``, ``this``, a ``SharedPtr``) is the node's own
namespace, ``""``, unless it comes from ``create_sub_node("ns")``.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Any

from clang.cindex import Cursor, CursorKind, TypeKind, conf

from ...model.source import NODELET_HANDLE as NODELET
from ...model.source import PROCESS_HANDLE as PROCESS
from . import api
from .call_sites import (
    CallSites,
    constructed_elsewhere,
    constructed_here,
    member_initialiser,
    uses_parameter,
    value_text,
)
from .cursors import MAX_OVERLOADS, Node, children_in, from_standin, overloads
from .expressions import qualified_name
from .members import MemberWrites
from .values import (
    PLACEHOLDER,
    UNKNOWN,
    Parts,
    Scope,
    initializer,
    key_of,
    literal,
    render,
    strip,
    written_arguments,
)
from .writes import writes_of

MAX_DEPTH = 16
_MAX_ASKED = 3  # handles' namespaces asked within one another (``value_namespace``)
# a declaration's initialiser that starts with a string literal and a ``+``
_PREFIX_PLUS = re.compile(rb'\s*[({]\s*("(?:[^"\\\n]|\\.)*")\s*\+')
_FUNCTIONS = frozenset({
    CursorKind.FUNCTION_DECL, CursorKind.CXX_METHOD, CursorKind.CONSTRUCTOR,
    CursorKind.DESTRUCTOR, CursorKind.FUNCTION_TEMPLATE, CursorKind.CONVERSION_FUNCTION,
})
_POINTERS = ("shared_ptr", "unique_ptr", "weak_ptr", "scoped_ptr")
_POINTER_READS = ("operator->", "operator*", "get")  # a smart pointer's handle
_UNSURE = (None, None)  # a member whose writes differ (``Namespaces._assigned``)
# a handle made where the unit does not show (``Namespaces.origin``)
_ORIGIN_UNSEEN = "?"


def join_name(namespace: str, name: str) -> str:
    """A name as seen from a handle in ``namespace`` (``~`` private, ``""`` the node's)."""
    if not namespace or name.startswith(("/", "~")):
        return name
    if namespace == "~" or namespace.endswith("/"):
        return namespace + name
    return f"{namespace}/{name}"


def normalise(namespace: str) -> str:
    if namespace.startswith("~/"):
        namespace = "~" + namespace[2:]
    return namespace.rstrip("/") if len(namespace) > 1 else namespace


def record_class(cursor: Cursor) -> Cursor | None:
    """The class an expression's value is, through references, pointers, smart pointers."""
    ctype = cursor.type.get_canonical()
    for _ in range(4):
        while ctype.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE,
                             TypeKind.POINTER):
            ctype = ctype.get_pointee().get_canonical()
        if ctype.kind != TypeKind.RECORD:
            return None
        decl = ctype.get_declaration()
        if decl.spelling in _POINTERS and ctype.get_num_template_arguments() > 0:
            ctype = ctype.get_template_argument_type(0).get_canonical()
            continue
        return decl
    return None


def is_ros2_node(decl: Cursor | None, depth: int = 0) -> bool:
    """True for rclcpp::Node, LifecycleNode and the classes derived from them. A node's
    (``cursors.Node``) answer is kept with it: every handle expression of a unit asks of
    its class."""
    if depth == 0 and isinstance(decl, Node):
        kept: bool | None = decl.__dict__.get("_ros2_node")
        if kept is None:
            kept = decl.__dict__["_ros2_node"] = _is_ros2_node(decl, 0)
        return kept
    return _is_ros2_node(decl, depth)


def _is_ros2_node(decl: Cursor | None, depth: int) -> bool:
    if decl is None or depth > 8:
        return False
    if qualified_name(decl) in api.RCLCPP_NODES:
        return True
    definition = decl.get_definition() or decl
    # a class template's specialisation (``class Filter : public PCLNode<PointCloud2>``)
    # lists no base of its own where the template is only instantiated: its bases are
    # the template's (perception_pcl's pcl_ros::PCLNode<T> derives from rclcpp::Node)
    template = conf.lib.clang_getSpecializedCursorTemplate(decl)
    if template is not None and isinstance(decl, Node):
        template = decl._unit.node(template)  # (its children asked of libclang once)
    for each in (definition, template):
        if each is None:
            continue
        for child in each.get_children():
            if child.kind == CursorKind.CXX_BASE_SPECIFIER:
                base = child.type.get_canonical().get_declaration()
                if is_ros2_node(base, depth + 1):
                    return True
    return False


def is_handle(expr: Cursor) -> bool:
    """True for an expression that is a node handle or a ROS 2 node."""
    decl = record_class(expr)
    return decl is not None and (qualified_name(decl) in api.HANDLE_CLASSES
                                 or is_ros2_node(decl))


class Namespaces:
    """Evaluates the namespace of handle expressions within one translation unit."""

    def __init__(self, macros: dict[str, str], source: dict[str, bytes]) -> None:
        self.macros = macros
        self.source = source
        self.sites: CallSites | None = None  # set once the file's functions are known
        self.members: MemberWrites | None = None  # likewise
        # the writes of the unit's global variables in its main file's functions (see
        # ``_global_value``), found once
        self._globals: dict[tuple[str, int], list[Cursor]] | None = None
        # the USR of each global variable those writes write, by the same key
        self._global_usrs: dict[tuple[str, int], str] = {}
        # the string that gave the last namespace asked (``of``) its one unknown run,
        # with the scope it reads in: ``ros::NodeHandle lnh(nh, firstcam)`` where
        # ``firstcam`` holds a parameter's value (pointgrey's stereo nodelet's
        # ``first_namespace``), for the call to name that parameter (``name_param``);
        # None when no string or several gave one
        self.unknown_from: tuple[Cursor, Scope] | None = None
        self._unknown_count = 0
        # the strings that gave it each of its unknown runs, in order, when each gave one
        # (hector's sonar plugin: ``ros::NodeHandle(*node_handle_, topic_)``, the
        # plugin's robotNamespace, then its topicName); empty otherwise
        self.unknown_parts: list[tuple[Cursor, Scope]] = []
        # the last namespace asked for is a ROS 1 controller's root handle
        # (``controller_root``): the manager's namespace, not known here
        self.root = False
        # where the last handle asked for was made (``PrimitiveCall.handle_origin``):
        # ``nodelet`` for a nodelet's own handles (``getNodeHandle()``, ...), ``process``
        # for one the code constructs (``ros::NodeHandle nh("~")``), which roscpp makes
        # in the process's node; None when the handles it may be disagree, or one of
        # them comes from where we do not see (another file, a controller's manager)
        self.origin: str | None = None
        self._origins: set[str] = set()
        self._asked = 0  # ``value_namespace`` questions open
        self._defaulting = False  # asked by ``member_origin``
        self.unit_root: Any = None  # the unit's root node (``cursors.root``), once known
        # whether a file is the workspace's, as the visitor asks (the same function: the
        # children it kept of a node are those ``children_in`` keeps for it)
        self.owned: Callable[[str], bool] | None = None

    def of_call(self, call: Cursor, callee: Cursor, scope: Scope) -> Parts:
        """The namespace of the handle or node a member call is made on."""
        if callee.kind != CursorKind.MEMBER_REF_EXPR:
            target = call.referenced
            if target is not None and is_ros2_node(target.semantic_parent):
                return ("",)  # create_publisher(...) inside a Node subclass
            return UNKNOWN
        objects = [c for c in callee.get_children() if c.kind.is_expression()]
        if not objects:  # implicit this->
            target = call.referenced
            parent = target.semantic_parent if target is not None else None
            return ("",) if is_ros2_node(parent) else UNKNOWN
        return self.of(objects[0], scope)

    def value_namespace(self, expr: Cursor, scope: Scope) -> Parts:
        """The namespace of the handle ``expr`` asked while a value is read (a handle's
        ``resolveName``, ``CallSites.handle_namespace``), perhaps within a question of
        this object, whose state it leaves as it was; unknown for a controller's root
        handle, or when asked within itself again and again (a handle named by its own
        ``resolveName``)."""
        if self._asked >= _MAX_ASKED:
            return UNKNOWN
        state = (self.unknown_from, self._unknown_count, self.root, self.unknown_parts,
                 self.origin, self._origins)
        self._asked += 1
        try:
            found = self.of(expr, scope)
            return UNKNOWN if self.root else found
        finally:
            self._asked -= 1
            (self.unknown_from, self._unknown_count, self.root, self.unknown_parts,
             self.origin, self._origins) = state

    def of(self, expr: Cursor, scope: Scope, depth: int = 0) -> Parts:
        """The namespace of the handle ``expr`` stands for."""
        if depth == 0:
            self.unknown_from, self._unknown_count, self.root = None, 0, False
            self.unknown_parts = []
            self._origins = set()
        found = self._namespace(expr, scope, depth)
        if depth == 0:
            # one origin, known, for every handle the expression may be
            self.origin = next(iter(self._origins)) if len(self._origins) == 1 else None
            self.origin = None if self.origin == _ORIGIN_UNSEEN else self.origin
        if depth == 0 and self._unknown_count != 1:
            self.unknown_from = None
        if depth == 0 and len(self.unknown_parts) != self._unknown_count:
            self.unknown_parts = []
        if (found == UNKNOWN or any(PLACEHOLDER in (p or "") for p in found)) and (
            is_ros2_node(record_class(expr))
        ):
            return ("",)  # a node's own namespace, unless it is a known sub node
        return found

    def _namespace(self, expr: Cursor, scope: Scope, depth: int) -> Parts:
        expr = strip(expr)
        if depth > MAX_DEPTH:
            return UNKNOWN
        kind = expr.kind
        if kind == CursorKind.CXX_THIS_EXPR:
            return ("",) if is_ros2_node(record_class(expr)) else UNKNOWN
        if kind == CursorKind.DECL_REF_EXPR:
            decl = expr.referenced
            if decl is not None and controller_root(decl):
                self.root = True
                self._origins.add(_ORIGIN_UNSEEN)  # the manager's handle
                return ("",)
            if decl is not None and scope.is_parameter(decl) and scope.sites is not None:
                return scope.sites.agreed(decl, lambda a, s: self.of(a, s, depth + 1), UNKNOWN)
            if decl is None or decl.kind != CursorKind.VAR_DECL:
                return UNKNOWN
            value = scope.variable(decl)
            if value is None and not _is_global(decl):
                # written several times: the last write before this use (darknet_ros'
                # nodelet: ``ros::NodeHandle nh("~"); nh = getPrivateNodeHandle();``)
                value = scope.written_before(decl, expr, depth)
            if value is None and _is_global(decl):
                value = self._global_value(decl)
                if value is not None:  # written in another function: its own scope
                    return self.of(value, Scope(None, self.macros, self.source, self.sites),
                                   depth + 1)
                marker = self._global_elsewhere(decl)
                if marker is not None:
                    self._origins.add(_ORIGIN_UNSEEN)  # made in another file
                    return (marker,)
            if value is None and initializer(decl) is None:
                return self._dropped_prefix(decl)
            return UNKNOWN if value is None else self.of(value, scope, depth + 1)
        if kind == CursorKind.MEMBER_REF_EXPR and expr.referenced is not None:
            return self.member(expr.referenced, scope.body, depth, is_handle(expr))
        if kind == CursorKind.CXX_NEW_EXPR:
            inner = [c for c in expr.get_children() if c.kind.is_expression()]
            return self.of(inner[-1], scope, depth + 1) if inner else UNKNOWN
        if kind == CursorKind.UNARY_OPERATOR:  # *pointer
            inner = [c for c in expr.get_children() if c.kind.is_expression()]
            return self.of(inner[0], scope, depth + 1) if inner else UNKNOWN
        if kind != CursorKind.CALL_EXPR:
            return UNKNOWN
        target = expr.referenced
        inner = [c for c in expr.get_children() if c.kind.is_expression()]
        if target is None:
            return self.of(inner[-1], scope, depth + 1) if inner else UNKNOWN
        owner = qualified_name(target.semantic_parent)
        factory = (owner, target.spelling)
        if factory in api.HANDLE_FACTORIES:
            self._origins.add(NODELET)
            return (api.HANDLE_FACTORIES[factory],)
        if factory in api.RCLCPP_SUB_NODE or target.spelling in _POINTER_READS:
            return self._sub_node(expr, factory, scope, depth)
        made = qualified_name(record_class(expr))
        if target.spelling in ("make_shared", "make_unique") and made in api.HANDLE_CLASSES:
            owner = made  # boost::make_shared<ros::NodeHandle>("ns")
        elif target.kind != CursorKind.CONSTRUCTOR or owner not in api.HANDLE_CLASSES:
            if target.kind == CursorKind.CONSTRUCTOR and len(inner) == 1:  # a copy
                return self.of(inner[0], scope, depth + 1)
            if target.kind == CursorKind.CXX_METHOD and not written_arguments(expr) and (
                    scope.sites is not None):
                # a getter of a handle (hector_pose_estimation's ``ros::NodeHandle&
                # getPrivateNodeHandle() { return private_nh_; }``): the namespace of
                # what each body a call may run returns, when they agree
                found = {self.of(value, scope.sites.scope(method), depth + 1)
                         for value, method in scope.sites.returns(target) or ()}
                return found.pop() if len(found) == 1 else UNKNOWN
            return UNKNOWN
        args = written_arguments(expr)
        if not args or not is_handle(args[0]):
            # a handle the code constructs from nothing or a namespace: roscpp's, of the
            # process (a child of another handle, or a copy, is where its parent is);
            # with remappings the code gives (``NodeHandle(ns, remappings)``), its own
            self._origins.add(PROCESS if len(args) < 2 and not in_main(scope)
                              else _ORIGIN_UNSEEN)
        if not args:
            return ("",)
        if is_handle(args[0]):
            parent = render(self.of(args[0], scope, depth + 1))
            if len(args) == 1 or owner != api.NODE_HANDLE:
                return (parent,)
            child = render(scope.string(args[1]))
            self._unknown(child, args[1], scope)
            return (normalise(join_name(parent, child)) if parent else normalise(child),)
        written = render(scope.string(args[0]))
        self._unknown(written, args[0], scope)
        return (normalise(written),)

    def member(self, field: Cursor, body: Cursor | None, depth: int = 0,
               handle: bool = True) -> Parts:
        """The namespace of the handle member ``field`` (read in ``body``, None: no
        function's)."""
        known = api.HANDLE_MEMBERS.get((qualified_name(field.semantic_parent),
                                        field.spelling))
        if known is not None:
            self._origins.add(NODELET)  # a nodelet base class's own handles
            return (known,)
        found = member_initialiser(field, self.source) if self.sites is None else (
            self.sites.member(field, body))
        if found is None or found[1].kind != CursorKind.CONSTRUCTOR:
            assigned = self._assigned(field, depth)  # not set by a constructor: by the unit
            if assigned is _UNSURE:
                return UNKNOWN
            # the unit's writes agree: theirs (an initialisation method's first write,
            # which ``found`` holds, may be one a later statement replaces unread)
            found = assigned or found
        value, where = found if found is not None else (None, None)
        if value is None and (found is not None or self.sites is None
                              or not constructed_elsewhere(field, self.source)):
            # left to its default initialiser, or set by no constructor (of this file:
            # one elsewhere may give it another): ``ros::NodeHandle pnh_{"~"};``,
            # ``ros::NodeHandle pnh_ = ros::NodeHandle("~");``
            value, where = initializer(field), None
        if value is None:
            # a member nothing sets: the default handle when it holds one, unless its
            # class's constructors are all in other files (a base class's handle that
            # the base's constructor, in another file of the node, sets: voxblox's
            # EsdfServer publishes on TsdfServer's ``nh_private_``): what those give it
            # (``links.MEMBER``); a pointer (or smart pointer) to one points to a handle
            # set where we do not see (``Impl impl{&nh}``, a copy of the struct): not known
            # (a reference member is bound by every constructor: there, what they give)
            held, bound = holds_handle(field), binds_handle(field)
            # a pointer to a handle that the constructors of another file set: what those
            # give it, as for a handle member (Kimera-VIO-ROS's RosOnlineDataProvider
            # subscribes on ``*it_``, which its base's constructor, in another file, makes
            # from ``nh_``)
            pointed = self.sites is not None and points_to_handle(field) and (
                constructed_elsewhere(field, self.source))
            if not (handle and (held or bound)) and not pointed:
                return UNKNOWN
            if self.sites is not None and constructed_elsewhere(field, self.source):
                self._origins.add(_ORIGIN_UNSEEN)  # set by a constructor of another file
                marker = self.sites.member_placeholder(field)
                return (marker,) if marker is not None else UNKNOWN
            if held and found is None and not self._defaulting and self.sites is not None \
                    and constructed_here(field):
                # a handle the unit's constructors leave to its default may be given
                # another by a file of the node that assigns it through an object of the
                # class (FUEL's SDFMap: ``mr_->node_ = nh``, MapROS reading
                # ``map_ros/fx`` on ``node_``): those values where there are
                # (``links.ASSIGNED``), else this unit's, the default (``links.MEMBER``)
                marker = self.sites.member_placeholder(field)
                if marker is not None:
                    self._origins.add(_ORIGIN_UNSEEN)
                    return (marker,)
            if held:
                self._origins.add(PROCESS)  # default-constructed: ``ros::NodeHandle nh_;``
            return ("",) if held else UNKNOWN
        # read where it is written: ``ros::NodeHandle right(nh, "right"); right_nh_ =
        # right;``
        return self.of(value, Scope(None, self.macros, self.source, self.sites)
                       if where is None or self.sites is None else self.sites.scope(where),
                       depth + 1)

    def member_origin(self, field: Cursor) -> tuple[Parts, str | None]:
        """The namespace of the handle member ``field`` as the unit's constructors of its
        class give it (``member``, read in no function), and where that handle was made
        (``origin``)."""
        self._origins = set()
        self._defaulting = True  # what the unit gives it, never the placeholder of itself
        try:
            found = self.member(field, None)
        finally:
            self._defaulting = False
        origin = next(iter(self._origins)) if len(self._origins) == 1 else None
        return found, None if origin == _ORIGIN_UNSEEN else origin

    def _unknown(self, written: str, expr: Cursor, scope: Scope) -> None:
        """Note ``expr`` as what gave a namespace its unknown run (``unknown_from``)."""
        if "?" in written:
            self.unknown_from = (expr, scope) if written.count("?") == 1 else None
            self._unknown_count += written.count("?")
            if written.count("?") == 1:
                self.unknown_parts.append((expr, scope))

    def _assigned(self, field: Cursor, depth: int = 0
                  ) -> tuple[Cursor | None, Cursor] | None:
        """What the unit's functions (but destructors) assign to a member that no
        constructor sets, when every such write agrees (the same text, or handles of one
        namespace: pointcloud_to_laserscan's ``nh_ = getNodeHandle()`` or, for a
        multithreaded nodelet, ``getMTNodeHandle()``), and the function that writes it;
        None when there is none (the default). ``_UNSURE`` when the writes differ, or
        the value reads a parameter of a method that no call of the file passes (a
        plugin's ``initialize(name)``: its host's value), unless the node's other files
        pass it (``CallSites.called_elsewhere``: a placeholder they fill)."""
        found = self.members.live_assignments(field) if self.members is not None else []
        if not found:
            return None
        value, function = found[0]
        if function.kind != CursorKind.CONSTRUCTOR and uses_parameter(value) and (
            self.sites is None or not (self.sites.callers(function)
                                       or self.sites.called_elsewhere(function)
                                       or self._host_given(function, value))
        ):
            return _UNSURE
        if len({value_text(v) for v, _ in found}) > 1:
            if self.sites is None or depth >= MAX_DEPTH:
                return _UNSURE
            spaces = {self.of(v, self.sites.scope(f), depth + 1) if v is not None
                      else UNKNOWN for v, f in found}
            if len(spaces) > 1 or None in next(iter(spaces)):
                return _UNSURE
        return value, function

    def _host_given(self, function: Cursor, value: Cursor) -> bool:
        """Whether a handle a virtual method stores in a member (``nh_ = nh;`` in a
        plugin base's ``initialize(nh, ...)``) is its parameter's placeholder, filled
        from the node's calls and, where none passes it, from the host's call of the
        method (``links.handles_given``, ``PrimitiveCall.host_handle``)."""
        return self.sites is not None and self.sites.external and (
            function.kind == CursorKind.CXX_METHOD and function.is_virtual_method()) and (
            is_handle(value))

    def _global_value(self, decl: Cursor) -> Cursor | None:
        """What a global handle holds when the functions of the unit's main file write it
        exactly once: ublox's ``boost::shared_ptr<ros::NodeHandle> nh;`` (a header) set by
        ``nh.reset(new ros::NodeHandle("~"))`` in ``main`` and used by every publisher
        (``nh = boost::make_shared<ros::NodeHandle>("~")`` alike)."""
        writes = self._global_writes_of(decl.translation_unit).get(key_of(decl), [])
        return writes[0] if len(writes) == 1 else None

    def _global_writes_of(self, unit: Any) -> dict[tuple[str, int], list[Cursor]]:
        """The writes of the unit's global variables in its main file's functions (of
        namespace scope: a class's own are not read), found once on the unit's nodes
        (``unit_root``, the visitor's: their children are made once for every
        analysis); none before the visitor has them."""
        if self._globals is None and self.unit_root is not None:
            self._globals = {}
            main = unit.spelling if unit is not None else ""

            def in_main(name: str) -> bool:
                return name == main

            owned = self.owned
            if owned is not None and owned(main):
                # the visitor's children in the workspace's files (kept with each
                # node), those in the main file of them: no second visit of the
                # thousands of children of the unit's headers
                def of_main(parent: Any) -> list[Cursor]:
                    return [child for child in children_in(parent, owned)
                            if (where := child.location.file) is not None
                            and where.name == main]
            else:
                def of_main(parent: Any) -> list[Cursor]:
                    return children_in(parent, in_main)

            stack = of_main(self.unit_root)
            while stack:
                node = stack.pop()
                if node.kind == CursorKind.NAMESPACE:
                    stack.extend(of_main(node))
                elif node.kind in _FUNCTIONS and node.is_definition():
                    self._global_writes(node)
        return self._globals if self._globals is not None else {}

    def _global_elsewhere(self, decl: Cursor) -> str | None:
        """The placeholder of a global handle that this unit only declares (``extern
        ros::NodeHandle* n;``: another file of the node defines it) and never writes:
        the namespace the file of the node whose functions write it once gives it
        (``global_handles``, ``links.MEMBER``), filled for the node; OpenMower's
        mower_logic sets ``n = new ros::NodeHandle()`` in main and its behaviours, in
        other files, make their clients and publishers on ``n``. None otherwise."""
        if self.sites is None or decl.get_definition() is not None or not is_handle(decl):
            return None
        if self._global_writes_of(decl.translation_unit).get(key_of(decl)):
            return None
        return self.sites.member_placeholder(decl)

    def global_handles(self, unit: Any) -> list[tuple[str, Parts, str | None]]:
        """(USR, namespace, origin) of each global handle the functions of the unit's
        main file write exactly once (``_global_value``), for the other files of the node
        that use it (``_global_elsewhere``)."""
        found: list[tuple[str, Parts, str | None]] = []
        for key, writes in sorted(self._global_writes_of(unit).items()):
            usr = self._global_usrs.get(key, "")
            if len(writes) == 1 and usr:
                namespace = self.of(writes[0], Scope(None, self.macros, self.source,
                                                     self.sites))
                found.append((usr, namespace, self.origin))
        return found

    def _global_writes(self, function: Cursor) -> None:
        assert self._globals is not None
        for node in function.walk_preorder():
            if node.kind not in _WHOLE_WRITES:
                continue  # a declaration writes itself, an operator in place no whole value
            for write in writes_of(node, self.source):
                target = write.target
                if write.whole and write.value is not None and (
                    target.kind == CursorKind.DECL_REF_EXPR
                    and target.referenced is not None and _is_global(target.referenced)
                ):
                    self._globals.setdefault(key_of(target.referenced), []).append(
                        write.value)
                    if is_handle(target.referenced):
                        self._global_usrs[key_of(target.referenced)] = (
                            target.referenced.get_usr())

    def _dropped_prefix(self, decl: Cursor) -> Parts:
        """A handle declared ``NodeHandle nh("~/" + name_)`` whose initialiser clang
        dropped (``name_`` of a type it could not see: fetch_depth_layer): the literal
        its written initialiser starts with and an unknown rest (``~?``), so that the
        private prefix is not lost."""
        made = decl.type.get_canonical().get_declaration()
        where = decl.extent.end
        if qualified_name(made) not in api.HANDLE_CLASSES or where.file is None:
            return UNKNOWN
        data = self.source.get(where.file.name)
        found = _PREFIX_PLUS.match(data, where.offset) if data else None
        prefix = literal(found.group(1).decode("utf-8", "replace")) if found else None
        if prefix is not None:
            self._origins.add(PROCESS)  # constructed from a namespace
        return UNKNOWN if prefix is None else (normalise(prefix + "?"),)

    def _sub_node(self, call: Cursor, factory: tuple[str, str], scope: Scope,
                  depth: int) -> Parts:
        """``node->create_sub_node("ns")``, ``pointer->``, ``*pointer``, ``pointer.get()``."""
        target = call.referenced
        children = [c for c in call.get_children() if c.kind.is_expression()]
        if children and children[0].kind == CursorKind.MEMBER_REF_EXPR:
            objects = [c for c in children[0].get_children() if c.kind.is_expression()]
        else:  # operator-> as a call: the object and the operator
            objects = [c for c in children if strip(c).referenced != target]
        parent = self.of(objects[0], scope, depth + 1) if objects else ("",)
        if factory not in api.RCLCPP_SUB_NODE:
            return parent
        args = written_arguments(call)
        index = api.RCLCPP_SUB_NODE[factory]
        if index >= len(args):
            return parent
        child = render(scope.string(args[index]))
        return (normalise(join_name(render(parent), child)),)


def in_main(scope: Scope) -> bool:
    """Whether ``scope`` is a program's ``main()``: no nodelet runs it, so a handle made
    there says nothing of a nodelet's handles, when a source compiled both as a program
    and as a nodelet library is read as the program (laser_filters'
    scan_to_cloud_filter_chain.cpp, whose ``#if BUILDING_NODELET`` one target defines:
    its nodelet passes ``getPrivateNodeHandle()`` where ``main()`` passes ``pnh("~")``)."""
    body = scope.body
    return body is not None and body.kind == CursorKind.FUNCTION_DECL and (
        body.spelling == "main")


def controller_root(decl: Cursor) -> bool:
    """Whether ``decl`` is the root handle of a ROS 1 controller: the second of the three
    parameters of an ``init`` that overrides ros_control's ``init(hw, root_nh,
    controller_nh)``, which the controller manager calls with its own handle and
    ``<manager>/<controller>`` (hector_quadrotor's controllers subscribe to
    ``command/pose`` on the first)."""
    function = decl.semantic_parent
    if decl.kind != CursorKind.PARM_DECL or function is None or (
            function.kind != CursorKind.CXX_METHOD or function.spelling != "init"):
        return False
    params = [c for c in function.get_children() if c.kind == CursorKind.PARM_DECL]
    if len(params) != 3 or params[1] != decl or not all(
            _node_handle(p) for p in params[1:]):
        return False  # sawyer's ``init(hw, nh, ctrl_type)``: one handle, the controller's
    return _controller(function.semantic_parent)


def _node_handle(param: Cursor) -> bool:
    """Whether ``param`` is a ``ros::NodeHandle`` (by reference, const or not)."""
    ctype = param.type.get_canonical()
    if ctype.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
        ctype = ctype.get_pointee()
    declaration = ctype.get_declaration()
    return declaration.kind != CursorKind.NO_DECL_FOUND and (
        qualified_name(declaration) == "ros::NodeHandle")


def _controller(cls: Cursor | None, depth: int = 0) -> bool:
    """Whether ``cls`` derives from a class of ros_control's controller_interface (a
    base that is a template's specialisation, ``Controller<EffortJointInterface>``, as
    its template: clang lists no members of it)."""
    if cls is None or depth > 8:
        return False
    for each in (cls, conf.lib.clang_getSpecializedCursorTemplate(cls)):
        if each is None or each.kind == CursorKind.NO_DECL_FOUND:
            continue
        if qualified_name(each).startswith("controller_interface::"):
            return True
        definition = each.get_definition() or each
        if any(_controller(child.type.get_canonical().get_declaration(), depth + 1)
               for child in definition.get_children()
               if child.kind == CursorKind.CXX_BASE_SPECIFIER):
            return True
    return False


def pointee(expr: Cursor) -> Cursor:
    """The smart pointer a read of its object is made through (``node->``, ``*node``,
    ``node.get()`` of a ``shared_ptr``: ``node``); ``expr`` itself for anything else."""
    expr = strip(expr)
    target = expr.referenced if expr.kind == CursorKind.CALL_EXPR else None
    parent = target.semantic_parent if target is not None else None
    if target is None or target.spelling not in _POINTER_READS or parent is None or (
        parent.spelling not in _POINTERS
    ):
        return expr
    children = [c for c in expr.get_children() if c.kind.is_expression()]
    if children and children[0].kind == CursorKind.MEMBER_REF_EXPR:  # pointer.get()
        children = [c for c in children[0].get_children() if c.kind.is_expression()]
    objects = [c for c in children if strip(c).referenced != target]
    return strip(objects[0]) if len(objects) == 1 else expr


def holds_handle(field: Cursor) -> bool:
    """A member whose type is a handle class itself, not a pointer or reference to one."""
    ctype = field.type.get_canonical()
    if ctype.kind in (TypeKind.POINTER, TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
        return False
    decl = ctype.get_declaration()
    return decl is not None and qualified_name(decl) in api.HANDLE_CLASSES


# the owning pointers a handle is held through (Kimera-VIO-ROS's
# ``std::unique_ptr<image_transport::ImageTransport> it_``)
_SMART_POINTERS = frozenset({"std::unique_ptr", "std::shared_ptr", "boost::shared_ptr"})


def points_to_handle(field: Cursor) -> bool:
    """A member that is a pointer, plain or smart, to a handle class."""
    ctype = field.type.get_canonical()
    if ctype.kind == TypeKind.POINTER:
        pointee = ctype.get_pointee().get_canonical()
    else:
        decl = ctype.get_declaration()
        if decl is None or qualified_name(decl) not in _SMART_POINTERS or (
                ctype.get_num_template_arguments() < 1):
            return False
        pointee = ctype.get_template_argument_type(0).get_canonical()
    decl = pointee.get_declaration()
    return decl is not None and qualified_name(decl) in api.HANDLE_CLASSES


def binds_handle(field: Cursor) -> bool:
    """A member that is a reference to a handle (``ros::NodeHandle& nh_``): every
    constructor of its class binds it, for good, to the handle it gives it."""
    ctype = field.type.get_canonical()
    if ctype.kind != TypeKind.LVALUEREFERENCE:
        return False
    decl = ctype.get_pointee().get_canonical().get_declaration()
    return decl is not None and qualified_name(decl) in api.HANDLE_CLASSES


# the nodes whose writes (``writes_of``) may set a variable named by a reference to a
# whole value: an assignment, a call (``operator=``, ``reset``, a search's result)
_WHOLE_WRITES = frozenset({CursorKind.CALL_EXPR, CursorKind.BINARY_OPERATOR})


def _is_global(decl: Cursor) -> bool:
    """A variable of a namespace (or of no namespace), not of a function or class."""
    parent = decl.semantic_parent
    return decl.kind == CursorKind.VAR_DECL and parent is not None and parent.kind in (
        CursorKind.NAMESPACE, CursorKind.TRANSLATION_UNIT)


def callback(args: list[Cursor], index: int | None) -> Cursor | None:
    """The function, method or lambda a callback argument names, where cheap."""
    if index is None or index >= len(args):
        return None
    return _callable(args[index], 0)


def _callable(expr: Cursor, depth: int) -> Cursor | None:
    expr = strip(expr)
    if depth > 6:
        return None
    if expr.kind == CursorKind.DECL_REF_EXPR and expr.referenced is not None and (
        expr.referenced.kind in _FUNCTIONS
    ):
        return expr.referenced
    if expr.kind == CursorKind.LAMBDA_EXPR:
        return expr
    if expr.kind == CursorKind.UNARY_OPERATOR:  # &Class::method
        inner = [c for c in expr.get_children() if c.kind.is_expression()]
        return _callable(inner[0], depth + 1) if inner else None
    if expr.kind == CursorKind.CALL_EXPR:
        # boost::function<...>(f), boost::bind(&Class::method, this, _1), std::bind(...)
        for arg in written_arguments(expr):
            found = _callable(arg, depth + 1)
            if found is not None:
                return found
        inner = [c for c in expr.get_children() if c.kind.is_expression()]
        if expr.referenced is None and len(inner) == 1:
            return _callable(inner[0], depth + 1)
        if expr.referenced is not None and expr.referenced.kind == CursorKind.CONSTRUCTOR:
            for child in inner:  # std::function<...>(lambda) copies
                found = _callable(child, depth + 1)
                if found is not None:
                    return found
    return None


def callback_name(function: Cursor | None) -> str | None:
    if function is None or function.kind == CursorKind.LAMBDA_EXPR:
        return None
    if function.kind == CursorKind.CXX_METHOD:
        return f"{qualified_name(function.semantic_parent).split('::')[-1]}::{function.spelling}"
    return function.spelling


def parameters(function: Cursor) -> list:
    if function.kind == CursorKind.LAMBDA_EXPR:
        return [c.type for c in function.get_children() if c.kind == CursorKind.PARM_DECL]
    return list(function.type.argument_types())


def looked_up(call: Cursor) -> list[Cursor]:
    """The declarations the name of a call the parse could not resolve was looked up to
    (its head's ``OVERLOADED_DECL_REF``: a call in a template with dependent arguments,
    ``set_parameters(std::forward<Rest>(rest)...)``); none when the lookup waits for a
    template argument (``node->declare_parameter(...)`` with ``NodeT node``)."""
    heads = list(call.get_children())[:1]
    return [named for head in heads for child in [head, *head.get_children()]
            if child.kind == CursorKind.OVERLOADED_DECL_REF
            for d in overloads(child) if d is not None for named in _through_using(d)]


# the functions whose own ``using ns::f;`` ``_through_using`` looks for
_USING_SCOPES = frozenset({CursorKind.FUNCTION_DECL, CursorKind.FUNCTION_TEMPLATE,
                           CursorKind.CXX_METHOD, CursorKind.CONSTRUCTOR})


def _through_using(decl: Cursor) -> list[Cursor]:
    """``decl``, or, when it is the name a function's ``using ns::f;`` brings in (clang's
    using-shadow, an unexposed declaration of that function), the declarations that
    using-declaration names (Autoware's ``using autoware_utils_rclcpp::
    get_or_declare_parameter;`` in VehicleInfoUtils' constructor template)."""
    parent = decl.semantic_parent if decl.kind == CursorKind.UNEXPOSED_DECL else None
    if parent is None or parent.kind not in _USING_SCOPES:
        return [decl]
    line = decl.location.line
    for node in parent.walk_preorder():
        if node.kind != CursorKind.USING_DECLARATION or node.location.line != line:
            continue
        found = [d for ref in node.get_children() if ref.kind == CursorKind.OVERLOADED_DECL_REF
                 and ref.spelling == decl.spelling for d in overloads(ref) if d is not None]
        if found:
            return found
    return [decl]


def own_functions_only(call: Cursor) -> bool:
    """Whether the name of a call the parse could not resolve was looked up to the code's
    own functions only (``looked_up``, every one of them read), none of them an API
    function (a row's) or a stand-in's: the call is one of them, whose code is read
    where it is defined, not the API function of the same name (a JWT library's
    ``jwt_object::set_parameters(...)`` in rmf_visualization_schedule is no rclcpp
    parameter write)."""
    found = looked_up(call)
    return 0 < len(found) < MAX_OVERLOADS and not any(
        from_standin(d) or api.ALL.get((qualified_name(d.semantic_parent), d.spelling))
        is not None for d in found)
