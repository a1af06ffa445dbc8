"""Functions of the workspace that wrap the ROS API, summarised as API rows of their own.

Real nodes often reach ROS through their own functions: a base class's
``create_publisher<MessageT>(topic_name, qos)`` that calls a free factory that calls
rclcpp, or ``declare_or_get_parameter(name, default)``. A function whose parameter flows
into the name argument of a ROS call (a row of ``api.ALL``, or of another wrapper) is a
*wrapper*: it gets a derived row of the same kind whose argument indexes are its own
parameters (``Wrapper``). A call of it is then a ROS call at the call site, with the
name, type (the call's template argument when the inner type is the wrapper's template
parameter, or, where the call writes none, the type of the argument that deduces it; or
the value / callback it passes on), QoS, queue, default, handle and
conditions of that call site, and under the conditions the call is under inside the
wrapper (and inside each wrapper of a chain: ``if (use_extra_)`` around a second
publisher the wrapper makes); the call inside the wrapper is no longer emitted on its
own (its name would be ``?``).

Summaries are built per translation unit from every function defined in its workspace
files (headers included): first the functions that call the API with a parameter-valued
name, then, up to ``MAX_DEPTH`` times, those that call such a wrapper. Calls inside
templates whose target depends on a template parameter (``node->declare_parameter(name,
v)`` with ``NodeT node``) match the node API rows by method name (``DEPENDENT``). A
recursive function is not a wrapper (its calls are read as before, its name stays
unknown). A name the wrapper builds (``"radar/" + name``) keeps the parts it adds; a name
fixed in the wrapper is not a wrapper's: that call stays where it is, once.
"""

from __future__ import annotations

import bisect
import dataclasses
import functools
import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, TypeVar

from clang.cindex import Cursor, CursorKind, Type, TypeKind, conf

from ...model.conditions import Condition
from ...model.values import Unknown
from . import api, msg_types
from .call_sites import (
    base_initialisers,
    closest,
    default_argument,
    delegation,
    fits,
    held_lambda,
    is_constructor,
    specialised_keys,
)
from .call_types import callee as callee_head
from .call_types import template_argument
from .cursors import Node, from_standin, overloads
from .expressions import constructed_name
from .handles import (
    callback,
    callback_name,
    is_handle,
    join_name,
    own_functions_only,
    pointee,
    qualified_name,
)
from .qos import qos as qos_of
from .tested import TestedCalls
from .tested import key as tested_key
from .values import (
    BACKREF,
    CHOICE,
    CHOICE_END,
    CHOICE_SEP,
    PLACEHOLDER,
    SEPARATOR,
    UNKNOWN,
    Parts,
    Scope,
    emptiness_test,
    initializer,
    render,
    strip,
    written_arguments,
)
from .values import key_of as _key  # a cursor's place: its file and offset
from .writes import between

if TYPE_CHECKING:
    from .visitor import CallFinder

__all__ = ["DEPENDENT", "DEPENDENT_ROS1", "DEPENDENT_ROS2", "MAX_DEPTH", "Wrapper", "Wrappers",
           "is_constructor", "of_class_template"]

MAX_DEPTH = 4  # a wrapper of a wrapper ... of an API call
Key = tuple[str, int]
Shape = TypeVar("Shape")  # what a string's shape holds between its known parts
# what a member call on an object whose type is a template parameter may be: the node
# handle's methods in ROS 1 code, rclcpp node's in ROS 2 code, by name (a ROS 2 unit's
# ``source.subscribe(o)``, RxCpp's operators in Open-RMF, is no ``NodeHandle::subscribe``)
DEPENDENT_ROS1: dict[str, api.RosFunction] = {
    name: row for (owner, name), row in api.ALL.items() if owner == api.NODE_HANDLE}
DEPENDENT_ROS2: dict[str, api.RosFunction] = {
    name: row for (owner, name), row in api.ALL.items() if owner in api.RCLCPP_NODES}
DEPENDENT: dict[str, api.RosFunction] = {**DEPENDENT_ROS1, **DEPENDENT_ROS2}
_ARGUMENTS = ("queue_arg", "latch_arg", "callback_arg", "qos_arg", "default_arg")
_API_NAMES = frozenset(
    [*DEPENDENT, *(name for _, name in api.ALL), *(name for _, name in api.FACTORIES)])
# the spellings of the functions a resolved call matches a row or a factory through
FACTORY_NAMES = frozenset([*(name for _, name in api.FACTORIES), "make_shared", "make_unique"])
_ROW_NAMES = _API_NAMES | FACTORY_NAMES
# the names an unresolved call can match a row through, each written in its text
_UNRESOLVED_NAMES = frozenset(name.encode() for name in _ROW_NAMES)
_WORD = re.compile(rb"\w+")
_THIS_CALLS = frozenset({"shared_from_this", "get", "weak_from_this"})
# the types of a call that may return whether a parameter is there: ``bool``, or not
# known until a template is instantiated
_MAY_BE_BOOL = frozenset({TypeKind.BOOL, TypeKind.DEPENDENT, TypeKind.UNEXPOSED})


@dataclass(frozen=True)
class Wrapper:
    """The ROS call a call of one wrapper makes: ``row`` reads the call site's
    arguments; the name is ``before`` + the name argument + ``after``; ``namespace`` is
    that of a handle the wrapper holds itself (None: from the call site, as ``row``
    says); ``through`` are the functions it was derived through (recursion)."""

    row: api.RosFunction
    before: Parts = ()
    after: Parts = ()
    namespace: str | None = None
    through: frozenset[Key] = frozenset()
    # what the wrapper gives itself (a QoS, queue, latch or callback it writes, or the
    # default value of its parameter that gives it): the call's fields, where the call
    # site gives none
    own: tuple[tuple[str, object], ...] = ()
    # the name is not an argument but ``T::name`` of the wrapper's template type
    # parameter of this index (an interface spec: ``create_publisher<Spec>()``); its
    # type is ``T::Message`` (``T::Service``)
    spec_param: int | None = None
    # the spec deduced from the call site's argument of this index instead (the wrapper's
    # parameter ``SharedPtrT & pub``), and the member types that lead from that
    # argument's type to the spec (``typename SharedPtrT::element_type::SpecType``:
    # Autoware's component interface adaptor, ``adaptor.init_pub(pub_)``)
    spec_arg: int | None = None
    spec_path: tuple[str, ...] = ()
    # the name is not an argument but the member of this place (``before`` + member +
    # ``after``): a method of a class template that names its call after a member its
    # constructor initialises (depthai_bridge's ``advertise`` with ``_rosTopic``); such a
    # summary is never emitted at a call site, only lifted into a constructor of the
    # class that calls the method (``Wrappers.members``)
    member: Key | None = None
    # made only for the constructions whose class template argument of index ``when[1]``
    # is (``when[3]``) or is not the type declared at ``when[2]`` (the class template at
    # ``when[0]``): one of tag-dispatched overloads, ``advertise(depth,
    # std::is_same<M, Image>{})`` with ``advertise(int, std::true_type)``
    when: tuple[Key, int, Key, bool] | None = None
    # the calls the summary was lifted through, the outermost first: the call inside the
    # wrapper (or the class template's method a member summary was made of), then the
    # call inside the function that one calls, down to the API call. The source
    # conditions each is under in its function (``Wrappers.read_inside``) go with every
    # call made through the summary: depthai_bridge's ``if(!_cameraName.empty())``
    # around the camera_info publisher; a wrapper's ``if (use_extra_)`` around a second
    # publisher it makes
    inside: tuple[Key, ...] = ()

    def same(self, other: Wrapper) -> bool:
        return (self.row, self.before, self.after, self.namespace, self.spec_param,
                self.spec_arg, self.spec_path, self.member, self.when, self.inside) == (
            other.row, other.before, other.after, other.namespace, other.spec_param,
            other.spec_arg, other.spec_path, other.member, other.when, other.inside)


class Wrappers:
    """The wrappers of one translation unit, and the calls inside them."""

    def __init__(self, finder: CallFinder) -> None:
        self.finder = finder
        self.summaries: dict[Key, list[Wrapper]] = {}
        self.names: frozenset[str] = frozenset()  # the wrappers' spellings
        self.site_names: frozenset[str] = frozenset()  # those a call-site grep looks for
        self.site_names_bare: frozenset[str] = frozenset()  # those called with no argument
        # the qualifiers a call of a wrapper that is a free function may be written with:
        # (name, namespace) for each namespace around each wrapper of that name, and
        # (name, "") to say that every wrapper of that name is a free function; a call
        # qualified by another class or namespace (``TypeGuard::create<T>()`` beside
        # ros_canopen's ``canopen::create(nh, name, ...)``) is none of theirs
        self.site_qualifiers: frozenset[tuple[str, str]] = frozenset()
        self._inner: dict[Key, Key] = {}  # call inside a wrapper -> the wrapper
        self._kept: set[Key] = set()  # wrappers whose inner calls are still emitted
        # those of them that the node's other files may call too: a call of one in this
        # unit passes its values on (``links``) and makes no call of its own
        self._shared: set[Key] = set()
        self._recursive: set[Key] = set()
        # the spellings of the functions summarised so far (None: one that an
        # unresolved call's text need not show, an operator)
        self._summarised: set[bytes] | None = set()
        self._opaque: dict[str, list[int]] = {}  # file -> offsets of macro expansions
        # constructor -> the argument list of the constructor it delegates to (``build``)
        self._delegations: dict[Key, Cursor] = {}
        # constructor -> (argument list, base constructor, whether the base is named with
        # the class's own template parameters) of each base it initialises (``build``)
        self._base_inits: dict[Key, list[tuple[Cursor, Key, bool]]] = {}
        # constructor -> (argument list, API row, whether typed) of each base of the API
        # it initialises (``build``, ``_base_call``)
        self._base_rows: dict[Key, list[tuple[Cursor, api.RosFunction, bool]]] = {}
        # id of each function of the unit -> its calls and unexposed expressions in
        # preorder (``_scan``), for ``CallFinder._gives``
        self.preorder: dict[int, list[Cursor]] = {}
        # id of each function of the unit -> its references to declarations
        # (``DECL_REF_EXPR``, ``MEMBER_REF_EXPR``) in preorder, for
        # ``call_conditions.site_facts``
        self.references: dict[int, list[Cursor]] = {}
        # the wrapper methods (not constructors) by name, for a call on a dependent object
        self._methods: dict[str, list[Cursor]] = {}
        # id of a call (a node of the unit) -> the constructors it may call through a
        # factory (``_constructed``), wrappers or not
        self._constructors: dict[int, list[Key]] = {}
        # each summarised function (and lambda) of the unit, by its key (``called``)
        self._functions: dict[Key, Cursor] = {}
        # a class template's method (not a constructor) -> its calls named after a member
        # of the class (``Wrapper.member``), lifted into the class's constructors that
        # call it on their own object; the members by place, and the calls by place
        self.members: dict[Key, list[Wrapper]] = {}
        self._fields: dict[Key, Cursor] = {}
        # (a call -> its method, and whether a constructor's summary may take it: typed
        # by the class's template parameter, as a construction gives it)
        self._member_inner: dict[Key, tuple[Key, bool]] = {}
        # a method -> (constructor, call) of each call of it lifted into a constructor
        self._lifted_sites: dict[Key, set[tuple[Key, Key]]] = {}
        self._left: set[Key] = set()  # the methods whose calls those constructions make
        # the tag-dispatched overloads lifted into a constructor under their test (``when``)
        self._dispatched: set[Key] = set()
        # a method's call a member summary was made of -> (the method, the call), and the
        # source conditions of the call there (``read_inside``)
        self._insides: dict[Key, tuple[Cursor, Cursor]] = {}
        self._inside_conditions: dict[Key, tuple[Condition, ...]] = {}
        # the parameter declarations among those calls: the argument that names the
        # parameter (``ConditionReader.declared_anyway``)
        self._declared: dict[Key, Cursor] = {}

    # -- building -----------------------------------------------------------------------

    def build(self) -> None:
        finder = self.finder
        # a constructor is no wrapper (the values its callers pass flow into its
        # parameters and members, call_sites, and its calls stay where they are
        # written), except one of a class template: the type of its call is the
        # construction's (nav2's ServiceServer<ServiceT>(name, node, callback))
        functions = [f for f in finder.functions if (
            _parameters(f) or _template_parameters(f)) and (
            f.kind != CursorKind.CONSTRUCTOR or of_class_template(f))]
        # each function's calls, and its lambdas: one with parameters may be returned
        # and pass one on as a name (nav2 MPPI's ``getParamGetter(ns)``:
        # ``getParam(x, "name", d)``), so it is summarised like a function
        for name, offset in finder.opaque:
            self._opaque.setdefault(name, []).append(offset)
        for offsets in self._opaque.values():
            offsets.sort()
        found: dict[Key, list[Cursor]] = {}
        # a class template's constructor that delegates to another with arguments that
        # depend on a template parameter (nav2's SimpleActionServer<ActionT>(NodeT node,
        # name, ...) : SimpleActionServer(node->get_node_base_interface(), ..., name)):
        # clang keeps no call of the constructor, only the argument list
        self._delegations = {_key(f.canonical): d for f in finder.functions
                             if (d := _delegation(f)) is not None}
        # and one that initialises a base with such arguments (turtlebot4's
        # Turtlebot4Service<ServiceT>(nh, service, timeout) : Turtlebot4BaseService<
        # ServiceT>(nh, service, timeout), whose constructor makes the client)
        self._base_inits = {_key(f.canonical): inits for f in finder.functions
                            if is_constructor(f) and of_class_template(f) and (
                                inits := [(arguments, _key(base.canonical),
                                           _same_parameters(f, base))
                                          for arguments, base in base_initialisers(f)])}
        # and one that initialises a base of the API with such arguments (stella_vslam_ros'
        # ``ModifiedSubscriber<M>(node, topic, qos) : message_filters::Subscriber<M>(node,
        # topic, qos)``): the base's row, made with those arguments
        self._base_rows = {_key(f.canonical): rows for f in finder.functions
                           if is_constructor(f) and of_class_template(f) and (
                               rows := [(arguments, spec, _first_parameter_passed(f, base))
                                        for arguments, base in base_initialisers(f)
                                        if (spec := self._api_base(base)) is not None])}
        todo = [f for f in finder.functions if f.kind != CursorKind.FIELD_DECL]
        top = {id(f) for f in todo}
        while todo:
            function = todo.pop()
            every: list[Cursor] | None = None
            references: list[Cursor] | None = None
            if id(function) in top:
                every = self.preorder[id(function)] = []
                references = self.references[id(function)] = []
            inner, lambdas = _scan(function, every, references)
            found[_key(function.canonical)] = inner
            todo += lambdas
            functions += [lam for lam in lambdas if _parameters(lam)]
        # a class template's method whose call is named after a member (``Wrapper.member``)
        methods = [f for f in finder.functions if f.kind in (
            CursorKind.CXX_METHOD, CursorKind.FUNCTION_TEMPLATE) and of_class_template(f)
            and not is_constructor(f) and not f.is_static_method()]
        api_names = {"", *_API_NAMES}
        for method in methods:
            for call in found.get(_key(method.canonical), ()):
                if call.spelling in api_names:
                    self._summarise_member(method, call)
        # the calls that may be of the API or of a wrapper (by name; "" depends on a
        # template parameter)
        wanted = {"", *_API_NAMES, *(f.spelling for f in functions),
                  *(f.spelling.split("<")[0] for f in methods
                    if _key(f.canonical) in self.members)}
        calls = {_key(f.canonical): [c for c in found.get(_key(f.canonical), ())
                                     if c.spelling in wanted]
                 for f in functions}
        todo = functions
        # the calls of each function read in this round: every one at first, then those
        # that call a function whose summary changed (a call of another gives what it
        # gave before: its rows are the same)
        read = calls
        for _round in range(MAX_DEPTH):
            changed: set[Key] = set()
            for function in todo:
                key = _key(function.canonical)
                if key in self._recursive:
                    continue
                for call in read[key]:
                    if self._summarise(function, key, call):
                        changed.add(key)
                delegation = self._delegations.get(key)
                if delegation is not None and self._delegate(function, key, delegation):
                    changed.add(key)
                for arguments, base, typed in self._base_inits.get(key, ()):
                    if self._delegate(function, key, arguments, [base], typed):
                        changed.add(key)
                for arguments, spec, typed in self._base_rows.get(key, ()):
                    if self._base_call(function, key, arguments, spec, typed):
                        changed.add(key)
            if not changed:
                break
            # the functions that call one that changed are read again
            read = {key: [call for call in each if self._calls_one_of(call, changed)]
                    for key, each in calls.items()}
            todo = [f for f in functions if read[_key(f.canonical)]
                    or (_key(f.canonical) in self._delegations and any(
                        k in changed for k in self._delegated(f, self._delegations[
                            _key(f.canonical)])))
                    or any(base in changed for _, base, _ in self._base_inits.get(
                        _key(f.canonical), ()))]
        # a recursive function is no wrapper, nor is one made through it; a class
        # template's constructor is one only where the construction gives the type (its
        # other calls stay in it, named by what its callers pass: call_sites, links), or
        # where the construction chooses the overload that makes the call (``when``: a
        # call of a type of its own in a tag-dispatched overload, depthai_bridge's
        # image_transport publisher, made only by the constructions of Image)
        constructors = {_key(f.canonical) for f in functions if is_constructor(f)}
        # (and one that makes the API's call by initialising its base, typed or not: no
        # call of it stays in the constructor, where clang keeps only the arguments)
        base_arguments = {(_key(arguments),) for rows in self._base_rows.values()
                          for arguments, _, _ in rows}
        self.summaries = {
            key: kept for key, found in self.summaries.items() if key not in self._recursive
            and not any(self._recursive & w.through for w in found)
            and (kept := [w for w in found if key not in constructors
                          or "template" in w.row.type_from or w.spec_param is not None
                          or w.when is not None or w.inside[:1] in base_arguments])}
        self._inner = {call: owner for call, owner in self._inner.items()
                       if owner in self.summaries}
        self._functions = {key: f for f in functions
                           if (key := _key(f.canonical)) in self.summaries}
        # a method's calls named after a member are made at the constructions of the
        # class when every call of the method in the unit is in a constructor whose
        # summary took them (the member's value is the constructor's argument there)
        # (or where nothing in the unit calls the method, nor names it in a call: a
        # member of a class template that is not virtual exists only where it is called;
        # a unit that calls it makes them there)
        sites = finder.sites
        named = _called_names(found.values()) if self.members else set()
        for method in methods:
            key = _key(method.canonical)
            if key not in self.members or sites is None:
                continue
            callers = [_key(c) for each in found.values() for c in each
                       if _may_call(c, method)]
            unused = not callers and not method.is_virtual_method() and (
                method.spelling not in named) and not self._mentioned(method)
            taken = {site for ctor, site in self._lifted_sites.get(key, ())
                     if any(key in w.through for w in self.summaries.get(ctor, ()))}
            if unused or (callers and all(c in taken for c in callers)):
                # (where the constructors take them: not a call of a type of its own,
                # which stays in the method, named through the call sites)
                # (a tag-dispatched overload's calls all go with the overload's choice)
                left = {call: owner for call, (owner, typed) in self._member_inner.items()
                        if owner == key and (typed or unused or key in self._dispatched)}
                if left:
                    self._left.add(key)
                    self._inner.update(left)
        main = finder.tu.spelling
        for function in functions:
            key = _key(function.canonical)
            # its callers are in the node's other files: ROS 1 names its calls there
            # (links); ROS 2 keeps them where they are written, with the names they
            # give (realsense2_camera's setParamT, whose callers are in named_filter.cpp)
            if key in self.summaries and sites is not None and (
                function.location.file is not None and function.location.file.name == main
                and not sites.callers(function)
            ):
                self._kept.add(key)
            # a free function the node's other files may call as well as this one
            # (msckf_vio's ``getTransformCV``, called in utils.cpp by getTransformEigen
            # and in image_processor.cpp): its calls are named where written, with every
            # value the node's files pass (links, with this file's calls among them),
            # not at this file's call sites only, which lost the other files' names
            elif key in self.summaries and sites is not None and (
                function.kind == CursorKind.FUNCTION_DECL and sites.shared(function)
            ):
                self._kept.add(key)
                self._shared.add(key)
        # a class template's constructor is spelled with its parameters
        # (``ServiceClient<ServiceT, NodeT>``), a construction's call without them
        self.names = frozenset(
            "operator()" if f.kind == CursorKind.LAMBDA_EXPR else f.spelling.split("<")[0]
            for f in functions if _key(f.canonical) in self.summaries)
        # and a variable holding such a lambda, by which a template calls it (``held_lambda``)
        self.names |= {node.spelling for nodes in self.preorder.values() for node in nodes
                       if node.kind == CursorKind.VAR_DECL
                       and (made := held_lambda(node)) is not None
                       and _key(made.canonical) in self.summaries}
        self._methods = {}
        for f in functions:
            if _key(f.canonical) in self.summaries and f.kind in (
                CursorKind.CXX_METHOD, CursorKind.FUNCTION_TEMPLATE
            ) and f.semantic_parent is not None and f.semantic_parent.kind in (
                CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL, CursorKind.CLASS_TEMPLATE
            ) and not is_constructor(f):
                self._methods.setdefault(f.spelling.split("<")[0], []).append(f)
        if self.names:
            self.names |= {""}  # a call that depends on a template parameter
        # the names a grep for call sites looks for (``recall``): not those of wrappers
        # named by a spec only (``Client<SpecT>``, ``create_service_handle<SpecT>``):
        # a node calls them through another wrapper, and their spelling is also a type
        # (``rclcpp::Client<S>::SharedFuture``, ``decltype(create_service_handle<S>(...))``)
        # and not those wrapping only rows that are no call site (an SDF element's value:
        # uuv_simulator's ``GetSDFParam<T>(sdf, name, ...)``, a Gazebo plugin's reader of
        # its <plugin> element, makes no ROS call)
        by_name: dict[str, bool] = {}  # spelling -> whether all its wrappers are a spec's
        for f in functions:
            summary = self.summaries.get(_key(f.canonical))
            if summary and f.kind != CursorKind.LAMBDA_EXPR:
                name = f.spelling.split("<")[0]
                by_name[name] = by_name.get(name, True) and all(
                    w.spec_param is not None or not w.row.call_site for w in summary)
        self.site_names = self.names - {name for name, spec in by_name.items() if spec}
        # those a call with no argument at all may be (``get()``): a wrapper with no
        # template parameter and a default for each parameter it has; a call ``get()``
        # of any other name is no call of a wrapper (a smart pointer's ``.get()`` where
        # the unit has a wrapper ``get(node, name)``: nav2_smac_planner's SearchInfo)
        self.site_names_bare = frozenset(
            f.spelling.split("<")[0] for f in functions
            if self.summaries.get(_key(f.canonical)) and f.kind != CursorKind.LAMBDA_EXPR
            and not _template_parameters(f)
            and all(default_argument(p) is not None for p in _parameters(f))
        ) & self.site_names
        qualifiers: dict[str, set[str] | None] = {}  # None: a method has the name
        for f in functions:
            if self.summaries.get(_key(f.canonical)) and f.kind != CursorKind.LAMBDA_EXPR:
                name = f.spelling.split("<")[0]
                around = _namespaces(f)
                known = qualifiers.get(name, set())
                qualifiers[name] = None if around is None or known is None else (
                    known | around)
        self.site_qualifiers = frozenset(
            (name, q) for name, every in qualifiers.items()
            if every is not None and name in self.site_names for q in {"", *every})

    def read_inside(self, conditions_of: Callable[[Cursor, list[Cursor]],
                                                  dict[Any, tuple[Condition, ...]]]
                    ) -> None:
        """Read the source conditions of each call a summary was lifted through
        (``Wrapper.inside``) in its function, with ``conditions_of`` (the finder's,
        before its walk: it readies the condition reader for the function and walks it
        once for all of them)."""
        used = {key for found in self.summaries.values() for w in found
                for key in w.inside}
        by_function: dict[Key, tuple[Cursor, list[Key]]] = {}
        for key in sorted(used):
            function, _call = self._insides[key]
            by_function.setdefault(_key(function), (function, []))[1].append(key)
        for function, keys in by_function.values():
            found = conditions_of(function, [self._insides[key][1] for key in keys])
            for key in keys:
                conditions = found.get(key, ())
                if key in self._declared:
                    conditions = self.finder.reader.declared_anyway(
                        conditions, self._declared[key])
                self._inside_conditions[key] = tuple(
                    c for c in conditions if c.kind == "source")

    def _mentioned(self, method: Cursor) -> bool:
        """Whether the unit's files write the method's name anywhere but where it is
        declared and defined (a pointer to it, ``std::bind(&C::m, this)``, a call a
        macro makes): it may then be instantiated and called there."""
        name = method.spelling.split("<")[0].encode()
        own = {(d.location.file.name, d.location.offset) for d in (method, method.canonical)
               if d.location.file is not None}
        pattern = re.compile(rb"\b" + re.escape(name) + rb"\b")
        for path, data in self.finder.source.items():
            if name not in data:
                continue
            if any((path, m.start()) not in own for m in pattern.finditer(data)):
                return True
        return False

    def silent(self, function: Cursor) -> bool:
        """Whether the calls inside ``function`` are emitted where it is called, not
        where they are written (a wrapper whose callers are in this unit)."""
        key = _key(function.canonical)
        return (key in self.summaries and key not in self._kept) or key in self._left

    def silent_lambdas(self) -> list[Cursor]:
        """The lambdas whose calls are emitted where they are called (``silent``): their
        bodies are no function of the unit's, and a call there that a generic lambda
        leaves dependent (MoveIt's planning scene monitor's ``[this](const std::string&
        name, auto value, ...) { return pnode_->declare_parameter(name, value, desc); }``)
        is resolved nowhere but at the lambda's calls."""
        return [f for f in self._functions.values()
                if f.kind == CursorKind.LAMBDA_EXPR and self.silent(f)]

    def _constructed(self, call: Cursor, args: list[Cursor]) -> list[Key]:
        """The wrapper constructors ``std::make_shared<C>(args)`` may call (C a class
        template of the unit whose constructor wraps the API), resolved or dependent."""
        # the same for every round of ``build``: asked once a node of the unit (whose
        # objects live as long as the unit, so their ids name them)
        found = self._constructors.get(id(call)) if isinstance(call, Node) else None
        if found is None:
            found = self._constructors_of(call, args)
            if isinstance(call, Node):
                self._constructors[id(call)] = found
        return [key for key in found if key in self.summaries]

    def _constructors_of(self, call: Cursor, args: list[Cursor]) -> list[Key]:
        """The constructors of the class template ``call`` makes through a factory that
        ``args`` fit (``_constructed`` keeps the wrappers among them)."""
        target = call.referenced
        head = next(iter(call.get_children()), None)
        heads = [target] if target is not None else [
            d for c in list(call.get_children())[:1] for d in _overloads(c)]
        if not any((qualified_name(d.semantic_parent), d.spelling) in api.FACTORIES
                   or _static_factory(d) for d in heads) and not (
                       target is None and head is not None and _static_factory_call(head)):
            return []
        classes = [d for c in (head.walk_preorder() if head is not None else ())
                   if c.kind in (CursorKind.TEMPLATE_REF, CursorKind.TYPE_REF)
                   and c.referenced is not None for d in _aliased(c.referenced)]
        pattern = next((c for c in classes if c.kind == CursorKind.CLASS_TEMPLATE), None)
        if pattern is None:
            return []
        found = []
        for child in pattern.get_children():
            key = _key(child.canonical)
            if (child.kind == CursorKind.CONSTRUCTOR or (
                child.kind == CursorKind.FUNCTION_TEMPLATE and is_constructor(child)
            )) and _fits(child, args):
                found.append(key)
        return found

    def _summarise_member(self, method: Cursor, call: Cursor) -> None:
        """Summarise the API call ``call`` of the class template's method ``method`` when
        its name is a member of the class (``Wrapper.member``)."""
        key = _key(method.canonical)
        for wrapper, args, cls, callee in self._inner_rows(call):
            if callee is not None:
                continue
            lifted = self._lift(method, wrapper, call, args, cls, member=True)
            if lifted is None or lifted.member is None:
                continue
            self._member_inner[_key(call)] = (key, self._member_inner.get(_key(call), (
                key, False))[1] or "template" in lifted.row.type_from
                or "template-value" in lifted.row.type_from)
            lifted = dataclasses.replace(lifted, inside=self._through(method, call))
            found = self.members.setdefault(key, [])
            if not any(lifted.same(w) for w in found):
                found.append(lifted)

    def _member_rows(self, function: Cursor, call: Cursor) -> list[Wrapper]:
        """The summaries named after a member (``Wrapper.member``) of the method that
        ``call``, in a constructor ``function`` of a class template, calls on the object it
        constructs: one method the call resolves to, or the one overload it may be, or
        each of tag-dispatched overloads under the test that chooses it (``when``)."""
        if not self.members or not is_constructor(function) or (
            not of_class_template(function)
        ):
            return []
        target = call.referenced
        children = list(call.get_children())
        head = strip(children[0]) if children else None
        if head is None or head.kind not in (CursorKind.MEMBER_REF_EXPR,
                                             CursorKind.DECL_REF_EXPR):
            return []
        objects = [c for c in head.get_children() if c.kind.is_expression()] if (
            head.kind == CursorKind.MEMBER_REF_EXPR) else []
        if objects and not _is_this(objects[0]):
            return []
        whens: list[tuple[Key, int, Key, bool] | None] = [None]
        if target is not None:
            decls = [target]
        else:
            decls = _fitting(head, _arguments(call))
            if len(decls) > 1:
                # overloads the construction chooses between: each under its test
                whens = [_dispatched(function, decl, _arguments(call)) for decl in decls]
                if None in whens:
                    return []
        found: list[Wrapper] = []
        for decl, when in zip(decls, whens * len(decls) if len(whens) == 1 else whens,
                              strict=True):
            parent, own = decl.semantic_parent, function.semantic_parent
            if parent is None or own is None or _key(parent) != _key(own):
                return []
            if when is not None:
                self._dispatched.add(_key(decl.canonical))
            found += [dataclasses.replace(w, when=when)
                      for w in self.members.get(_key(decl.canonical), [])]
        return found

    def _summarise(self, function: Cursor, key: Key, call: Cursor) -> bool:
        members = self._member_rows(function, call)
        if members:
            added = False
            args = _arguments(call)
            for wrapper in members:
                lifted = self._lift(function, wrapper, call, args, None)
                if lifted is None:
                    continue
                row = lifted.row
                for source in ("template", "template-value"):
                    # the class's type parameter: the construction's, as in the method
                    if source in wrapper.row.type_from and source not in row.type_from:
                        row = dataclasses.replace(row, type_from=(*row.type_from, source),
                                                  fixed_type=None)
                self._inner[_key(call)] = key
                for method in wrapper.through:
                    self._lifted_sites.setdefault(method, set()).add((key, _key(call)))
                added = self._keep(function, key, dataclasses.replace(
                    lifted, row=row, when=wrapper.when,
                    inside=self._through(function, call, wrapper))) or added
            return added
        target = call.referenced
        if target is not None and target.spelling not in _ROW_NAMES and (
            _key(target.canonical) not in self.summaries
        ):
            return False  # no row and no wrapper (``_inner_rows`` yields none): cheap
        if target is None and self._unnamed(call):
            return False
        added = False
        rows = list(self._inner_rows(call))
        if call.referenced is None and any(r[3] not in (key, None) for r in rows):
            # an unresolved call whose overloads are the caller and another one
            # (``create_service<SpecT>(std::bind(...), group)`` in the overload that
            # takes an instance): the other one, not a recursion
            rows = [r for r in rows if r[3] != key]
        for wrapper, args, cls, callee in rows:
            if callee == key or key in wrapper.through:
                self._recursive.add(key)
                return False
            if wrapper.row.loads is not None and not _returned_whole(function, call):
                # a class load whose instance the function does not return as it is
                # (ros_canopen's ClassAllocator<T>::allocateInstance, returning
                # ``this->createInstance(name)->allocate(t1)``): its call's type is no
                # holder of the loaded class's base, which a load is read with
                continue
            lifted = self._lift(function, wrapper, call, args, cls)
            if lifted is None:
                continue
            self._inner[_key(call)] = key
            if callee is None and wrapper.row.kind == "declare":
                shift = 1 if wrapper.row.optional_handle and args and is_handle(args[0]) else 0
                if wrapper.row.name_arg + shift < len(args):
                    self._declared[_key(call)] = args[wrapper.row.name_arg + shift]
            added = self._keep(function, key, dataclasses.replace(
                lifted, inside=self._through(function, call, wrapper))) or added
        return added

    def _through(self, function: Cursor, call: Cursor, inner: Wrapper | None = None
                 ) -> tuple[Key, ...]:
        """``Wrapper.inside`` of a summary lifted at ``call`` in ``function`` from
        ``inner`` (None: made there from the API call itself)."""
        self._insides[_key(call)] = (function, call)
        return (_key(call), *(inner.inside if inner is not None else ()))

    def _keep(self, function: Cursor, key: Key, lifted: Wrapper) -> bool:
        """Add ``lifted`` to the summary of ``function`` (``key``); whether it is new."""
        found = self.summaries.setdefault(key, [])
        spelling = function.spelling.split("<")[0]
        if self._summarised is not None:
            if spelling.isidentifier() and not spelling.startswith("operator"):
                self._summarised.add(spelling.encode())
            else:
                self._summarised = None
        if any(lifted.same(w) for w in found):
            return False
        found.append(lifted)
        return True

    def _delegated(self, function: Cursor, delegation: Cursor) -> list[Key]:
        """The wrapper constructors of ``function``'s class a delegation may call (by
        the number and kind of its arguments)."""
        parent = function.semantic_parent
        args = [c for c in delegation.get_children() if c.kind.is_expression()]
        return [_key(c.canonical) for c in (parent.get_children() if parent else ())
                if is_constructor(c) and c.kind in (CursorKind.CONSTRUCTOR,
                                                     CursorKind.FUNCTION_TEMPLATE)
                and _key(c.canonical) != _key(function.canonical)
                and _key(c.canonical) in self.summaries and _fits(c, args)]

    def _delegate(self, function: Cursor, key: Key, delegation: Cursor,
                  callees: list[Key] | None = None, typed: bool = True) -> bool:
        """``_summarise`` for the constructor ``function`` delegates to (or ``callees``,
        the base constructor it initialises with the argument list ``delegation``): its
        wrappers, in terms of ``function``'s parameters. The type of a row typed by the
        construction's template argument stays so: the class is the same, or (``typed``)
        a base named with the class's own template parameters, in order; with other
        arguments (``Derived<A, B> : Base<B>``) such a row is not lifted."""
        args = [c for c in delegation.get_children() if c.kind.is_expression()]
        added = False
        for callee in (self._delegated(function, delegation) if callees is None else callees):
            for wrapper in self.summaries.get(callee, ()):
                if key in wrapper.through:
                    self._recursive.add(key)
                    return False
                if not typed and {"template", "template-value"} & set(wrapper.row.type_from):
                    continue
                lifted = self._lift(function, wrapper, delegation, args, None)
                if lifted is None:
                    continue
                row = lifted.row
                for source in ("template", "template-value"):
                    if source in wrapper.row.type_from and source not in row.type_from:
                        row = dataclasses.replace(row, type_from=(*row.type_from, source))
                added = self._keep(function, key, dataclasses.replace(
                    lifted, row=row, when=wrapper.when, inside=wrapper.inside)) or added
        return added

    def _api_base(self, base: Cursor) -> api.RosFunction | None:
        """The API row of a base constructor a class template's constructor calls
        (``base_initialisers``): one of the API's classes (a stand-in's row only on the
        stand-in's class, a ROS 2 one in a ROS 2 unit)."""
        owner = base.semantic_parent
        if owner is None:
            return None
        spec = api.ALL.get((qualified_name(owner), base.spelling.split("<")[0]))
        if spec is None or (spec.ros2_only and not self.finder.ros2) or (
                spec.standin_only and not from_standin(base)):
            return None
        return dataclasses.replace(spec, standin_only=False)

    def _base_call(self, function: Cursor, key: Key, arguments: Cursor,
                   spec: api.RosFunction, typed: bool) -> bool:
        """``_summarise`` for the API call a class template's constructor makes by
        initialising its base (``_api_base``) with the argument list ``arguments``: a row
        typed by the class's template argument (``Subscriber<M>``) is typed by the
        construction's (``ModifiedSubscriber<Image>``) where the base is named with the
        class's first template parameter (``typed``), else not typed."""
        by_class = "class" in spec.type_from
        spec = dataclasses.replace(spec, type_from=tuple(
            source for source in spec.type_from if source != "class"))
        args = [c for c in arguments.get_children() if c.kind.is_expression()]
        lifted = self._lift(function, Wrapper(spec), arguments, args, None)
        if lifted is None:
            return False
        row = lifted.row
        if by_class and typed:
            row = dataclasses.replace(row, type_from=(*row.type_from, "template"))
        return self._keep(function, key, dataclasses.replace(
            lifted, row=row, inside=self._through(function, arguments)))

    def _unnamed(self, call: Cursor) -> bool:
        """Whether an unresolved call names no API function, factory or wrapper in its
        text, which then holds all its code (no macro expansion in it): each row
        ``_inner_rows`` can give it comes through a name written there (the method of
        a dependent member call, a name whose overloads are looked up, a factory)."""
        if self._summarised is None:
            return False
        start, end = call.extent.start, call.extent.end
        if start.file is None or end.file is None or start.file.name != end.file.name:
            return False
        name = start.file.name
        data = self.finder.source.get(name)
        offsets = self._opaque.get(name, [])
        at = bisect.bisect_left(offsets, start.offset)
        if data is None or (at < len(offsets) and offsets[at] <= end.offset):
            return False
        words = set(_WORD.findall(data[start.offset:end.offset]))
        return not (words & _UNRESOLVED_NAMES or words & self._summarised)

    def _calls_one_of(self, call: Cursor, keys: set[Key]) -> bool:
        if any(k in keys for k in _targets(call)):
            return True
        target = call.referenced  # ``_constructed`` needs a factory (or an unresolved call)
        return (target is None or target.spelling in FACTORY_NAMES) and any(
            k in keys for k in self._constructed(call, _arguments(call)))

    def _inner_rows(self, call: Cursor) -> Iterator[
            tuple[Wrapper, list[Cursor], Cursor | None, Key | None]]:
        """The rows ``call`` matches: (row, its arguments, class, the wrapper called)."""
        args = _arguments(call)
        target = call.referenced
        if target is not None:
            for callee in self._constructed(call, args) or [_key(target.canonical)]:
                for wrapper in self.summaries.get(callee, ()):
                    yield wrapper, args, None, callee
            spec, cls = self.finder._row(call)
            if spec is not None:
                # (a stand-in's row, checked by ``_row`` here: a wrapper's callers are no
                # stand-in's functions)
                yield Wrapper(dataclasses.replace(spec, standin_only=False)), args, cls, None
            return
        for callee in self._constructed(call, args):
            for wrapper in self.summaries.get(callee, ()):
                yield wrapper, args, None, callee
        children = list(call.get_children())
        head = children[0] if children else None
        if head is None:
            return
        if head.kind == CursorKind.MEMBER_REF_EXPR:
            name = _member_name(head)
            qualifier = _class_qualifier(head)
            if qualifier is not None:
                # a static method of a class template of the API on a template parameter
                # (``InterProcessPollingSubscriber<MessageT>::create_subscription(node,
                # topic, qos)`` in Autoware's polling wrapper): that class's row
                template = qualifier[0].referenced
                spec = api.ALL.get((qualified_name(template), name or called_name(call))) if (
                    template is not None) else None
                if spec is not None and (not spec.standin_only or from_standin(template)):
                    yield Wrapper(dataclasses.replace(spec, standin_only=False)), args, None, None
                    return
            spec = (DEPENDENT_ROS2 if self.finder.ros2 else DEPENDENT_ROS1).get(name)
            if spec is not None and not own_functions_only(call):
                yield Wrapper(spec), args, None, None
            # a class load on a pluginlib ClassLoader of the template's parameter (ros_canopen's
            # GuardedClassLoader<T>: ``loader_->createUniqueInstance(lookup_name)``, its
            # ``std::shared_ptr<pluginlib::ClassLoader<T>> loader_``): the load's row, as on
            # a ClassLoader of a known class
            loader = _dependent_loader(head)
            spec = api.PLUGINLIB.get((qualified_name(loader), name)) if (
                loader is not None) else None
            if spec is not None and from_standin(loader):
                yield Wrapper(dataclasses.replace(spec, standin_only=False)), args, None, None
            # a method of the unit called on a dependent object (``this`` in a generic
            # lambda: its overloads are named): the wrappers among them
            for decl in _fitting(head, args):
                callee = _key(decl.canonical)
                for wrapper in self.summaries.get(callee, ()):
                    yield wrapper, args, None, callee
            return
        for decl in _fitting(head, args):
            callee = _key(decl.canonical)
            for wrapper in self.summaries.get(callee, ()):
                yield wrapper, args, None, callee
            spec = api.ALL.get((qualified_name(decl.semantic_parent), decl.spelling))
            if spec is not None and (not spec.standin_only or from_standin(decl)):
                # (a stand-in's row checked here, on the declaration the call may be of:
                # a dependent call names none)
                yield Wrapper(dataclasses.replace(spec, standin_only=False)), args, None, None

    def _lift(self, function: Cursor, inner: Wrapper, call: Cursor, args: list[Cursor],
              cls: Cursor | None, member: bool = False) -> Wrapper | None:
        """``inner`` as made by ``function`` at ``call``, in terms of ``function``'s
        parameters; None unless its name comes from one of them (``member``: from a
        member of ``function``'s class, ``Wrapper.member``)."""
        spec = inner.row
        if spec.fixed_name is not None or spec.per_element:
            return None
        params = _parameters(function)
        shift = 1 if spec.optional_handle and args and is_handle(args[0]) else 0

        def arg(index: int | None) -> Cursor | None:
            if index is None or index + shift >= len(args):
                return None
            return args[index + shift]

        scope = self.finder.sites.scope(function) if self.finder.sites else None
        spec_param: int | None = None
        spec_arg: int | None = None
        spec_path = inner.spec_path
        member_key: Key | None = None
        if inner.member is not None:
            # a method's call named after a member, in a constructor of its class: the
            # member's value is what this constructor initialises it with
            decl = self._fields.get(inner.member)
            given = scope.field(decl) if scope is not None and decl is not None else None
            if given is None or given[1] is not scope:
                return None
            shape = _name_shape(given[0], params, scope, 1)
            if shape is None:
                return None
            before, name_arg, after = shape
        elif member:
            name_expr = arg(spec.name_arg)
            found = _member_shape(name_expr, function, scope, 0) if (
                name_expr is not None) else None
            if found is None:
                return None
            before, decl, after = found
            name_arg, member_key = spec.name_arg, _key(decl)
            self._fields[member_key] = decl
        elif inner.spec_param is not None:
            if inner.spec_arg is not None:
                # a spec deduced from the argument the inner wrapper is given: this
                # function's parameter, passed on (``init_sub(sub, std::bind(...))``)
                spec_param = inner.spec_param
                spec_arg = _parameter_index(
                    args[inner.spec_arg] if inner.spec_arg < len(args) else None, params)
                if spec_arg is None:
                    return None
            else:
                # a wrapper named by its template argument: this function's template
                # parameter, passed on as that argument (``make_publisher<SpecT>(node)``),
                # or a type this function names after one of its parameters' types
                # (``using SpecT = typename SharedPtrT::element_type::SpecType``)
                ref = _explicit_template_argument(call, inner.spec_param)
                spec_param = _template_parameter_index(ref, function)
                if spec_param is None:
                    deduced = _deduced_spec(ref, function, params)
                    if deduced is None:
                        return None
                    spec_param, spec_arg, path = deduced
                    spec_path = (*path, *spec_path)
            before, name_arg, after = inner.before, spec.name_arg, inner.after
            inner = dataclasses.replace(inner, before=(), after=())
        else:
            name_expr = arg(spec.name_arg)
            for index in spec.name_candidates:
                if index < len(args) and msg_types.param_type(args[index].type) == "str":
                    name_expr = args[index]
                    break
            if name_expr is None:
                return None
            # set_parameter(rclcpp::Parameter(param_name, value)): named by param_name
            name_expr = constructed_name(name_expr, api.RCLCPP_PARAMETER) or name_expr
            spec_param = _spec_member(name_expr, function, "name")
            if spec_param is not None:
                before, name_arg, after = (), spec.name_arg, ()
            else:
                shape = _name_shape(name_expr, params, scope, 0)
                if shape is None:
                    return None
                before, name_arg, after = shape
        fields: dict[str, object] = {
            field: _parameter_index(arg(getattr(spec, field)), params) for field in _ARGUMENTS}
        if fields["default_arg"] is None:  # ``ParameterValue{default_value}``
            fields["default_arg"] = _parameter_index(
                _converted(arg(spec.default_arg)), params)
        fields.update(self._handle(function, spec, call, args, shift, params, scope))
        fields.update(self._type(function, spec, call, args, shift, params, cls, member))
        namespace = fields.pop("namespace", None)
        if inner.namespace is not None:
            namespace = inner.namespace
        own = dict(inner.own)
        for field, value in self._own(spec, args, shift, arg, fields, params, scope).items():
            if value is not None and value is not False:
                own.setdefault(field, value)
        if spec.kind == "read" and self._handles_absence(function, call):
            own.setdefault("tested", True)
        given = arg(spec.default_arg)
        if spec.kind in ("read", "declare") and given is not None and (
            fields["default_arg"] is None and scope is not None
        ) and not any(node.kind == CursorKind.DECL_REF_EXPR and node.referenced is not None
                      and node.referenced.kind == CursorKind.PARM_DECL
                      for node in given.walk_preorder()):
            # a default the wrapper writes itself (``nh.param(n, v, false)``, a local's
            # ``declare_parameter<bool>(name + ".inverted", parameter.inverted)``):
            # each call of it has that default, its value where it is a literal (not
            # one its callers pass, which each call site gives)
            has_default, default = self.finder._default(spec, args[shift:], scope)
            if has_default:
                own.setdefault("has_default", True)
                if default is not None:
                    own.setdefault("default", default)
        elif spec.kind in ("read", "declare") and given is not None and (
            fields["default_arg"] is None and scope is not None
        ) and not given.type.get_canonical().spelling.endswith("ParameterType"):
            # a default computed from the wrapper's own parameters
            # (``declare_parameter<int>(name + ".can_id", defaults.can_id)``): every call
            # gives one, its value the call site's (not a type it is handed:
            # ``declare_parameter(name, type)`` declares without a value)
            has_default, _ = self.finder._default(spec, args[shift:], scope)
            if has_default:
                own.setdefault("has_default", True)
        row = dataclasses.replace(
            spec, name_arg=name_arg, optional_handle=False, name_candidates=(),
            out_arg=None, **fields)  # type: ignore[arg-type]
        return Wrapper(row, (*inner.before, *before), (*after, *inner.after),
                       namespace if isinstance(namespace, str) else None,
                       inner.through | {_key(function.canonical)}, tuple(own.items()),
                       spec_param, spec_arg, spec_path, member_key)

    def _handles_absence(self, function: Cursor, call: Cursor) -> bool:
        """Whether ``function`` tests whether the parameter that ``call`` reads is there
        (``call`` returns that, and is a condition in ``function``: ``tested``) and keeps
        the answer to itself: it returns no ``bool`` that would hand it to its callers,
        whose own tests then decide (ublox's ``getRosUint(node, key, u, default_val)``
        sets ``u = default_val`` when ``getRosUint(node, key, u)`` says the parameter is
        not there: each call of it has a default; the three-argument one returns that
        answer, and a call site that tests it is ``tested`` there)."""
        if call.type.get_canonical().kind not in _MAY_BE_BOOL or (
                function.result_type.get_canonical().kind == TypeKind.BOOL):
            return False  # (a call a template leaves to its instantiation: its type)
        found = tested_key(call)
        if found is None:
            return False
        calls = TestedCalls(self.finder.reader)
        for node in function.walk_preorder():
            calls.visit(node)
        return found in calls.keys

    def _own(self, spec: api.RosFunction, args: list[Cursor], shift: int,
             arg: Callable[[int | None], Cursor | None], fields: dict[str, object],
             params: list[Cursor], scope: Scope | None) -> dict[str, object]:
        """The QoS (ROS 2) or queue (ROS 1), latch and callback the wrapper writes itself
        (or the default value of the parameter that gives it)."""
        if scope is None:
            return {}
        found: dict[str, object] = {}
        if fields.get("callback_arg") is None and spec.callback_arg is not None:
            found["callback"] = callback_name(callback(args, spec.callback_arg + shift))
        if spec.latch_arg is not None and fields.get("latch_arg") is None:
            latch = arg(spec.latch_arg)
            found["latch"] = latch is not None and scope.boolean(latch) is True
        field = "qos_arg" if self.finder.ros2 else "queue_arg"
        index = fields.get(field)
        expr: Cursor | None = None
        if isinstance(index, int):
            expr = next((c for c in params[index].get_children() if c.kind.is_expression()),
                        None)
        elif getattr(spec, field) is not None:
            expr = arg(getattr(spec, field))
        if expr is None:
            return found
        if self.finder.ros2:
            qos = qos_of(expr, scope)
            found.update(qos=qos, queue_size=qos.get("depth") if qos else None)
        else:
            found["queue_size"] = scope.integer(expr)
        return found

    def _handle(self, function: Cursor, spec: api.RosFunction, call: Cursor,
                args: list[Cursor], shift: int, params: list[Cursor],
                scope: Scope | None) -> dict[str, object]:
        """Where the derived row's handle is: the call site's object (``on_handle``), one
        of its arguments (``handle_arg``), or a namespace fixed in the wrapper."""
        none: dict[str, object] = {"on_handle": False, "handle_arg": None}
        if spec.on_handle:
            callee = strip(next(iter(call.get_children()), call))
            objects = [c for c in callee.get_children() if c.kind.is_expression()] if (
                callee.kind == CursorKind.MEMBER_REF_EXPR) else []
            handle = objects[0] if objects else None
        elif spec.handle_arg is not None:
            index = 0 if shift else spec.handle_arg
            handle = args[index] if index < len(args) else None
            if handle is None:
                return none
        else:
            return none
        if handle is None or _is_this(handle):
            if function.semantic_parent is not None and function.semantic_parent.kind in (
                CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL, CursorKind.CLASS_TEMPLATE
            ):
                return {"on_handle": True, "handle_arg": None}
            return none
        passed = _parameter_index(handle, params)
        if passed is not None:
            return {"on_handle": False, "handle_arg": passed}
        if scope is not None and is_handle(handle):
            parts = self.finder.namespaces.of(handle, scope)
            if None not in parts:
                return {**none, "namespace": "".join(p for p in parts if p is not None)}
            if not self.finder.ros2:
                # a ROS 1 handle whose namespace is not known here (a pointer member a
                # setter of another file sets: open_vins' YamlParser::nh, given by
                # ``set_node_handler`` in main): its names are in that unknown
                # namespace, not the node's own
                return {**none, "namespace": render(parts)}
        return none

    def _type(self, function: Cursor, spec: api.RosFunction, call: Cursor,
              args: list[Cursor], shift: int, params: list[Cursor],
              cls: Cursor | None, member: bool = False) -> dict[str, object]:
        """The derived row's type sources: the call site's template argument for the
        wrapper's first template parameter, its value or callback arguments, or the type
        fixed in the wrapper."""
        templates = [c for c in function.get_children()
                     if c.kind == CursorKind.TEMPLATE_TYPE_PARAMETER]
        if of_class_template(function) and (is_constructor(function) or member):
            # a constructor of a class template: the class's first parameter is what a
            # construction's template argument gives (make_shared<Server<T>>); so in a
            # method lifted into one (``Wrapper.member``)
            templates = _class_parameters(function)
        sources: list[str] = []
        type_arg: int | None = None

        def passed(index: int | None) -> int | None:
            """The wrapper parameter the inner call's argument ``index`` is, if any."""
            if index is None or index + shift >= len(args):
                return None
            found = _parameter_index(args[index + shift], params)
            if found is None and index == spec.default_arg == spec.type_arg:
                found = _parameter_index(_converted(args[index + shift]), params)
            return found

        for source in spec.type_from:
            if source in ("template", "template-value"):
                ref = template_argument(call)
                decl = ref.referenced if ref is not None else None
                if decl is not None and decl.kind == CursorKind.TEMPLATE_TYPE_PARAMETER:
                    if templates and _key(decl) == _key(templates[0]):
                        sources.append(source)
                        deduced = _deducing(params, templates[0]) if (
                            source == "template" and type_arg is None) else None
                        if deduced is not None:
                            # a call site that writes no template argument: the type
                            # deduced from its argument (autoware_utils'
                            # ``DebugPublisher::publish(name, const T & data)``)
                            sources.append("arg")
                            type_arg = deduced
                    continue
            elif source in ("value", "arg") and spec.type_arg is not None:
                index = passed(spec.type_arg)
                if index is not None:
                    sources.append(source)
                    if source == "value":
                        sources.append("template-value")
                    type_arg = index
                    continue
                if source == "arg" and templates and spec.type_arg + shift < len(args) and (
                        _made_as(args[spec.type_arg + shift], templates[0])):
                    # the argument is a value of the wrapper's first template parameter:
                    # the call site's template argument (autoware_utils'
                    # ``publish<T_msg>(name, to_debug_msg<T_msg>(data, stamp))``)
                    sources.append("template")
                    continue
            elif source in ("callback", "service-callback") and (
                    passed(spec.callback_arg) is not None):
                sources.append(source)
                continue
            elif source == "class" and templates and (
                    (qualifier := _class_qualifier(callee_head(call))) is not None) and (
                    qualifier[1] is not None and _key(qualifier[1]) == _key(templates[0])):
                sources.append("template")  # ``Class<T>::f(...)``: T, the wrapper's own
                continue
            if sources:
                continue
            fixed = self._fixed_type(spec, source, call, args, shift, cls)
            if fixed is not None:
                return {"type_from": tuple(sources), "type_arg": type_arg,
                        "fixed_type": fixed}
        return {"type_from": tuple(dict.fromkeys(sources)), "type_arg": type_arg,
                "fixed_type": spec.fixed_type}

    def _fixed_type(self, spec: api.RosFunction, source: str, call: Cursor,
                    args: list[Cursor], shift: int, cls: Cursor | None) -> str | None:
        """The type one source gives inside the wrapper, when it does not depend on a
        template parameter."""
        function = callback(args, None if spec.callback_arg is None
                            else spec.callback_arg + shift)
        one = dataclasses.replace(spec, type_from=(source,), fixed_type=None)
        empty = Scope(None, self.finder.macros, self.finder.source, self.finder.sites)
        found = self.finder.types.of_call(one, call, args, function, cls, empty)
        return None if found is None or _dependent_name(found) else found

    # -- at a call site -----------------------------------------------------------------

    def emit(self, call: Cursor, conditions: tuple[Condition, ...], scope: Scope) -> bool:
        """Emit the ROS calls a call of a wrapper makes; True when ``call`` is done with
        (a wrapper's call, or a call inside a wrapper that its callers make instead)."""
        owner = self._inner.get(_key(call))
        if owner is not None and owner not in self._kept:
            return True
        target = call.referenced
        if target is not None and _key(target.canonical) in self._shared:
            return True
        wrappers = self._called(call)
        if not wrappers:
            return False
        finder = self.finder
        args = _arguments(call)
        bound = _made_with(call, scope)
        done: set[tuple[object, ...]] = set()
        for wrapper in wrappers:
            row = wrapper.row
            if wrapper.when is not None and _chosen(call, wrapper.when) is False:
                continue  # the other overload's
            if wrapper.spec_param is not None:
                # a spec the call site does not name, or whose name is no literal:
                # the call is kept, its name unknown
                row = self._of_spec(row, call, wrapper) or dataclasses.replace(
                    row, fixed_name="?")
            elif row.name_arg >= len(args):
                # the name is a parameter the call leaves to its default (hector's
                # ``limiter.init(nh)``; MoveIt's ``startPublishingPlanningScene(event)``,
                # its topic defaulting to MONITORED_PLANNING_SCENE_TOPIC)
                args = _with_defaults(call, args)
                if row.name_arg >= len(args):
                    continue
            before, after = _bind(wrapper.before, bound), _bind(wrapper.after, bound)
            inside = self._inside_at(wrapper, call, args, scope)
            if inside is None:
                continue  # a condition in the wrapper this call site makes false
            if (row, before, after, inside) in done:
                continue  # two summaries that differ only in the value now bound
            done.add((row, before, after, inside))
            named = _NamedScope(scope, args[row.name_arg], before, after) if (
                before or after) else scope
            start = len(finder.calls)
            finder._emit(row, call, args, None, (*conditions, *inside), named)
            # the QoS (queue) is the call site's argument when it passes one: a value not
            # known there stays unknown, not the parameter's default (autoware_utils'
            # ``InterProcessPollingSubscriber{this, topic, single_depth_sensor_qos()}``,
            # its parameter defaulting to ``rclcpp::QoS{1}``)
            given = row.qos_arg if finder.ros2 else row.queue_arg
            passed = given is not None and given < len(args)
            for made in finder.calls[start:]:
                if wrapper.namespace:
                    if not finder.ros2 and not made.name.startswith(("/", "~")):
                        made.handle_namespace = wrapper.namespace  # remapped first (ROS 1)
                    made.name = join_name(wrapper.namespace, made.name)
                for field, value in wrapper.own:
                    if getattr(made, field) in (None, False) and (
                        field not in ("qos", "queue_size") or (
                            made.queue_size is None and not passed)
                    ):
                        setattr(made, field, value)
        return True

    def _inside_at(self, wrapper: Wrapper, call: Cursor, args: list[Cursor], scope: Scope
                   ) -> tuple[Condition, ...] | None:
        """The conditions ``wrapper``'s call is under inside the wrappers, at the call
        site ``call``: those of the wrapper it calls over that wrapper's own parameters
        are decided with the literals the site passes (or the parameter's default),
        as the graph decides a condition (navigation's ``move_parameter(old, new, name,
        should_delete = true)`` deletes ``if (should_delete)``: not where a call passes
        ``false``); None when one is false there."""
        found: list[Condition] = []
        for level, key in enumerate(wrapper.inside):
            conditions = self._inside_conditions.get(key, ())
            if level == 0 and conditions:
                values = self._passed(self._insides[key][0], call, args, scope)
                if values:
                    from ...graph.conditions import decide  # (graph imports extraction)
                    kept = []
                    for condition in conditions:
                        answer = decide(condition, functools.partial(_passed_value, values))
                        if answer is False:
                            return None
                        if answer is None:
                            kept.append(condition)
                    conditions = tuple(kept)
            found.extend(conditions)
        return tuple(found)

    def _passed(self, function: Cursor, call: Cursor, args: list[Cursor], scope: Scope
                ) -> dict[str, object]:
        """The literal values (``bool``, numbers) the call site passes to the
        parameters of ``function`` that its body never assigns, by name."""
        params = _parameters(function)
        sites = self.finder.sites
        if not params or sites is None:
            return {}
        given = _with_defaults(call, args) if len(args) < len(params) else args
        body = sites.scope(function)
        values: dict[str, object] = {}
        for param, arg in zip(params, given, strict=False):
            name = param.spelling
            if not name or body.written(param):
                continue
            value: object = scope.boolean(arg)
            if value is None:
                value = scope.integer(arg)
            if value is not None:
                values[name] = value
        return values

    def parameter_calls(self, call: Cursor, scope: Scope
                        ) -> list[tuple[api.RosFunction, Scope]]:
        """For a call of a wrapper that reads or declares a parameter (nav2's
        ``declare_or_get_parameter``), each row it makes and the call site's scope in which
        its name argument reads as the wrapper names it (what ``emit`` gives the calls);
        empty for any other call."""
        args = _arguments(call)
        if _key(call) in self._inner or len(args) != len(written_arguments(call)):
            return []  # (a lambda's call: ``_parameter`` reads the written arguments)
        found: list[tuple[api.RosFunction, Scope]] = []
        bound = _made_with(call, scope)
        for wrapper in self._called(call):
            row = wrapper.row
            if row.kind not in ("read", "declare") or wrapper.namespace or (
                row.name_arg >= len(args) or row.fixed_name is not None
                or wrapper.spec_param is not None
            ):
                return []
            before, after = _bind(wrapper.before, bound), _bind(wrapper.after, bound)
            found.append((row, _NamedScope(scope, args[row.name_arg], before, after)
                          if before or after else scope))
        return found

    def _of_spec(self, row: api.RosFunction, call: Cursor,
                 wrapper: Wrapper) -> api.RosFunction | None:
        """``row`` with the name and type of the interface spec ``call`` passes as its
        template argument ``wrapper.spec_param`` (``Spec::name``, ``Spec::Message``), or
        that the type of its argument ``wrapper.spec_arg`` leads to, as a fixed name
        (once per node, as the spec's topic is); None when the call site does not name
        a spec whose name is a literal."""
        decl: Cursor | None = None
        if wrapper.spec_arg is not None:
            args = _arguments(call)
            given = args[wrapper.spec_arg].type if wrapper.spec_arg < len(args) else None
            spec = nested_type(given, wrapper.spec_path) if given is not None else None
            decl = spec.get_declaration() if spec is not None else None
        else:
            ref = _explicit_template_argument(call, wrapper.spec_param or 0)
            decl = ref.referenced if ref is not None else None
            if decl is not None and wrapper.spec_path:
                spec = nested_type(decl.type, wrapper.spec_path)
                decl = spec.get_declaration() if spec is not None else None
        if decl is None or decl.kind not in (CursorKind.STRUCT_DECL,
                                             CursorKind.CLASS_DECL):
            return None
        decl = decl.get_definition() or decl
        members = {c.spelling: c for c in decl.get_children()}
        name = members.get("name")
        value = initializer(name) if name is not None and name.kind == CursorKind.VAR_DECL \
            else None
        literal = _literal(value) if value is not None else None
        if literal is None:
            return None
        service = row.kind in ("server", "client")
        alias = members.get("Service" if service else "Message")
        found: str | None = None
        if alias is not None and alias.kind in (CursorKind.TYPE_ALIAS_DECL,
                                                CursorKind.TYPEDEF_DECL):
            found = msg_types.message_type(alias.underlying_typedef_type, service, {},
                                           self.finder.ros2)
        return dataclasses.replace(row, fixed_name=literal, fixed_type=found, type_from=())

    def calls_wrapper(self, call: Cursor) -> bool:
        """Whether ``emit`` may make calls for ``call``: it calls a wrapper."""
        return bool(self._called(call))

    def _called(self, call: Cursor) -> list[Wrapper]:
        """The wrappers ``call`` calls (through the overloads a dependent call names)."""
        return [w for key in self._called_keys(call) for w in self.summaries.get(key, ())]

    def _called_keys(self, call: Cursor) -> list[Key]:
        """The keys of the wrapper functions ``call`` calls (``_called``)."""
        target = call.referenced
        held = held_lambda(target) if target is not None else None
        if held is not None:
            return [_key(held.canonical)]
        if target is not None:
            return self._constructed(call, _arguments(call)) or specialised_keys(target)
        # a construction through a factory that depends on a template parameter
        # (``std::make_shared<ActionServer>(node, name_, ...)`` in nav2's
        # TimedBehavior<ActionT>, ``using ActionServer = SimpleActionServer<ActionT>``)
        made = self._constructed(call, _arguments(call))
        if made:
            return made
        children = list(call.get_children())
        args = written_arguments(call)
        for decl in _fitting(children[0], args) if children else []:
            if self.summaries.get(_key(decl.canonical)):
                return [_key(decl.canonical)]
        if children and children[0].kind == CursorKind.MEMBER_REF_EXPR:
            # a method called on an object whose type depends on a template parameter
            # (``this->node_.lock()`` in nav2's DriveOnHeading<ActionT>): the wrapper
            # methods of that name, as the node's own API rows are matched by name
            for method in _preferred(self._methods.get(_member_name(children[0]), []), args):
                return [_key(method.canonical)]
        return []

    def called(self, call: Cursor) -> list[tuple[Key, Cursor]]:
        """The wrapper functions ``call`` calls, with their keys: empty for a call of no
        wrapper, or of one whose definition this unit does not hold."""
        found = [(key, self._functions.get(key)) for key in self._called_keys(call)
                 if self.summaries.get(key)]
        return [(key, f) for key, f in found if f is not None] if all(
            f is not None for _, f in found) else []

    def inner_of(self, call: Cursor) -> Key | None:
        """The wrapper whose callers make ``call`` (a read or declaration inside it whose
        name comes from its parameters), if any."""
        return self._inner.get(_key(call))


class _NamedScope(Scope):
    """A call site's scope in which the wrapper's name argument reads as the name the
    wrapper makes of it (``before`` + argument + ``after``)."""

    def __init__(self, scope: Scope, arg: Cursor, before: Parts, after: Parts) -> None:
        self.__dict__.update(scope.__dict__)
        self._arg, self._before, self._after = arg, before, after

    def string(self, cursor: Cursor, depth: int = 0) -> Parts:
        parts = super().string(cursor, depth)
        return (*self._before, *parts, *self._after) if cursor == self._arg else parts


def _choice_shape(children: list[Cursor], params: list[Cursor], scope: Scope | None,
                  depth: int) -> tuple[Parts, int, Parts] | None:
    """``test ? a : b`` whose test is whether the wrapper's parameter is empty
    (hector_quadrotor's ``!field.empty() ? field + "/" : ""``): a choice (``values.
    CHOICE``) tested on the argument each call site binds, each side the text around
    it (``BACKREF`` where it is) or a constant; None for any other test of a parameter
    (a longest side would be a name no call makes)."""
    found = emptiness_test(children[0])
    index = _parameter_index(strip(found[0]), params) if found is not None else None
    if found is None or index is None:
        return None
    sides: list[str] = []
    for branch in children[1:]:
        shape = _name_shape(branch, params, scope, depth + 1)
        if shape is not None and shape[1] == index:
            sides.append(_text(shape[0]) + BACKREF + _text(shape[2]))
            continue
        value = scope.string(branch) if scope is not None else UNKNOWN
        if None in value or any(PLACEHOLDER in (part or "") or CHOICE in (part or "")
                                for part in value):
            return None
        sides.append(_text(value))
    if_empty, if_not = sides if found[1] else sides[::-1]
    return (CHOICE,), index, (f"{CHOICE_SEP}{if_empty}{CHOICE_SEP}{if_not}{CHOICE_END}",)


def _text(parts: Parts) -> str:
    return "".join("?" if part is None else part for part in parts)


def _name_shape(expr: Cursor, params: list[Cursor], scope: Scope | None,
                depth: int) -> tuple[Parts, int, Parts] | None:
    """``expr`` as (parts before, index of the wrapper's parameter, parts after), when it
    is a parameter with known text around it."""
    expr = strip(expr)
    if depth > 8:
        return None
    index = _parameter_index(expr, params)
    if index is not None:
        return (), index, ()
    kind = expr.kind
    if kind in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR):
        decl = expr.referenced
        value = scope.variable(decl) if scope is not None and decl is not None else None
        if value is None and scope is not None and decl is not None and (
                _of_local(expr, scope)):
            # a field of a local this function fills before the call (nav2_util's
            # ``descriptor.name = name; declare_parameter(descriptor.name, ...)``); not
            # a member of the object, which outlives the call (a plugin's ``name_ =
            # name`` in ``configure``, whose other methods read it too)
            value = scope.assigned(decl, expr)
        if value is None and scope is not None and decl is not None:
            # a member that this very constructor initialises (``: name_(name)``, a
            # class template's constructor that keeps its name argument): what it gives
            initialised = scope.field(decl)
            if initialised is not None and initialised[1] is scope:
                value = initialised[0]
        return _name_shape(value, params, scope, depth + 1) if value is not None else None
    if kind == CursorKind.CONDITIONAL_OPERATOR:
        # ``ns.empty() ? name : ns + "." + name``: the branch that keeps the most text;
        # not a test of the parameter that names it (``!field.empty() ? field + "/" :
        # ""``): each call site's value picks the branch, as a call read through its
        # call sites does (``Scope.string``), not the longest text
        children = [c for c in expr.get_children() if c.kind.is_expression()]
        if len(children) == 3 and any(_parameter_index(node, params) is not None
                                      for node in children[0].walk_preorder()):
            return _choice_shape(children, params, scope, depth)
        branches = children[1:]
        shapes = [found for b in branches
                  if (found := _name_shape(b, params, scope, depth + 1)) is not None]
        return max(shapes, key=lambda f: len(f[0]) + len(f[2])) if shapes else None
    operands, inner = _string_parts(expr, scope, every_member=True)
    if inner is not None:
        return _name_shape(inner, params, scope, depth + 1)
    if len(operands) != 2 or scope is None:
        return None
    if all(_names_parameter(operand, params) for operand in operands):
        # ``prefix + param`` of two of the wrapper's parameters: the shape holds one, and
        # the other's value here would be the one every call site agrees on, else a
        # placeholder filled from every site, not this one's (convex_plane_decomposition's
        # ``loadParameter(nh, prefix, "epsilon", v)`` read each prefix with each name):
        # none, so the call is read where it is made, its placeholders per site
        return None
    return _around(operands, scope, lambda part: _name_shape(part, params, scope, depth + 1))


def _names_parameter(expr: Cursor, params: list[Cursor]) -> bool:
    """Whether ``expr`` names one of the wrapper's parameters ``params`` anywhere."""
    return any(_parameter_index(node, params) is not None for node in expr.walk_preorder())


def _of_local(expr: Cursor, scope: Scope) -> bool:
    """Whether ``expr`` is a field of a local variable of the function ``scope`` reads
    (``descriptor.name``, ``descriptor`` declared in its body)."""
    if expr.kind != CursorKind.MEMBER_REF_EXPR or scope.body is None:
        return False
    inner = [c for c in expr.get_children() if c.kind.is_expression()]
    base = strip(inner[0]) if inner else None
    decl = base.referenced if base is not None and base.kind == CursorKind.DECL_REF_EXPR \
        else None
    return decl is not None and decl.kind == CursorKind.VAR_DECL and scope.holds(
        decl.extent.start)


def _member_shape(expr: Cursor, function: Cursor, scope: Scope | None,
                  depth: int) -> tuple[Parts, Cursor, Parts] | None:
    """``expr`` as (parts before, a member of ``function``'s own object, parts after),
    when it is such a member (``_rosTopic``, ``this->topic_``) with known text around it
    (``_cameraName + "/camera_info"``)."""
    expr = strip(expr)
    if depth > 8:
        return None
    kind = expr.kind
    if kind == CursorKind.MEMBER_REF_EXPR:
        decl = expr.referenced
        objects = [c for c in expr.get_children() if c.kind.is_expression()]
        parent, own = (decl.semantic_parent if decl is not None else None,
                       function.semantic_parent)
        if decl is None or decl.kind != CursorKind.FIELD_DECL or parent is None or (
            own is None or _key(parent) != _key(own)
        ) or (objects and not _is_this(objects[0])):
            return None
        return (), decl, ()
    operands, inner = _string_parts(expr, scope, every_member=False)
    if inner is not None:
        return _member_shape(inner, function, scope, depth + 1)
    if len(operands) != 2 or scope is None:
        return None
    return _around(operands, scope,
                   lambda part: _member_shape(part, function, scope, depth + 1))


def _string_parts(expr: Cursor, scope: Scope | None,
                  every_member: bool) -> tuple[list[Cursor], Cursor | None]:
    """How the string ``expr`` is made: the two operands of a ``+`` (an ``operator+``
    call, or with a scope to read it a ``+`` a template leaves to its instantiation), or
    the one expression a conversion, a constructor or ``c_str()`` / ``str()`` wraps (of
    ``name.c_str()`` the object ``name``; of another member access written there too,
    its object, when ``every_member``); neither: ``([], None)``."""
    kind = expr.kind
    if kind == CursorKind.CALL_EXPR and expr.spelling == "operator+":
        return written_arguments(expr), None
    if kind == CursorKind.BINARY_OPERATOR and scope is not None:
        children = list(expr.get_children())
        if len(children) == 2 and between(children[0], children[1], scope.source) == "+":
            return children, None
    elif kind == CursorKind.CALL_EXPR:
        inner = [c for c in expr.get_children() if c.kind.is_expression()]
        target = expr.referenced
        if len(inner) == 1 and (target is None or target.kind == CursorKind.CONSTRUCTOR
                                or expr.spelling in ("c_str", "str")):
            found = inner[0]
            if found.kind == CursorKind.MEMBER_REF_EXPR and (
                every_member or expr.spelling in ("c_str", "str")
            ):
                objects = [c for c in found.get_children() if c.kind.is_expression()]
                found = objects[0] if objects else found
            return [], found
    return [], None


def _around(operands: list[Cursor], scope: Scope,
            shape: Callable[[Cursor], tuple[Parts, Shape, Parts] | None]
            ) -> tuple[Parts, Shape, Parts] | None:
    """The shape of ``left + right`` from its operand that has one (the left first),
    with the other's text before or after it."""
    left = shape(operands[0])
    if left is not None:
        return left[0], left[1], (*left[2], *scope.string(operands[1]))
    right = shape(operands[1])
    if right is not None:
        return (*scope.string(operands[0]), *right[0]), right[1], right[2]
    return None


def _template_parameters(function: Cursor) -> list[Cursor]:
    return [c for c in function.get_children()
            if c.kind == CursorKind.TEMPLATE_TYPE_PARAMETER]


def _template_parameter_index(ref: Cursor | None, function: Cursor) -> int | None:
    """The index of ``function``'s template type parameter ``ref`` names, if any; of a
    class template's constructor, its class's (what a construction's template
    arguments give)."""
    decl = ref.referenced if ref is not None else None
    if decl is None or decl.kind != CursorKind.TEMPLATE_TYPE_PARAMETER:
        return None
    where = _key(decl)
    params = _class_parameters(function) if (
        of_class_template(function) and is_constructor(function)
    ) else _template_parameters(function)
    return next((i for i, p in enumerate(params) if _key(p) == where), None)


def _deducing(params: list[Cursor], template: Cursor) -> int | None:
    """The index of the function parameter of type ``template`` (``T``, ``const T &``,
    ``T &&``): a call's argument there deduces it."""
    for index, param in enumerate(params):
        ptype = param.type
        if ptype.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
            ptype = ptype.get_pointee()
        # (clang exposes no declaration for it: the spelling, as ``_deduced_spec``)
        if ptype.spelling.replace("const ", "").strip() == template.spelling:
            return index
    return None


def _made_as(expr: Cursor, template: Cursor) -> bool:
    """Whether ``expr`` is a value of the template type parameter ``template``: a call
    of a function template that returns its own first template parameter, written with
    ``template`` as that argument (``to_debug_msg<T_msg>(data, stamp)``), whose type
    clang leaves dependent."""
    expr = strip(expr)
    if expr.kind != CursorKind.CALL_EXPR:
        return False
    ref = template_argument(expr)
    given = ref.referenced if ref is not None else None
    if given is None or given.kind != CursorKind.TEMPLATE_TYPE_PARAMETER or (
            _key(given) != _key(template)):
        return False
    head = next(iter(expr.get_children()), None)
    while head is not None and head.kind == CursorKind.UNEXPOSED_EXPR:
        head = next(iter(head.get_children()), None)
    if head is None:
        return False
    # a name looked up at instantiation (clang's unresolved lookup): the templates it
    # may be are its first child's
    names = next((c for c in head.get_children()
                  if c.kind == CursorKind.OVERLOADED_DECL_REF), head)
    called = overloads(names) if names.kind == CursorKind.OVERLOADED_DECL_REF else [
        names.referenced]
    for function in called:
        if function is None or function.kind != CursorKind.FUNCTION_TEMPLATE:
            return False
        own = _template_parameters(function)
        if not own or function.result_type.spelling != own[0].spelling:
            return False
    return bool(called)


def _class_parameters(constructor: Cursor) -> list[Cursor]:
    """The template type parameters of a class template's constructor's class, as its
    body names them: defined out of the class, its own template header declares them
    again, first (depthai_bridge's ``template <class RosMsg, class SimMsg>
    BridgePublisher<RosMsg, SimMsg>::BridgePublisher(..)``, whose body's ``RosMsg`` is
    the header's); defined in the class, the class's."""
    cls = constructor.semantic_parent
    own = _template_parameters(cls) if cls is not None else []
    lexical = constructor.lexical_parent
    if lexical is not None and cls is not None and _key(lexical) != _key(cls):
        header = _template_parameters(constructor)
        if len(header) >= len(own):
            return header[:len(own)]
    return own


_DEPENDENT_MEMBERS = re.compile(r"(?:typename\s+)?(\w+)((?:::\w+)+)")
# the smart pointers whose ``element_type`` is their first template argument
_POINTER_CLASSES = frozenset({"std::shared_ptr", "std::unique_ptr", "std::weak_ptr"})


def _deduced_spec(ref: Cursor | None, function: Cursor, params: list[Cursor]
                  ) -> tuple[int, int, tuple[str, ...]] | None:
    """For a template argument that names a type alias of ``function`` written as member
    types of one of its template parameters (``using SpecT = typename
    SharedPtrT::element_type::SpecType``), deduced from a parameter of that type
    (``SharedPtrT & pub``): the template parameter's index, the parameter's, and the
    member names."""
    alias = ref.referenced if ref is not None else None
    if alias is None or alias.kind not in (CursorKind.TYPE_ALIAS_DECL,
                                           CursorKind.TYPEDEF_DECL):
        return None
    written = _DEPENDENT_MEMBERS.fullmatch(alias.underlying_typedef_type.spelling.strip())
    if written is None:
        return None
    templates = _template_parameters(function)
    index = next((i for i, t in enumerate(templates) if t.spelling == written.group(1)),
                 None)
    if index is None:
        return None
    for position, param in enumerate(params):
        ptype = param.type
        if ptype.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
            ptype = ptype.get_pointee()
        if ptype.spelling.replace("const ", "").strip() == written.group(1):
            return index, position, tuple(written.group(2).split("::")[1:])
    return None


def nested_type(given: Type, path: tuple[str, ...]) -> Type | None:
    """The type ``given::a::b`` for ``path`` ``(a, b)``, each a member type alias of a
    class template that stands for one of its template parameters (``using SpecType =
    SpecT``: that template argument of the specialisation), or a smart pointer's
    ``element_type``."""
    found = given
    for member in path:
        found = found.get_canonical()
        if found.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
            found = found.get_pointee().get_canonical()
        decl = found.get_declaration()
        if decl is None or decl.kind == CursorKind.NO_DECL_FOUND:
            return None
        if member == "element_type" and qualified_name(decl) in _POINTER_CLASSES:
            argument = found.get_template_argument_type(0)
            if argument.kind == TypeKind.INVALID:
                return None
            found = argument
            continue
        template = conf.lib.clang_getSpecializedCursorTemplate(decl)
        if template is None or template.kind != CursorKind.CLASS_TEMPLATE:
            return None
        alias = next((c for c in template.get_children() if c.spelling == member and c.kind in (
            CursorKind.TYPE_ALIAS_DECL, CursorKind.TYPEDEF_DECL)), None)
        if alias is None:
            return None
        named = alias.underlying_typedef_type.spelling
        index = next((i for i, t in enumerate(_template_parameters(template))
                      if t.spelling == named), None)
        if index is None:
            return None
        argument = found.get_template_argument_type(index)
        if argument.kind == TypeKind.INVALID:
            return None
        found = argument
    return found


def _spec_member(expr: Cursor, function: Cursor, member: str) -> int | None:
    """The index of ``function``'s template type parameter ``T`` when ``expr`` is
    ``T::member`` (an interface spec's static member)."""
    expr = strip(expr)
    # (in a member function clang may keep ``T::name`` as a member reference)
    if expr.kind not in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR):
        return None
    tokens = [t.spelling for t in expr.get_tokens()]
    if len(tokens) != 3 or tokens[1:] != ["::", member]:
        return None
    refs = [c for c in expr.get_children() if c.kind == CursorKind.TYPE_REF]
    return _template_parameter_index(refs[0], function) if len(refs) == 1 else None


def _explicit_template_argument(call: Cursor, index: int) -> Cursor | None:
    """The type reference written as the ``index``-th template argument of ``call``'s
    callee (``make_publisher<SpecT>(node)``, ``adaptor.create_publisher<ns::Spec>()``)."""
    head = next(iter(call.get_children()), None)
    if head is None:
        return None
    opening = next((t.extent.start.offset for t in head.get_tokens() if t.spelling == "<"),
                   None)
    if opening is None:
        return None
    refs = [c for c in head.walk_preorder() if c.kind == CursorKind.TYPE_REF
            and c.extent.start.offset > opening]
    return refs[index] if index < len(refs) else None


def _static_factory(decl: Cursor) -> bool:
    """``C<T>::make_shared(args)``: a class template's static factory (rclcpp's
    ``RCLCPP_SMART_PTR_DEFINITIONS``), a construction of ``C<T>``."""
    return decl.spelling in ("make_shared", "make_unique") and decl.is_static_method() \
        and decl.semantic_parent is not None and decl.semantic_parent.kind in (
            CursorKind.CLASS_TEMPLATE, CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL)


def _static_factory_call(head: Cursor) -> bool:
    """``C<T>::make_shared`` written in a template, where ``T`` is its parameter (the
    call is not resolved)."""
    if not any(c.kind == CursorKind.TEMPLATE_REF and c.referenced is not None
               and c.referenced.kind == CursorKind.CLASS_TEMPLATE for c in head.get_children()):
        return False  # asked first: the tokens are read through libclang
    tokens = [t.spelling for t in head.get_tokens()]
    return len(tokens) > 2 and tokens[-1] in ("make_shared", "make_unique") and (
        tokens[-2] == "::")


def _literal(expr: Cursor) -> str | None:
    """The text of a string literal (``"/api/x"``, as a ``char[]`` or ``auto``)."""
    expr = strip(expr)
    for node in expr.walk_preorder():
        if node.kind == CursorKind.STRING_LITERAL:
            text = node.spelling
            return text[1:-1] if text.startswith('"') and text.endswith('"') else None
    return None


def _parameters(function: Cursor) -> list[Cursor]:
    return [c for c in function.get_children() if c.kind == CursorKind.PARM_DECL]


def _unmoved(expr: Cursor) -> Cursor:
    """``expr`` without ``std::move(x)`` / ``std::forward<T>(x)`` around it, which hand on
    ``x`` itself (MPPI's ``getParamGetter`` lambda passes ``std::move(default_value)``
    to ``getParam``: the default its callers give); a call of them in a template, which
    clang leaves unresolved, too."""
    for _ in range(3):
        stripped = strip(expr)
        if stripped.kind != CursorKind.CALL_EXPR:
            return expr
        inner = [c for c in stripped.get_children() if c.kind.is_expression()]
        callee = stripped.spelling or next(
            (c.spelling for c in inner[0].walk_preorder()
             if c.kind == CursorKind.OVERLOADED_DECL_REF), "") if inner else ""
        target = stripped.referenced
        if callee not in ("move", "forward") or len(inner) < 2 or (
                target is not None and qualified_name(target.semantic_parent) != "std"):
            return expr
        expr = inner[-1]
    return expr


def _parameter_index(expr: Cursor | None, params: list[Cursor]) -> int | None:
    """The index of the wrapper's parameter ``expr`` is (as it is, or dereferenced,
    also through a smart pointer: ``node->``, ``*node``, ``node.get()``; moved or
    forwarded, ``std::move(node)``)."""
    if expr is None:
        return None
    expr = pointee(_unmoved(expr))
    if expr.kind == CursorKind.UNARY_OPERATOR:  # *node
        inner = [c for c in expr.get_children() if c.kind.is_expression()]
        expr = pointee(inner[0]) if len(inner) == 1 else expr
    if expr.kind != CursorKind.DECL_REF_EXPR or expr.referenced is None or (
        expr.referenced.kind != CursorKind.PARM_DECL
    ):
        return None
    where = _key(expr.referenced)
    for index, param in enumerate(params):
        if _key(param) == where:
            return index
    return None


_CONVERSIONS = frozenset({CursorKind.CALL_EXPR, CursorKind.INIT_LIST_EXPR,
                          CursorKind.CXX_FUNCTIONAL_CAST_EXPR, CursorKind.UNEXPOSED_EXPR})


def _converted(expr: Cursor | None, depth: int = 0) -> Cursor | None:
    """What a value built of one argument is built of (``rclcpp::ParameterValue{v}``,
    ``T(v)``): the argument, as far as such constructions nest."""
    if expr is None or depth > 3:
        return None
    expr = strip(expr)
    target = expr.referenced if expr.kind == CursorKind.CALL_EXPR else None
    if expr.kind not in _CONVERSIONS or (
        target is not None and target.kind != CursorKind.CONSTRUCTOR
    ):
        return None
    inner = [c for c in expr.get_children() if c.kind.is_expression()]
    if len(inner) != 1:
        return None
    found = strip(_unmoved(inner[0]))
    if found.kind == CursorKind.DECL_REF_EXPR:
        return found
    return _converted(found, depth + 1)


def _is_this(expr: Cursor) -> bool:
    """``this``, ``*this``, ``shared_from_this()``: the object the wrapper is a method of."""
    expr = strip(expr)
    if expr.kind == CursorKind.CXX_THIS_EXPR:
        return True
    if expr.kind == CursorKind.UNARY_OPERATOR:
        inner = [c for c in expr.get_children() if c.kind.is_expression()]
        return len(inner) == 1 and _is_this(inner[0])
    if expr.kind == CursorKind.CALL_EXPR and expr.spelling in _THIS_CALLS:
        callee = next(iter(expr.get_children()), None)
        objects = [c for c in callee.get_children() if c.kind.is_expression()] if (
            callee is not None and callee.kind == CursorKind.MEMBER_REF_EXPR) else []
        return not objects or _is_this(objects[0])
    return False


def _class_qualifier(head: Cursor) -> tuple[Cursor, Cursor | None] | None:
    """The class template that qualifies a dependent call's name (``Class<T>::f``: the
    reference to ``Class``) and the template type parameter its first argument is
    (``T``; None when another type), when the name is so qualified."""
    children = list(head.get_children())
    for index, child in enumerate(children):
        if child.kind == CursorKind.TEMPLATE_REF and child.referenced is not None and (
                child.referenced.kind == CursorKind.CLASS_TEMPLATE):
            after = children[index + 1] if index + 1 < len(children) else None
            param = after.referenced if after is not None and (
                after.kind == CursorKind.TYPE_REF) else None
            return child, param if param is not None and (
                param.kind == CursorKind.TEMPLATE_TYPE_PARAMETER) else None
    return None


def called_name(call: Cursor) -> str:
    """The name an unresolved call calls, from its tokens (or its head's): the last name
    before its arguments, outside template arguments (``Class<T>::create_subscription(
    ...)``: ``create_subscription``; ``std::make_shared<C<T>>``: ``make_shared``)."""
    name, depth = "", 0
    for token in call.get_tokens():
        text = token.spelling
        if text == "<":
            depth += 1
        elif text == ">":
            depth -= 1
        elif text == ">>":
            depth -= 2
        elif text == "(" and depth <= 0:
            break
        elif depth <= 0 and text.isidentifier() and text != "template":
            name = text
    return name


def _returned_whole(function: Cursor, call: Cursor) -> bool:
    """Whether ``function`` returns the value of ``call`` as it is (converted to its
    return type at most: ``return loader_->createUniqueInstance(name);`` into a
    ``std::shared_ptr<T>``)."""
    for node in function.walk_preorder():
        if node.kind != CursorKind.RETURN_STMT:
            continue
        value = next((c for c in node.get_children() if c.kind.is_expression()), None)
        for _depth in range(MAX_DEPTH):
            if value is None:
                break
            value = strip(value)
            made = value.referenced if value.kind == CursorKind.CALL_EXPR else None
            if made is None or made.kind != CursorKind.CONSTRUCTOR:
                break
            inner = [c for c in value.get_children() if c.kind.is_expression()]
            value = inner[0] if len(inner) == 1 else None
        if value is not None and _key(value) == _key(call):
            return True
    return False


def _dependent_loader(member: Cursor) -> Cursor | None:
    """The class template of the object a dependent member call is made on, when a
    ClassLoader of pluginlib holds it (``loader_->createUniqueInstance(name)`` with
    ``std::shared_ptr<pluginlib::ClassLoader<T>> loader_``, or the loader itself, by value,
    reference or plain pointer): its declaration; else None."""
    objects = [c for c in member.get_children() if c.kind.is_expression()]
    if not objects:
        return None
    ctype = objects[0].type.get_canonical()
    if ctype.kind in (TypeKind.POINTER, TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
        ctype = ctype.get_pointee().get_canonical()
    decl = ctype.get_declaration()
    if decl is not None and decl.kind != CursorKind.NO_DECL_FOUND and (
        qualified_name(decl) in _OWNING_POINTERS and ctype.get_num_template_arguments() > 0
    ):
        ctype = ctype.get_template_argument_type(0).get_canonical()
        decl = ctype.get_declaration()
    if decl is None or decl.kind == CursorKind.NO_DECL_FOUND:
        return None
    return decl if any(owner == qualified_name(decl) for owner, _ in api.PLUGINLIB) else None


_OWNING_POINTERS = frozenset({"std::unique_ptr", "std::shared_ptr", "boost::shared_ptr"})


def _member_name(member: Cursor) -> str:
    """The method a dependent member call names (``node->template create_publisher<M>``:
    ``create_publisher``); its cursor has no spelling."""
    if member.spelling:
        return member.spelling
    tokens = [t.spelling for t in member.get_tokens()]
    depth, name = 0, ""
    for index, token in enumerate(tokens):
        if token in ("(", "["):
            depth += 1
        elif token in (")", "]"):
            depth -= 1
        elif token in ("->", ".") and depth == 0:
            rest = [t for t in tokens[index + 1:] if t != "template"]
            name = rest[0] if rest else ""
    return name


_ALIASES = (CursorKind.TYPE_ALIAS_DECL, CursorKind.TYPEDEF_DECL)
MAX_ALIASES = 8  # aliases of aliases followed


def _aliased(decl: Cursor) -> list[Cursor]:
    """``decl``, or, for a type alias, the declarations its type names, through aliases
    of aliases (``using Server = nav2_util::SimpleActionServer<Action>``: the class
    template, then the template argument's class)."""
    found: list[Cursor] = []
    todo = [decl]
    for _ in range(MAX_ALIASES):
        if not todo:
            break
        each = todo.pop(0)
        if each.kind not in _ALIASES:
            found.append(each)
            continue
        todo += [c.referenced for c in each.get_children()
                 if c.kind in (CursorKind.TEMPLATE_REF, CursorKind.TYPE_REF)
                 and c.referenced is not None]
    return found


def _overloads(head: Cursor) -> list[Cursor]:
    """The functions an unresolved call's name may be (``ns::create_publisher<M>(...)``
    with dependent arguments)."""
    found: list[Cursor | None] = []
    for child in [head, *head.get_children()]:
        if child.kind == CursorKind.OVERLOADED_DECL_REF:
            found += overloads(child)
    return [d for d in found if d is not None and d.kind in (
        CursorKind.FUNCTION_TEMPLATE, CursorKind.FUNCTION_DECL, CursorKind.CXX_METHOD)]


def _fitting(head: Cursor, args: list[Cursor]) -> list[Cursor]:
    """The overloads an unresolved call's name may be that C++ would rather call with
    ``args``."""
    return _preferred(_overloads(head), args)


def _preferred(functions: list[Cursor], args: list[Cursor]) -> list[Cursor]:
    """Of ``functions``, those that may take ``args`` and that C++ would rather call
    (``call_sites.closest``)."""
    return closest([f for f in functions if _fits(f, args)], args)


def _fits(decl: Cursor, args: list[Cursor]) -> bool:
    """Whether overload ``decl`` may be the one called with ``args`` (``call_sites.fits``)."""
    return fits(decl, [strip(arg).type for arg in args])


def _dispatched(constructor: Cursor, decl: Cursor, args: list[Cursor]
                ) -> tuple[Key, int, Key, bool] | None:
    """The test that picks overload ``decl`` for ``args``: a parameter of type
    ``std::true_type`` (``std::false_type``) given ``std::is_same<T, X>{}``, T a type
    parameter of the class of ``constructor``, X a class: (the class template, T's
    index, X's place, whether T is X)."""
    cls = constructor.semantic_parent
    templates = _class_parameters(constructor)
    for param, arg in zip(_parameters(decl), args, strict=False):
        wanted = param.type.get_canonical().spelling.replace(" ", "")
        if wanted not in ("std::integral_constant<bool,true>",
                          "std::integral_constant<bool,false>"):
            continue
        refs = [c for c in strip(arg).walk_preorder()
                if c.kind in (CursorKind.TEMPLATE_REF, CursorKind.TYPE_REF)]
        if len(refs) != 3 or refs[0].kind != CursorKind.TEMPLATE_REF or (
            refs[0].spelling != "is_same"
        ):
            continue
        sides = [r.referenced for r in refs[1:]]
        index = next((i for side in sides for i, t in enumerate(templates)
                      if side is not None and _key(side) == _key(t)), None)
        other = next((side for side in sides if side is not None and side.kind in (
            CursorKind.STRUCT_DECL, CursorKind.CLASS_DECL)), None)
        if index is None or other is None or cls is None:
            continue
        return (_key(cls), index, _key(other.canonical), wanted.endswith("true>"))
    return None


def _chosen(call: Cursor, when: tuple[Key, int, Key, bool]) -> bool | None:
    """Whether the construction ``call`` (``C<T> c(..)``, ``make_unique<C<T>>(..)``)
    makes an overload chosen by ``when`` (``Wrapper.when``); None where its class is not
    known."""
    made = call.type.get_canonical()
    candidates = [made]
    if made.get_num_template_arguments() > 0:
        candidates.append(made.get_template_argument_type(0).get_canonical())
    for each in candidates:
        decl = each.get_declaration()
        template = conf.lib.clang_getSpecializedCursorTemplate(decl) if (
            decl.kind != CursorKind.NO_DECL_FOUND) else None
        if template is None or template.kind == CursorKind.NO_DECL_FOUND or (
            _key(template) != when[0] and _key(template.canonical) != when[0]
        ) or each.get_num_template_arguments() <= when[1]:
            continue
        given = each.get_template_argument_type(when[1]).get_canonical().get_declaration()
        if given.kind == CursorKind.NO_DECL_FOUND:
            return None
        return (_key(given.canonical) == when[2]) == when[3]
    return None


def _may_call(call: Cursor, method: Cursor) -> bool:
    """Whether ``call`` may call ``method``: it resolves to it, or it is unresolved and
    may be one of the overloads of its name."""
    target = call.referenced
    if target is not None:
        return _key(method.canonical) in specialised_keys(target) or (
            _key(target.canonical) == _key(method.canonical))
    head = next(iter(call.get_children()), None)
    if head is None:
        return False
    decls = _overloads(head)
    if decls:
        return any(_key(d.canonical) == _key(method.canonical) for d in decls)
    return head.kind == CursorKind.MEMBER_REF_EXPR and _member_name(head) == (
        method.spelling.split("<")[0])


def _called_names(calls: Iterator[list[Cursor]] | Any) -> set[str]:
    """The names the calls of the unit may call: each call's, a dependent member call's
    method and the overloads an unresolved call's name may be."""
    found: set[str] = set()
    for each in calls:
        for call in each:
            if call.spelling:
                found.add(call.spelling.split("<")[0])
                continue
            head = next(iter(call.get_children()), None)
            if head is None:
                continue
            if head.kind == CursorKind.MEMBER_REF_EXPR:
                found.add(_member_name(head))
            found.update(d.spelling for d in _overloads(head))
    return found


def _targets(call: Cursor) -> list[Key]:
    target = call.referenced
    if target is not None:
        return [_key(target.canonical)]
    children = list(call.get_children())
    return [_key(d.canonical) for d in _overloads(children[0])] if children else []


def of_class_template(function: Cursor) -> bool:
    parent = function.semantic_parent
    return parent is not None and parent.kind in (
        CursorKind.CLASS_TEMPLATE, CursorKind.CLASS_TEMPLATE_PARTIAL_SPECIALIZATION)


def _arguments(call: Cursor) -> list[Cursor]:
    """A call's written arguments; of a call of a lambda (``getParam(x, "name")``, an
    ``operator()`` call), without the lambda object clang lists first."""
    args = written_arguments(call)
    if call.spelling == "operator()" and args:
        target = call.referenced
        parent = target.semantic_parent if target is not None else None
        if parent is not None and parent.spelling.startswith("(lambda at "):
            return args[1:]
    return args


def _with_defaults(call: Cursor, args: list[Cursor]) -> list[Cursor]:
    """``args`` with the defaults of the parameters the call leaves out, in order, as
    far as each has one (hector_quadrotor's ``attitude_limiter_.init(controller_nh)``
    of ``init(nh, field = std::string())``, which names its parameters after
    ``field``)."""
    target = call.referenced
    if target is None or call.spelling == "operator()":
        return args
    params = [c for c in target.get_children() if c.kind == CursorKind.PARM_DECL]
    out = list(args)
    for parm in params[len(args):]:
        found = default_argument(parm)
        if found is None:
            break
        out.append(found)
    return out


def _made_with(call: Cursor, scope: Scope) -> dict[str, Parts]:
    """For a call of a lambda held in a variable that a function call made
    (``auto getParam = handler->getParamGetter(ns)``), the placeholder part of each of
    that function's parameters (``call_sites.placeholder``) and the value this site's
    maker passes for it: the lambda's captures are that call's arguments."""
    if call.spelling != "operator()":
        return {}
    objects = written_arguments(call)
    held = strip(objects[0]) if objects else None
    decl = held.referenced if held is not None and held.kind == CursorKind.DECL_REF_EXPR \
        else None
    made = initializer(decl) if decl is not None and decl.kind == CursorKind.VAR_DECL \
        else None
    made = strip(made) if made is not None else None
    maker = made.referenced if made is not None and made.kind == CursorKind.CALL_EXPR \
        else None
    if maker is None:
        return {}
    usr = maker.canonical.get_usr()
    return {f"{PLACEHOLDER}{usr}{SEPARATOR}{index}{PLACEHOLDER}": scope.string(arg)
            for index, arg in enumerate(written_arguments(made))}


def _bind(parts: Parts, bound: dict[str, Parts]) -> Parts:
    if not bound:
        return parts
    found: list[str | None] = []
    for part in parts:
        found.extend(bound[part] if isinstance(part, str) and part in bound else (part,))
    return tuple(found)


_REFERENCES = frozenset({CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR,
                         CursorKind.OVERLOADED_DECL_REF})
_LAMBDA_END = object()  # in ``_scan``'s stack: the walk leaves a lambda's body


# what ``_scan`` puts in ``every`` besides calls: expressions kept unresolved, and the
# objects a function builds (``CallFinder._unseen_class`` reads them in every function)
_EVERY = frozenset({CursorKind.UNEXPOSED_EXPR, CursorKind.VAR_DECL, CursorKind.CXX_NEW_EXPR})


def _scan(function: Cursor, every: list[Cursor] | None = None,
          references: list[Cursor] | None = None) -> tuple[list[Cursor], list[Cursor]]:
    """The calls in ``function``'s body, in order, and the lambdas it makes; not the
    calls inside those (a lambda's body runs when it is called, not where it is
    written): one walk of the body. With ``every``, the walk goes into the lambdas'
    bodies too and puts in it every call, unexposed expression, variable and ``new`` of
    the function's whole subtree, in the order of ``walk_preorder`` (what
    ``CallFinder._gives`` reads: the function's nodes are then walked once for both);
    with ``references``, the walk puts in it the subtree's references to declarations,
    in the same order (what ``call_conditions.site_facts`` reads)."""
    calls: list[Cursor] = []
    lambdas: list[Cursor] = []
    stack: list[Any] = list(reversed(list(function.get_children())))
    inside = 0  # lambdas the walk is in (with ``every``)
    while stack:
        node = stack.pop()
        if node is _LAMBDA_END:
            inside -= 1
            continue
        kind = node.kind
        if kind == CursorKind.CALL_EXPR:
            if not inside:
                calls.append(node)
            if every is not None:
                every.append(node)
        elif kind in _EVERY:
            if every is not None:
                every.append(node)
        elif references is not None and kind in _REFERENCES:
            references.append(node)
        elif kind == CursorKind.LAMBDA_EXPR:
            if not inside:
                lambdas.append(node)
            if every is None:
                continue
            inside += 1
            stack.append(_LAMBDA_END)
        stack.extend(reversed(list(node.get_children())))
    return calls, lambdas


def _base_arguments(function: Cursor, base: Cursor) -> tuple[list[str], list[str]] | None:
    """The template parameters of the class of constructor ``function`` and the template
    arguments it names the class of constructor ``base`` with as its base (None when it
    does not derive from that class)."""
    cls, owner = function.semantic_parent, base.semantic_parent
    if cls is None or owner is None:
        return None
    params = [c.spelling for c in cls.get_children()
              if c.kind == CursorKind.TEMPLATE_TYPE_PARAMETER]
    for spec in cls.get_children():
        if spec.kind == CursorKind.CXX_BASE_SPECIFIER and spec.referenced is not None and (
                _key(spec.referenced.canonical) == _key(owner.canonical)):
            text = spec.type.spelling
            given = text[text.find("<") + 1:text.rfind(">")] if "<" in text else ""
            return params, [a.strip() for a in given.split(",")]
    return None


def _same_parameters(function: Cursor, base: Cursor) -> bool:
    """Whether the class of constructor ``function`` names the class of constructor
    ``base`` as its base with its own template parameters, in order
    (``Service<ServiceT> : BaseService<ServiceT>``)."""
    found = _base_arguments(function, base)
    return found is not None and bool(found[0]) and found[1] == found[0]


def _first_parameter_passed(function: Cursor, base: Cursor) -> bool:
    """Whether the class of constructor ``function`` names the class of constructor
    ``base`` as its base with its own first template parameter as the base's first
    template argument (``Modified<M, NodeType> : message_filters::Subscriber<M>``)."""
    found = _base_arguments(function, base)
    return found is not None and bool(found[0]) and found[1][0] == found[0][0]


def _delegation(function: Cursor) -> Cursor | None:
    """A class template's constructor's delegation (``call_sites.delegation``): clang
    keeps no call of the constructor it delegates to, only the argument list."""
    found = delegation(function) if of_class_template(function) else None
    return found if found is not None and found.kind == CursorKind.UNEXPOSED_EXPR else None


def _dependent_name(name: str) -> bool:
    return "type-parameter" in name


def _passed_value(values: dict[str, object], name: str) -> object:
    return values.get(name, Unknown())


def _namespaces(function: Cursor) -> set[str] | None:
    """The names of the namespaces around a free function (those a call of it may be
    qualified with); None for a function of a class, whose calls may name it through
    an alias or a derived class."""
    if function.kind not in (CursorKind.FUNCTION_DECL, CursorKind.FUNCTION_TEMPLATE):
        return None
    found: set[str] = set()
    parent = function.canonical.semantic_parent
    while parent is not None and parent.kind == CursorKind.NAMESPACE:
        if parent.spelling:
            found.add(parent.spelling)
        parent = parent.semantic_parent
    return found if parent is not None and parent.kind == CursorKind.TRANSLATION_UNIT else None
