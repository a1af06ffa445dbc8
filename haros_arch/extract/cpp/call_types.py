"""The ROS type a primitive call gives its topic, service, action or parameter.

Read from the sources its API row names (``api.RosFunction.type_from``): a template
argument, the class the call is made on or constructs, the callback's parameter, an
argument's C++ type, or an argument that names the type as a string
(``create_generic_publisher(topic, "std_msgs/msg/String", qos)``). A custom type that a
``rclcpp::TypeAdapter`` specialisation of the translation unit adapts is its ROS type.
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from clang.cindex import Cursor, CursorKind, Type, TypeKind, conf

from . import api, msg_types
from .expressions import stripped_to_cast
from .handles import parameters, qualified_name
from .values import Scope, key_of, render, strip

_INTERFACE = ("msg", "srv", "action")
# the canonical spelling of a class template's own type parameter, as a type that uses
# it inside the template reads (``Server<ActionT>`` in ``Navigator<ActionT>``)
_PARAMETER = re.compile(r"type-parameter-0-(\d+)")
_TEMPLATE_PARAMETERS = frozenset({CursorKind.TEMPLATE_TYPE_PARAMETER,
                                  CursorKind.TEMPLATE_NON_TYPE_PARAMETER,
                                  CursorKind.TEMPLATE_TEMPLATE_PARAMETER})
MAX_USES = 64  # specialisations of one class template recorded per unit


class CallTypes:
    """Types of the calls of one translation unit (ROS 1 or ROS 2 spelling)."""

    def __init__(self, ros2: bool) -> None:
        self.ros2 = ros2
        self.adapters: dict[str, Type] = {}  # custom type's spelling -> ROS message type
        # class template -> (specialisation, the class or class template naming it) for
        # each base class and member type of the unit's classes that specialises it
        self.uses: dict[tuple[str, int], list[tuple[Type, Cursor]]] = {}

    def adapter(self, specialisation: Cursor) -> None:
        """Record what a ``TypeAdapter`` / ``ImplicitTypeAdapter`` specialisation adapts."""
        found = msg_types.adapted_types(specialisation)
        if found is not None:
            self.adapters[found[0]] = found[1]

    def specialised(self, ctype: Type, owner: Cursor, depth: int = 0) -> None:
        """Record the class template specialisations ``ctype`` (a base class or a
        member's type, declared in ``owner``) names, its template arguments' too
        (``std::unique_ptr<Server<ActionT>>``)."""
        if depth > 3 or ctype.kind == TypeKind.INVALID:
            return
        if ctype.get_canonical().get_num_template_arguments() > 0:
            ctype = ctype.get_canonical()  # with the defaults (``Heading<>``)
        count = ctype.get_num_template_arguments()
        if count < 1:
            return
        decl = ctype.get_canonical().get_declaration()
        if decl.kind == CursorKind.NO_DECL_FOUND:
            decl = ctype.get_declaration()  # a dependent one names the template itself
        template = decl if decl.kind == CursorKind.CLASS_TEMPLATE else \
            conf.lib.clang_getSpecializedCursorTemplate(decl)
        if template is not None and template.kind == CursorKind.CLASS_TEMPLATE:
            uses = self.uses.setdefault(key_of(template.canonical), [])
            if len(uses) < MAX_USES:
                uses.append((ctype, owner))
        for index in range(count):
            self.specialised(ctype.get_template_argument_type(index), owner, depth + 1)

    def bound(self, parm: Cursor, depth: int = 0, within: Cursor | None = None
              ) -> Type | None:
        """The type a class template's type parameter ``parm`` stands for in this unit:
        the argument every specialisation of the template that the unit's classes derive
        from or hold as members gives it, through the parameters of class templates that
        pass theirs on (``class Spin : public Timed<SpinAction>``, ``Navigator<ActionT>``
        holding a ``Server<ActionT>``); None when they disagree or none is known."""
        template = parm.semantic_parent
        if (template is None or template.kind != CursorKind.CLASS_TEMPLATE) and (
            within is not None and any(key_of(c) == key_of(parm)
                                       for c in within.get_children())
        ):  # a parameter of a member defined out of its class template (``template<class
            # T> void Server<T>::on_configure()``): the class's parameter
            template = within.semantic_parent
        own = _PARAMETER.fullmatch(parm.type.get_canonical().spelling)
        if depth > 4 or own is None or template is None or (
                template.kind != CursorKind.CLASS_TEMPLATE):
            return None
        index = int(own.group(1))
        found: dict[str, Type] = {}
        for ctype, owner in self.uses.get(key_of(template.canonical), []):
            if index >= ctype.get_num_template_arguments():
                return None
            given = ctype.get_template_argument_type(index)
            if given.kind == TypeKind.INVALID:
                return None
            passed = _PARAMETER.fullmatch(given.get_canonical().spelling)
            if passed is not None:  # the owner's own parameter, passed on
                owner_params = [c for c in owner.get_children()
                                if c.kind in _TEMPLATE_PARAMETERS]
                at = int(passed.group(1))
                if owner.kind != CursorKind.CLASS_TEMPLATE or at >= len(owner_params):
                    return None
                bound = self.bound(owner_params[at], depth + 1)
                if bound is None:
                    return None
                given = bound
            found.setdefault(given.get_canonical().spelling, given)
        return next(iter(found.values())) if len(found) == 1 else None

    def template_parameter(self, function: Cursor | None) -> tuple[Cursor, int] | None:
        """The class template and the index of its type parameter that the first
        parameter of a callback (``function``) takes (``const M&`` of
        ``StateSubscriber<M>::setMessage``), where nothing in the unit binds it to one
        type (``bound``): each construction then gives its own (``links.TYPE_ARGUMENT``)."""
        if function is None or function.kind == CursorKind.LAMBDA_EXPR:
            return None
        params = parameters(function)
        if not params:
            return None
        ctype = params[0]
        if ctype.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE,
                          TypeKind.POINTER):
            ctype = ctype.get_pointee()
        own = _PARAMETER.fullmatch(ctype.get_canonical().spelling.removeprefix("const "))
        template = function.semantic_parent
        if own is None or template is None or template.kind != CursorKind.CLASS_TEMPLATE:
            return None
        return template, int(own.group(1))

    def ros_type(self, name: str) -> str:
        """A ROS 1 type name, written the ROS 2 way (``pkg/msg/Name``) in a ROS 2 node."""
        if not self.ros2 or name.count("/") != 1:
            return name
        package, base = name.split("/")
        return f"{package}/msg/{base}"

    def of_call(self, spec: api.RosFunction, call: Cursor, args: list[Cursor],
                function: Cursor | None, cls: Cursor | None, scope: Scope) -> str | None:
        found = self._declared(spec, call, args, function, cls, scope)
        if found is not None and spec.action_type and found.endswith("Action"):
            found = found.removesuffix("Action")
        if found is None and spec.fixed_type is not None:
            found = self.ros_type(spec.fixed_type)
        return found

    def message(self, ctype: Type) -> str | None:
        """The ROS message type ``ctype`` is, if it is one."""
        return self._message(ctype)

    def _message(self, ctype: Type, service: bool = False) -> str | None:
        return msg_types.message_type(ctype, service, self.adapters, self.ros2)

    def _declared(self, spec: api.RosFunction, call: Cursor, args: list[Cursor],
                  function: Cursor | None, cls: Cursor | None, scope: Scope) -> str | None:
        for source in spec.type_from:
            found: str | None = None
            if source in ("template", "template-value"):
                ref = template_argument(call)
                if source == "template" and ref is not None:
                    ref = aliased_argument(call, ref) or ref
                ctype = ref.type if ref is not None else constructed_argument(call)
                held = ref.referenced if ref is not None else None
                if held is not None and held.kind == CursorKind.TEMPLATE_TYPE_PARAMETER:
                    ctype = self.bound(held, within=scope.body) or ctype
                if ctype is None and source == "template-value":
                    ctype = _explicit_parameter_type(call, spec.type_arg)
                if ctype is None and spec.kind == "declare" and spec.per_element:
                    # declare_parameters(prefix, std::map<std::string, T>) deduces T,
                    # each parameter's type: the element of the std::vector<T> it returns
                    returned = call.type.get_canonical()
                    if returned.get_declaration().spelling == "vector" and (
                        returned.get_num_template_arguments() >= 1
                    ):
                        ctype = returned.get_template_argument_type(0)
                written = _class_template_first(call)
                if source == "template-value" and written is not None:
                    # declare_parameter<std::vector<T>>: T[], what it returns (a call the
                    # parse could not resolve has no type: the element written, then [])
                    array = msg_types.param_type(call.type)
                    if (array is None or not array.endswith("[]")) and (
                            written.spelling == "vector" and ctype is not None):
                        element = msg_types.param_type(ctype)
                        array = None if element is None or element.endswith("[]") \
                            else element + "[]"
                    if array is not None and array.endswith("[]"):
                        return array
                if source == "template" and written is not None and (
                    cloud := msg_types.template_message(written, self.ros2)
                ) is not None:  # advertise<pcl::PointCloud<P>>: not P
                    return cloud
                if ctype is not None:
                    found = (self._message(ctype) if source == "template"
                             else msg_types.param_type(ctype))
            elif source == "class" and cls is not None:
                ctype = cls.type
                if ctype.get_num_template_arguments() > 0:
                    found = self._message(ctype.get_template_argument_type(0))
            elif source in ("callback", "service-callback") and (
                function is not None or spec.callback_arg is not None
            ):
                params = parameters(function) if function is not None else _held_parameters(
                    args, spec.callback_arg if not spec.optional_handle else None)
                if source == "service-callback" and len(params) == 3:
                    params = params[1:]  # ROS 2: (request header, request, response)
                if params:
                    found = self._message(params[0], source == "service-callback")
            elif source in ("arg", "value", "type-name") and spec.type_arg is not None and (
                spec.type_arg < len(args)
            ):
                arg = args[spec.type_arg]
                # (a value's type as written: ``static_cast<double>(0)`` is a double)
                ctype = (stripped_to_cast(arg) if source == "value" else strip(arg)).type
                if source == "type-name":
                    found = _type_name(render(scope.string(arg)), self.ros2)
                elif source == "arg":
                    # ros::service::call(name, request, response): the request names its
                    # service
                    found = self._message(ctype, spec.kind in ("client", "server"))
                else:  # the value a ParameterValue holds; a ParameterType constant
                    found = msg_types.param_type(ctype)
                    if found is None:
                        held = msg_types.held_value(arg, typed=True)
                        found = msg_types.param_type(held.type) if held is not arg else (
                            msg_types.parameter_type_constant(arg))
            elif source == "result" and call.kind == CursorKind.CALL_EXPR:
                found = msg_types.param_type(call.type)
            if found is not None:
                return found
        return None


def _held_parameters(args: list[Cursor], index: int | None) -> list[Type]:
    """The parameter types of a callback given as a variable that holds one
    (``boost::function<void(const M::ConstPtr&)> cb = boost::bind(...);
    ops.init("topic", 1, cb)``): of the function type its class is instantiated with."""
    if index is None or index >= len(args):
        return []
    held = strip(args[index]).type.get_canonical()
    if held.kind == TypeKind.LVALUEREFERENCE or held.kind == TypeKind.RVALUEREFERENCE:
        held = held.get_pointee().get_canonical()
    if held.get_num_template_arguments() < 1:
        return []
    signature = held.get_template_argument_type(0).get_canonical()
    if signature.kind != TypeKind.FUNCTIONPROTO:
        return []
    return list(signature.argument_types())


def callee(call: Cursor) -> Cursor:
    """The expression a call calls (its function's name, or the member it calls)."""
    children = list(call.get_children())
    return strip(children[0]) if children else call


def _qualifiers(head: Cursor) -> set[int]:
    """The start offsets of the type references that qualify the called name before
    its template arguments (``Cache::get<M>``'s ``Cache``: followed by ``::`` and before
    the first ``<``). In a template the call's function may not be resolved, so its
    class is not known to leave out: the tokens say which is the qualifier."""
    tokens = [(t.extent.start.offset, t.spelling) for t in head.get_tokens()]
    opening = next((at for at, text in tokens if text == "<"), None)
    found: set[int] = set()
    for child in head.get_children():
        if child.kind != CursorKind.TYPE_REF:
            continue
        end = child.extent.end.offset
        if opening is not None and end > opening:
            break
        after = next((text for at, text in tokens if at >= end), None)
        if after == "::":
            found.add(child.extent.start.offset)
    return found


def _written_references(call: Cursor) -> Iterator[Cursor]:
    """The template and type references written in the called function's name, in
    order, but the class a resolved method is of (``Class::`` of ``Class::f<M>``) and the
    qualifiers before the template arguments (``_qualifiers``: the same, where the call
    is not resolved, the tokens tell)."""
    target = call.referenced
    owner = target.semantic_parent if target is not None else None
    head = callee(call)
    qualifiers: set[int] | None = None
    children = list(head.get_children())
    for index, child in enumerate(children):
        if child.kind == CursorKind.TYPE_REF and (owner is None or child.referenced != owner):
            if qualifiers is None:
                qualifiers = _qualifiers(head)
            if child.extent.start.offset not in qualifiers and not _nests(
                    head, child, children[index + 1:index + 2]):
                yield child
        elif child.kind == CursorKind.TEMPLATE_REF:
            yield child


def _nests(head: Cursor, ref: Cursor, following: list[Cursor]) -> bool:
    """Whether the type reference ``ref`` only qualifies the type written next, its
    member (``create_publisher<VectorMap::Message>``, Autoware's interface specs: the
    type is ``Message``, the message ``VectorMap`` names, not the spec class)."""
    if not following or following[0].kind != CursorKind.TYPE_REF:
        return False
    end, start = ref.extent.end.offset, following[0].extent.start.offset
    between = [t.spelling for t in head.get_tokens()
               if end <= t.extent.start.offset < start]
    return between == ["::"]


def _class_template_first(call: Cursor) -> Cursor | None:
    """The class template written first among the template arguments of the called
    function (``subscribe<pcl::PointCloud<P>>``, whose first type reference is ``P``);
    None when a type is written first."""
    for child in _written_references(call):
        if child.kind == CursorKind.TYPE_REF:
            return None
        if child.referenced is not None:
            return child.referenced
    return None


def template_argument(call: Cursor) -> Cursor | None:
    """The first type written as a template argument of the called function."""
    return next((child for child in _written_references(call)
                 if child.kind == CursorKind.TYPE_REF), None)


def _explicit_parameter_type(call: Cursor, index: int | None) -> Type | None:
    """The type of the called function's parameter ``index`` when the call writes the
    function's template arguments: ``declare_parameter<double>("t", 20)`` declares a
    double (the parameter ``const double &``), not an int as the literal is. A builtin
    type written as a template argument has no cursor of its own to read it from."""
    target = call.referenced
    if index is None or target is None:
        return None
    tokens = [token.spelling for token in callee(call).get_tokens()]
    opened = tokens.index("<") if "<" in tokens else -1
    if opened < 1 or tokens[opened - 1] != target.spelling:
        return None
    params = list(target.get_arguments())
    return params[index].type if index < len(params) else None


def factory_made(call: Cursor) -> Cursor | None:
    """The declaration of the class ``std::make_shared<C>(...)`` (a row of
    ``api.FACTORIES``) makes: the pointer's own template argument, so that a class
    template's arguments (``make_unique<Subscriber<M, Node>>``) are not taken for it;
    else the first type written in the call."""
    made = call.type.get_canonical()
    if made.get_num_template_arguments() > 0:
        decl = made.get_template_argument_type(0).get_canonical().get_declaration()
        if decl.kind != CursorKind.NO_DECL_FOUND:
            return decl
    ref = template_argument(call)
    decl = ref.type.get_canonical().get_declaration() if ref is not None else None
    return None if decl is None or decl.kind == CursorKind.NO_DECL_FOUND else decl


def row_class(decl: Cursor, depth: int = 0) -> Cursor:
    """The class whose API row a construction of ``decl`` is: ``decl`` itself, or the
    base whose constructors it inherits and whose row it has (nav2's
    ``struct TransformListener : tf2_ros::TransformListener { using
    tf2_ros::TransformListener::TransformListener; }``), through several such classes.
    A class that writes constructors of its own is itself: its constructors' code says
    what they build."""
    if (qualified_name(decl), decl.spelling) in api.ALL or depth > 4:
        return decl
    definition = decl.get_definition() or decl
    own = decl.spelling.split("<")[0]
    for using in definition.get_children():
        if using.kind != CursorKind.USING_DECLARATION:
            continue
        # ``using Base::Base;``: clang names it after the class that inherits them
        bases = [ref.referenced for ref in using.get_children()
                 if ref.kind in (CursorKind.TYPE_REF, CursorKind.TEMPLATE_REF)
                 and ref.referenced is not None]
        if not bases or using.spelling not in (own, bases[-1].spelling):
            continue
        made = row_class(bases[-1], depth + 1)
        if (qualified_name(made), made.spelling) in api.ALL:
            return made
    return decl


def constructed_argument(call: Cursor) -> Type | None:
    """A class template's construction written without ``make_shared`` (a member
    initialiser ``client_(name, node)``, a local ``Client<T> c(name, node)``): the
    class's first template argument, which the call's type carries."""
    target = call.referenced
    if target is None or target.kind != CursorKind.CONSTRUCTOR:
        return None
    made = call.type.get_canonical()
    if made.get_num_template_arguments() < 1:
        return None
    found = made.get_template_argument_type(0)
    return found if found.kind != TypeKind.INVALID else None


def aliased_argument(call: Cursor, ref: Cursor) -> Cursor | None:
    """A factory's construction of a class template through a type alias
    (``std::make_unique<ActionServer>(...)`` with ``using ActionServer =
    nav2_util::SimpleActionServer<Action>``, ``<ActionT>`` in a template): the type
    reference of the class's first template argument in the alias, the type
    ``make_unique<SimpleActionServer<Action>>`` writes first."""
    target = call.referenced
    alias = ref.referenced
    if alias is None or alias.kind not in (CursorKind.TYPE_ALIAS_DECL,
                                           CursorKind.TYPEDEF_DECL):
        return None
    if target is not None and (qualified_name(target.semantic_parent),
                               target.spelling) not in api.FACTORIES:
        return None
    if target is None:  # a dependent call: the name written before its ``<``
        tokens = [token.spelling for token in callee(call).get_tokens()]
        if "<" not in tokens or tokens.index("<") < 1 or tokens[tokens.index("<") - 1] not in {
                name for _, name in api.FACTORIES}:
            return None
    children = list(alias.get_children())
    opened = next((i for i, c in enumerate(children) if c.kind == CursorKind.TEMPLATE_REF),
                  None)
    if opened is None:
        return None  # an alias of a class (a message's is a specialisation too)
    return next((c for c in children[opened + 1:] if c.kind == CursorKind.TYPE_REF), None)


def _type_name(text: str, ros2: bool = True) -> str | None:
    """A ROS 2 type as a string names it (``pkg/msg/Name``; ``pkg/Name`` is a message);
    a ROS 1 type, ``pkg/Name`` (roscpp's options of a datatype given as text)."""
    parts = text.split("/")
    if "?" in text or not all(parts):
        return None
    if not ros2:
        return text if len(parts) == 2 else None
    if len(parts) == 2:
        return f"{parts[0]}/msg/{parts[1]}"
    return text if len(parts) == 3 and parts[1] in _INTERFACE else None
