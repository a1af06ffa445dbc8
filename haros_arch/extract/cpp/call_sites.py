"""The calls of a file's own functions, so that a parameter's value can be read where the
function is called, and the values a constructor gives a class's members.

``setup(nh, "scan")`` makes ``topic`` of ``void setup(NodeHandle& nh, const std::string&
topic)`` the string ``scan``. A constructor is called by ``T obj(args)``, ``new T(args)``
and ``std::make_shared<T>(args)`` / ``make_unique`` (std or boost); an argument a call
leaves out is the parameter's default. When the calls disagree, or no call in the file
calls the function (a node's other files may), a string parameter is a placeholder part
(see ``values.PLACEHOLDER``) that ``links.resolve`` fills with each value the node's
files pass: one ROS call per value.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass

from clang.cindex import Cursor, CursorKind, LinkageKind, Type, TypeKind, conf

from . import api, msg_types
from .cursors import overloads
from .expressions import NULL_POINTERS, is_default_argument, lost_class, qualified_name, strip
from .synthesis import ANY as ANY_CLASS
from .values import (
    PLACEHOLDER,
    SEPARATOR,
    Parts,
    Scope,
    Value,
    _plain_value,
    initializer,
    key_of,
    render,
    written_arguments,
)
from .writes import Write, default_constructed, out_argument, parameter_callback, writes_in

_CALLABLE = frozenset({CursorKind.FUNCTION_DECL, CursorKind.CXX_METHOD, CursorKind.CONSTRUCTOR,
                       CursorKind.FUNCTION_TEMPLATE})
_CONSTRUCTORS = frozenset({CursorKind.CONSTRUCTOR, CursorKind.FUNCTION_TEMPLATE})
_MAKERS = frozenset({"make_shared", "make_unique", "allocate_shared"})


class CallSites:
    """The calls of the functions of one translation unit, by the function they call."""

    MAX_SITES = 16

    def __init__(self, functions: list[Cursor], macros: dict[str, str],
                 source: dict[str, bytes], external: bool = False,
                 main: str | None = None) -> None:
        self.functions = functions
        # the unit's own source: a function defined in a header is also compiled in
        # the node's other units, which may hold it with a placeholder (``passing_sites``)
        self.main = main
        self.macros = macros
        self.source = source
        # a string parameter whose value is not one the file agrees on: a placeholder
        # part that the calls in the node's files fill (``links``)
        self.external = external
        self.marked: set[tuple[str, int]] = set()  # functions given a placeholder
        # a virtual method given a placeholder -> (itself, the USRs of the base methods
        # it overrides): a call of one of those may run it (``links.OVERRIDES``)
        self.overrides: dict[str, tuple[Cursor, list[str]]] = {}
        self._index: dict[tuple[str, int], list[tuple[Cursor, Cursor]]] | None = None
        # the base constructor each argument list of ``base_initialisers`` calls
        self._base_calls: dict[tuple[str, int], Cursor] = {}
        # (site, callee) -> callee for the sites that are no call: a variable whose
        # construction the parse dropped, a constructor that leaves a base to C++
        self._implicit: dict[tuple[tuple[str, int], tuple[str, int]], Cursor] = {}
        self._scopes: dict[tuple[str, int], Scope] = {}
        self._active: set[tuple[str, int]] = set()  # parameters being read (recursion)
        # members whose constructors disagree, met while a call is emitted (None: not
        # recorded), and the constructor to take for one of them (member, constructor)
        self.forks: list[Fork] | None = None
        self._members: dict[tuple[str, int], list[tuple[Cursor | None, Cursor]]] = {}
        self._written: dict[tuple[str, int], bool] = {}  # ``written``, by member
        self._read_into: dict[tuple[str, int], bool] = {}  # ``read_into``, by member
        self._loaded: dict[tuple[str, int], bool] = {}  # ``loaded_elsewhere``, by class
        # the classes some function of the unit assigns an object of as a whole
        # (``whole_records``), read once when first asked
        self._whole: set[tuple[str, int]] | None = None
        self.choice: tuple[tuple[str, int], tuple[str, int]] | None = None
        # ``Class::member`` of each member read while a value was asked whose class's
        # constructors are all defined in other files, which may set it (cleared by the
        # caller that reports why a name is unknown)
        self.elsewhere: list[str] = []
        # the namespace of the handle an expression stands for, asked while a value is
        # read (``handles.Namespaces.value_namespace``, set by the visitor): where a
        # handle's ``resolveName(name)`` resolves ``name``
        self.handle_namespace: Callable[[Cursor, Scope], Parts] | None = None

    def agreed(self, parm: Cursor, read: Callable[[Cursor, Scope], Value],
               unknown: Value) -> Value:
        """``read`` of the argument each call passes for ``parm``, when all agree."""
        key = key_of(parm)
        if key in self._active:
            return unknown
        strings = self.external and isinstance(unknown, tuple)
        if strings and (not self._sites().get(self._function_key(parm))
                        or self._shared(parm.semantic_parent)
                        or _overriding(parm.semantic_parent)):
            marker = self.placeholder(parm)
            if marker is not None:
                return (marker,)  # type: ignore[return-value]
        self._active.add(key)
        arguments = self._arguments(parm)
        try:
            values = [read(arg, scope) for arg, scope in arguments]
        finally:
            self._active.discard(key)
        if values and all(v == values[0] for v in values) and not (
                strings and len(values) > 1 and None in values[0]  # type: ignore[operator]
                and not _one_variable(arg for arg, _ in arguments)):
            return values[0]
        # several calls, not one known value: each call's own, filled where the node's
        # calls are (``links``); calls that pass unknown strings from different variables
        # agree on nothing, each may pass another parameter's value (f1tenth's mux adds a
        # channel per parameter, ``add_channel(rand_drive_topic, ...)``, a method that
        # constructs it); the same member or variable passed by each is one value (nav2's
        # velocity smoother builds its OdomSmoother with ``odom_topic_`` at three places)
        # (and calls too many to read here: OrbbecSDK_ROS2's setAndGetNodeParameter,
        # called with ~180 names in its own file)
        if strings and (len(values) > 1 or (not arguments and self._many(parm))):
            marker = self.placeholder(parm)
            if marker is not None:
                return (marker,)  # type: ignore[return-value]
        return unknown

    def given_elsewhere(self, parm: Cursor) -> str | None:
        """The placeholder of ``parm`` when the values its function is given are not this
        file's to tell: no call of this file calls it, or the node's other files may
        (``_shared``); None when the unit passes no value to other files
        (``external``). A value read from it then comes from the node's calls
        (``links``), and none where no file of the node calls the function (an overload
        of autoware_utils' ``publish_if_subscribed`` the node never calls)."""
        if not self.external or (self._sites().get(self._function_key(parm))
                                 and not self._shared(parm.semantic_parent)):
            return None
        return self.placeholder(parm)

    def _many(self, parm: Cursor) -> bool:
        """Whether the function of ``parm`` has more calls in this file than
        ``_arguments`` reads."""
        return len(self._sites().get(self._function_key(parm), [])) > self.MAX_SITES

    def _shared(self, function: Cursor | None) -> bool:
        """Whether the node's other files may call the function ``function`` too, and
        only this unit reads its code: defined in this unit's own source, first declared
        in a header, with external linkage. The calls this unit holds are then not all its
        calls, and their agreeing on a value does not give the value (ouster_ros'
        ``OusterSensor(name, options)``: its own file delegates to it with "os_sensor",
        os_driver_node.cpp calls it with "os_driver"); a placeholder does, filled from
        every file's calls (``links``). A function defined in a header is read by every
        unit that includes it, each with its own calls (nav2's ``LifecycleNode(name, ns,
        options)``)."""
        if function is None or self.main is None or function.kind not in (
                CursorKind.CONSTRUCTOR, CursorKind.FUNCTION_DECL, CursorKind.CXX_METHOD) or (
                function.kind == CursorKind.CXX_METHOD and function.is_virtual_method()):
            # a constructor's, a free function's (msckf_vio's ``utils::getTransformCV(
            # nh, field)``, called in utils.cpp and with its transforms' names in
            # image_processor.cpp) or a non-virtual method's (hector_exploration_planner's
            # ``initialize(name, costmap)``, called by its own file's constructor and by
            # the exploration node's file); a virtual method's values come from the
            # host's calls of the methods it overrides (``links.OVERRIDES``, ``HOST_NAMED``)
            return False
        canonical = function.canonical
        where = canonical.location.file if canonical is not None else None
        if where is None or where.name == self.main:
            return False
        definition = function.get_definition()
        if definition is None or _defined_in(definition) != self.main:
            return False
        return canonical.linkage == LinkageKind.EXTERNAL

    def shared(self, function: Cursor) -> bool:
        """Whether the node's other files may call ``function`` (``_shared``), when its
        string parameters are placeholders (``external``)."""
        return self.external and self._shared(function)

    def member_placeholder(self, field: Cursor) -> str | None:
        """The placeholder of a handle member ``field`` that the unit's files never set
        and whose class's constructors are all defined in other files
        (``constructed_elsewhere``): the value those files' code gives it
        (``links.MEMBER``), filled for the node; also of a global handle the unit only
        declares ``extern`` (``Namespaces._global_elsewhere``). None when the unit
        passes no value to other files (``external``) or the member has no USR."""
        usr = field.get_usr()
        if not self.external or not usr or PLACEHOLDER in usr or SEPARATOR in usr:
            return None
        return f"{PLACEHOLDER}{usr}{SEPARATOR}0{PLACEHOLDER}"

    def member_elsewhere(self, field: Cursor) -> str | None:
        """The placeholder of a string member ``field`` that no function of this unit
        writes and whose class's constructors are all defined in other files: the value
        those give it (``links.MEMBER``; navigation2's ``Source::source_name_``, set in
        source.cpp from the constructor's parameter, read in pointcloud.cpp), when a
        constructor of the class takes a string; None otherwise: constructors that
        take none can give it only a constant, and what names it is another method's
        write (navigation2's ``Layer()`` leaves ``name_`` to ``initialize(..., name,
        ...)``, which the plugin hosts call with the layer's name)."""
        if field.kind != CursorKind.FIELD_DECL or msg_types.param_type(field.type) != "str" or (
                not constructed_elsewhere(field, self.source)) or self.written(field) or (
                not _takes_string(field.semantic_parent)):
            return None
        return self.member_placeholder(field)

    def constructed_text(self, field: Cursor) -> str | None:
        """The text every constructor of ``field``'s class defined in this unit gives
        the string member (a constructor's parameters as placeholders), when each writes
        it and all agree, and no other function writes it (``written``); else None."""
        if self.written(field):
            return None
        options = self._members.get(key_of(field))
        if options is None:
            options = self._members[key_of(field)] = constructor_values(field, self.source)
        texts = {render(self.scope(constructor).string(value)) if value is not None else "?"
                 for value, constructor in options}
        text = texts.pop() if len(texts) == 1 else "?"
        if options and all(value is not None and names_node(value, constructor)
                           for value, constructor in options):
            # the name the node was constructed with, whatever constructor built it
            return BUILT_OPEN + text + BUILT_CLOSE
        return None if "?" in text else text

    def placeholder(self, parm: Cursor) -> str | None:
        """The placeholder part of ``parm`` (None for a parameter of no function)."""
        function = parm.semantic_parent
        if function is None or function.kind not in _CALLABLE:
            return None
        index = _index_of(function, parm)
        usr = function.canonical.get_usr()
        if index is None or not usr or PLACEHOLDER in usr or SEPARATOR in usr:
            return None
        self.marked.add(key_of(function.canonical))
        if usr not in self.overrides:
            self.overrides[usr] = (function,
                                   [b.canonical.get_usr() for b in overridden(function)])
        return f"{PLACEHOLDER}{usr}{SEPARATOR}{index}{PLACEHOLDER}"

    def passing_sites(self, done: set[tuple[str, int]]
                      ) -> Iterator[tuple[Cursor, Cursor, Cursor, Cursor | None]]:
        """(callee, call, caller, specialisation) for the calls of functions not defined
        here, of those defined in a header (the node's other units that include it and
        do not call it hold it with a placeholder: turtlebot3's ``TwistSubscriber``,
        built in one file, its header included by others) and of those given a
        placeholder, except the functions in ``done``; ``specialisation``: the one of
        function template ``caller`` in which ``call`` calls ``callee``
        (``instantiated``), else None."""
        from .handles import is_handle  # (handles imports this module)

        defined = {key_of(f.canonical) for f in self.functions
                   if self.main is None or _defined_in(f) == self.main}
        # a virtual method given a handle: a method of another unit that overrides it
        # takes that handle where it is called (``links.OVERRIDES``: costmap_2d's
        # ObstacleLayer::onInitialize calls its ``setupDynamicReconfigure(nh)``, which
        # voxel_layer.cpp's VoxelLayer overrides)
        dispatching = {key_of(f.canonical) for f in self.functions
                       if f.kind == CursorKind.CXX_METHOD and f.is_virtual_method()
                       and any(c.kind == CursorKind.PARM_DECL and is_handle(c)
                               for c in f.get_children())}
        for key, sites in list(self._sites().items()):
            if key in done or (key in defined and key not in self.marked
                               and key not in dispatching):
                continue
            for call, caller in sites:
                picked = self.instantiated(call, caller)
                if picked:
                    # in each specialisation of the template the unit calls, the
                    # overload C++ picks there (``instantiated_callee``)
                    for callee, specialisation in picked:
                        wanted = key_of(callee.canonical)
                        if wanted not in done and (wanted not in defined or (
                                wanted in self.marked)):
                            yield callee, call, caller, specialisation
                    continue
                callee = self._implicit.get((key_of(call), key)) if call.kind in (
                    CursorKind.VAR_DECL, *_CONSTRUCTORS) else (
                    callee_of(call) or self._base_calls.get(key_of(call)))
                bound = bound_function(call)[0] if call.kind == CursorKind.CALL_EXPR \
                    else None
                if bound is not None and key_of(bound.canonical) == key:
                    callee = bound  # the function a bind or a thread calls
                if callee is not None:
                    yield callee, call, caller, None

    def specialisations(self, template: Cursor) -> list[Cursor]:
        """The specialisations of function template ``template`` the unit calls."""
        found: dict[str, Cursor] = {}
        for call, _caller in self._sites().get(key_of(template.canonical), ()):
            callee = call.referenced if call.kind == CursorKind.CALL_EXPR else None
            if callee is None or callee.kind != CursorKind.FUNCTION_DECL:
                continue
            origin = conf.lib.clang_getSpecializedCursorTemplate(callee)
            if origin is not None and origin.kind == CursorKind.FUNCTION_TEMPLATE and (
                    key_of(origin.canonical) == key_of(template.canonical)):
                found.setdefault(callee.get_usr(), callee)
        return list(found.values())

    def instantiated(self, call: Cursor, caller: Cursor) -> list[tuple[Cursor, Cursor]]:
        """(callee, specialisation) for each specialisation of function template
        ``caller`` that the unit calls, where ``call``, one clang does not resolve in
        the template (its arguments depend on the template's parameters), calls the
        overload ``instantiated_callee`` picks there; empty unless it picks one in every
        one of them (then what the call may be is as ``callee_of`` says)."""
        if caller.kind != CursorKind.FUNCTION_TEMPLATE or call.kind != CursorKind.CALL_EXPR or (
                call.referenced is not None):
            return []
        found = []
        for specialisation in self.specialisations(caller):
            callee = instantiated_callee(call, caller, specialisation)
            if callee is None:
                return []
            found.append((callee, specialisation))
        return found

    def scope(self, function: Cursor) -> Scope:
        key = key_of(function)
        if key not in self._scopes:
            self._scopes[key] = Scope(function, self.macros, self.source, self)
        return self._scopes[key]

    def returns(self, method: Cursor, given: bool = False
                ) -> list[tuple[Cursor, Cursor]] | None:
        """(expression, method) for each body a call of ``method`` (a method without
        parameters) may run, whose one statement returns the expression: its own
        definition unless it is pure, and for a virtual one each of this unit's
        definitions that override it (a base class's ``getName()``, pure, that each
        navigator defines as ``return std::string("navigate_to_pose");``); a function
        without parameters likewise, by its definition (``inline std::string
        imu_topic() { return "imu/data"; }``, a header's constant of a library). None when
        one of them is not such a body, or none is known. ``given``: a function or
        method with parameters, not virtual (the call's own arguments are its
        parameters' values: ``Scope.given_return``), by its definition only."""
        if method.kind not in (CursorKind.CXX_METHOD, CursorKind.FUNCTION_DECL) or (
                given == (not any(c.kind == CursorKind.PARM_DECL
                                  for c in method.get_children()))):
            return None
        if given and method.kind == CursorKind.CXX_METHOD and method.is_virtual_method():
            return None
        bodies: list[Cursor] = []
        definition = method.get_definition()
        if definition is not None and not method.is_pure_virtual_method():
            bodies.append(definition)
        owner = method.semantic_parent
        if method.kind == CursorKind.CXX_METHOD and method.is_virtual_method() and (
                owner is not None):
            target = key_of(owner.canonical)
            bodies.extend(
                function for function in self.functions
                if function.kind == CursorKind.CXX_METHOD and function not in bodies
                and function.spelling == method.spelling and function.is_virtual_method()
                and not any(c.kind == CursorKind.PARM_DECL for c in function.get_children())
                and function.semantic_parent is not None
                and target in base_keys(function.semantic_parent))
        found: list[tuple[Cursor, Cursor]] = []
        for body in bodies:
            statements = [c for c in body.get_children() if c.kind == CursorKind.COMPOUND_STMT]
            inner = list(statements[0].get_children()) if len(statements) == 1 else []
            values = list(inner[0].get_children()) if len(inner) == 1 and (
                inner[0].kind == CursorKind.RETURN_STMT) else []
            if len(values) != 1:
                return None
            found.append((values[0], body))
        return found or None

    def virtual_callees(self) -> set[str]:
        """The USRs of the virtual methods taking one string that this unit's functions
        call (defined here or not): a plugin's own code that calls one (nav2's
        ``Polygon`` calls ``createSubscription(topic)``, which ``Circle`` overrides) gives
        its string itself (``links.CALLED_VIRTUAL``)."""
        found: set[str] = set()
        for calls in self._sites().values():
            callee = callee_of(calls[0][0])
            if callee is None or callee.kind != CursorKind.CXX_METHOD or (
                    not callee.is_virtual_method()):
                continue
            if len(string_parameters(callee)) == 1:
                found.add(callee.canonical.get_usr())
        return found

    def callers(self, function: Cursor) -> list[tuple[Cursor, Cursor]]:
        """(call, calling function) for the calls of ``function`` in this file."""
        return self._sites().get(self._key(function), [])

    def called_elsewhere(self, function: Cursor) -> bool:
        """Whether the arguments of ``function``, a non-virtual function or method no
        call of this file calls, are placeholders the node's other files fill
        (``external``), declared in a header: ego-planner's ``GridMap::initMap(nh)``
        stores ``node_ = nh``, called from planner_manager.cpp. A virtual method's are its
        host's (``uses_parameter``)."""
        if not self.external or function.kind not in (
                CursorKind.FUNCTION_DECL, CursorKind.CXX_METHOD) or (
                function.kind == CursorKind.CXX_METHOD and function.is_virtual_method()) or (
                _overriding(function)) or self.callers(function):
            return False
        # declared in a header: the unit's own source alone cannot call it otherwise
        canonical = function.canonical
        where = canonical.location.file if canonical is not None else None
        return where is not None and self.main is not None and where.name != self.main

    def field(self, field: Cursor, function: Cursor | None = None, initial: bool = False
              ) -> tuple[Cursor, Scope] | None:
        """What a member holds, read in ``function``: the value a constructor of its
        class initialises or assigns it with (read in that constructor), else its default
        initialiser, unless another function writes it (``written``; ``initial``: the
        value it holds first all the same). When the class's constructors disagree, the
        one ``function`` is (``member``)."""
        found = self.member(field, function)
        if found is not None:
            value, constructor = found
            if value is not None:
                if not initial and (_filled(field, constructor, self.source)
                                    or self.read_into(field)
                                    or self.loaded_elsewhere(field)):
                    return None  # (``initial``: the default of the read that fills it)
                return value, self.scope(constructor)
        value = initializer(field)
        if value is None or (not initial and self.written(field)):
            return None
        return value, Scope(None, self.macros, self.source, self)

    def read_into(self, field: Cursor) -> bool:
        """Whether a method of this unit but a constructor, a destructor or a parameter
        callback passes the string or number member ``field`` as the out argument of a
        ROS parameter read (``_reads_parameter``), as an initialisation method does
        (teb_local_planner's ``nh.param("odom_topic", odom_topic, odom_topic)`` in
        ``loadRosParamFromNodeHandle`` after its constructor's ``odom_topic = "odom"``):
        then what the constructor gives it is the read's default, not what it holds when
        the node runs (``_filled``, for a read in the constructor itself)."""
        found = key_of(field)
        cached = self._read_into.get(found)
        if cached is not None:
            return cached
        result = _plain_value(field) and any(
            out_argument(write) and _reads_parameter(write.at) for write in self._writes_to(
                field, (CursorKind.CONSTRUCTOR, CursorKind.DESTRUCTOR)))
        self._read_into[found] = result
        return result

    def loaded_elsewhere(self, field: Cursor) -> bool:
        """Whether this unit hands a ROS handle to a method of the string member
        ``field``'s class that is defined in no file of the unit and may write its
        object (not ``const``): a settings class whose loader reads parameters into its
        members in another source (teb_local_planner's ``cfg_.loadRosParamFromNodeHandle
        (nh)``, defined in teb_config.cpp, after ``odom_topic = "odom"`` in the
        constructor its header defines); what the constructor gives the member is then
        not known to be what it holds."""
        from .handles import is_handle  # (handles imports this module)

        owner = field.semantic_parent
        if owner is None or msg_types.param_type(field.type) != "str":
            return False  # (a number's or a flag's default stays the declaration's)
        key = key_of(owner.canonical)
        cached = self._loaded.get(key)
        if cached is not None:
            return cached
        result = False
        for function in self.functions:
            for node in function.walk_preorder():
                target = node.referenced if node.kind == CursorKind.CALL_EXPR else None
                if target is None or target.kind != CursorKind.CXX_METHOD or (
                        target.is_const_method() or target.is_static_method()):
                    continue
                parent = target.semantic_parent
                if parent is None or key_of(parent.canonical) != key or (
                        target.get_definition() is not None):
                    continue
                if any(is_handle(arg) for arg in node.get_arguments()):
                    result = True
                    break
            if result:
                break
        self._loaded[key] = result
        return result

    def written(self, field: Cursor) -> bool:
        """Whether a function of this unit but a destructor writes ``field`` (on any
        object): then its default initialiser is not what it holds where it is read
        (``camera_name_`` of OrbbecSDK_ROS2's OBLidarNode, set in getParameters() by a
        helper that takes it by non-const reference). A constructor's or initialisation
        method's write with a known value is ``member``'s answer, taken before; a
        parameter callback's writes come after start-up (``parameter_callback``)."""
        found = key_of(field)
        cached = self._written.get(found)
        if cached is not None:
            return cached
        result = any(True for _ in self._writes_to(field, (CursorKind.DESTRUCTOR,)))
        if not result and field.kind == CursorKind.FIELD_DECL:
            owner = field.semantic_parent
            result = owner is not None and key_of(owner.canonical) in self.whole_records()
        self._written[found] = result
        return result

    def _writes_to(self, field: Cursor, skipped: tuple[CursorKind, ...]) -> Iterator[Write]:
        """The writes of ``field`` (on any object) in the unit's functions, in order, but
        in functions of the kinds ``skipped``, in parameter callbacks (their writes come
        after start-up) and in functions whose text cannot name it."""
        found = key_of(field)
        spelling = field.spelling.encode("utf-8")
        for function in self.functions:
            if function.kind in skipped or not _may_name(
                    function, spelling, self.source) or parameter_callback(function):
                continue
            for write in writes_in(function, self.source):
                if write.variable is not None and key_of(write.variable) == found:
                    yield write

    def whole_records(self) -> set[tuple[str, int]]:
        """The classes (their canonical declarations' places) of which a function of this
        unit but a destructor assigns an object as a whole, ``=`` or a constructor's
        initialiser with arguments: each field of such an object may then hold what
        was copied into it, not its default initialiser (depthai's ImagePublisher:
        ``pubConfig = pubConf;`` in ``setup``, then ``pubConfig.topicName +
        pubConfig.topicSuffix``, whose ``topicName = ""`` the callers in other files
        set before they pass the struct)."""
        if self._whole is not None:
            return self._whole
        found: set[tuple[str, int]] = set()
        for function in self.functions:
            if function.kind == CursorKind.DESTRUCTOR or parameter_callback(function):
                continue
            children = list(function.get_children())
            for child, value in itertools.pairwise(children):  # ``config_(conf)``
                if child.kind == CursorKind.MEMBER_REF and child.referenced is not None and (
                        not default_constructed(value)):
                    _note_record(child.referenced.type, found)
            for write in writes_in(function, self.source):
                if write.whole and write.value is not None and (
                        write.target.kind != CursorKind.VAR_DECL):
                    _note_record(write.target.type, found)
        self._whole = found
        return found

    def unset(self, field: Cursor) -> None:
        """Note ``field``, a member nothing in this unit gives a value, when its class
        declares constructors and this unit defines none of them (``elsewhere``)."""
        owner = field.semantic_parent
        where = owner.location.file if owner is not None else None
        if owner is None or field.kind != CursorKind.FIELD_DECL or (
            where is None or where.name not in self.source
        ):  # a class of the workspace's own files, not a message (synthesised): its
            # field holds what is received or filled in at run time
            return
        if constructed_elsewhere(field, self.source):
            named = f"{owner.spelling}::{field.spelling}"
            if named not in self.elsewhere:
                self.elsewhere.append(named)

    def member(self, field: Cursor, function: Cursor | None = None
               ) -> tuple[Cursor | None, Cursor] | None:
        """The value one constructor of ``field``'s class gives it (None: it leaves the
        member to its default) and that constructor; else what an initialisation method
        (``onInit``) gives it, as ``member_initialiser``; None when nothing does.

        Constructors that disagree give one value per construction: the constructor
        ``function`` is, else the one ``choice`` names (a call emitted once per
        constructor, ``CppVisitor._emit``), else those this file calls when it
        constructs the class, else every one: the first (the first that writes the
        member) is taken and, while ``forks`` records, the alternatives are kept there
        for the call being emitted to be made once per constructor."""
        key = key_of(field)
        options = self._members.get(key)
        if options is None:
            options = self._members[key] = constructor_values(field, self.source)
        if not options or all(value is None for value, _ in options):
            return member_initialiser(field, self.source)
        texts = {value_text(value) for value, _ in options}
        if len(texts) == 1:
            return options[0]
        mine = next((o for o in options if function is not None
                     and key_of(o[1]) == key_of(function)), None)
        if mine is not None:
            return mine
        if self.choice is not None and self.choice[0] == key:
            return next((o for o in options if key_of(o[1]) == self.choice[1]), options[0])
        here = [o for o in options if self.callers(o[1])]
        if here:  # the file constructs the class: by these constructors
            if len({value_text(value) for value, _ in here}) == 1:
                return here[0]
            options = here
        if self.forks is not None and not any(f.field == key for f in self.forks):
            self.forks.append(Fork(key, options[:MAX_CONSTRUCTORS], local=bool(here)))
        return options[0]

    def _function_key(self, parm: Cursor) -> tuple[str, int]:
        function = parm.semantic_parent
        return self._key(function) if function is not None else ("", -1)

    def _key(self, function: Cursor) -> tuple[str, int]:
        """The key a function's calls are indexed by: its first declaration's place; for
        a member of a class template defined outside the class, its definition's when
        only that has calls (a call of a specialisation's member names the definition
        it is instantiated from: aerostack2's ``BehaviorServer<actionT>::
        BehaviorServer``, declared in the class, defined in an implementation header)."""
        key = key_of(function.canonical)
        parent = function.semantic_parent
        if key not in self._sites() and function.is_definition() and parent is not None and (
                parent.kind in (CursorKind.CLASS_TEMPLATE,
                                CursorKind.CLASS_TEMPLATE_PARTIAL_SPECIALIZATION)):
            own = key_of(function)
            if own in self._sites():
                return own
        return key

    def _arguments(self, parm: Cursor) -> list[tuple[Cursor, Scope]]:
        function = parm.semantic_parent
        if function is None:
            return []
        index = _index_of(function, parm)
        sites = self._sites().get(self._key(function), [])
        if index is None or len(sites) > self.MAX_SITES:
            return []
        found = []
        for call, caller in sites:
            arg = argument(call, parm, index)
            if arg is None:
                return []  # a call that does not say: the value is not known
            found.append((arg, self.scope(caller)))
        return found

    def _sites(self) -> dict[tuple[str, int], list[tuple[Cursor, Cursor]]]:
        if self._index is None:
            self._index = {}
            bases: list[tuple[Cursor, Cursor, Cursor]] = []
            implicit: list[tuple[Cursor, Cursor]] = []
            for function in self.functions:
                for node in function.walk_preorder():
                    callee = callee_of(node) if node.kind == CursorKind.CALL_EXPR else None
                    if callee is None and node.kind == CursorKind.CALL_EXPR and (
                            node.referenced is not None):
                        callee = held_lambda(node.referenced)
                    if node.kind == CursorKind.INIT_LIST_EXPR:
                        # ``{"alpha", mAlpha, 0.05}`` building a class by a constructor
                        # (a list's element: mrover's ParameterWrapper): clang keeps no
                        # call there, the list is its argument list
                        for made, callee in list_constructions(node):
                            self._base_calls[key_of(made)] = callee
                            for key in specialised_keys(callee):
                                self._index.setdefault(key, []).append((made, function))
                        callee = None
                    if node.kind == CursorKind.CXX_NEW_EXPR:
                        # ``new C(args)`` in a template, an argument depending on its
                        # parameters: clang keeps the argument list, no call
                        # (rosserial_server's ``Session<Socket>`` makes ``new
                        # Subscriber(nh_, info, boost::bind(&Session::write_message,
                        # this, _1))``): the list is the call's argument list
                        made = dependent_new(node)
                        if made is not None:
                            self._base_calls[key_of(made[0])] = made[1]
                            for key in specialised_keys(made[1]):
                                self._index.setdefault(key, []).append((made[0], function))
                    if node.kind == CursorKind.VAR_DECL:
                        # a variable whose default construction the parse dropped: a
                        # call of the default constructor that passes nothing
                        callee = dropped_constructor(node)
                        if callee is not None:
                            self._implicit[(key_of(node), key_of(callee.canonical))] = callee
                    if callee is not None:
                        for key in specialised_keys(callee):
                            self._index.setdefault(key, []).append((node, function))
                    bound = bound_function(node)[0] if node.kind == CursorKind.CALL_EXPR \
                        else None
                    if bound is not None:
                        # ``boost::bind(&f, nh)`` / ``std::thread(&f, nh)``: f is
                        # called with the arguments after it (``argument``)
                        self._index.setdefault(key_of(bound.canonical), []).append(
                            (node, function))
                # a constructor that delegates to another calls it with that argument
                # list (``Filter(nh, priv) : Filter(nh, priv, getName()) {}``)
                if function.kind in _CONSTRUCTORS:
                    arguments = delegation(function)
                    target = delegated_to(function, arguments) if arguments is not None \
                        else None
                    if arguments is not None and target is not None and (
                        arguments.kind != CursorKind.CALL_EXPR  # that is one above
                    ):
                        self._index.setdefault(key_of(target.canonical), []).append(
                            (arguments, function))
                    # and a class template's constructor its base's, with the argument
                    # list clang keeps there instead of a call
                    bases.extend((arguments, target, function)
                                 for arguments, target in base_initialisers(function))
                    implicit.extend((function, target) for target in implicit_bases(function))
            # (only where this file instantiates that constructor: one no call here
            # makes passes nothing here, a base's ``Node(name)`` of a template beside
            # the subclass that names the node)
            for arguments, target, function in bases:
                if key_of(function.canonical) in self._index or key_of(function) in (
                        self._index):
                    self._index.setdefault(key_of(target.canonical), []).append(
                        (arguments, function))
                    self._base_calls[key_of(arguments)] = target
            # a constructor that leaves a base to C++ calls the base's default
            # constructor, with nothing passed, where this file calls it (a chain of
            # such bases: as far as it goes)
            for _round in range(8):
                todo = [(function, target) for function, target in implicit
                        if (key_of(function), key_of(target.canonical)) not in self._implicit
                        and (key_of(function.canonical) in self._index
                             or key_of(function) in self._index)]
                for function, target in todo:
                    self._index.setdefault(key_of(target.canonical), []).append(
                        (function, function))
                    self._implicit[(key_of(function), key_of(target.canonical))] = target
                if not todo:
                    break
        return self._index


def _takes_string(cls: Cursor | None) -> bool:
    """Whether a constructor the class ``cls`` declares takes a string parameter."""
    definition = cls.get_definition() if cls is not None else None
    return definition is not None and any(
        msg_types.param_type(parm.type) == "str"
        for constructor in definition.get_children()
        if constructor.kind == CursorKind.CONSTRUCTOR
        for parm in constructor.get_children() if parm.kind == CursorKind.PARM_DECL)


def base_keys(cls: Cursor, depth: int = 0, named: bool = False) -> set[tuple[str, int]]:
    """The keys of ``cls``'s base classes, transitively; a base that is a class
    template's specialisation (``Navigator<ToPose>``) also as that template. ``named``:
    only the bases whose members an unqualified name may find, not one that depends on
    a template parameter (C++ looks no name up there until the template is used: rovio's
    ``FeatureOutputCT<STATE> : public LWF::CoordinateTransform<STATE, ...>``)."""
    found: set[tuple[str, int]] = set()
    if depth > 8:
        return found
    for base in cls.get_children():
        if base.kind != CursorKind.CXX_BASE_SPECIFIER:
            continue
        if named and base.type.get_canonical().kind != TypeKind.RECORD:
            continue  # a dependent base (a template parameter's, or a template of one)
        decl = base.type.get_canonical().get_declaration()
        template = conf.lib.clang_getSpecializedCursorTemplate(decl)
        for each in (decl, template):
            if each is not None and each.kind != CursorKind.NO_DECL_FOUND:
                found.add(key_of(each.canonical))
        definition = decl.get_definition()
        if definition is None and template is not None:
            definition = template.get_definition()
        if definition is not None:
            found |= base_keys(definition, depth + 1, named)
    return found


def string_parameters(function: Cursor) -> list[int]:
    """The indices of ``function``'s string parameters."""
    params = [c for c in function.get_children() if c.kind == CursorKind.PARM_DECL]
    return [index for index, parm in enumerate(params)
            if msg_types.param_type(parm.type) == "str"]


def _overriding(function: Cursor | None) -> bool:
    """Whether ``function`` is a virtual method overriding one of a base class, with one
    string parameter: a host may call it through that base with a value none of this
    unit's calls gives (navfn's ``NavfnROS::initialize(name, costmap_ros)``, which its
    own constructor calls too): its values are the node's calls' and the host's
    (``links.HOST_NAMED``), not this unit's alone."""
    if function is None or function.kind != CursorKind.CXX_METHOD or (
            not function.is_virtual_method()):
        return False
    return len(string_parameters(function)) == 1 and bool(overridden(function))


def overridden(method: Cursor, depth: int = 0) -> list[Cursor]:
    """The virtual methods of ``method``'s base classes (transitively) that it
    overrides: the same name and number of parameters (``AnalyzerGroup::init`` over
    ``Analyzer::init``, called as ``boost::shared_ptr<Analyzer>``'s ``group->init``)."""
    if method.kind != CursorKind.CXX_METHOD or not method.is_virtual_method() or depth > 8:
        return []
    params = len([c for c in method.get_children() if c.kind == CursorKind.PARM_DECL])
    found: list[Cursor] = []
    parent = method.semantic_parent
    for base in parent.get_children() if parent is not None else []:
        if base.kind != CursorKind.CXX_BASE_SPECIFIER:
            continue
        decl = base.type.get_canonical().get_declaration()
        decl = decl.get_definition() or decl
        for other in decl.get_children():
            if other.kind == CursorKind.CXX_METHOD and other.spelling == method.spelling and (
                other.is_virtual_method()
            ) and len([c for c in other.get_children()
                       if c.kind == CursorKind.PARM_DECL]) == params:
                found.append(other)
                break
        else:
            continue
        found.extend(overridden(found[-1], depth + 1))
    return found


def held_lambda(decl: Cursor) -> Cursor | None:
    """The lambda variable ``decl`` was made with, when a call names the variable: in a
    template, where the parse leaves the call of the lambda's ``operator()`` dependent
    and the call refers to the variable (kr_mav_control's simulator base, a class
    template, reads each parameter with ``get_param("mass")``, ``auto get_param =
    [&n](const std::string &name) {...}``)."""
    if decl.kind != CursorKind.VAR_DECL:
        return None
    made = initializer(decl)
    made = strip(made) if made is not None else None
    return made if made is not None and made.kind == CursorKind.LAMBDA_EXPR else None


def argument(call: Cursor, parm: Cursor, index: int) -> Cursor | None:
    """What ``call`` passes for parameter ``parm`` (at ``index``): the written argument,
    or the parameter's default when the call leaves it out. A constructor's delegation
    (``delegation``) is its argument list. A ``bind`` or thread of the function of
    ``parm`` (``bound_function``) passes what follows the function (and its object)."""
    # (a variable whose construction the parse dropped, a constructor that leaves a
    # base to C++: nothing passed)
    args = list(call.get_arguments()) if call.kind == CursorKind.CALL_EXPR \
        else [] if call.kind in (CursorKind.VAR_DECL, *_CONSTRUCTORS) \
        else list(call.get_children())
    if call.kind == CursorKind.CALL_EXPR and parm.semantic_parent is not None:
        bound, skip = bound_function(call)
        if bound is not None and key_of(bound.canonical) == key_of(
                parm.semantic_parent.canonical):
            if any(is_default_argument(a) for a in args[skip:]):
                return None  # a placeholder (``_1``) or a default: not known here
            args = args[skip:]
    if call.kind == CursorKind.CALL_EXPR and _object_first(call, parm, args):
        args = args[1:]
    if index < len(args) and not is_default_argument(args[index]):
        return args[index]
    return default_argument(parm)


def _object_first(call: Cursor, parm: Cursor, args: list[Cursor]) -> bool:
    """Whether ``args`` begin with the object a call in operator syntax is made on: a
    call of a lambda through its variable (``getP(ns, "takeoff_height", h)``, clang's
    operator call of its ``operator()``) or of a functor's ``operator()`` lists that
    object first (jetyak_uav_utils' behaviours read ``ns + name`` with the arguments
    one place off: ``?~``)."""
    method = parm.semantic_parent
    if not args or method is None or method.kind != CursorKind.CXX_METHOD or (
            not call.spelling.startswith("operator")):
        return False
    owner = method.semantic_parent
    first = args[0].type.get_canonical().get_declaration()
    return owner is not None and first is not None and first.kind != CursorKind.NO_DECL_FOUND \
        and first == owner


# what calls a function it is given, with the arguments given after it: std::bind and
# boost::bind, and the threads started with a function (std::thread, boost::thread)
_BINDERS = frozenset({("std", "bind"), ("boost", "bind")})
_THREADS = frozenset({"std::thread", "std::jthread", "boost::thread"})


def bound_function(call: Cursor) -> tuple[Cursor | None, int]:
    """The function of the workspace a ``bind`` or a thread's construction is given
    first (``boost::thread(boost::bind(&thread_subscribe, private_nh_))``, Doosan's
    dsr_control, whose static ``thread_subscribe(ros::NodeHandle nh)`` subscribes on
    ``nh``), and how many arguments go before those it is called with: the function,
    and the object for a method that is not static. (None, 0) for any other call."""
    target = call.referenced
    if target is None:
        return None, 0
    if target.kind == CursorKind.CONSTRUCTOR:
        if qualified_name(target.semantic_parent) not in _THREADS:
            return None, 0
    elif (qualified_name(target.semantic_parent), target.spelling) not in _BINDERS:
        return None, 0
    args = list(call.get_arguments())
    first = strip(args[0]) if args else None
    if first is not None and first.kind == CursorKind.UNARY_OPERATOR:  # ``&f``
        inner = [c for c in first.get_children() if c.kind.is_expression()]
        first = strip(inner[0]) if len(inner) == 1 else None
    function = first.referenced if first is not None and first.kind in (
        CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR) else None
    if function is None or function.kind not in (CursorKind.FUNCTION_DECL,
                                                 CursorKind.CXX_METHOD):
        return None, 0
    own = function.kind == CursorKind.CXX_METHOD and not function.is_static_method()
    return function, 2 if own else 1


def default_argument(parm: Cursor) -> Cursor | None:
    """The default value a parameter declaration gives (on any declaration of it)."""
    function = parm.semantic_parent
    if function is None:
        return None
    index = _index_of(function, parm)
    declarations = [function, function.canonical]
    definition = function.get_definition()
    if definition is not None:
        declarations.append(definition)
    for declaration in declarations:
        params = [c for c in declaration.get_children() if c.kind == CursorKind.PARM_DECL]
        if index is not None and index < len(params):
            value = [c for c in params[index].get_children() if c.kind.is_expression()]
            if value:
                return value[-1]
    return None


def is_constructor(function: Cursor) -> bool:
    """A constructor, or a constructor template (``ServiceServer<ServiceT>``)."""
    parent = function.semantic_parent
    return function.kind == CursorKind.CONSTRUCTOR or (
        parent is not None and function.spelling.split("<")[0] == parent.spelling)


def implicit_bases(function: Cursor) -> list[Cursor]:
    """The constructor of each base of its class that constructor ``function`` leaves
    to C++, no initialiser of its own naming the base: the base's one constructor that
    takes no argument (ethzasl_msf's ``PoseSensorManager(pnh)`` over
    ``MSF_SensorManagerROS<EKFState>(ros::NodeHandle pnh = ros::NodeHandle("~core"))``).
    None for a constructor that delegates to another of its class."""
    parent = function.semantic_parent
    if parent is None or not is_constructor(function) or not function.is_definition() or (
            delegation(function) is not None):
        return []
    written = {key_of(c.referenced.canonical) for c in function.get_children()
               if c.kind in (CursorKind.TYPE_REF, CursorKind.TEMPLATE_REF)
               and c.referenced is not None}
    found: list[Cursor] = []
    for base in parent.get_children():
        ctype = base.type.get_canonical() if base.kind == CursorKind.CXX_BASE_SPECIFIER \
            else None
        if ctype is None or ctype.kind != TypeKind.RECORD:
            continue  # a base that depends on a template parameter
        decl = ctype.get_declaration()
        template = conf.lib.clang_getSpecializedCursorTemplate(decl)
        classes = [each for each in (decl, template)
                   if each is not None and each.kind != CursorKind.NO_DECL_FOUND]
        if any(key_of(each.canonical) in written for each in classes):
            continue
        for each in classes:
            cls = each.get_definition() or each
            chosen = [c for c in cls.get_children() if c.kind in _CONSTRUCTORS
                      and is_constructor(c) and _takes(c, 0)]
            if chosen:
                if len(chosen) == 1:
                    found.append(chosen[0])
                break
    return found


def dropped_constructor(variable: Cursor) -> Cursor | None:
    """The constructor that a variable declared without an initialiser runs when the
    parse kept no construction of it (``owners.construction_dropped``): the one of its
    class that takes no argument (with its defaults)."""
    cls = lost_class(variable)
    if cls is None:
        return None
    found = [c for c in cls.get_children() if c.kind in _CONSTRUCTORS and is_constructor(c)
             and _takes(c, 0)]
    return found[0] if len(found) == 1 else None


def delegation(function: Cursor) -> Cursor | None:
    """The call of the constructor that constructor ``function`` delegates to (``T(a) :
    T(a, "x") {}``): the reference to its own class, then the call, or the argument list
    when clang kept no call (always so in a class template, whose arguments depend on a
    template parameter): an unexposed expression whose children are the arguments."""
    if not is_constructor(function):
        return None
    parent = function.semantic_parent
    own = parent.spelling.split("<")[0] if parent is not None else ""
    for first, second in itertools.pairwise(function.get_children()):
        if first.kind == CursorKind.TYPE_REF and own and (
            first.spelling.split("<")[0].split("::")[-1].split()[-1] == own  # "class T"
        ) and second.kind in (CursorKind.UNEXPOSED_EXPR, CursorKind.CALL_EXPR):
            inner = list(second.get_children()) if second.kind == CursorKind.UNEXPOSED_EXPR \
                else [second]
            target = inner[0].referenced if len(inner) == 1 and (
                inner[0].kind == CursorKind.CALL_EXPR) else None
            if target is not None and target.kind == CursorKind.CONSTRUCTOR and (
                target.semantic_parent is not None
                and target.semantic_parent.spelling.split("<")[0] == own
            ):
                return inner[0]  # the call, resolved (not one of an argument's class)
            return second if second.kind == CursorKind.UNEXPOSED_EXPR else None
    return None


_NAMING = (CursorKind.TYPE_REF, CursorKind.TEMPLATE_REF)


def base_initialisers(function: Cursor) -> list[tuple[Cursor, Cursor]]:
    """(argument list, base constructor) for each base a class template's constructor
    initialises where clang keeps no call, only the list of arguments (an unexposed
    expression; aerostack2's ``BehaviorServer<actionT>(name, options) : as2::Node(name,
    options)``): the one constructor of that base that C++ would call with them
    (``closest``); none when no single one would."""
    parent = function.semantic_parent
    if parent is None or parent.kind not in (
            CursorKind.CLASS_TEMPLATE, CursorKind.CLASS_TEMPLATE_PARTIAL_SPECIALIZATION):
        return []
    bases = {key_of(b.referenced) for b in parent.get_children()
             if b.kind == CursorKind.CXX_BASE_SPECIFIER and b.referenced is not None}
    found = []
    # the base an initialiser names: a class (``as2::Node``), or a class template then
    # the references of its arguments (turtlebot4's ``Turtlebot4Service<ServiceT>(...)
    # : Turtlebot4BaseService<ServiceT>(nh, service, timeout)``: the template, then
    # ``ServiceT``), then its argument list
    base: Cursor | None = None
    for child in function.get_children():
        named = child.referenced if child.kind in _NAMING else None
        if named is not None and key_of(named) in bases:
            base = named
            continue
        if base is not None and base.kind == CursorKind.CLASS_TEMPLATE and (
                child.kind in _NAMING or child.kind == CursorKind.NAMESPACE_REF):
            continue  # an argument of the base template
        named, base = base, None
        if named is None or child.kind != CursorKind.UNEXPOSED_EXPR:
            continue
        named = named.get_definition() or named
        args = list(child.get_children())
        chosen = closest([c for c in named.get_children() if c.kind in _CONSTRUCTORS
                          and is_constructor(c) and _takes(c, len(args))], args)
        if len(chosen) == 1:
            found.append((child, chosen[0]))
    return found


def delegated_to(function: Cursor, arguments: Cursor) -> Cursor | None:
    """The one other constructor of ``function``'s class that may take the delegation's
    ``arguments`` (the closest, as ``closest``), None when no single one does."""
    parent = function.semantic_parent
    if parent is None:
        return None
    if arguments.kind == CursorKind.CALL_EXPR:
        target = arguments.referenced
        return target if target is not None and target.semantic_parent is not None and (
            key_of(target.semantic_parent) == key_of(parent)) else None
    args = list(arguments.get_children())
    own = key_of(function.canonical)
    found = [c for c in parent.get_children() if c.kind in _CONSTRUCTORS and is_constructor(c)
             and key_of(c.canonical) != own and _takes(c, len(args))]
    found = closest(found, args)
    return found[0] if len(found) == 1 else None


# what a specialisation of a template is called as (``specialised_keys``)
_SPECIALISABLE = frozenset({CursorKind.CONSTRUCTOR, CursorKind.CXX_METHOD,
                            CursorKind.FUNCTION_DECL})


def specialised_keys(function: Cursor) -> list[tuple[str, int]]:
    """The keys a call of ``function`` is a call of: its first declaration's place, and
    for a specialisation the first declaration's of what it is specialised from (a
    function template, a class template's member). One declared in its class and
    defined outside it (OrbbecSDK_ROS2's ``FrameLatencyNode::createListener<MsgType>``,
    ``template <class M> Bridge<M>::Bridge(...)``) is specialised from the definition,
    whose place is the specialisation's own, while the template's functions (its
    summary as a wrapper, its parameters) are known by the declaration in the class."""
    found = [key_of(function.canonical)]
    if function.kind in _SPECIALISABLE:
        template = conf.lib.clang_getSpecializedCursorTemplate(function)
        if template is not None and template.kind != CursorKind.NO_DECL_FOUND and (
            key_of(template.canonical) not in found
        ):
            found.append(key_of(template.canonical))
    return found


def callee_of(call: Cursor) -> Cursor | None:
    """The function a call calls; for ``std::make_shared<T>(args)`` / ``make_unique``
    (std or boost) the one constructor of ``T`` that takes that many arguments (with
    its defaults)."""
    target = call.referenced
    if target is None:
        return _dependent_maker(call) or _dependent_function(call)
    if target.kind not in _CALLABLE:
        return None
    if target.spelling not in _MAKERS or target.kind == CursorKind.CONSTRUCTOR:
        return target
    ctype = call.type.get_canonical()
    if ctype.kind != TypeKind.RECORD or ctype.get_num_template_arguments() < 1:
        return None
    decl = ctype.get_template_argument_type(0).get_canonical().get_declaration()
    args = written_arguments(call)
    # a constructor, or a constructor template (``template<class F> T(node, topic, F cb)``)
    found = [c for c in decl.get_children()
             if (c.kind == CursorKind.CONSTRUCTOR or (
                 c.kind == CursorKind.FUNCTION_TEMPLATE
                 and c.spelling.split("<")[0] == decl.spelling.split("<")[0]))
             and _takes(c, len(args))]
    found = closest(found, args)
    return found[0] if len(found) == 1 else None


def parameter_places(constructor: Cursor | None, names: tuple[str, str]
                     ) -> tuple[int, int] | None:
    """Where ``constructor`` takes the parameters ``names`` (a node's name and namespace:
    ``api.STANDIN_NODE_NAME``), as argument indices; the second past the end when it has
    no such parameter, None when it has not the first (or is not known)."""
    if constructor is None:
        return None
    params = [p.spelling for p in constructor.get_children() if p.kind == CursorKind.PARM_DECL]
    if names[0] not in params:
        return None
    return params.index(names[0]), (
        params.index(names[1]) if names[1] in params else len(params))


def _dependent_maker(call: Cursor) -> Cursor | None:
    """In a template, ``std::make_unique<C<T>>(args)`` whose class depends on a template
    parameter is no call clang resolves: the one constructor of class template ``C``
    that takes that many arguments (nav2's ``BehaviorTreeNavigator<ActionT>`` makes its
    ``BtActionServer<ActionT, ...>`` so)."""
    children = list(call.get_children())
    refs = list(children[0].get_children()) if children and (
        children[0].kind == CursorKind.DECL_REF_EXPR) else []
    makers = [i for i, c in enumerate(refs) if c.kind == CursorKind.OVERLOADED_DECL_REF
              and c.spelling in _MAKERS]
    if not makers:
        return None
    classes = [c.referenced for c in refs[makers[0] + 1:]
               if c.kind == CursorKind.TEMPLATE_REF and c.referenced is not None
               and c.referenced.kind == CursorKind.CLASS_TEMPLATE]
    if not classes:
        return None
    decl = classes[0].get_definition() or classes[0]
    args = written_arguments(call)
    found = closest([c for c in decl.get_children() if c.kind == CursorKind.CONSTRUCTOR
                     and _takes(c, len(args))], args)
    return found[0] if len(found) == 1 else None


def _dependent_function(call: Cursor) -> Cursor | None:
    """In a template, a call of a free function (template) whose arguments depend on a
    template parameter is no call clang resolves (joint_trajectory_controller's
    ``getSegmentTolerances<Scalar>(tol_nh, joint_names_)`` with ``Scalar`` its segment's):
    the one function the name was looked up to that takes that many arguments."""
    children = list(call.get_children())
    if not children:
        return None
    head = children[0]
    refs = [c for c in (head, *head.get_children()) if c.kind == CursorKind.OVERLOADED_DECL_REF]
    if len(refs) != 1:
        return None
    args = written_arguments(call)
    found = closest([d for d in overloads(refs[0]) if d is not None
                     and d.kind in (CursorKind.FUNCTION_DECL, CursorKind.FUNCTION_TEMPLATE)
                     and _takes(d, len(args))], args)
    return found[0] if len(found) == 1 else None


_BUILTINS = frozenset({TypeKind.BOOL, TypeKind.INT, TypeKind.LONG, TypeKind.DOUBLE,
                       TypeKind.FLOAT, TypeKind.UINT, TypeKind.ULONG, TypeKind.LONGLONG})


def fits(decl: Cursor, types: list[Type]) -> bool:
    """Whether overload ``decl`` may be the one called with arguments of ``types``:
    their number, and no builtin value (``true``, ``0.25``) passed for a class parameter
    (a descriptor), nor for one of a class template's (``const Vector2<T>&``)."""
    params = [p for p in decl.get_children() if p.kind == CursorKind.PARM_DECL]
    variadic = bool(params) and params[-1].type.spelling.endswith("...")
    if variadic:
        params = params[:-1]  # a pack (``R&&... rest``): any number of arguments
    elif decl.type.kind == TypeKind.FUNCTIONPROTO and decl.type.is_function_variadic():
        variadic = True  # C's ``...`` (no parameter of its own): any number after them
    required = [p for p in params if not any(c.kind.is_expression() for c in p.get_children())]
    if not len(required) <= len(types) <= (len(types) if variadic else len(params)):
        return False
    for param, given_type in zip(params, types, strict=False):
        wanted = param.type.get_canonical()
        if wanted.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
            wanted = wanted.get_pointee().get_canonical()
        given = given_type.get_canonical()
        if given.kind in _BUILTINS and (wanted.kind == TypeKind.RECORD or (
                wanted.kind == TypeKind.UNEXPOSED and wanted.spelling.endswith(">"))):
            return False  # (a class template's specialisation, ``Vector2<T>``)
        if wanted.kind == TypeKind.RECORD and given.kind == TypeKind.POINTER and (
            given.get_pointee().get_canonical().kind == TypeKind.RECORD
        ):
            return False  # an object's address (``this``) for a class (a logger)
        if wanted.kind == TypeKind.RECORD and given.kind == TypeKind.RECORD and (
            msg_types.param_type(wanted) == "str" and msg_types.param_type(given) != "str"
        ):
            return False  # a string parameter given another class (a duration)
    return True


def instantiated_callee(call: Cursor, template: Cursor, specialisation: Cursor
                        ) -> Cursor | None:
    """The function ``call``, in function template ``template``, calls in its
    ``specialisation``: a call whose arguments depend on the template's parameters is
    no call clang resolves in the template (``param(nh, name + "/x", value.x)`` with
    ``const Vector2<T>& value``, quori_face's overloads for ``uint32_t`` and
    ``double``), and C++ picks the overload in each specialisation by the types the
    arguments have there. None where an argument's type there is not known, or no one
    overload is the one."""
    children = list(call.get_children())
    head = children[0] if children else None
    refs = [c for c in (head, *head.get_children()) if c.kind == CursorKind.OVERLOADED_DECL_REF
            ] if head is not None else []
    if len(refs) != 1:
        return None
    types: list[Type] = []
    for arg in written_arguments(call):
        found = instantiated_type(arg, template, specialisation)
        if found is None:
            return None
        types.append(found)
    chosen = closest_typed([d for d in overloads(refs[0]) if d is not None and d.kind in (
        CursorKind.FUNCTION_DECL, CursorKind.FUNCTION_TEMPLATE) and fits(d, types)], types)
    return chosen[0] if len(chosen) == 1 else None


def instantiated_type(expr: Cursor, template: Cursor, specialisation: Cursor
                      ) -> Type | None:
    """The type expression ``expr`` of function template ``template`` has in its
    ``specialisation``: a parameter's as the specialisation declares it, a member's as
    the class it is read from there declares it, a template type parameter's the
    specialisation's argument; None where that is not known."""
    expr = strip(expr)
    ctype = expr.type
    if not _depends(ctype):
        return ctype
    parameters = [c for c in template.get_children()
                  if c.kind == CursorKind.TEMPLATE_TYPE_PARAMETER]
    target = expr.referenced if expr.kind == CursorKind.DECL_REF_EXPR else None
    if target is not None and target.kind == CursorKind.PARM_DECL:
        own = [p for p in template.get_children() if p.kind == CursorKind.PARM_DECL]
        given = list(specialisation.get_arguments())
        index = next((i for i, p in enumerate(own) if p == target), None)
        return given[index].type if index is not None and index < len(given) and (
            len(given) == len(own)) else None
    if expr.kind == CursorKind.MEMBER_REF_EXPR:
        bases = [c for c in expr.get_children() if c.kind.is_expression()]
        name = _member_spelling(expr)
        base = instantiated_type(bases[0], template, specialisation) if (
            len(bases) == 1 and name) else None
        if base is None:
            return None
        if base.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
            base = base.get_pointee()
        base = base.get_canonical()
        if base.kind == TypeKind.POINTER:
            base = base.get_pointee().get_canonical()
        if base.kind != TypeKind.RECORD:
            return None
        field = next((f for f in base.get_fields() if f.spelling == name), None)
        return field.type if field is not None else None
    # a variable or a value of one of the template's type parameters (``T local``)
    spelling = ctype.spelling.removeprefix("const ").removesuffix(" const")
    if ctype.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
        spelling = ctype.get_pointee().spelling.removeprefix("const ")
    index = next((i for i, p in enumerate(parameters) if p.spelling == spelling), None)
    if index is None or index >= specialisation.get_num_template_arguments():
        return None
    found = specialisation.get_template_argument_type(index)
    return found if found.kind != TypeKind.INVALID else None


def _depends(ctype: Type) -> bool:
    """Whether a type in a template is one its parameters decide."""
    if ctype.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
        ctype = ctype.get_pointee()
    canonical = ctype.get_canonical()
    return canonical.kind in (TypeKind.DEPENDENT, TypeKind.UNEXPOSED, TypeKind.INVALID) or (
        "type-parameter" in canonical.spelling)


def _member_spelling(member: Cursor) -> str:
    """The member a member reference names; a dependent one has no spelling, its last
    token after ``.`` or ``->`` is the name."""
    if member.spelling:
        return member.spelling
    tokens = [t.spelling for t in member.get_tokens()]
    return tokens[-1] if len(tokens) >= 2 and tokens[-2] in (".", "->") and (
        tokens[-1].isidentifier()) else ""


def closest(functions: list[Cursor], args: list[Cursor]) -> list[Cursor]:
    """``closest_typed`` with the types of the arguments ``args``."""
    return closest_typed(functions, [arg.type for arg in args])


def closest_typed(functions: list[Cursor], types: list[Type]) -> list[Cursor]:
    """The overloads, of those that may take arguments of ``types``, that C++ would
    rather call: the ones that take the most arguments as they are, by a parameter of
    that very type first, then by one of a template's own type (which takes any), and
    one that is no template before a template (nav2's CostmapSubscriber takes a
    ``LifecycleNode::WeakPtr``, or any ``NodeT``, and a topic; nav2's
    ``declare_or_get_parameter(node, name, descriptor)`` before the overload over any
    ``default_value``), then by one of the same class template as the argument (a
    ``std::shared_ptr<MultiThreadedExecutor>`` for a ``std::shared_ptr<Executor>``, not
    a ``std::unique_ptr<ResourceManager>``: ros2_control's ControllerManager
    constructors). Fewer than two are as they are."""
    if len(functions) < 2:
        return functions

    def score(function: Cursor) -> tuple[bool, int, int, int, bool]:
        params = [p for p in function.get_children() if p.kind == CursorKind.PARM_DECL]
        same = generic = alike = 0
        viable = True
        for param, arg in zip(params, types, strict=False):
            wanted, given = _bare(param.type), _bare(arg)
            if wanted is None:
                generic += 1
            elif wanted == given:
                same += 1
            elif given is not None and "<" in wanted and (
                    wanted.split("<", 1)[0] == given.split("<", 1)[0]):
                alike += 1
            if wanted is not None and wanted != given and _unconvertible(param.type, arg):
                viable = False
        return viable, same, generic, alike, function.kind != CursorKind.FUNCTION_TEMPLATE

    scores = [score(f) for f in functions]
    best = max(scores)
    return [f for f, found in zip(functions, scores, strict=True) if found == best]


# the smart pointers a pointer to a class converts to only when it points to that class
# or one derived from it; and those it may come from (a ``unique_ptr`` only as a
# temporary, which a maker's argument is)
_POINTERS_TO = frozenset({"std::shared_ptr", "std::weak_ptr", "boost::shared_ptr",
                          "boost::weak_ptr"})
_POINTERS_FROM = _POINTERS_TO | {"std::unique_ptr"}


def _pointee(ctype: Type, kinds: frozenset[str]) -> Cursor | None:
    """The class definition a raw pointer or a smart pointer of ``kinds`` (reference
    and const aside) points to; None for another type, or one not defined here."""
    if ctype.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
        ctype = ctype.get_pointee()
    canonical = ctype.get_canonical()
    if canonical.kind == TypeKind.POINTER:
        pointee = canonical.get_pointee().get_canonical()
    elif canonical.kind == TypeKind.RECORD and canonical.get_num_template_arguments() == 1:
        template = conf.lib.clang_getSpecializedCursorTemplate(canonical.get_declaration())
        if template is None or qualified_name(template) not in kinds:
            return None
        pointee = canonical.get_template_argument_type(0).get_canonical()
    else:
        return None
    if pointee.kind != TypeKind.RECORD:
        return None
    return pointee.get_declaration().get_definition()


def _unconvertible(wanted: Type, given: Type) -> bool:
    """Whether an argument of type ``given``, a pointer to a class the parse defines,
    cannot convert to a parameter of type ``wanted``, a smart pointer to another class
    that is none of its bases (a ``weak_ptr<rclcpp::Node>`` from a
    ``shared_ptr<nav2_util::LifecycleNode>``). False where either is not known so."""
    target = _pointee(wanted, _POINTERS_TO)
    source = _pointee(given, _POINTERS_FROM)
    if target is None or source is None:
        return False
    if key_of(target.canonical) == key_of(source.canonical):
        return False
    return key_of(target.canonical) not in base_keys(source)


def _bare(ctype: Type) -> str | None:
    """A type without reference and const, as its canonical spelling; None for one
    that depends on a template parameter."""
    if ctype.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
        ctype = ctype.get_pointee()
    canonical = ctype.get_canonical()
    if canonical.kind in (TypeKind.UNEXPOSED, TypeKind.INVALID) or (
        "type-parameter" in canonical.spelling
    ):
        return None
    return canonical.spelling.removeprefix("const ").removesuffix(" const")


MAX_CONSTRUCTORS = 4  # alternatives of a member that constructors initialise differently


@dataclass
class Fork:
    """A member whose value depends on the constructor: ``options`` (value or None for
    the member's default, constructor), the first the one taken; ``local``: the file
    constructs the class by each of them."""

    field: tuple[str, int]
    options: list[tuple[Cursor | None, Cursor]]
    local: bool = False


def constructed_elsewhere(field: Cursor, source: dict[str, bytes]) -> bool:
    """Whether ``field`` is a member of a class of the workspace's files that declares
    constructors and whose every constructor is defined outside this unit: what they
    give the member is not seen here."""
    owner = field.semantic_parent
    where = owner.location.file if owner is not None else None
    if owner is None or field.kind != CursorKind.FIELD_DECL or (
            where is None or where.name not in source):
        return False
    constructors = [c for c in owner.get_children() if c.kind in _CONSTRUCTORS
                    and is_constructor(c)]
    return bool(constructors) and all(c.get_definition() is None for c in constructors)


def constructed_here(field: Cursor) -> bool:
    """Whether ``field`` is a member of a class a constructor of which this unit's own
    source defines, or that declares none and a method of which it defines
    (``links.member_facts`` says what it gives the member)."""
    owner = field.semantic_parent
    if owner is None or field.kind != CursorKind.FIELD_DECL:
        return False
    main = field.translation_unit.spelling
    implicit = declares_no_constructor(owner)
    for member in owner.get_children():
        if (member.kind in _CONSTRUCTORS and is_constructor(member)) or (
                implicit and member.kind == CursorKind.CXX_METHOD):
            definition = member.get_definition()
            place = definition.location.file if definition is not None else None
            if place is not None and place.name == main:
                return True
    return False


def declares_no_constructor(owner: Cursor | None) -> bool:
    """Whether the class ``owner`` declares no constructor of its own."""
    return owner is not None and owner.kind in (
        CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL) and not any(
        member.kind in _CONSTRUCTORS and is_constructor(member)
        for member in owner.get_children())


def constructor_values(field: Cursor, source: dict[str, bytes]
                       ) -> list[tuple[Cursor | None, Cursor]]:
    """Per constructor of ``field``'s class defined in this file (its definition): the
    value it initialises or assigns the member with, None when it leaves it (the
    member's default); those that write it first, each in declaration order."""
    owner = field.semantic_parent
    if owner is None:
        return []
    writing: list[tuple[Cursor | None, Cursor]] = []
    leaving: list[tuple[Cursor | None, Cursor]] = []
    for member in owner.get_children():
        if member.kind != CursorKind.CONSTRUCTOR and not (
            member.kind == CursorKind.FUNCTION_TEMPLATE and is_constructor(member)
        ):  # (a constructor template: nav2's ``CostmapSubscriber(const NodeT &, topic)``)
            continue
        definition = member.get_definition()
        if definition is None or _copies(definition, owner):
            continue
        value = _written(field, definition, True, source)
        if value is None and _delegates(definition):
            continue  # the constructor it delegates to gives the value, with its arguments
        (writing if value is not None else leaving).append((value, definition))
    return writing + leaving


# around the text of a member that holds the name its node was constructed with
# (``names_node``), where ``links.resolve`` fills it in a call's name: the call's
# ``name_built`` is that name with ``?`` there
BUILT_OPEN = "\x1a"
BUILT_CLOSE = "\x1b"


def names_node(value: Cursor, constructor: Cursor) -> bool:
    """Whether ``value``, which ``constructor`` initialises a member with, is what that
    constructor hands its node base class as the node's name (``node_name_given``): the
    same parameter of the constructor, or the same text reading none (nav2's
    ``Costmap2DROS(name, ...) : nav2_util::LifecycleNode(name, "", ...), name_(name)``,
    and ``Costmap2DROS(options) : LifecycleNode("costmap", "", options), name_(
    "costmap")``): the member is the node's name as constructed, which the code that
    constructs the class gives (a nav2 server its costmap: ``local_costmap``), whatever
    the program that runs the class alone gives."""
    given = node_name_given(constructor)
    if given is None:
        return False
    one, other = _unconverted(value), _unconverted(given)
    refs = [e.referenced if e.kind == CursorKind.DECL_REF_EXPR else None for e in (one, other)]
    if all(r is not None and r.kind == CursorKind.PARM_DECL for r in refs):
        return key_of(refs[0]) == key_of(refs[1])
    texts = {value_text(e) for e in (one, other)}
    return len(texts) == 1 and not texts.pop().startswith("\x00")


def node_name_given(constructor: Cursor) -> Cursor | None:
    """The argument ``constructor`` hands its base class that is, or derives from,
    rclcpp's Node or LifecycleNode, for the base constructor's first parameter when that
    is a string: the node's name (rclcpp's constructors take it first; so do those of
    classes derived from them, nav2_util's LifecycleNode); None when the constructor
    initialises no such base, or clang kept no call of the base's constructor."""
    parent = constructor.semantic_parent
    if parent is None:
        return None
    for first, second in itertools.pairwise(constructor.get_children()):
        base = first.referenced if first.kind == CursorKind.TYPE_REF else None
        inner = list(second.get_children()) if second.kind == CursorKind.UNEXPOSED_EXPR \
            else [second]
        # (the call, unexposed where an argument is converted; an unexposed expression
        # of no children is no call: a member's ``command(double())``)
        if base is None or key_of(base) == key_of(parent) or not _node_class(base, 0) or (
                len(inner) != 1 or inner[0].kind != CursorKind.CALL_EXPR):
            continue
        second = inner[0]
        target = second.referenced
        args = written_arguments(second)
        params = [c for c in target.get_children() if c.kind == CursorKind.PARM_DECL] if (
            target is not None and target.kind == CursorKind.CONSTRUCTOR) else []
        if args and params and msg_types.param_type(params[0].type) == "str":
            return args[0]
    return None


def _unconverted(value: Cursor) -> Cursor:
    """``value`` without the conversions and copies around it (a ``std::string`` built
    of a literal or of another string)."""
    for _ in range(8):
        value = strip(value)
        inner = [c for c in value.get_children() if c.kind.is_expression()]
        target = value.referenced if value.kind == CursorKind.CALL_EXPR else None
        if len(inner) == 1 and (value.kind == CursorKind.UNEXPOSED_EXPR or (
                target is not None and target.kind == CursorKind.CONSTRUCTOR)):
            value = inner[0]
            continue
        break
    return value


def _node_class(cls: Cursor | None, depth: int) -> bool:
    """Whether ``cls`` is rclcpp's Node or LifecycleNode, or derives from one."""
    if cls is None or depth > 8:
        return False
    cls = cls.get_definition() or cls
    if qualified_name(cls) in api.RCLCPP_NODES:
        return True
    return any(_node_class(base.referenced, depth + 1) for base in cls.get_children()
               if base.kind == CursorKind.CXX_BASE_SPECIFIER)


def _delegates(constructor: Cursor) -> bool:
    """Whether a constructor delegates to one other constructor of its class that this
    file defines (whose values, read with the delegation's arguments, are the members')."""
    arguments = delegation(constructor)
    target = delegated_to(constructor, arguments) if arguments is not None else None
    return target is not None and target.get_definition() is not None


def _copies(constructor: Cursor, owner: Cursor) -> bool:
    """A copy or move constructor: it gives the members another object's values."""
    params = [p for p in constructor.get_children() if p.kind == CursorKind.PARM_DECL]
    if len(params) != 1:
        return False
    pointee = params[0].type.get_pointee()
    declaration = pointee.get_canonical().get_declaration() if pointee is not None else None
    return declaration is not None and key_of(declaration) == key_of(owner)


def value_text(value: Cursor | None) -> str:
    """An initialiser as its tokens (empty for none): two constructors that write the
    same text give the same value when it reads none of their parameters."""
    if value is None:
        return ""
    if any(node.kind == CursorKind.DECL_REF_EXPR and node.referenced is not None
           and node.referenced.kind == CursorKind.PARM_DECL for node in value.walk_preorder()):
        return f"\x00{key_of(value)}"  # a parameter of its constructor: its own value
    return " ".join(t.spelling for t in value.get_tokens())


# methods a host calls once, right after construction, to set a plugin or nodelet up
INIT_METHODS = frozenset({"onInit", "initialize", "init", "configure", "on_configure",
                          "on_init"})


def member_initialiser(field: Cursor, source: dict[str, bytes]
                       ) -> tuple[Cursor, Cursor] | None:
    """What a constructor of ``field``'s class initialises or assigns it with, or else an
    initialisation method (``onInit``, ``initialize``, ...), and that function (its
    definition, where this file has it)."""
    owner = field.semantic_parent
    if owner is None:
        return None
    members = list(owner.get_children())
    # constructors first, then the methods that initialise a plugin or nodelet after it
    # is made (``onInit``: ``private_nh_ = getPrivateNodeHandle();``, the nodelet idiom)
    ordered = [m for m in members if m.kind == CursorKind.CONSTRUCTOR] + [
        m for m in members if m.kind == CursorKind.CXX_METHOD and m.spelling in INIT_METHODS]
    for member in ordered:
        definition = member.get_definition()
        if definition is None:
            continue
        value = _written(field, definition, member.kind == CursorKind.CONSTRUCTOR, source)
        if value is not None:
            return value, definition
    return None


def _note_record(of: Type, found: set[tuple[str, int]]) -> None:
    """Add to ``found`` the class of an object of type ``of`` (not a pointer's)."""
    declaration = of.get_canonical().get_declaration()
    if declaration.kind in (CursorKind.STRUCT_DECL, CursorKind.CLASS_DECL):
        found.add(key_of(declaration.canonical))


def _written(field: Cursor, definition: Cursor, constructor: bool,
             source: dict[str, bytes]) -> Cursor | None:
    """What a constructor's initialiser list, or a write of the body of it or of an
    initialisation method that replaces the member's value (``member_ = value``,
    ``member_.reset(new T(..))``: ``writes``), gives ``field``. A null pointer in the
    initialiser list (``it_(nullptr)``) holds nothing yet: the body's write, when there is
    one, is what the member holds after the constructor (Kimera-VIO-ROS's
    ``it_(nullptr)``, then ``it_ = VIO::make_unique<image_transport::ImageTransport>(nh_)``
    in the body)."""
    children = list(definition.get_children())
    null: Cursor | None = None
    for i, child in enumerate(children[:-1]):
        if child.kind == CursorKind.MEMBER_REF and child.referenced == field:
            if not _null_pointer(children[i + 1]):
                return children[i + 1]
            null = children[i + 1]
            break
    for write in writes_in(definition, source):
        target, value = write.target, write.value
        if write.whole and value is not None and (
            target.kind == CursorKind.MEMBER_REF_EXPR and target.referenced == field
        ) and (constructor or not uses_parameter(value)):
            return value
    return null


def _null_pointer(value: Cursor) -> bool:
    """Whether an initialiser is a null pointer (``nullptr``, ``NULL``), through the
    conversions around it."""
    inner = strip(value)
    if inner.kind in NULL_POINTERS:
        return True
    given = [c for c in inner.get_children() if c.kind.is_expression()]
    return inner.kind == CursorKind.CALL_EXPR and len(given) == 1 and (
        strip(given[0]).kind in NULL_POINTERS)  # a smart pointer's constructor from nullptr


def _filled(field: Cursor, body: Cursor, source: dict[str, bytes]) -> bool:
    """Whether a constructor's ``body`` (or the constructor's) passes member ``field``, a
    string or a number, as an out argument (``writes.out_argument``): Kimera-VIO-ROS's
    RosbagDataProvider initialises ``left_imgs_topic_("")`` and then
    ``CHECK(nh_private_.getParam("left_cam_rosbag_topic", left_imgs_topic_))``; the
    initialiser is not what the member holds after the constructor (it is the read's
    default: ``CallSites.field``'s ``initial``)."""
    body = next((c for c in body.get_children() if c.kind == CursorKind.COMPOUND_STMT),
                None) if body.kind != CursorKind.COMPOUND_STMT else body
    if body is None or not _plain_value(field):
        return False
    return any(write.variable is not None and write.variable == field
               and out_argument(write)
               for write in writes_in(body, source))


# the ROS API's reads of a parameter into a variable given by reference (roscpp's handle
# and ``ros::param``, rclcpp's node): the rows of a read with an out argument
_READS_INTO = frozenset(key for table in (api.ROSCPP, api.RCLCPP) for key, row in table.items()
                        if row.kind == "read" and row.out_arg is not None)


def _reads_parameter(call: Cursor) -> bool:
    """Whether ``call`` is a read of a ROS parameter into a variable (``_READS_INTO``); a
    run-time helper that takes a member by reference (rtabmap's ``util3d`` functions given
    ``decimation_``) is not."""
    target = call.referenced if call.kind == CursorKind.CALL_EXPR else None
    if target is None or target.semantic_parent is None:
        return False
    return (qualified_name(target.semantic_parent), target.spelling) in _READS_INTO


def uses_parameter(expr: Cursor) -> bool:
    """Whether an expression reads a function parameter: in an initialisation method the
    host gives it (a plugin's ``initialize(name)``), which no call site here shows, so a
    member set from it stays unknown for the plugin's host to fill."""
    return any(node.kind == CursorKind.DECL_REF_EXPR and node.referenced is not None
               and node.referenced.kind == CursorKind.PARM_DECL
               for node in expr.walk_preorder())


def list_constructions(node: Cursor) -> list[tuple[Cursor, Cursor]]:
    """(braced list, the constructor it calls) for a braced list (``INIT_LIST_EXPR``)
    that initialises a class of the project's code by a constructor, or for each such
    element of a braced list of an array of that class (what a ``std::vector<T>{{...},
    {...}}`` builds its ``std::initializer_list`` from: clang types those elements
    ``void`` and keeps no call, mrover's ``std::vector<ParameterWrapper> params{{"alpha",
    mAlpha, 0.05}, ...}``); the list is the call's argument list."""
    ctype = node.type.get_canonical()
    if ctype.kind == TypeKind.RECORD:
        callee = _list_constructor(node, ctype)
        return [(node, callee)] if callee is not None else []
    if ctype.kind not in (TypeKind.CONSTANTARRAY, TypeKind.INCOMPLETEARRAY):
        return []
    element = ctype.element_type.get_canonical()
    if element.kind != TypeKind.RECORD:
        return []
    found = []
    for child in node.get_children():
        if child.kind == CursorKind.INIT_LIST_EXPR and (
                child.type.get_canonical().kind != TypeKind.RECORD):
            callee = _list_constructor(child, element)
            if callee is not None:
                found.append((child, callee))
    return found


def dependent_new(node: Cursor) -> tuple[Cursor, Cursor] | None:
    """(argument list, the constructor it calls) for a new-expression of a class of the
    project's code (not a template) that holds no call of a constructor, only the list
    of its arguments, one of which depends on a template's parameters: the one
    constructor C++ would call with them (``closest``); None when no single one would."""
    made = node.type.get_canonical().get_pointee()
    if made.kind != TypeKind.RECORD:
        return None
    children = [c for c in node.get_children() if c.kind.is_expression()]
    if len(children) != 1 or children[0].kind != CursorKind.UNEXPOSED_EXPR or (
            children[0].spelling) or any(
            c.kind == CursorKind.CALL_EXPR and c.referenced is not None
            and c.referenced.kind == CursorKind.CONSTRUCTOR for c in children):
        return None
    callee = _list_constructor(children[0], made)
    return None if callee is None else (children[0], callee)


def _list_constructor(node: Cursor, ctype: Type) -> Cursor | None:
    """The constructor of class ``ctype`` the braced list ``node`` calls: the one
    overload that may take its elements, the closest as C++ picks (``closest``); None
    for an aggregate, a standard class, or a choice not made here."""
    decl = ctype.get_declaration()
    definition = decl.get_definition() if decl is not None else None
    if definition is None or definition.location.file is None or (
            definition.location.is_in_system_header):
        return None
    args = [c for c in node.get_children() if c.kind.is_expression()]
    found = [c for c in definition.get_children()
             if c.kind == CursorKind.CONSTRUCTOR and _takes(c, len(args))
             and _binds(c, args)]
    found = closest(found, args)
    return found[0] if len(found) == 1 else None


def _binds(function: Cursor, args: list[Cursor]) -> bool:
    """Whether each of ``args`` that ``function`` takes by non-const lvalue reference is
    of that very type (no conversion makes such a reference: a ``float`` member passed
    where one overload takes ``double&`` and another ``float&`` picks the second)."""
    for ptype, arg in zip(function.type.argument_types(), args, strict=False):
        if ptype.kind != TypeKind.LVALUEREFERENCE:
            continue
        wanted = ptype.get_pointee()
        if wanted.is_const_qualified():
            continue
        given = arg.type.get_canonical()
        if given.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
            given = given.get_pointee().get_canonical()
        if given.kind in (TypeKind.INVALID, TypeKind.UNEXPOSED, TypeKind.DEPENDENT) or (
                ANY_CLASS in given.spelling):
            continue  # a type the parse does not know (a missing header's): may be it
        if given.spelling != wanted.get_canonical().spelling:
            return False
    return True


def _takes(constructor: Cursor, count: int) -> bool:
    params = [p for p in constructor.get_children() if p.kind == CursorKind.PARM_DECL]
    required = sum(1 for p in params if not any(c.kind.is_expression()
                                                for c in p.get_children()))
    return required <= count <= len(params)


def _may_name(function: Cursor, spelling: bytes, source: dict[str, bytes]) -> bool:
    """Whether ``function``'s text may name ``spelling``: it does, or its text is not
    at hand in one file (read then, to be safe)."""
    start, end = function.extent.start, function.extent.end
    if start.file is None or end.file is None or start.file.name != end.file.name:
        return True
    data = source.get(start.file.name)
    return data is None or spelling in data[start.offset:end.offset]


def _defined_in(function: Cursor) -> str | None:
    where = function.location.file
    return where.name if where is not None else None


def _one_variable(args: Iterable[Cursor]) -> bool:
    """Whether each argument is the same variable, member or parameter, as written (or a
    copy of it: a string passed by value)."""
    found: set[tuple[str, int]] = set()
    for arg in args:
        node = strip(arg)
        while node.kind == CursorKind.CALL_EXPR and node.referenced is not None and (
                node.referenced.kind == CursorKind.CONSTRUCTOR) and (
                node.referenced.semantic_parent is not None) and _copies(
                node.referenced, node.referenced.semantic_parent):
            inner = [c for c in node.get_children() if c.kind.is_expression()]
            if len(inner) != 1:
                break
            node = strip(inner[0])
        if node.kind not in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR) or (
                node.referenced is None):
            return False
        found.add(key_of(node.referenced.canonical))
    return len(found) == 1


def _index_of(function: Cursor, parm: Cursor) -> int | None:
    params = [c for c in function.get_children() if c.kind == CursorKind.PARM_DECL]
    return next((i for i, p in enumerate(params) if p.spelling == parm.spelling), None)
