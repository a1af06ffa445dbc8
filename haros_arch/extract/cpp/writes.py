"""What is written to a variable, and where: the one reading of a function body's writes
that the analyses share.

``writes_of(node, source)`` gives the writes one node of a body makes, each a ``Write``:
the variable written (its declaration, or the expression that names it), the expression
it holds afterwards when that is known, and whether the write replaces its value or
changes it in place. A write that replaces the value: a declaration with an initialiser
(``std::string t = "scan";``), ``=`` (a builtin's assignment, or ``operator=``), a smart
pointer's ``reset(p)`` (``right_nh_.reset(new ros::NodeHandle(nh, "right"))``). A write
that changes it in place, to a value not known: a compound assignment (``+=``), ``++`` /
``--``, its address taken (``&x``), passing it as a non-const reference or, for an
array, as a pointer to its data (``snprintf(topic, ...)``), a non-const method called
on it (``p->m()`` changes ``*p``, not ``p``), except a string's ``clear()``, which
replaces its value with "". Each analysis keeps the writes it follows:
``values.Scope`` the local variables of a function, ``members.MemberWrites`` the members
of a file, ``handles.Namespaces`` the node handles a unit's functions set.
"""

from __future__ import annotations

from dataclasses import dataclass

from clang.cindex import Cursor, CursorKind, TypeKind

from .cursors import Node
from .expressions import initializer, qualified_name, strip, written_arguments
from .synthesis import ANY as ANY_CLASS

_NAMES = (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR)
_MAKERS = ("make_shared", "make_unique", "allocate_shared")
# the operators of a call clang leaves unresolved (``a_ && f(x)`` in a template) that
# read both sides
_READING = ("&&", "||", "==", "!=", "<", ">", "<=", ">=", "+", "-", "*", "/", "%")
SMART_POINTERS = ("shared_ptr", "unique_ptr", "scoped_ptr")


@dataclass(frozen=True)
class Write:
    """``target`` (a variable's declaration, or the expression naming what is written,
    without its wrappers) holds ``value`` after ``at``; None when not known. ``whole``:
    the write replaces the value (a declaration, ``=``, ``reset(p)``), else it changes
    it in place."""

    target: Cursor
    value: Cursor | None
    at: Cursor
    whole: bool

    @property
    def variable(self) -> Cursor | None:
        """The declaration of what is written (a variable, a parameter, a member)."""
        if self.target.kind in _NAMES:
            return self.target.referenced
        return self.target if self.target.kind == CursorKind.VAR_DECL else None


def writes_of(node: Cursor, source: dict[str, bytes]) -> list[Write]:
    """The writes that ``node`` itself makes (not those of its children); a unit's node
    keeps them (the unit's walks ask each node again: call sites, members, values,
    conditions), a list not to be changed."""
    if type(node) is not Node:
        return _writes_of(node, source)
    facts = node.__dict__
    found: list[Write] | None = facts.get("_writes")
    if found is None:
        found = facts["_writes"] = _writes_of(node, source)
    return found


def writes_in(node: Cursor, source: dict[str, bytes]) -> list[Write]:
    """The writes of ``node``'s subtree, in the order of its ``walk_preorder`` (each
    node's ``writes_of`` in turn); a unit's node keeps them (a constructor's body is
    read again for each member, a function's for each field), a list not to be
    changed."""
    if type(node) is not Node:
        return [write for each in node.walk_preorder() for write in writes_of(each, source)]
    facts = node.__dict__
    found: list[Write] | None = facts.get("_writes_in")
    if found is None:
        found = facts["_writes_in"] = [write for each in node.walk_preorder()
                                       for write in writes_of(each, source)]
    return found


def _writes_of(node: Cursor, source: dict[str, bytes]) -> list[Write]:
    kind = node.kind
    if kind == CursorKind.VAR_DECL:
        init = initializer(node)
        if init is None or default_constructed(init):
            return []
        return [Write(node, init, node, True)]
    if kind == CursorKind.CALL_EXPR:
        return _call(node, source)
    if kind == CursorKind.INIT_LIST_EXPR:
        return _listed(node)
    if kind == CursorKind.BINARY_OPERATOR:
        children = list(node.get_children())
        if len(children) == 2 and between(children[0], children[1], source) == "=":
            return [Write(strip(children[0]), children[1], node, True)]
        return []
    if kind == CursorKind.COMPOUND_ASSIGNMENT_OPERATOR:
        children = list(node.get_children())
        return [Write(strip(children[0]), None, node, False)] if children else []
    if kind == CursorKind.UNARY_OPERATOR and _assigning(node, source):
        return [Write(strip(child), None, node, False) for child in node.get_children()]
    return []


def _listed(node: Cursor) -> list[Write]:
    """The variables a braced list that builds a class by a constructor passes to that
    constructor's non-const lvalue reference parameters (mrover-ros2's ``{"device_name",
    mDeviceName, "zed"}``, an element of a ``std::vector<ParameterWrapper>`` whose
    constructor keeps ``&variable`` and writes the parameter's value there later): the
    constructor may store into them, as a call's out argument (``_call``). Clang keeps
    no call there (``call_sites.list_constructions``)."""
    from .call_sites import list_constructions  # (call_sites imports this module)

    found: list[Write] = []
    for made, constructor in list_constructions(node):
        types = list(constructor.type.argument_types())
        args = [c for c in made.get_children() if c.kind.is_expression()]
        for arg, ptype in zip(args, types, strict=False):
            arg = strip(arg)
            if arg.kind in _NAMES and arg.referenced is not None and (
                ptype.kind == TypeKind.LVALUEREFERENCE
                and not ptype.get_pointee().is_const_qualified()
            ):
                found.append(Write(arg, None, made, False))
    return found


def by_operator(write: Write) -> bool:
    """Whether ``write`` is an operator's change in place (``n_++``, ``n_ += 2``,
    ``topic_ += "/x"``), not a call that may write what it is given."""
    at = write.at
    return at.kind in (CursorKind.COMPOUND_ASSIGNMENT_OPERATOR, CursorKind.UNARY_OPERATOR) or (
        at.kind == CursorKind.CALL_EXPR and at.spelling in _COMPOUND)


def out_argument(write: Write) -> bool:
    """Whether ``write`` is of a variable passed to a function the parse resolved whose
    parameter there is a non-const lvalue reference: the function's own declaration says
    it may store into it (``CHECK(pnh.getParam("left_cam_rosbag_topic", left_imgs_topic_))``,
    Kimera-VIO-ROS; ``std::getline(in, name_)``). Not a call clang leaves unresolved (in a
    class template every call is dependent: nav2_util's ``create_server(..., action_name_,
    ...)``), nor one of a permissive value's (``haros_any``'s ``operator()`` takes what it
    is given by forwarding reference)."""
    at = write.at
    if at.kind != CursorKind.CALL_EXPR or write.whole or by_operator(write):
        return False
    target = at.referenced
    if target is None or target.type.kind != TypeKind.FUNCTIONPROTO:
        return False
    parent = target.semantic_parent
    if parent is not None and parent.spelling == ANY_CLASS:
        return False
    args = list(at.get_arguments())
    types = list(target.type.argument_types())
    if target.kind == CursorKind.CXX_METHOD and at.spelling.startswith("operator") and (
            len(args) == len(types) + 1):
        args = args[1:]  # a member operator's call lists its object first
    for arg, ptype in zip(args, types, strict=False):
        # (the cursor itself: in a macro's expansion every argument has one place)
        if arg == write.target or strip(arg) == write.target:
            return ptype.kind == TypeKind.LVALUEREFERENCE and (
                not ptype.get_pointee().is_const_qualified())
    return False


def _call(call: Cursor, source: dict[str, bytes]) -> list[Write]:
    args = list(call.get_arguments())
    if call.spelling == "operator=" and len(args) == 2:
        return [Write(strip(args[0]), args[1], call, True)]
    if call.spelling in _COMPOUND and len(args) == 2:
        # ``topic += "/more"`` on a class (std::string): a member operator whose object
        # is argument 0, changed in place (not the first parameter of its signature)
        return [Write(strip(args[0]), None, call, False)]
    operator = between(args[0], args[1], source) if (
        call.referenced is None and len(args) == 2) else None
    if operator in _READING:
        return []  # ``a_ && f(x)`` in a template: an operator clang leaves unresolved
    if operator == "<<" or (operator == "" and len(args) == 2 and _inserting(args[0])):
        args = args[:1]  # ``out << "x is " << x_`` in a template inserts x_: reads it
    found: list[Write] = []
    searched = searched_key(call)
    for index, arg in enumerate(args):  # an lvalue passed as it is: a reference
        if arg.kind in _NAMES and arg.referenced is not None:
            if searched is not None and index == len(args) - 1:
                # ``nh.searchParam("tf_prefix", key)`` writes the name it found to
                # ``key``: the call is its value (``values.Scope.string`` reads it so)
                found.append(Write(arg, call, call, True))
            elif may_write(call, index):
                found.append(Write(arg, None, call, False))
            continue
        bare = strip(arg)
        if _is_array(bare) and not const_array(bare.referenced) and (
                may_write(call, index, decayed=True)):
            # ``snprintf(topic, size, "analog_output%02d", i)`` fills the array
            # ``char topic[] = "analog_output00"`` (phidgets): not its initializer
            found.append(Write(bare, None, call, False))
    children = list(call.get_children())
    method = call.referenced
    unresolved = unresolved_string_method(call, source)
    if unresolved is not None and unresolved[1] in _STRING_CHANGES:
        # a method that changes the string, its overload left to the template's
        # instantiation: the string is changed (``append``: ``values`` reads it as ``+=``)
        found.append(Write(unresolved[0], None, call, False))
    if children and children[0].kind == CursorKind.MEMBER_REF_EXPR and (
        method is not None and not method.is_const_method()
    ):
        for obj in children[0].get_children():
            obj = strip(obj)
            if obj.type.get_canonical().kind == TypeKind.POINTER:
                continue  # p->m() changes *p, not p
            given = written_arguments(call) if call.spelling == "reset" else []
            if len(given) == 1 and _smart_pointer(obj):
                found.append(Write(obj, given[0], call, True))
            elif emptied(call):
                # ``namespace_.clear()``: the string holds "" after it, the call as its
                # value (``values.Scope.string`` reads it so)
                found.append(Write(obj, call, call, True))
            else:
                found.append(Write(obj, None, call, False))
    return found


# output-only streams: ``in >> x_`` writes x_, and a stringstream may be read from
_STREAMS = frozenset({"ostream", "ostringstream", "ofstream", "basic_ostream",
                      "basic_ostringstream", "basic_ofstream"})


def _inserting(left: Cursor) -> bool:
    """Whether ``left`` is a chain of ``<<`` that starts at an output stream (in a macro,
    ``RF_DEBUG(... << x_)``, where the operator's text is not at hand): what it inserts
    is read, whatever the operator between ``left`` and the next operand."""
    for _ in range(256):
        left = strip(left)
        if left.kind != CursorKind.CALL_EXPR:
            break
        args = list(left.get_arguments())
        if len(args) == 2 and (left.referenced is None or left.spelling == "operator<<"):
            left = args[0]
        elif left.spelling == "operator<<" and len(args) == 1:
            objects = [c for c in left.get_children() if c.kind.is_expression()]
            if not objects:
                return False
            left = objects[0]
        else:
            break
    spelling = left.type.get_canonical().spelling.split("<")[0].rstrip(" &")
    return spelling.rpartition("::")[2] in _STREAMS


# the methods of std::string that change it
_STRING_CHANGES = frozenset({"append", "assign", "insert", "replace", "erase", "push_back",
                             "pop_back", "clear", "resize", "swap"})


def unresolved_string_method(call: Cursor, source: dict[str, bytes]
                             ) -> tuple[Cursor, str] | None:
    """(the string, the method's name, read from the text) of ``s.method(...)`` on a
    ``std::string`` that a template leaves unresolved, an argument of a type that
    depends on its parameters (robocup-pkg's robot_comm: ``name.append(m.name())`` in
    ``UdpToTopicEntry<T, P>::execute``, ``m`` a ``T&``); else None."""
    if call.referenced is not None:
        return None
    children = list(call.get_children())
    if not children or children[0].kind != CursorKind.MEMBER_REF_EXPR:
        return None
    # the object first (the parse may keep the overloads it could not choose after it)
    objects = [strip(c) for c in children[0].get_children()]
    if not objects or "basic_string<char" not in objects[0].type.get_canonical().spelling:
        return None
    start, end = children[0].extent.start, children[0].extent.end
    text = source.get(start.file.name) if start.file is not None else None
    if text is None or end.file is None or end.file.name != start.file.name:
        return None
    written = text[start.offset:end.offset].decode("utf-8", "replace")
    name = written.replace("->", ".").rpartition(".")[2].strip()
    return (objects[0], name) if name.isidentifier() else None


def appended_to(call: Cursor, source: dict[str, bytes] | None = None
                ) -> tuple[Cursor, Cursor] | None:
    """(the string, the text appended) when ``call`` is ``s.append(text)`` of a
    ``std::string``, which changes ``s`` as ``s += text`` does (also one a template
    leaves unresolved, read with the ``source`` text); else None."""
    given = written_arguments(call)
    if call.spelling != "append":
        unresolved = unresolved_string_method(call, source) if source is not None else None
        if unresolved is None or unresolved[1] != "append" or len(given) != 1:
            return None
        return unresolved[0], given[0]
    method = call.referenced
    parent = method.semantic_parent if method is not None else None
    if len(given) != 1 or parent is None or (
            parent.spelling.split("<")[0] not in ("basic_string", "string")):
        return None
    children = list(call.get_children())
    if not children or children[0].kind != CursorKind.MEMBER_REF_EXPR:
        return None
    objects = [strip(c) for c in children[0].get_children()]
    if len(objects) != 1 or objects[0].type.get_canonical().kind == TypeKind.POINTER:
        return None
    return objects[0], given[0]


def emptied(call: Cursor) -> bool:
    """Whether ``call`` is ``s.clear()`` of a ``std::string``, which leaves it empty."""
    if call.spelling != "clear" or written_arguments(call):
        return False
    method = call.referenced
    parent = method.semantic_parent if method is not None else None
    return parent is not None and parent.spelling.split("<")[0] in ("basic_string", "string")


# roscpp's searches for a parameter up the namespaces: the key searched for, and the
# result (the name found) written to the last argument; ``ros::param::search(ns, key,
# result)`` searches from the namespace it is given
_SEARCHES = {("ros::NodeHandle", "searchParam"): (2,), ("ros::param", "search"): (2, 3)}


def searched_from_node(call: Cursor) -> bool:
    """Whether a search ``searched_key`` names starts at the node's own name:
    ``ros::param::search(key, result)`` asks the master from this_node::getName() up,
    the node's private namespace first (a NodeHandle's from the handle's namespace, the
    three-argument ``search(ns, key, result)``'s from ``ns``)."""
    method = call.referenced
    parent = method.semantic_parent if method is not None else None
    return call.spelling == "search" and parent is not None and (
        qualified_name(parent) == "ros::param") and len(written_arguments(call)) == 2


def searched_key(call: Cursor) -> Cursor | None:
    """The key argument of roscpp's ``NodeHandle::searchParam(key, result)`` or
    ``ros::param::search([ns, ]key, result)``, whose result is the full name of the
    parameter ``key`` names in the nearest namespace that has it; None for any other
    call."""
    if call.spelling not in ("searchParam", "search"):
        return None
    method = call.referenced
    parent = method.semantic_parent if method is not None else None
    args = written_arguments(call)
    if parent is None or len(args) not in _SEARCHES.get(
            (qualified_name(parent), call.spelling), ()):
        return None
    return args[-2]


def _smart_pointer(expr: Cursor) -> bool:
    ctype = expr.type.get_canonical()
    if ctype.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
        ctype = ctype.get_pointee().get_canonical()
    return ctype.kind == TypeKind.RECORD and (
        ctype.get_declaration().spelling in SMART_POINTERS)


def _assigning(node: Cursor, source: dict[str, bytes]) -> bool:
    """Whether a unary operator writes its operand: ``++``, ``--`` (before or after it)
    or ``&`` (its address taken), read from the source text (the tokens where the text
    is not at hand)."""
    start, end = node.extent.start, node.extent.end
    text = source.get(start.file.name) if start.file is not None else None
    if text is not None and end.file is not None and end.file.name == start.file.name:
        written = text[start.offset:end.offset]
        return written.startswith((b"++", b"--")) or written.endswith((b"++", b"--")) or (
            written.startswith(b"&") and not written.startswith(b"&&"))
    tokens = [t.spelling for t in node.get_tokens()]
    return bool(tokens) and (tokens[0] in ("++", "--", "&") or tokens[-1] in ("++", "--"))


def between(first: Cursor, second: Cursor, source: dict[str, bytes]) -> str:
    """The source text between two operands: a binary operator's token."""
    end, start = first.extent.end, second.extent.start
    if end.file is None or start.file is None or end.file.name != start.file.name:
        return ""
    text = source.get(end.file.name)
    if text is None:
        return ""
    return text[end.offset:start.offset].decode("utf-8", "replace").strip()


# compound assignments a class overloads: they change their left operand
_COMPOUND = frozenset(f"operator{op}=" for op in ("+", "-", "*", "/", "%", "&", "|", "^",
                                                   "<<", ">>"))


def may_write(call: Cursor, index: int, decayed: bool = False) -> bool:
    """Whether the call may change a variable passed as its argument ``index``: unless
    the parameter is a value or a const reference (``make_shared<T>(args)`` forwards to
    a constructor, which takes names by value or const reference). An array passed as a
    pointer to its data (``decayed``) may be changed through a pointer to non-const."""
    target = call.referenced
    if target is None:
        return True
    if target.spelling in _MAKERS:
        return False
    ftype = target.type
    if ftype.kind != TypeKind.FUNCTIONPROTO:
        return True
    types = list(ftype.argument_types())
    if target.kind == CursorKind.CXX_METHOD and call.spelling.startswith("operator") and (
        call.spelling != "operator()" and len(list(call.get_arguments())) == len(types) + 1
    ):  # a member operator's call lists its object first (``f % kNs``: boost::format).
        # Not ``operator()``, left as it was (its arguments matched one parameter on): a
        # permissive value's call (``haros_any``'s ``operator()(A &&...)``) would make
        # every lvalue it is given a write, a change of its own to decide (cob_bms_driver's
        # ``socketcan_interface_.init(can_device_, false)`` would lose the default can0)
        if index == 0:
            return not target.is_const_method()
        index -= 1
    if index >= len(types):
        return not decayed  # a C variadic: a printf family's arguments are read
    ptype = types[index]
    if ptype.kind == TypeKind.LVALUEREFERENCE:
        return not ptype.get_pointee().is_const_qualified()
    if decayed and ptype.get_canonical().kind == TypeKind.POINTER:
        return not ptype.get_canonical().get_pointee().is_const_qualified()
    return False


def default_constructed(init: Cursor) -> bool:
    """A declaration's initialiser that is the default constructor: no value given."""
    init = strip(init)
    return (init.kind == CursorKind.CALL_EXPR and init.referenced is not None
            and init.referenced.kind == CursorKind.CONSTRUCTOR
            and not written_arguments(init) and not list(init.get_children()))


def _is_array(cursor: Cursor) -> bool:
    """A variable of array type named as it is (passed, it is a pointer to its data)."""
    return (cursor.kind in _NAMES
            and cursor.referenced is not None and cursor.referenced.type.get_canonical().kind
            in (TypeKind.CONSTANTARRAY, TypeKind.INCOMPLETEARRAY))


def const_array(decl: Cursor) -> bool:
    """``constexpr char kTopic[] = "submap_list";`` (cartographer_ros' node_constants.h):
    the const is on the elements, not on the array type."""
    arrays = (TypeKind.CONSTANTARRAY, TypeKind.INCOMPLETEARRAY)
    canonical = decl.type.get_canonical()  # whose element type has lost its const
    if canonical.kind not in arrays:
        return False
    # a typedef of an array type (va_list) has no element type of its own
    written = decl.type if decl.type.kind in arrays else canonical
    return bool(written.element_type.is_const_qualified())


def parameter_callback(function: Cursor) -> bool:
    """Whether ``function`` takes rclcpp parameters (``std::vector<rclcpp::Parameter>``,
    ``const rclcpp::Parameter &``): a callback of parameter changes at run time (every
    navigation2 server's ``dynamicParametersCallback``). What it writes is written when
    a user sets a parameter after start-up, not on the way to the node's calls: the
    member readers leave its writes out (amcl's ``scan_topic_``, set from its parameter
    in ``initParameters`` and again there)."""
    for child in function.get_children():
        if child.kind == CursorKind.PARM_DECL and "rclcpp::Parameter" in (
                child.type.get_canonical().spelling.replace("rclcpp::ParameterEvent", "")):
            return True
    return False

