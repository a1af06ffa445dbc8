"""Whose ROS 2 node a C++ call is made on, when one executable creates several.

Every function's calls have an owner (``owner_of``): the class of a method, else the free
function (or static method) itself. A node construction (``: Node("name")``,
``make_shared<rclcpp::Node>``) names its owner's node; a class of the workspace that names
none takes the node of the owners that construct it (``constructed_class``), as a device
object given the node.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from clang.cindex import Cursor, CursorKind, Type, TypeKind, conf

from . import api
from .call_types import factory_made
from .cursors import from_standin
from .expressions import lost_class
from .handles import qualified_name
from .values import initializer, strip

MAX_DEPTH = 6

_CLASSES = frozenset({
    CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL, CursorKind.CLASS_TEMPLATE,
    CursorKind.CLASS_TEMPLATE_PARTIAL_SPECIALIZATION,
})


def owner_of(function: Cursor) -> str:
    """Whose node a function's calls are made on, as far as the file tells: its class
    (``ns::Driver`` for a method, a default member initialiser), else the free function
    or static method itself (``main()``, ``ns::Driver::footprint()``). In a translation
    unit's result a call's ``node_name`` is its owner; the node's result turns it into
    the name that owner's constructor gives."""
    parent = function.semantic_parent
    if parent is not None and parent.kind in _CLASSES:
        # a static method runs on no object of its class: it is a function of its own,
        # whose calls are made where it is called (a call of it builds nothing)
        if function.kind in (CursorKind.CXX_METHOD, CursorKind.FUNCTION_TEMPLATE) and (
                function.is_static_method()):
            return f"{qualified_name(parent)}::{function.spelling}()"
        return qualified_name(parent)
    scope = qualified_name(parent)
    return f"{scope}::{function.spelling}()" if scope else f"{function.spelling}()"


def static_class(function: Cursor) -> list[str]:
    """The class of a static method (``[ns::C]`` for ``ns::C::m()``, whose owner is the
    function itself: ``owner_of``); none for any other function."""
    parent = function.semantic_parent
    if parent is not None and parent.kind in _CLASSES and function.kind in (
            CursorKind.CXX_METHOD, CursorKind.FUNCTION_TEMPLATE) and (
            function.is_static_method()):
        return [qualified_name(parent)]
    return []


def constructed_class(call: Cursor, owned: Callable[[str], bool]) -> str | None:
    """The class of the workspace a call constructs (``T(...)``, ``new T(...)``,
    ``std::make_shared<T>(...)``), by its qualified name."""
    made = _construction(call, owned)
    return (qualified_name(made[0]) or None) if made is not None else None


def constructed_bases(call: Cursor, owned: Callable[[str], bool]) -> list[tuple[str, str]]:
    """(class, base) for each base of the workspace, transitively, of the class ``call``
    constructs: constructing a class runs its bases' constructors, implicit ones too
    (a base whose constructor names the node: ``class D : public B {}``)."""
    made = _construction(call, owned)
    return class_bases(made[0], owned) if made is not None else []


def class_bases(cls: Cursor, owned: Callable[[str], bool]) -> list[tuple[str, str]]:
    """(class, base) for each base of the workspace of class ``cls``, transitively."""
    out: list[tuple[str, str]] = []
    stack = [(cls, 0)]
    while stack:
        cls, depth = stack.pop()
        definition = cls.get_definition() or cls
        # a class template's specialisation (``class Zones : public Server<int>``): the
        # bases its template declares (clang lists none on the implicit specialisation)
        template = conf.lib.clang_getSpecializedCursorTemplate(definition)
        children = [*definition.get_children(), *(
            template.get_children() if template is not None else ())]
        for child in children:
            base = child.referenced if child.kind == CursorKind.CXX_BASE_SPECIFIER else None
            if base is None:
                continue
            base = base.get_definition() or base
            where = base.location.file
            if base.kind not in _CLASSES or where is None or not owned(where.name):
                continue
            pair = (qualified_name(cls), qualified_name(base))
            if all(pair) and pair not in out and depth < MAX_DEPTH:
                out.append(pair)
                stack.append((base, depth + 1))
    return out


def construction_dropped(variable: Cursor, owned: Callable[[str], bool]) -> Cursor | None:
    """The class of the workspace that a variable declared without an initialiser
    (``msf_pose_sensor::PoseSensorManager manager;``) is of, when the parse kept no
    construction of it: C++ default-constructs it all the same, and clang leaves the
    construction out when the class's code holds errors (ethzasl_msf's sensor managers,
    whose state types need boost::fusion: abstract to the parse). None for a variable
    the parse kept (``construction_lost``), or of a class with no constructor of its
    own, or of a class that is not the workspace's."""
    cls = lost_class(variable)
    if cls is None:
        return None
    where = cls.location.file
    if cls.kind not in _CLASSES or where is None or not owned(where.name):
        return None
    template = conf.lib.clang_getSpecializedCursorTemplate(cls)
    own = [c for each in (cls, template) if each is not None
           for c in each.get_children() if c.kind == CursorKind.CONSTRUCTOR]
    return cls if own else None


# the types of the variables our stand-ins' registration macros declare
# (``RCLCPP_COMPONENTS_REGISTER_NODE(C)``, ``PLUGINLIB_EXPORT_CLASS(C, Base)``): their
# first template argument is the class a container, nodelet manager or host constructs
REGISTRATIONS = frozenset({"haros_standin::component_registration",
                           "haros_standin::plugin_export"})


def registered_class(variable: Cursor, owned: Callable[[str], bool]) -> Cursor | None:
    """The class of the workspace a variable of a registration macro registers
    (``REGISTRATIONS``), else None."""
    kind = variable.type.get_canonical()
    declaration = kind.get_declaration()
    if declaration is None or qualified_name(declaration) not in REGISTRATIONS:
        return None
    argument = kind.get_template_argument_type(0)
    if argument is None or argument.kind == TypeKind.INVALID:
        return None
    cls = argument.get_canonical().get_declaration()
    cls = cls.get_definition() or cls
    where = cls.location.file if cls is not None else None
    if cls is None or cls.kind not in _CLASSES or where is None or not owned(where.name):
        return None
    return cls


def registered_alias(variable: Cursor) -> str | None:
    """The qualified name a registration macro's variable (``REGISTRATIONS``) writes
    for its class when that is an alias (``using SmacPlannerHybrid =
    SmacPlannerHybridT<NodeHybrid>; PLUGINLIB_EXPORT_CLASS(nav2_smac_planner::
    SmacPlannerHybrid, ...)``, a ``typedef``): the name a plugin description gives the
    class, which is not the class's own; else None."""
    written = variable.type.get_template_argument_type(0)
    declaration = written.get_declaration() if written.kind != TypeKind.INVALID else None
    if declaration is None or declaration.kind not in (CursorKind.TYPE_ALIAS_DECL,
                                                       CursorKind.TYPEDEF_DECL):
        return None
    scope = qualified_name(declaration.semantic_parent)
    return f"{scope}::{declaration.spelling}" if scope else declaration.spelling


def _construction(call: Cursor, owned: Callable[[str], bool]
                  ) -> tuple[Cursor, Cursor | None] | None:
    """The class of the workspace a call constructs and the constructor it calls (None
    when made through a factory: ``make_shared``, ``new`` of a template argument)."""
    target = call.referenced
    if target is None:
        return None
    cls: Cursor | None = None
    constructor: Cursor | None = None
    if target.kind == CursorKind.CONSTRUCTOR:
        cls, constructor = target.semantic_parent, target
    elif (qualified_name(target.semantic_parent), target.spelling) in api.FACTORIES:
        cls = factory_made(call)
    elif target.kind == CursorKind.CXX_METHOD and target.is_static_method():
        cls = _own_factory(target)
    if cls is None or cls.kind not in _CLASSES:
        return None
    where = cls.location.file
    if where is None or not owned(where.name):
        return None
    return cls, constructor


def _own_factory(method: Cursor) -> Cursor | None:
    """The class of a static method that returns a new object of it, by value, pointer
    or smart pointer (``static Ptr make_shared(action, node) { return
    std::make_shared<ActionExecutor>(action, node); }``): calling it constructs the
    class, as ``std::make_shared<ActionExecutor>`` would."""
    cls = method.semantic_parent
    if cls is None or cls.kind not in _CLASSES:
        return None
    returned = method.result_type.get_canonical()
    while returned.kind in (TypeKind.POINTER, TypeKind.LVALUEREFERENCE):
        returned = returned.get_pointee().get_canonical()
    decl = returned.get_declaration()
    if decl.kind != CursorKind.NO_DECL_FOUND and decl.spelling in _SMART_POINTERS and (
            returned.get_num_template_arguments() > 0):
        decl = returned.get_template_argument_type(0).get_canonical().get_declaration()
    own = cls.get_definition() or cls
    return cls if decl.kind != CursorKind.NO_DECL_FOUND and (
        (decl.get_definition() or decl) == own) else None


# the node classes whose object a node's code hands to other code (``*this`` of a class
# derived from one, or an expression of one of these types)
_NODE_CLASSES = ("rclcpp::Node", "rclcpp_lifecycle::LifecycleNode", "ros::NodeHandle")
_SMART_POINTERS = frozenset({"shared_ptr", "weak_ptr", "unique_ptr"})
_NODE_TYPE = re.compile(r"\b(?:rclcpp::Node|rclcpp_lifecycle::LifecycleNode|ros::NodeHandle|"
                        r"rclcpp::node_interfaces::Node(?:Topics|Services|Parameters)Interface)\b")


def unseen_construction(call: Cursor, owned: Callable[[str], bool]
                        ) -> tuple[Cursor, Cursor] | None:
    """A construction of a workspace class whose constructor's code is not in this
    translation unit (declared in a header, defined in another library's source) and
    that is given the node (``*this``, ``this``, ``shared_from_this()``, a node or
    NodeHandle, a node interface): the class and the argument. Its constructor may make
    ROS calls on the node that this unit does not show (Autoware's controller node
    builds its lateral and longitudinal controllers so)."""
    cls = opaque_construction(call, owned)
    given = node_arguments(call) if cls is not None else []
    if cls is None or not given:
        return None
    return cls, given[0]


def opaque_construction(call: Cursor, owned: Callable[[str], bool]) -> Cursor | None:
    """The workspace class ``call`` constructs when the code of its constructor is not
    in this translation unit: what that constructor builds is not seen here."""
    made = opaque_constructor(call, owned)
    return made[0] if made is not None else None


def opaque_constructor(call: Cursor, owned: Callable[[str], bool]
                       ) -> tuple[Cursor, Cursor | None] | None:
    """``opaque_construction``'s class with the constructor ``call`` calls (None when
    made through a factory, which may call any)."""
    made = _construction(call, owned)
    if made is None or _code_here(made[1], made[0]):
        return None
    return made


def constructors_here(cls: Cursor) -> bool:
    """Whether the unit has the code of a constructor of ``cls``: defined in the class,
    out of it in a file of the unit, or as a template (``_code_here``)."""
    definition = cls.get_definition() or cls
    for child in definition.get_children():
        if child.kind == CursorKind.CONSTRUCTOR and child.get_definition() is not None:
            return True
    return _code_here(None, cls)


def _code_here(constructor: Cursor | None, cls: Cursor) -> bool:
    """Whether the unit has the code of the constructor (or, made through make_shared,
    of one of the class's constructors), a template's too (a header's class template or
    template constructor: nav2's TwistSubscriber; defined in the class or out of it)."""
    if constructor is not None:
        if constructor.get_definition() is not None:
            return True
        template = conf.lib.clang_getSpecializedCursorTemplate(constructor)
        if template is not None and template.get_definition() is not None:
            return True
    template = conf.lib.clang_getSpecializedCursorTemplate(cls)
    for each in (cls, template):
        if each is None:
            continue
        for child in each.get_children():
            constructs = child.kind == CursorKind.CONSTRUCTOR or (
                child.kind == CursorKind.FUNCTION_TEMPLATE and CursorKind.from_id(
                    conf.lib.clang_getTemplateCursorKind(child)) == CursorKind.CONSTRUCTOR)
            # defined in the class, or out of it in the unit (depthai_bridge's header:
            # ``template <..> BridgePublisher<R, S>::BridgePublisher(..) { .. }``)
            if constructs and (child.is_definition() or child.get_definition() is not None):
                return True
    return False


def node_arguments(call: Cursor) -> list[Cursor]:
    """The arguments of ``call`` that are the node (``_is_node``)."""
    return [arg for arg in call.get_arguments() if _is_node(arg)]


def options_arguments(call: Cursor) -> list[Cursor]:
    """The arguments of ``call`` that are an ``rclcpp::NodeOptions``: an object built
    with them is a node of its own (a component class), in the process of the caller."""
    return [arg for arg in call.get_arguments()
            if qualified_name(_pointee(arg.type.get_canonical()).get_declaration())
            == "rclcpp::NodeOptions"]


def node_names(function: Cursor) -> frozenset[str]:
    """The words by which ``function``'s code names its node: its parameters and locals
    of a node type (a node, NodeHandle, node interface, or a pointer to one: a main's
    ``auto node = rclcpp::Node::make_shared(..)``, which moveit2_tutorials' mains hand
    to ``MoveGroupInterface`` of a header not found), and ``this`` / ``shared_from_this``
    in a method of a class derived from a node; in a method, its class's members of a
    node type (rpg_quadrotor_control's sbus_bridge reads every parameter with
    ``quadrotor_common::getParam(name, value, pnh_)`` of a missing header)."""
    found: set[str] = set()
    parent = function.semantic_parent
    if function.kind != CursorKind.FUNCTION_DECL and parent is not None and (
        _derives_from_node(parent, 0)
    ):
        found |= {"this", "shared_from_this"}
    if function.kind != CursorKind.FUNCTION_DECL and parent is not None and (
            parent.kind in (CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL,
                            CursorKind.CLASS_TEMPLATE)):
        found |= {c.spelling for c in parent.get_children()
                  if c.kind == CursorKind.FIELD_DECL and c.spelling
                  and _NODE_TYPE.search(c.type.get_canonical().spelling)}
    for c in function.walk_preorder():
        if c.kind not in (CursorKind.PARM_DECL, CursorKind.VAR_DECL) or not c.spelling:
            continue
        kind = c.type.get_canonical()
        # a NodeOptions (a parameter or a local): what is built with it is a node of its
        # own in this process, a component class (raspimouse_ros2_examples'
        # line_follower builds ``raspimouse::Raspimouse(options)`` of a missing header
        # beside its own node)
        if (_NODE_TYPE.search(kind.spelling) and (
            c.kind == CursorKind.VAR_DECL or c.semantic_parent == function
        )) or qualified_name(_pointee(kind).get_declaration()) == "rclcpp::NodeOptions":
            found.add(c.spelling)
    return frozenset(found)


def binds_own_member(call: Cursor, given: list[Cursor]) -> bool:
    """Whether ``call`` is given, beside the node object, a pointer to a member function
    of that object's class or of one of its bases (kobuki_ros' ``ecl::Slot<...>(
    &KobukiRos::publishVersionInfo, *this)``, a signal's slot), or such a class's static
    member function, cast or not (camera_aravis2's ``g_signal_connect(device,
    "control-lost", (GCallback)CameraAravisNodeBase::handleControlLostSignal, this)``,
    a C library's callback and its user data): a callback binding, which calls that
    member with the object, whose calls are read where it is defined."""
    classes: set[str] = set()
    for arg in given:
        kind = arg.type.get_canonical()
        if kind.kind == TypeKind.POINTER:
            kind = kind.get_pointee()
        decl = kind.get_declaration()
        for _ in range(MAX_DEPTH):  # the class and its bases, first base first
            if decl is None or decl.kind not in _CLASSES:
                break
            classes.add(decl.get_usr())
            bases = [c.referenced for c in decl.get_children()
                     if c.kind == CursorKind.CXX_BASE_SPECIFIER and c.referenced is not None]
            decl = bases[0].get_definition() or bases[0] if bases else None
    if not classes:
        return False
    for arg in call.get_arguments():
        kind = arg.type.get_canonical()
        if kind.kind != TypeKind.MEMBERPOINTER:
            if _static_member_of(arg, classes):
                return True
            continue
        owner = kind.get_class_type().get_declaration()
        if owner is not None and owner.get_usr() in classes:
            return True
    return False


def _static_member_of(arg: Cursor, classes: set[str]) -> bool:
    """Whether ``arg`` names, through casts and ``&``, a static member function of one of
    ``classes`` (their USRs). A cast to a type of a missing header (``GCallback``) is a
    conversion the parse makes by a constructor of the permissive class: gone through."""
    expr = arg
    for _ in range(2 * MAX_DEPTH):  # each cast is a few implicit levels
        if expr.kind == CursorKind.DECL_REF_EXPR:
            method = expr.referenced
            return method is not None and method.kind == CursorKind.CXX_METHOD and \
                method.is_static_method() and method.semantic_parent is not None and \
                method.semantic_parent.get_usr() in classes
        if expr.kind not in (CursorKind.CSTYLE_CAST_EXPR, CursorKind.CXX_STATIC_CAST_EXPR,
                             CursorKind.CXX_REINTERPRET_CAST_EXPR, CursorKind.UNEXPOSED_EXPR,
                             CursorKind.PAREN_EXPR, CursorKind.UNARY_OPERATOR) and not (
                expr.kind == CursorKind.CALL_EXPR and expr.referenced is not None
                and expr.referenced.kind == CursorKind.CONSTRUCTOR):
            return False
        inner = [c for c in expr.get_children() if c.kind.is_expression()]
        if len(inner) != 1:
            return False
        expr = inner[0]
    return False


def _is_node(arg: Cursor) -> bool:
    """Whether an argument is the node (or a handle or interface of one)."""
    expr = strip(arg)
    for _ in range(MAX_DEPTH):  # *this, this
        if expr.kind == CursorKind.UNARY_OPERATOR or (
                expr.kind == CursorKind.UNEXPOSED_EXPR and not expr.spelling):
            inner = [c for c in expr.get_children() if c.kind.is_expression()]
            if len(inner) != 1:
                break
            expr = strip(inner[0])
        else:
            break
    if expr.kind == CursorKind.CXX_THIS_EXPR:
        return _derives_from_node(expr.type.get_pointee().get_declaration(), 0)
    if expr.kind == CursorKind.CALL_EXPR and expr.spelling == "shared_from_this":
        # the node's (rclcpp::Node is a std::enable_shared_from_this<Node>), not that of
        # another class that enables it for itself (MOLA's ExecutableBase::getAsPtr(),
        # in a program of no node); a type the parse cannot tell may be the node's
        made = _pointee(expr.type.get_canonical()).get_declaration()
        return made.kind not in _CLASSES or _derives_from_node(made, 0)
    canonical = arg.type.get_canonical()
    if _NODE_TYPE.search(canonical.spelling) is not None:
        return True
    # a node class of our stand-ins (navigation2's lifecycle nodes, when navigation2 is
    # installed: ``auto node = shared_from_this();`` in a class deriving nav2_util's)
    decl = _pointee(canonical).get_declaration()
    return from_standin(decl) and _derives_from_node(decl, 0)


def _pointee(ctype: Type) -> Type:
    """What a reference, pointer or smart pointer (``std::shared_ptr<T>``,
    ``weak_ptr``, ``unique_ptr``) type refers to."""
    for _ in range(MAX_DEPTH):
        if ctype.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE,
                          TypeKind.POINTER):
            ctype = ctype.get_pointee().get_canonical()
        elif ctype.get_declaration().spelling in _SMART_POINTERS and (
            ctype.get_num_template_arguments() > 0
        ):
            ctype = ctype.get_template_argument_type(0).get_canonical()
        else:
            break
    return ctype


def _derives_from_node(cls: Cursor, depth: int) -> bool:
    if cls is None or depth > MAX_DEPTH or cls.kind not in _CLASSES:
        return False
    if qualified_name(cls) in _NODE_CLASSES:
        return True
    return any(_derives_from_node(base.referenced, depth + 1)
               for base in cls.get_children()
               if base.kind == CursorKind.CXX_BASE_SPECIFIER and base.referenced is not None)


def handle_node(callee: Cursor) -> tuple[str, Cursor, tuple[str, str]] | None:
    """The node a call is made on when it is a local variable initialised by a node
    construction (``auto node = rclcpp::Node::make_shared("x"); node->create_x(...)``):
    the variable as an owner, the construction call and its ``api.RCLCPP_NODE_NAME``
    key."""
    objects = [c for c in callee.get_children() if c.kind.is_expression()]
    handle = strip(objects[0]) if objects else None
    for _ in range(MAX_DEPTH):  # through the smart pointer's operator->
        if handle is None or handle.kind == CursorKind.DECL_REF_EXPR:
            break
        inner = [c for c in handle.get_children() if c.kind.is_expression()]
        handle = strip(inner[0]) if inner else None
    variable = handle.referenced if handle is not None and handle.kind == (
        CursorKind.DECL_REF_EXPR) else None
    if variable is None or variable.kind != CursorKind.VAR_DECL:
        return None
    made = node_construction(initializer(variable))
    return None if made is None else (f"{variable.get_usr()}", *made)


def node_construction(value: Cursor | None) -> tuple[Cursor, tuple[str, str]] | None:
    """The node construction a variable's initialiser is (``rclcpp::Node n("x")``,
    ``std::make_shared<rclcpp::Node>("x")``, ``rclcpp::Node::make_shared("x")``), through
    the casts and copies around it, with its ``api.RCLCPP_NODE_NAME`` key; a factory's
    class is the one it makes (``factory_made``), not a type among that class's own
    template arguments."""
    for _ in range(MAX_DEPTH):
        if value is None:
            return None
        value = strip(value)
        target = value.referenced if value.kind == CursorKind.CALL_EXPR else None
        if target is not None:
            key = (qualified_name(target.semantic_parent), target.spelling)
            if key in api.FACTORIES:
                decl = factory_made(value)
                key = (qualified_name(decl), decl.spelling) if decl is not None else key
            if key in api.RCLCPP_NODE_NAME:
                return value, key
        inner = [c for c in value.get_children() if c.kind.is_expression()]
        value = inner[0] if len(inner) == 1 else None
    return None
