"""Values that cross the translation units of one node, or its calls.

A handle or a string passed to a function (a constructor, ``std::make_shared<T>``,
``new T``, a member initialiser) defined in another file of the same node is not known
in that file, and one that callers in the same file disagree on is not one value:
``call_sites.CallSites`` writes it as a placeholder part naming the function (by USR)
and the parameter's index. Every file records what it passes to those functions
(``argument_facts``: the handle's namespace, or the string; a default where the call
leaves the argument out), and ``resolve`` fills each node's placeholders with what its
own files pass, once all of them are read (a file shared by two nodes is filled per
node). Callers that disagree give one call per value (up to ``MAX_VALUES``); a
parameter no file of the node passes stays ``?``, except in a call a constructor makes
(``PrimitiveCall.made_in``): a class no file of the node constructs makes none of its
calls there (a header's class the node includes and never builds), when the parse of
its files left no error that could hide a construction.
"""

from __future__ import annotations

import dataclasses
import functools
import re
from collections.abc import Callable, Collection, Iterable, Iterator

from clang.cindex import Cursor, CursorKind, Type, TypeKind, conf

from ... import diagnostics as diag
from ...diagnostics import Diagnostic
from ...model.conditions import Condition
from ...model.rosname import node_name_joined
from ...model.source import JOINED, LOADED, NODELET_HANDLE, PROCESS_HANDLE, PrimitiveCall
from . import msg_types
from .cache import conditions_of_text, conditions_text
from .call_conditions import (
    BASES,
    HIDDEN,
    INDICES,
    INSTANTIATED,
    NAMED_CLASS,
    NOT_CARRIED,
    OVERLOADED,
    REFERENCED,
    RUNS_WHEN_CALLED,
    SITE_UNDER,
    qualified_call,
    site_of,
)
from .call_sites import (
    BUILT_CLOSE,
    BUILT_OPEN,
    CallSites,
    argument,
    declares_no_constructor,
    string_parameters,
)
from .handles import Namespaces, holds_handle, is_handle, join_name, normalise
from .owners import owner_of
from .values import (
    PLACEHOLDER,
    SEPARATOR,
    VARIABLES,
    Scope,
    _walk,
    choose,
    key_of,
    render,
    strip,
)
from .writes import writes_of

Fact = tuple[str, int, str, str]  # callee USR, parameter index, value passed, call site

CALLED = -1  # the index of a fact that says only that the call site calls the function
# the index of a fact that says the function (a virtual method) overrides the one whose
# USR is its value: the handle a call of that one passes (at the parameter whose index
# is the fact's site) is passed to it too, as the call may run it
# (``boost::shared_ptr<Analyzer> group; group->init(base, nh)`` runs
# ``AnalyzerGroup::init``). Handles only: a string member a call passes is read as its
# constructor sets it, not as a later method does (nav2's CostmapFilter::activate passes
# ``filter_info_topic_``, "" in its constructor, set from a parameter in onInitialize)
OVERRIDES = -2
# the index of a fact that says the call site (a construction) is made under the source
# conditions its value holds (``cache.conditions_text``)
CONDITIONS = -3
# the index of a fact that says the function is a virtual method whose one string
# parameter is the one at the fact's site (its value: the USRs of the base methods it
# overrides, one per line): a host calls a plugin through its base class, and the one
# string such a method takes from it is the plugin's name (nav2's ``configure(parent,
# name, tf, ...)``, ROS 1 nav_core's ``initialize(name, ...)``). A call named wholly by
# that parameter, where no file of the node calls the method or one it overrides (nav2's
# CostmapFilter calls its filters' ``initializeFilter(topic)`` itself), is
# ``PrimitiveCall.host_named``
HOST_NAMED = -4
# the index of a fact that says the unit's code calls the function, a virtual method
# taking one string (``CallSites.virtual_callees``), wherever it is defined
CALLED_VIRTUAL = -5
# the index of a fact that says the function (a virtual method) overrides the one whose
# USR is its value, for a string parameter (the fact's site its index): a call of that one
# passes it the strings it writes as literals alone (``LITERAL``), which no later code can
# change, and ``?`` for any other (a member's may change before the call: ``OVERRIDES``):
# rviz_common's ``VisualizerApp::init`` calls ``RosClientAbstractionIface::init(argc,
# argv, "rviz", false)``, which runs ``RosClientAbstraction::init``, whose ``name`` names
# the node
STRING_OVERRIDES = -10
# the index of a fact that says the call site passes, at the parameter whose index is
# the fact's value, a string written in literals alone (no variable, member or parameter)
LITERAL = -11
# the index of a fact that says the unit builds an object through the constructor (the
# fact's USR) without its code, and the words of the class's declaration (the value, one
# space between them) name what that code may construct: unseen by the node unless one
# of its units has the code (``DEFINED``). voxblox's esdf_server_node.cc builds
# ``EsdfServer(nh, nh_private)``, whose class derives from TsdfServer; esdf_server.cc,
# of the same node, defines that constructor and shows which of TsdfServer's it calls
OPAQUE = -15
# the index of a fact that says the unit's own source defines the constructor
DEFINED = -16
# the index of a fact that says the namespace of a handle member (the fact's USR, a
# field's) is its value where the unit (its own source the fact's site) defines a
# constructor of the member's class: another unit that reads the member and has none of
# those constructors holds it as a placeholder (``CallSites.member_placeholder``); and of
# a global handle (a variable's USR) that the unit's own source writes once
# (``global_facts``), which another unit declares ``extern`` and never writes
MEMBER = -17
# the index of a fact that says the call site (the fact's site) calls the virtual method
# (the fact's USR) by its class's name, ``Base::setup(nh)``: it runs that method alone,
# not the methods overriding it (no site of theirs for ``OVERRIDES``)
QUALIFIED = -20
# the index of a fact that says the call site (the fact's site) is in the code of a class
# (the fact's USR: its qualified name) that the unit exports for a host to build (a
# plugin's registration): where the node's code never builds it, the site is in code
# the process never runs and passes nothing (``extract.cpp._exported_unbuilt``)
EXPORTED_AT = -21
# the start of a ``PrimitiveCall.built_in`` that names a class (by its USR), not a
# constructor: a method's calls exist where objects of the class are built, under the
# conditions every construction of it in the node's files shares (``_built_under``)
CLASS_BUILT = "class:"
# the index of a fact that says the call site (the fact's site) is in the constructor whose
# USR is the fact's value, which its unit never calls: where no file of the node calls it
# either, the site passes nothing (``NodeFacts.idle``)
WITHIN = -18
# the index of a fact that says the call site (the fact's site) calls the virtual method
# (the fact's USR) through its class, not naming it (``plugin->initialize(nh, nhp)``):
# the call may run any override, a plugin's the host loads (``handles_given``)
VIRTUAL_CALL = -22
# the index of a fact that says the unit's own source assigns the handle member (the
# fact's USR) the namespace (the value) through an object of its class, not ``this``
# (FUEL's SDFMap hands its handle to its MapROS: ``mr_->node_ = nh``): where a file of
# the node does, its values replace what the class's constructors leave (``MEMBER``)
ASSIGNED = -23
# the index, plus K, of a fact that says the construction (the fact's site) builds the
# class template whose constructor is the fact's USR with the ROS type (the value) as its
# K-th template argument: a call whose callback takes that type parameter is typed by it
# (``CallFinder._per_construction_type``; OpenMower's ``StateSubscriber<M>``)
TYPE_ARGUMENT = 1000
# facts that say no call of their function
NOT_CALLS = frozenset({OVERRIDES, HOST_NAMED, CALLED_VIRTUAL, STRING_OVERRIDES, LITERAL,
                       OPAQUE, DEFINED, MEMBER, WITHIN, QUALIFIED, EXPORTED_AT,
                       VIRTUAL_CALL, ASSIGNED})
_SPECIALISED = frozenset({CursorKind.FUNCTION_DECL, CursorKind.CONSTRUCTOR,
                          CursorKind.CXX_METHOD})
# realsense2_camera's setParam is called with ~30 names in its files, OrbbecSDK_ROS2's
# OBCameraNode::setAndGetNodeParameter with ~180
MAX_VALUES = 256
MAX_DEPTH = 8
_MARK = re.compile(f"{PLACEHOLDER}([^{PLACEHOLDER}{SEPARATOR}]*){SEPARATOR}(\\d+){PLACEHOLDER}")
_SPLIT = "\x02"


def argument_facts(sites: CallSites, namespaces: Namespaces,
                   owned: Callable[[str], bool],
                   named: Callable[[Cursor, Scope], str | None] | None = None,
                   conditioned: Callable[[Cursor, Cursor], tuple[Condition, ...]] | None = None,
                   struct: Callable[[Cursor, Scope], str | None] | None = None,
                   typed: Callable[[Type], str | None] | None = None,
                   exported: Collection[str] = ()) -> list[Fact]:
    """What this file passes, as handles' namespaces or strings, to the workspace
    functions it calls but does not define; ``named`` gives a string that is (or holds)
    a parameter's value with that parameter marked (``parameter_mark``); ``conditioned``
    the source conditions of a call in its function, said of the constructions
    (``CONDITIONS``); ``struct`` the name of the parameter a ROS 1 ``XmlRpcValue``
    holds (a struct parameter's member handed to a constructor that reads its keys);
    ``typed`` the ROS type of a class template's argument at a construction
    (``TYPE_ARGUMENT``); ``exported`` the classes the unit registers for a host, whose
    code's sites are said (``EXPORTED_AT``)."""
    facts: list[Fact] = []
    done: set[tuple[str, int]] = set()
    for _round in range(MAX_DEPTH):  # reading a value may give another function a mark
        todo = list(sites.passing_sites(done))
        if not todo:
            break
        for callee, call, caller, specialisation in todo:
            where = callee.location.file
            usr = callee.canonical.get_usr()
            done.add(key_of(callee.canonical))
            if where is None or not owned(where.name) or not usr:
                continue
            scope = sites.scope(caller)
            at = call.location
            site = site_of(at)
            params = [c for c in callee.get_children() if c.kind == CursorKind.PARM_DECL]
            given = len(facts)
            for index, parm in enumerate(params):
                arg = argument(call, parm, index)
                value = _value(arg, scope, namespaces, named) if arg is not None else None
                if value is None and arg is not None and struct is not None:
                    value = struct(arg, scope)
                if value is not None and specialisation is not None:
                    # what the template's callers pass: those of this specialisation
                    value = value.replace(
                        f"{PLACEHOLDER}{caller.canonical.get_usr()}{SEPARATOR}",
                        f"{PLACEHOLDER}{specialisation.get_usr()}{SEPARATOR}")
                if value is not None:
                    facts.append((usr, index, value, site))
                    if _literal(arg, value):
                        facts.append((usr, LITERAL, str(index), site))
            if len(facts) == given:  # called, with nothing read: called all the same
                facts.append((usr, CALLED, "", site))
            if exported and (holder := owner_of(caller)) in exported:
                facts.append((holder, EXPORTED_AT, "", site))
            if callee.kind == CursorKind.CXX_METHOD and callee.is_virtual_method() and (
                    call.kind == CursorKind.CALL_EXPR):
                facts.append((usr, QUALIFIED if qualified_call(call) else VIRTUAL_CALL,
                              "", site))
            within = caller.canonical.get_usr() if (
                caller.kind == CursorKind.CONSTRUCTOR and not sites.callers(caller)) else ""
            if within:
                facts.append((usr, WITHIN, within, site))
            if conditioned is not None and callee.kind == CursorKind.CONSTRUCTOR:
                under = conditioned(caller, call)
                if under:
                    facts.append((usr, CONDITIONS, conditions_text(under), site))
            template = conf.lib.clang_getSpecializedCursorTemplate(callee)
            if template is not None and callee.kind in _SPECIALISED and (
                template.kind == CursorKind.FUNCTION_TEMPLATE or _of_class_template(template)
            ):
                # a function template's specialisation: what is passed to it is passed
                # to the template, whose code holds the calls (and their placeholders:
                # ``CallFinder._made_in``, a constructor template's names)
                facts.extend((template.get_usr(), index, value, at)
                             for _usr, index, value, at in facts[given:])
            if typed is not None and template is not None and (
                    callee.kind == CursorKind.CONSTRUCTOR and _of_class_template(template)):
                # the ROS types the construction gives the class template's arguments
                made = callee.semantic_parent.type
                for index in range(max(made.get_num_template_arguments(), 0)):
                    given_type = made.get_template_argument_type(index)
                    value = typed(given_type) if given_type.kind != TypeKind.INVALID else None
                    facts.append((template.get_usr(), TYPE_ARGUMENT + index, value or "?",
                                  site))
    for usr, (function, bases) in sites.overrides.items():
        params = [c for c in function.get_children() if c.kind == CursorKind.PARM_DECL]
        facts.extend((usr, OVERRIDES, base, str(index)) for base in bases if base
                     for index, parm in enumerate(params) if is_handle(parm))
        strings = string_parameters(function)
        facts.extend((usr, STRING_OVERRIDES, base, str(index)) for base in bases if base
                     for index in strings)
        if len(strings) == 1 and function.is_virtual_method():
            facts.append((usr, HOST_NAMED, "\n".join(b for b in bases if b),
                          str(strings[0])))
    facts.extend((usr, CALLED_VIRTUAL, "", "") for usr in sorted(sites.virtual_callees()))
    return list(dict.fromkeys(facts))


def opaque_facts(functions: Iterable[Cursor], main: str,
                 words: dict[str, set[bytes]]) -> list[Fact]:
    """The ``OPAQUE`` facts of the constructions whose constructor's code the unit has
    not (``words``: by the constructor's USR), and a ``DEFINED`` fact for each
    constructor the unit's own source ``main`` defines."""
    facts: list[Fact] = [(usr, OPAQUE, " ".join(sorted(w.decode() for w in found)), "")
                         for usr, found in sorted(words.items())]
    for function in _own_constructors(functions, main):
        usr = function.canonical.get_usr()
        if usr:
            facts.append((usr, DEFINED, "", ""))
    return facts


def _own_constructors(functions: Iterable[Cursor], main: str) -> Iterator[Cursor]:
    """The constructors among ``functions`` that the unit's own source ``main`` defines."""
    for function in functions:
        where = function.location.file
        if function.kind == CursorKind.CONSTRUCTOR and where is not None and (
                where.name == main) and function.is_definition():
            yield function


def member_facts(functions: Iterable[Cursor], main: str,
                 namespace: Callable[[Cursor], str | None]) -> list[Fact]:
    """A ``MEMBER`` fact for each handle member of the classes whose constructors the
    unit's own source ``main`` defines, with its namespace as ``namespace`` gives it
    (None: not one to say); also of each handle member of a class that declares no
    constructor and a method of which ``main`` defines (``constructed_here``)."""
    facts: list[Fact] = []
    seen: set[str] = set()
    functions = list(functions)
    owners = [(function.semantic_parent, False)
              for function in _own_constructors(functions, main)]
    owners.extend((function.semantic_parent, True) for function in functions
                  if function.kind == CursorKind.CXX_METHOD and function.is_definition()
                  and function.location.file is not None
                  and function.location.file.name == main
                  and declares_no_constructor(function.semantic_parent))
    for owner, implicit in owners:
        if owner is None:
            continue
        for field in owner.get_children():
            usr = field.get_usr() if field.kind == CursorKind.FIELD_DECL else ""
            if not usr or usr in seen or (implicit and not holds_handle(field)):
                continue
            seen.add(usr)
            value = namespace(field)
            if value is not None and usr not in marked_usrs(value):
                facts.append((usr, MEMBER, value, main))
    return facts


def assigned_facts(functions: Iterable[Cursor], main: str, sites: CallSites,
                   namespaces: Namespaces) -> list[Fact]:
    """An ``ASSIGNED`` fact for each handle member that the functions the unit's own
    source ``main`` defines assign through an object of its class (``obj.nh_ = nh``,
    ``obj->nh_ = nh``), with the namespace it gives it (``?`` where the unit's writes
    of it differ)."""
    found: dict[str, str] = {}
    for function in functions:
        where = function.location.file
        if where is None or where.name != main or not function.is_definition():
            continue
        for node in _walk(function):
            if node.kind not in (CursorKind.CALL_EXPR, CursorKind.BINARY_OPERATOR):
                continue
            for write in writes_of(node, sites.source):
                target, value = write.target, write.value
                field = target.referenced if target.kind == CursorKind.MEMBER_REF_EXPR \
                    else None
                if not write.whole or value is None or field is None or (
                        field.kind != CursorKind.FIELD_DECL) or not holds_handle(field):
                    continue
                base = [strip(child) for child in target.get_children()]
                usr = field.get_usr()
                if not base or base[0].kind == CursorKind.CXX_THIS_EXPR or not usr:
                    continue
                text = _value(value, sites.scope(function), namespaces, None)
                if text is None or usr in marked_usrs(text):
                    text = "?"
                found[usr] = text if found.get(usr, text) == text else "?"
    return [(usr, ASSIGNED, value, main) for usr, value in found.items()]


def global_facts(found: Iterable[tuple[str, str]], main: str) -> list[Fact]:
    """A ``MEMBER`` fact for each global handle (by USR) the unit's own source ``main``
    writes once, with the namespace it gives it (``Namespaces.global_handles``): another
    file of the node that declares it ``extern`` holds it as a placeholder."""
    return [(usr, MEMBER, value, main) for usr, value in found
            if usr not in marked_usrs(value)]


def opaque_unseen(facts: Iterable[Fact]) -> set[str]:
    """The words of the node's ``OPAQUE`` facts whose constructor no unit of the node
    defines: what that code may construct is not seen."""
    facts = list(facts)
    defined = {usr for usr, index, _value, _site in facts if index == DEFINED}
    return {word for usr, index, value, _site in facts
            if index == OPAQUE and usr not in defined for word in value.split()}


def _literal(arg: Cursor, value: str) -> bool:
    """Whether a string argument is written in literals alone: its value known whole and
    no variable, member or parameter read in it (``"rviz"``, ``std::string("a") + "b"``)."""
    if "?" in value or PLACEHOLDER in value or PARAMETER in value or is_handle(arg):
        return False
    return not any(node.kind in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR)
                   and (node.referenced is None or node.referenced.kind in VARIABLES)
                   for node in arg.walk_preorder())


# before a handle's namespace passed to another file's function: the handle is a ROS 1
# controller's root handle (``handles.controller_root``), whose names its host's plugin
# stage puts in its manager's namespace (hector_quadrotor's controllers hand ``root_nh``
# to ``getMassAndInertia(nh, ...)`` of hector_quadrotor_interface's library, which reads
# ``robot_description`` on it); only ``resolve`` keeps it, as ``root_handle``
ROOT_MARK = "\x17"
# before a handle's namespace passed to another file's function: where the handle was
# made (``Namespaces.origin``, ``PrimitiveCall.handle_origin``), for the calls made on it
# there (msckf_vio's nodelet hands ``getPrivateNodeHandle()`` to ImageProcessor's
# constructor in image_processor.cpp); only ``resolve`` reads it
ORIGIN_MARKS = {NODELET_HANDLE: "\x18", PROCESS_HANDLE: "\x19"}
_MARKS = re.compile("[" + ROOT_MARK + "".join(ORIGIN_MARKS.values()) + BUILT_OPEN
                    + BUILT_CLOSE + "]")
# a run a member that holds the node's name as constructed filled (``call_sites.
# names_node``), between its marks
_BUILT = re.compile(BUILT_OPEN + "[^" + BUILT_CLOSE + "]*" + BUILT_CLOSE)


def _built(name: str) -> str | None:
    """``name`` (as ``_expand`` filled it, marks and all) with ``?`` for the one run that
    is the node's name as constructed, without the other marks; None when no run, or
    several, are (``PrimitiveCall.name_built``)."""
    if len(_BUILT.findall(name)) != 1:
        return None
    return _plain(_BUILT.sub("?", name))


def origin_marked(text: str, origin: str | None) -> str:
    """A handle's namespace text as passed to another file, marked with its origin."""
    return ORIGIN_MARKS.get(origin or "", "") + text


# unknown runs side by side: the values of two placeholders, each not known
# (jsk_aerial_robot's sensor plugins: ``ros::NodeHandle(nh_, sensor_name +
# std::to_string(index))``), are one unknown run, written once as ``render`` writes it
_UNKNOWN_RUN = re.compile(r"\?{2,}")


def _plain(text: str) -> str:
    """A passed value without the marks of a handle's root or origin, an unknown run
    written once."""
    return _UNKNOWN_RUN.sub("?", _MARKS.sub("", text))


def _value(arg: Cursor, scope: Scope, namespaces: Namespaces,
           named: Callable[[Cursor, Scope], str | None] | None) -> str | None:
    if is_handle(arg):
        text = origin_marked(render(namespaces.of(arg, scope)), namespaces.origin)
        return ROOT_MARK + text if namespaces.root else text
    if msg_types.param_type(arg.type) == "str":
        parts = scope.string(arg)
        # only a string with one unknown run can hold a parameter's value with a mark
        # (or several joined: ``prefix + arm + "_controller"``, unknown parts side by side)
        runs = sum(1 for index, part in enumerate(parts)
                   if part is None and (index == 0 or parts[index - 1] is not None))
        marked = named(arg, scope) if named is not None and runs == 1 else None
        return marked if marked is not None else render(parts)
    return None


# A string passed to another file's function whose one unknown run is a parameter's value
# (or each element of a list parameter in turn) holds, in the place of its ``?``,
# PARAMETER, the parameter's name, PARAMETER, the element's field (``name_each``, or
# nothing), PARAMETER: the call named by it there takes the parameter as its
# ``name_param`` (navigation2's collision monitor passes each name of its ``polygons``
# list to a ``Polygon`` made in another file, which reads ``polygon_name_ + ".enabled"``)
PARAMETER = "\x03"
# before a mark's parameter: it is the USR of a member that another file of the node
# writes (``PrimitiveCall.name_member``), not a parameter
MEMBER_MARK = "\x04"
_PARAMETER = re.compile(f"{PARAMETER}([^{PARAMETER}]*){PARAMETER}([^{PARAMETER}]*){PARAMETER}")


# after a mark's parameter: the parameter's default as a name, when the caller's code
# knows it (slam_toolbox's ``map_name_``, written "/map" before it is read back from the
# parameter it declares with that value, handed to ``MapSaver``)
DEFAULT_MARK = "\x05"


def parameter_mark(name: str, param: str, each: str | None,
                   joined: Iterable[str] = (), default: str | None = None) -> str:
    """``name`` (one ``?``) with the parameter it is named by in the place of its ``?``;
    ``joined``: the parameters whose values follow that one's in the same ``?``
    (``prefix + arm``), each marked right after it; ``default``: the first one's default
    (``DEFAULT_MARK``)."""
    marks = "".join(f"{PARAMETER}{p}{PARAMETER}{PARAMETER}" for p in joined)
    if default is not None:
        param = f"{param}{DEFAULT_MARK}{default}"
    return name.replace("?", f"{PARAMETER}{param}{PARAMETER}{each or ''}{PARAMETER}{marks}",
                        1)


# marks with nothing between them: the values of one ``?`` (``values.render``)
_PARAMETER_RUN = re.compile(f"(?:{_PARAMETER.pattern})+")


def _unmarked(text: str) -> str:
    return _PARAMETER_RUN.sub("?", text)


def _named_by(call: PrimitiveCall) -> PrimitiveCall:
    """``call`` with the parameter marks of its name taken out: its ``name_param`` when
    the name holds one mark and no other unknown run; when every unknown run of it is
    made of marks (a run of several: the values joined, ros_kortex's ``m_prefix +
    m_arm_name + "_joint_trajectory_controller/..."`` handed to its action server's
    constructor), the first mark's parameter, then the others' (``name_more``), each
    in a run after its first JOINED to the one before it."""
    if PARAMETER not in call.name:
        return call
    name = _unmarked(call.name)
    runs = [_PARAMETER.findall(run.group(0)) for run in _PARAMETER_RUN.finditer(call.name)]
    marks = [mark for run in runs for mark in run]
    if name.count("?") != len(runs) or call.name_param is not None or any(
            PLACEHOLDER in param or "?" in param for param, _ in marks):
        # (a parameter named after what no file passes, or after what several pass)
        return dataclasses.replace(call, name=name)
    if len(marks) == 1:
        param, each = marks[0]
        if param.startswith(MEMBER_MARK):
            return dataclasses.replace(call, name=name, name_member=param[len(MEMBER_MARK):])
        if not param and each.startswith(LOADED):
            return dataclasses.replace(call, name=name, name_each=each)  # no parameter
        param, _, default = param.partition(DEFAULT_MARK)
        return dataclasses.replace(call, name=name, name_param=normalise(param),
                                   name_default=default or call.name_default,
                                   name_each=each or None)
    if any(each or param.startswith(MEMBER_MARK) for param, each in marks):
        return dataclasses.replace(call, name=name)
    more: list[list[str | None]] = [
        [normalise(param), default or None, *([JOINED] if index else [])]
        for run in runs for index, (param, _, default) in enumerate(
            mark[0].partition(DEFAULT_MARK) for mark in run)]
    return dataclasses.replace(call, name=name, name_param=more[0][0],
                               name_default=more[0][1], name_more=more[1:])


# ``made_in`` of one alternative of a call whose member the class's constructors give
# different values (``CallSites.member``): the constructor's USR after ``ALTERNATIVE``,
# and ``LOADABLE`` first for a constructor that takes no argument (a loader may call it)
ALTERNATIVE = "|"
LOADABLE = "*"


def constructed_by(constructor: Cursor) -> str | None:
    """The ``made_in`` of the alternative of a call that ``constructor`` makes."""
    usr = constructor.canonical.get_usr()
    if not usr:
        return None
    params = [p for p in constructor.get_children() if p.kind == CursorKind.PARM_DECL]
    required = [p for p in params if not any(c.kind.is_expression() for c in p.get_children())]
    return (ALTERNATIVE if required else LOADABLE + ALTERNATIVE) + usr


def _made(made_in: str, called: set[str], constructed: set[str | None],
          unseen: Collection[str]) -> bool:
    """Whether a call made in a constructor (``made_in``) is made in the node: its
    constructor is called by a file of the node, or the parse left errors that could
    hide that. One alternative of a member's value (``ALTERNATIVE``) is made when its
    constructor is called, not when the node's files construct the class by another
    one; when they construct it by none, a default constructor's is (a loader calls
    it), another's only where errors could hide the construction."""
    loadable = made_in.startswith(LOADABLE + ALTERNATIVE)
    usr = made_in.removeprefix(LOADABLE).removeprefix(ALTERNATIVE)
    if usr in called:
        return True
    cls = class_of(usr)
    if usr != made_in:  # an alternative
        if cls in constructed:
            return False
        if loadable:
            return True
    return "*" in unseen or cls in unseen


class NodeFacts:
    """The facts of one node's files, with what ``resolve`` reads of them worked out once
    for all its units' calls, and only when a call needs it (most need none)."""

    def __init__(self, facts: Iterable[Fact]) -> None:
        self.facts = list(facts)

    @functools.cached_property
    def passed(self) -> dict[str, dict[str, dict[int, str]]]:
        return _passed(self.facts)

    @functools.cached_property
    def called(self) -> set[str]:
        return {fact[0] for fact in self.facts if fact[1] not in NOT_CALLS | INDICES}

    @functools.cached_property
    def constructed(self) -> set[str | None]:
        return {class_of(usr) for usr in self.called if is_constructor_usr(usr)}

    @functools.cached_property
    def run(self) -> set[str]:
        """The functions a file of the node calls (its own file too), or uses otherwise
        (``&f``, a virtual method's bases), or may call unseen (``HIDDEN``)."""
        return self.called | {fact[0] for fact in self.facts if fact[1] in (
            SITE_UNDER, REFERENCED, BASES, HIDDEN, CALLED_VIRTUAL, INSTANTIATED)}

    @functools.cached_property
    def overloaded(self) -> set[str]:
        return {fact[0] for fact in self.facts if fact[1] == OVERLOADED}

    @functools.cached_property
    def named_classes(self) -> set[str]:
        return {fact[0] for fact in self.facts if fact[1] == NAMED_CLASS}

    @functools.cached_property
    def runs_when_called(self) -> dict[str, str]:
        """USR -> the function's name where its USR does not spell it (a template's)."""
        return {fact[0]: fact[2] for fact in self.facts if fact[1] == RUNS_WHEN_CALLED}

    @functools.cached_property
    def site_under(self) -> dict[str, tuple[Condition, ...]]:
        """Call site -> the source conditions its function makes it under (a
        construction's ``CONDITIONS``, a call's ``SITE_UNDER``), not a loop's or a
        ``try``'s (``NOT_CARRIED``); a site with none is not here."""
        found: dict[str, tuple[Condition, ...]] = {}
        for _usr, index, value, site in self.facts:
            if index not in (CONDITIONS, SITE_UNDER) or not value:
                continue
            place = site.partition("\n")[0] if index == SITE_UNDER else site
            try:
                under = conditions_of_text(value)
            except (ValueError, TypeError, KeyError):
                continue
            kept = tuple(c for c in under if c.kind == "source"
                         and c.statement not in NOT_CARRIED)
            if kept:
                found[place] = tuple(dict.fromkeys((*found.get(place, ()), *kept)))
        return found

    @functools.cached_property
    def within(self) -> dict[str, str]:
        """Call site -> the constructor it is in, which its unit never calls (``WITHIN``)."""
        return {site: caller for _usr, index, caller, site in self.facts if index == WITHIN}

    def idle(self, unseen: Collection[str], naming: bool = False,
             exported_here: Callable[[str], bool] | None = None) -> Callable[[str], bool]:
        """Whether a call site is in code the node never runs: a constructor no file of
        the node calls, of a class its files construct by another one (no loader builds
        it by that one then), where no parse error may hide a call of it and no variable
        outside functions names its class (a plugin's export). f1tenth_simulator's mux:
        ``Channel::Channel() { Channel("", "", -1, nullptr); }``, a default constructor
        nothing calls, passed "" to the constructor that subscribes (mux.cpp:242-251): a
        subscription to the node's own name.

        With ``naming``, for the name a node is given (``resolve_name``): the node
        handed to code the parse does not read (``*``) and a loader's export of the
        class do not keep the site: that code is another package's, which builds no
        class of this one unless it names it (a word of ``unseen``), and a loader builds
        a plugin or component as a node of its own, not this process's (rtabmap_odom's
        OdometryROS, exported as a component and built by rgbd_odometry's main through
        ``RGBDOdometry``, whose base initialiser names the node ``rgbd_odometry``: its
        delegating ``OdometryROS(options) : OdometryROS("odometry", options)`` made
        every rtabmap odometry executable two nodes).

        ``exported_here``: whether a loader's export of a class (by its USR) builds it
        in this node, when that is known (``extract.cpp._exported_here``): a
        component's own class, not another class its files register, which a
        container builds as a node of its own (ouster_ros' OusterDriver is built by
        ``OusterSensor("os_driver", options)``; its files register OusterSensor too,
        whose ``OusterSensor(options) : OusterSensor("os_sensor", options)`` made
        the driver a client of ``os_sensor/change_state``); None: any may be."""
        unbuilt = constructor_unbuilt(self, set(unseen) - {"*"} if naming else unseen)

        def idle(site: str) -> bool:
            caller = self.within.get(site)
            owner = caller.rsplit("@F@", 1)[0] if caller is not None else ""
            return caller is not None and unbuilt(caller) and (
                class_of(caller) in self.constructed) and (
                naming or owner not in self.named_classes or (
                    exported_here is not None and not exported_here(owner)))
        return idle

    @functools.lru_cache(maxsize=4)  # noqa: B019 (one NodeFacts per node, dropped with it)
    def never_run(self, unseen: frozenset[str]) -> frozenset[str]:
        """The functions ``links.never_run`` says never run, for the words ``unseen``
        (no ``*``): those that run only when called, that nothing calls but at sites in
        functions of this set or in constructors that never run (the largest such set:
        functions that call only each other are in it)."""
        sited: dict[str, dict[str, str]] = {}  # function -> call site -> its caller
        for usr, index, _value, site in self.facts:
            if index == SITE_UNDER:
                place, _, rest = site.partition("\n")
                sited.setdefault(usr, {})[place] = rest.partition("\n")[0]
        # used where no site says who calls it: anywhere
        used = {usr for usr, index, _value, site in self.facts
                if index in (REFERENCED, BASES, HIDDEN, CALLED_VIRTUAL, INSTANTIATED) or (
                    index not in NOT_CALLS | INDICES and site not in sited.get(usr, {}))}
        dead = {usr for usr in self.runs_when_called
                if usr not in used and _runs_when_called(self, usr, unseen)}
        idle = functools.lru_cache(maxsize=None)(
            lambda caller: _idle_constructor(self, caller, unseen, sited))
        changed = True
        while changed:
            changed = False
            for usr in list(dead):
                if any(caller != usr and caller not in dead and not idle(caller)
                       for caller in sited.get(usr, {}).values()):
                    dead.discard(usr)
                    changed = True
        return frozenset(dead)

    @functools.cached_property
    def host_callable(self) -> frozenset[str]:
        """The virtual methods a host may call through a base class they override, with
        the one string they take (``HOST_NAMED``), whether the node's code calls them or
        not (``hosted`` keeps those it does not)."""
        return frozenset(usr for usr, index, bases, _site in self.facts
                         if index == HOST_NAMED and bases)

    @functools.cached_property
    def hosted(self) -> dict[tuple[str, int], str]:
        calling = self.called | {fact[0] for fact in self.facts if fact[1] == CALLED_VIRTUAL}
        return {(usr, int(site)): " ".join(dict.fromkeys(
                    qualified_class(base) for base in bases.split("\n") if base))
                for usr, index, bases, site in self.facts
                if index == HOST_NAMED and bases and usr not in calling
                and not any(base in calling for base in bases.split("\n"))}


def resolve(calls: Iterable[PrimitiveCall], facts: Iterable[Fact] | NodeFacts,
            unseen: Collection[str] = ("*",), named: dict[str, str] | None = None,
            hosting: bool = False, exported_here: Callable[[str], bool] | None = None,
            ) -> tuple[list[PrimitiveCall], list[Diagnostic]]:
    """The calls with their placeholders filled from ``facts`` (of the same node). A
    call a constructor makes with a name from its parameters (``made_in``) is left out
    when no file of the node calls that constructor and the class's name is not among
    the words ``unseen`` of the code where the parse left errors (``*``: anywhere); so is
    a call made in a function the node never runs (``called_in``, ``never_run``), unless
    code the node's files do not show may call any of their functions (``hosting``: no
    ``main()`` read, a plugin's class, or a load of code by name into the process,
    ``extract.cpp._runs_any``).

    ``named``: owner -> the node name its constructor writes from its parameters, where
    the node's files pass it several values (``Node(node_name)`` of a class built
    twice, ``LifecycleServiceClient("domain_expert_lc_mngr", ...)`` and
    ``("planner_lc_mngr", ...)``): each call of that owner is made once per
    construction, on the node that construction names, filled with the values of the
    same site (``_expand``); its ``node_name`` then says both (``per_construction``).
    A construction whose name is not known leaves the owner's call as it was."""
    known = facts if isinstance(facts, NodeFacts) else NodeFacts(facts)
    named = named or {}
    out: list[PrimitiveCall] = []
    found: list[Diagnostic] = []
    unbuilt = constructor_unbuilt(known, unseen)
    unrun = never_run(known, unseen)
    idle = known.idle(unseen, exported_here=exported_here)
    host_called = known.host_callable
    overridden: dict[tuple[str, int], set[str]] | None = None
    for call in calls:
        if call.called_in is not None and not hosting and unrun(call.called_in):
            continue  # made in a function the node never runs (``never_run``)
        if call.made_in is not None:
            if not _made(call.made_in, known.called, known.constructed, unseen):
                continue  # no file of the node constructs the class so: not made
            call = dataclasses.replace(call, made_in=None)
        # a parameter named on a handle a caller passes: filled with the values that
        # fill the name, site by site, where the name has placeholders too (move_base's
        # two costmaps each read their own ``observation_sources``)
        raw_param = call.name_param if call.name_param is not None and (
            PLACEHOLDER in call.name_param) else None
        if raw_param is not None:
            call = dataclasses.replace(call, name_param=_parameter_filled(raw_param,
                                                                          known.passed))
        call = _held_filled(call, known.passed)
        # the lists a condition's names hold elements of (``Condition.elements``) read on
        # such a handle: filled as the name is
        lists = sorted({listed for c in call.conditions for _, listed, _ in c.elements or ()
                        if PLACEHOLDER in listed})
        node_text = _site_asked(named.get(call.node_name or ""))
        typed = call.type if call.type is not None and PLACEHOLDER in call.type else None
        # a camera_info call named ``camera_info`` whose image topic a constructor's
        # parameter names: one per construction, as its image call (naoqi_driver2's
        # CameraPublisher, made once per camera)
        camera_raw = call.camera_of if call.camera_of and PLACEHOLDER in call.camera_of and (
            not call.handle_namespace) else None
        if PLACEHOLDER not in call.name and PLACEHOLDER not in (call.handle_namespace or "") \
                and typed is None and camera_raw is None:
            filled_lists = _lists_filled(call, {
                listed: _parameter_filled(listed, known.passed) for listed in lists})
            if node_text is None:
                out.append(filled_lists)
                continue
            out.extend(_on_each_node(filled_lists, _rootless(_expand(
                node_text, known.passed, 0, unbuilt, unrun, idle)), known.within, unbuilt))
            continue
        namespace = call.handle_namespace
        written = call.name
        if namespace:
            prefix = namespace if namespace == "~" or namespace.endswith("/") else (
                namespace + "/")
            # a name that is the namespace itself (``n.subscribe(n.resolveName("command"))``:
            # roscpp's resolved prefix, the visitor's ``names_prefix``) is nothing below it
            written = "" if call.name == namespace else call.name[len(prefix):] if (
                call.name.startswith(prefix)) else call.name
        text = f"{_JOINED.sub(_join_mark, namespace or '')}{_SPLIT}{written}"
        if raw_param is not None:
            text += _PARAM_SPLIT + _param_text(raw_param)
        if lists:
            text += "".join(_LIST_SPLIT + _param_text(listed) for listed in lists)
        if node_text is not None:
            text += _NODE_SPLIT + node_text
        if typed is not None:  # filled from the same construction as the name
            text += _TYPE_SPLIT + typed
        if camera_raw is not None:  # so is the image topic a camera_info call names
            text += _CAMERA_SPLIT + camera_raw
        # a camera's camera_info names its image topic as written on the same handle
        camera = call.camera_of[len(prefix):] if namespace and call.camera_of and (
            call.camera_of.startswith(prefix)) else None
        start = len(out)
        # the sites each value was filled at: a call named at one site exists only under
        # that site's conditions (a class built on ``nh_ttl`` under one ``if``, on
        # ``nh_can`` under another), which the conditions all sites share drop
        chains: dict[str, list[frozenset[str]]] = {}
        for filled in _expand(text, known.passed, 0, unbuilt, unrun, idle, host_called,
                              chains):
            under = _chain_conditions(chains.get(filled, [frozenset()]), known.site_under)
            filled, _, camera_filled = filled.partition(_CAMERA_SPLIT)
            filled, _, type_filled = filled.partition(_TYPE_SPLIT)
            filled, _, node_filled = filled.partition(_NODE_SPLIT)
            filled, *lists_text = filled.split(_LIST_SPLIT)
            filled, _, param_text = filled.partition(_PARAM_SPLIT)
            ns, _, name = filled.partition(_SPLIT)
            root = ROOT_MARK in ns
            # the handles the namespace was filled from, by where they were made: one
            # origin, else none known; none passed: the call's own
            origins = {o for o, mark in ORIGIN_MARKS.items() if mark in ns}
            origin = call.handle_origin if not origins else (
                origins.pop() if len(origins) == 1 else None)
            built = _built(name)
            ns, name = _plain(ns), _plain(name)
            node_filled = _plain(node_filled)
            param_text = _plain(param_text)
            lists_text = [_plain(text) for text in lists_text]
            type_filled = _plain(type_filled)
            camera_filled = _plain(camera_filled)
            # (a parameter's mark in the namespace names the call, as one in the name
            # does: costmap_2d's ``ros::NodeHandle target_layer(nh, plugin_name)``)
            ns = _rejoined(ns) if ns else ""
            marked = normalise(ns) if ns else ""
            ns = normalise(_unmarked(ns)) if ns else ""
            if name.startswith("~/"):  # written as the visitor writes a private name
                name = "~" + name[2:]
            if built is not None and built.startswith("~/"):
                built = "~" + built[2:]
            made = dataclasses.replace(
                call, name=(join_name(marked, name) if name else marked) if ns else name,
                name_built=None if built is None else join_name(marked, built) if ns
                else built,
                root_handle=call.root_handle or (root and not name.startswith(("/", "~"))),
                handle_origin=origin,
                handle_namespace=ns if ns and not name.startswith(("/", "~")) else None,
                camera_of=call.camera_of if call.camera_of is None or (
                    PLACEHOLDER not in call.camera_of) else (
                    join_name(ns, _unmarked(camera)) if camera and PLACEHOLDER not in camera
                    else None))
            if typed is not None:
                made = dataclasses.replace(made, type=type_filled if type_filled and (
                    PLACEHOLDER not in type_filled) else "?")
            if camera_raw is not None:
                made = dataclasses.replace(made, camera_of=_unmarked(camera_filled) if (
                    camera_filled and PLACEHOLDER not in camera_filled) else None)
            if param_text:
                filled_param = _param_joined(param_text)
                if filled_param and PLACEHOLDER not in filled_param:
                    made = dataclasses.replace(made, name_param=filled_param)
            made = _named_by(_lists_filled(made, dict(zip(lists, map(
                _param_joined, lists_text), strict=False))))
            whole = _MARK.fullmatch(written) if not namespace else None
            classes = known.hosted.get((whole.group(1), int(whole.group(2)))) if (
                whole) else None
            if made.name == "?" and classes:
                made = dataclasses.replace(made, host_named=classes)
            if namespace and (ns == "?" or ns.startswith("?/")) and (
                    made.name == ns or made.name.startswith(ns + "/")):
                # the namespace of a plugin's entry handle, which its host's call gives
                if overridden is None:
                    overridden = _overridden(known)
                host = _host_handle(namespace, known, overridden)
                if host is not None:
                    made = dataclasses.replace(made, host_handle=host)
            if made.struct_member and made.name.startswith(("?", "~?")):
                continue  # what was handed is no parameter's value: nothing read
            if under:
                made = dataclasses.replace(made, conditions=(
                    *(c for c in under if c not in made.conditions), *made.conditions))
            if node_text is not None:
                made = _on_each_node(made, [node_filled], known.within, unbuilt, call)[0]
            out.append(made)
            if "?" in made.name:
                members = _fields_marked(written)
                found.append(diag.make(
                    "CPP_NAME_MEMBER_ELSEWHERE", made.location, kind=made.kind,
                    name=made.name, member=", ".join(members)) if members else diag.make(
                    "CPP_DYNAMIC_NAME", made.location, kind=made.kind, name=made.name))
        _origins_agreed(out, start)
    return out, found


def _origins_agreed(calls: list[PrimitiveCall], start: int) -> None:
    """Of the calls one call made from ``start`` on (one per site that fills it), those
    alike but for the origin of their handles (``handle_origin``: a class built on a
    nodelet's handle in one file, on one the code makes in another) have none known:
    one call of a node is not made on two handles."""
    for index in range(start, len(calls)):
        call = calls[index]
        if call.handle_origin is None:
            continue
        bare = dataclasses.replace(call, handle_origin=None)
        if any(other.handle_origin != call.handle_origin
               and dataclasses.replace(other, handle_origin=None) == bare
               for other in calls[start:]):
            calls[index] = bare


def _fields_marked(text: str) -> list[str]:
    """``Class::member`` for each member placeholder in ``text`` (``CallSites.
    member_elsewhere``): a member whose class's constructors are in files of the node
    that give it no value this run can tell."""
    return [f"{class_of(usr) or '?'}::{usr.rsplit('@FI@', 1)[1]}"
            for usr in sorted(marked_usrs(text)) if "@FI@" in usr]


_PARAM_SPLIT = "\x0e"  # before the name parameter expanded with a call's name
_NODE_SPLIT = "\x11"  # before the node name expanded with a call's name (``resolve``)
_TYPE_SPLIT = "\x15"  # before the type expanded with a call's name (``TYPE_ARGUMENT``)
_CAMERA_SPLIT = "\x16"  # before the image topic a camera_info call names (``camera_of``)
# around a function's USR: ``_expand`` writes the call site whose values it takes for that
# function's placeholders in its stead (after ``_SITE_AT``)
_SITE_OF = "\x13"
_SITE_AT = "\x14"
# between a call's owner and the node one construction of it names (``resolve``)
NODE_OF = "\x12"


def per_construction(owner: str | None) -> tuple[str | None, str | None]:
    """A call's ``node_name`` as ``resolve`` leaves it: its owner, and the node that
    the construction it was made for names (None: not told per construction)."""
    if owner is None or NODE_OF not in owner:
        return owner, None
    owner, _, node = owner.partition(NODE_OF)
    return owner, node


def _site_asked(text: str | None) -> str | None:
    """A node name with placeholders, asking ``_expand`` for the site of the constructor
    they name (``_SITE_OF``)."""
    if text is None:
        return None
    found = _MARK.search(text)
    return text if found is None else f"{text}{_SITE_OF}{found.group(1)}{_SITE_OF}"


def _on_each_node(call: PrimitiveCall, names: list[str], within: dict[str, str],
                  unbuilt: Callable[[str], bool], whole: PrimitiveCall | None = None
                  ) -> list[PrimitiveCall]:
    """``call`` once per node name (``resolve``'s ``named``), each fully known one
    written into its ``node_name``; one not known leaves the call's owner alone. A
    construction in a constructor the node never runs (``within``, ``unbuilt``: a
    subclass no file builds, topic_tools' Mux beside the Relay main makes) makes none;
    when no construction is left, the call as it was (``whole``, else ``call``)."""
    out: list[PrimitiveCall] = []
    for filled in names:
        filled, _, site = filled.partition(_SITE_AT)
        site = site.rstrip(_SITE_OF)
        if _SITE_OF in filled:  # no site filled it: not asked of any
            filled = filled.split(_SITE_OF, 1)[0]
        caller = within.get(site) if site else None
        if caller is not None and unbuilt(caller):
            continue
        name = node_name_joined(_unmarked(filled)) if PLACEHOLDER not in filled else "?"
        made = call if not name or "?" in name else dataclasses.replace(
            call, node_name=f"{call.node_name}{NODE_OF}{name}")
        if made not in out:
            out.append(made)
    return out or [call if whole is None else dataclasses.replace(call, node_name=whole.node_name)]
_LIST_SPLIT = "\x10"  # before each list of its conditions' elements expanded with it


def _held_filled(call: PrimitiveCall, passed: dict[str, dict[str, dict[int, str]]]
                 ) -> PrimitiveCall:
    """``call`` with the parameters its conditions' names hold (``Condition.parameters``)
    read on a handle a caller in another file passes named as that handle makes them
    (``_parameter_filled``: teleop_twist_joy's ``if (pimpl_->is_3D)``, read on the
    private handle its node file passes); one still not known is dropped (its condition
    stays undecided)."""
    if not any(PLACEHOLDER in param for c in call.conditions for _, param in (
            c.parameters or ())):
        return call
    conditions = []
    for condition in call.conditions:
        held = tuple((name, _parameter_filled(param, passed) if PLACEHOLDER in param
                      else param) for name, param in condition.parameters or ())
        kept = tuple(h for h in held if PLACEHOLDER not in h[1] and "?" not in h[1])
        conditions.append(condition if held == condition.parameters else (
            dataclasses.replace(condition, parameters=kept or None)))
    return dataclasses.replace(call, conditions=tuple(conditions))


def _lists_filled(call: PrimitiveCall, filled: dict[str, str]) -> PrimitiveCall:
    """``call`` with the lists of its conditions' elements (``Condition.elements``)
    named as ``filled`` gives them; an element of a list still not known is dropped
    (its condition stays undecided)."""
    if not filled:
        return call
    conditions = []
    for condition in call.conditions:
        elements = tuple((name, filled.get(listed, listed), field)
                         for name, listed, field in condition.elements or ())
        kept = tuple(e for e in elements if PLACEHOLDER not in e[1] and "?" not in e[1])
        conditions.append(condition if elements == condition.elements else (
            dataclasses.replace(condition, elements=kept or None)))
    return dataclasses.replace(call, conditions=tuple(conditions))


# a handle's namespace joined to the namespace a placeholder stands for (``NodeHandle
# nh1(nh, "stereo")`` with ``nh`` a parameter another file passes): the placeholder, the
# ``/`` of the join (``handles.join_name``), and ``_JOIN`` in its place until it is filled,
# then joined as ``join_name`` does: the public handle's ``""`` gives ``stereo``, not
# the global ``/stereo``
_JOINED = re.compile(f"({_MARK.pattern})/")
_JOIN = "\x0f"


def _join_mark(found: re.Match[str]) -> str:
    return found.group(1) + _JOIN


def _rejoined(namespace: str) -> str:
    """``namespace`` with each ``_JOIN`` a join of what precedes it and what follows."""
    first, *rest = namespace.split(_JOIN)
    for part in rest:
        first = join_name(first, part) if first else part
    return first


def _param_text(param: str) -> str:
    """A ``name_param`` whose namespace is a placeholder, split after it for
    ``_param_joined``; one that a placeholder starts with no ``/`` after it (a string
    member's text, ``Layer::name_`` then ``.observation_sources``) is one text."""
    mark = _MARK.match(param)
    rest = param[mark.end():] if mark else ""
    if mark is None or (rest and not rest.startswith("/")):
        return param
    return f"{param[:mark.end()]}{_SPLIT}{rest.lstrip('/')}"


def placeholder_namespace(name: str) -> str | None:
    """The placeholder ``name`` starts with when a ``/`` follows it: the namespace of a
    handle a caller passes, joined to the rest as ``join_name`` does before it is known
    (the parameter a class load reads, ``_param_text``'s split); else None."""
    mark = _MARK.match(name)
    return name[:mark.end()] if mark is not None and (
        name[mark.end():].startswith("/")) else None


def _param_joined(filled: str) -> str:
    """A ``_param_text`` with its placeholders filled: the namespace joined to the name."""
    ns, _, name = filled.partition(_SPLIT)
    ns = normalise(_unmarked(ns)) if ns else ""
    return join_name(ns, name) if ns and name else ns or name


def _parameter_filled(param: str, passed: dict[str, dict[str, dict[int, str]]]) -> str:
    """The parameter that names a call (``name_param``) read on a handle a caller in
    another file passes (its namespace a placeholder, then ``/name``): that handle's
    namespace joined to the name, as the read's own name is (``~costmap_topic``); ``?``
    in its place when the callers pass several handles or none (``~?/plan_topic`` of a
    plugin's ``initialize(name)``, which its host names)."""
    found = {_param_joined(filled)
             for filled in _rootless(_expand(_param_text(param), passed, 0))}
    value = found.pop() if len(found) == 1 else ""
    if value and PLACEHOLDER not in value:
        return value
    return _unmarked(choose(_MARK.sub("?", param)))


# a translation unit's node names made in constructors no call in that unit makes:
# ``<constructor USR>UNBUILT<name>``, several joined by UNBUILT_NAMES (``node_rosnames``)
UNBUILT = "\x03"
UNBUILT_NAMES = "\x04"


def unbuilt_name(constructor: str, name: str) -> str:
    return f"{constructor}{UNBUILT}{name}"


def is_unbuilt_name(name: str) -> bool:
    return UNBUILT in name


def node_rosnames(names: Iterable[str | None], facts: NodeFacts,
                  unseen: Collection[str] = ("*",)) -> list[str]:
    """The names the node's units give it (in file order), as the constructions the node
    makes give them (the node's name: the one they agree on, else ``?``; units that
    tell apart may see only a node class the process never makes, a header's
    ``UsbCameraInterfaceNode`` beside the behaviour another file builds). A name made
    in a constructor (``unbuilt_name``) counts when a file of the node calls that
    constructor; failing any such, when errors could hide the call (``_made``).
    aerostack2's ``as2::Node`` has a ``(name, ns, options)`` and a ``(name, options)``
    constructor, and a subclass calls only the second. None made so: the first name."""
    candidates = [each.rpartition(UNBUILT) for written in names if written is not None
                  for each in written.split(UNBUILT_NAMES)]
    if not candidates:
        return []
    unbuilt = constructor_unbuilt(facts, unseen)
    made = [resolve_name(name, facts, unseen) for usr, marked, name in candidates
            if (not marked or usr in facts.called) and not _named_unbuilt(name, unbuilt)]
    if not made:
        made = [resolve_name(name, facts, unseen) for usr, _, name in candidates
                if _made(usr, facts.called, facts.constructed, unseen)]
    return made or [resolve_name(candidates[0][2], facts, unseen)]


def _named_unbuilt(name: str, unbuilt: Callable[[str], bool]) -> bool:
    """Whether a unit's name for its node is a parameter of a constructor no file of the
    node calls and no error hides (a header's delegating ``LifecycleNode(name, options) :
    LifecycleNode(name, "", options)``, as a unit that has not the subclass's constructor
    sees it): that constructor makes no node, so it names none."""
    marked = constructor_marked(name)
    return marked is not None and unbuilt(marked)


def constructor_unbuilt(known: NodeFacts, unseen: Collection[str]) -> Callable[[str], bool]:
    """Whether a USR is a constructor no file of the node calls, whose class no error may
    hide (``_expand``)."""
    def unbuilt(usr: str) -> bool:
        return is_constructor_usr(usr) and usr not in known.called and "*" not in unseen and (
            class_of(usr) not in unseen)
    return unbuilt


def construction_unseen(unseen: Collection[str]) -> Callable[[str], bool]:
    """Whether a USR is a constructor whose class the errors the parse left may construct
    unseen (its name among their words ``unseen``; any, ``*``)."""
    def hidden(usr: str) -> bool:
        return is_constructor_usr(usr) and ("*" in unseen or class_of(usr) in unseen)
    return hidden


def never_run(known: NodeFacts, unseen: Collection[str]) -> Callable[[str], bool]:
    """Whether a USR is a function whose code runs only when called or used
    (``call_conditions.RUNS_WHEN_CALLED``: a free function, a non-virtual method) that no
    file of the node calls, uses otherwise (``&f``, a callback, a name a template's
    dependent call, an overloaded ``&f`` or Qt's ``SLOT(f())`` may mean) or may call
    where the parse left errors, nor a method of a class a variable outside functions
    names (a plugin's export); or, at any depth, one whose every call site is in such a
    function or in a constructor that never runs (``_idle_constructor``). Its calls are
    never made (Fast-Planner's plan_env library, which fast_planner_node links, defines
    ``ObjPredictor::init()``, subscribing to ``/dynamic/pose_<i>``; nothing in the node
    calls it, nor constructs an ObjPredictor), nor is a value taken from one of its
    parameters (msckf_vio's ``getTransformEigen(nh, field)``, in utils.cpp that the image
    processor compiles and never calls, passes ``field`` on to the ``getTransformCV`` it
    does call). Nothing is when the parse may hide a call anywhere (``*``)."""
    if "*" in unseen:
        return lambda usr: False
    return known.never_run(frozenset(unseen)).__contains__


def _runs_when_called(known: NodeFacts, usr: str, unseen: Collection[str]) -> bool:
    """Whether ``usr`` runs only where the node's code calls or names it (``never_run``'s
    first test, before its calls and uses are looked at)."""
    if usr not in known.runs_when_called:
        return False
    if "@F@" in usr and usr.rsplit("@F@", 1)[0] in known.named_classes:
        return False  # a method of a class exported as a plugin, or a global's
    names = _FUNCTION.findall(usr) or [
        name for name in (known.runs_when_called[usr],) if name]
    return bool(names) and names[-1] not in known.overloaded and names[-1] not in unseen and (
        names[-1] not in _UNWRITTEN)


# the functions C++ calls where no call is written: a range-based ``for`` over an object
# calls its ``begin()`` and ``end()``
_UNWRITTEN = frozenset({"begin", "end"})


def _idle_constructor(known: NodeFacts, usr: str, unseen: Collection[str],
                      sited: Collection[str]) -> bool:
    """Whether ``usr`` is a constructor that never runs, for the functions it calls
    (``never_run``): no file of the node calls it (``constructor_unbuilt``, no site of it
    either), nor may a loader or C++ unwritten (it takes arguments and is no copy or
    move: C++ calls a default or copy constructor where no code writes the call), nor
    a library's template given the class (BehaviorTree.CPP's ``registerNodeType<C>``
    builds ``C(name, config)``, ``emplace_back(args)`` builds an element): the node's
    files build the class by another constructor; it is no class template's, and its
    class no plugin's export."""
    if not is_constructor_usr(usr) or usr in sited or "@ST>" in usr or "@SP>" in usr or (
            class_of(usr) not in known.constructed) or not constructor_unbuilt(
            known, unseen)(usr):
        return False
    cls, _, function = usr.rpartition("@F@")
    if cls in known.named_classes:
        return False
    params = function.partition("#")[2]
    # (a copy's or move's one parameter: ``&1$@N@p@S@C#``, ``&&$@N@p@S@C#``)
    return bool(params) and re.fullmatch(
        r"&{1,2}\d*\$" + re.escape(cls.removeprefix("c:")) + "#?", params) is None


def resolve_name(name: str, facts: Iterable[Fact] | NodeFacts,
                 unseen: Collection[str] = ("*",)) -> str:
    """A node name (``Node(name)`` in a constructor) with its placeholders filled: the
    one value the node's files pass, else ``?`` where they pass none or several. A value
    passed on from a parameter of a constructor that no file of the node calls gives
    nothing (a header's delegating ``Router(name) : Router(NodeOptions(), name)`` beside
    the ``Router(options, "mavros_router")`` that mavros_node builds); nor does a value
    passed in code the node never runs (``NodeFacts.idle``), unless every site is:
    rtabmap_odom's delegating ``OdometryROS(options) : OdometryROS("odometry", options)``
    beside the ``OdometryROS("rgbd_odometry", options)`` of the RGBDOdometry main builds."""
    if PLACEHOLDER not in name:
        return name
    known = facts if isinstance(facts, NodeFacts) else NodeFacts(facts)
    found = _rootless(_expand(name, known.passed, 0, constructor_unbuilt(known, unseen),
                              idle=known.idle(unseen, naming=True)))
    if len(found) == 1 and PLACEHOLDER not in found[0]:
        return node_name_joined(_unmarked(found[0]))
    return choose(_MARK.sub("?", name))


def handles_given(facts: NodeFacts, unseen: Collection[str] = ("*",),
                  ) -> dict[str, list[str]]:
    """``Node.handles_given``: what the node's code passes at each parameter of a virtual
    method it calls through its class (``VIRTUAL_CALL``: a host's ``plugin->initialize(
    nh_, nhp_, ...)``), as ``<method USR>#<index>`` -> the values, filled from the node's
    files as a call's namespace is (``?`` where they give none: a member of a class no
    file builds). Strings come along too; a plugin reads only a handle's
    (``PrimitiveCall.host_handle``)."""
    virtual = {(usr, site) for usr, index, _value, site in facts.facts
               if index == VIRTUAL_CALL}
    if not virtual:
        return {}
    unbuilt = constructor_unbuilt(facts, unseen)
    unrun = never_run(facts, unseen)
    out: dict[str, list[str]] = {}
    for usr, index, value, site in facts.facts:
        if index < 0 or index >= TYPE_ARGUMENT or (usr, site) not in virtual:
            continue
        text = _JOINED.sub(_join_mark, value) + _SPLIT
        for filled in _expand(text, facts.passed, 0, unbuilt, unrun):
            namespace = _plain(filled.partition(_SPLIT)[0])
            namespace = normalise(_unmarked(_rejoined(namespace))) if namespace else ""
            if PLACEHOLDER in namespace:
                namespace = "?"
            values = out.setdefault(f"{usr}#{index}", [])
            if namespace not in values:
                values.append(namespace)
    return out


def _overridden(facts: NodeFacts) -> dict[tuple[str, int], set[str]]:
    """(virtual method USR, handle parameter's index) -> the USRs of the methods it
    overrides, directly or through others (``OVERRIDES``)."""
    direct: dict[tuple[str, int], set[str]] = {}
    for usr, index, base, parameter in facts.facts:
        if index == OVERRIDES and base and parameter.isdigit():
            direct.setdefault((usr, int(parameter)), set()).add(base)
    out: dict[tuple[str, int], set[str]] = {}
    for key in direct:
        found: set[str] = set()
        todo = list(direct[key])
        while todo:
            base = todo.pop()
            if base not in found:
                found.add(base)
                todo.extend(direct.get((base, key[1]), ()))
        out[key] = found
    return out


def _host_handle(namespace: str, facts: NodeFacts,
                 overridden: dict[tuple[str, int], set[str]]) -> str | None:
    """``PrimitiveCall.host_handle`` of a call whose handle namespace, as written
    (``namespace``), begins with a function's handle parameter: followed through the
    sites that pass each such parameter on, the one parameter of an override that no
    file of the node passes (a plugin's ``initialize(nh, ...)``, which its host calls
    through a base class), as ``<base USR>#<index>`` of each method it overrides; None
    when any site passes something else, or the chain ends elsewhere."""
    match = _MARK.match(_plain(namespace))
    seen: set[tuple[str, int]] = set()
    while match is not None:
        key = (match.group(1), int(match.group(2)))
        if key in seen or len(seen) > MAX_DEPTH:
            return None
        seen.add(key)
        values = {values[key[1]] for values in facts.passed.get(key[0], {}).values()
                  if key[1] in values}
        if not values:
            # the method itself too: a host calling it through its own class (a base's
            # ``initialize`` the plugin does not override)
            bases = overridden.get(key, set()) | {key[0]}
            return " ".join(sorted(f"{base}#{key[1]}" for base in bases))
        if len(values) != 1:
            return None
        match = _MARK.match(_plain(values.pop()))
    return None


def qualified_class(usr: str) -> str:
    """The qualified name of the class of a method's USR (``nav2_core::Behavior``)."""
    parts = usr.split("@F@")[0].split("@")[1:]
    names = [name for kind, name in zip(parts[::2], parts[1::2], strict=False)
             if kind == "N" or kind.startswith("S")]
    return "::".join(names)


_CLASS = re.compile(r"@(?:S|ST>\d+(?:#[^@]*)?)@([A-Za-z_]\w*)@F")
_FUNCTION = re.compile(r"@F@([A-Za-z_]\w*)")


def class_of(usr: str) -> str | None:
    """The name of the class of a constructor's (or method's) USR."""
    found = _CLASS.findall(usr)
    return found[-1] if found else None


def constructor_marked(text: str) -> str | None:
    """The first constructor (of a class, not a class template: a template's
    constructions name its specialisations) a placeholder in ``text`` names."""
    for found in _MARK.finditer(text):
        usr = found.group(1)
        if is_constructor_usr(usr) and "@ST>" not in usr and "@SP>" not in usr:
            return usr
    return None


def is_constructor_usr(usr: str) -> bool:
    """Whether a USR is a constructor's (its function named as its class)."""
    cls, function = class_of(usr), _FUNCTION.findall(usr)
    return cls is not None and bool(function) and function[-1] == cls


def _passed(facts: Iterable[Fact]) -> dict[str, dict[str, dict[int, str]]]:
    """USR -> call site -> parameter index -> the value passed there."""
    passed: dict[str, dict[str, dict[int, str]]] = {}
    facts = list(facts)
    for usr, index, value, site in facts:
        if index >= 0:
            passed.setdefault(usr, {}).setdefault(site, {})[index] = value
        elif index == MEMBER:  # a member's value where its constructors are
            passed.setdefault(usr, {}).setdefault(site, {})[0] = value
    assigned: dict[str, dict[str, dict[int, str]]] = {}
    for usr, index, value, site in facts:
        if index == ASSIGNED:  # written through an object: not the constructors' value
            assigned.setdefault(usr, {})[site] = {0: value}
    passed.update(assigned)
    qualified = {(usr, site) for usr, index, _value, site in facts if index == QUALIFIED}
    for usr, index, base, parameter in facts:
        if index == OVERRIDES and base in passed and parameter.isdigit():
            # the calls of the base method: sites of the override too, for that
            # parameter (a site that passes the override's own placeholder back, a
            # recursive group of analyzers, is a chain of any length: ``_expand``), but
            # a call that names the base method's class, which runs that one alone
            mine = passed.setdefault(usr, {})
            for site, values in passed[base].items():
                if int(parameter) in values and (base, site) not in qualified:
                    mine.setdefault(site, {})[int(parameter)] = values[int(parameter)]
    literal = {(usr, site, value) for usr, index, value, site in facts if index == LITERAL}
    for usr, index, base, parameter in facts:
        if index == STRING_OVERRIDES and base in passed and parameter.isdigit():
            mine = passed.setdefault(usr, {})
            for site, values in list(passed[base].items()):
                if int(parameter) in values:  # another value, a member's, is unknown
                    mine.setdefault(site, {})[int(parameter)] = values[int(parameter)] if (
                        base, site, parameter) in literal else "?"
    return passed


def marked_usrs(text: str) -> set[str]:
    """The functions whose placeholders ``text`` holds."""
    return {found.group(1) for found in _MARK.finditer(text)} if PLACEHOLDER in text else set()


def _expand(text: str, passed: dict[str, dict[str, dict[int, str]]],
            depth: int, unbuilt: Callable[[str], bool] | None = None,
            unrun: Callable[[str], bool] | None = None,
            idle: Callable[[str], bool] | None = None,
            hosted: Collection[str] = (),
            chains: dict[str, list[frozenset[str]]] | None = None) -> list[str]:
    """``text`` with its placeholders filled: the placeholders of one function take the
    values of the same call site together (``attach(n, "left")``, ``attach(base,
    "right")`` never give ``base/left``). A value that a caller takes from a parameter of
    a constructor that ``unbuilt`` says the node never runs gives nothing: that caller
    never runs either (vesc_ackermann's ``getRequiredParam(nh, ...)`` in the constructor
    of a class the nodelet does not build); nor does one of a function ``unrun`` says
    nothing in the node calls or uses (``never_run``), at any depth: the call itself, or
    the value a caller passes on, is never made; nor does a call site ``idle`` says is
    in code the node never runs (``NodeFacts.idle``), unless every site is. A virtual
    method of ``hosted`` (one a host may call through a base class it overrides,
    ``NodeFacts.host_callable``) whose calls in the node give nothing is the host's to
    call, with a value not known here: navfn's plugin ``NavfnROS::initialize(name,
    costmap_ros)``, called in its own file only by a constructor the host never runs,
    hands its ``name`` to the overload that makes every call (``~<name>/plan``).

    ``chains``, when given, gets for each value the call sites each way of filling it
    went through (one set per way): the call so named exists only where they all run."""
    match = _MARK.search(text)
    if match is None:
        value = choose(text)
        if chains is not None:
            chains.setdefault(value, []).append(frozenset())
        return [value]
    usr = match.group(1)
    items = list(passed.get(usr, {}).items()) if depth < MAX_DEPTH else []
    if idle is not None and len(items) > 1:
        running = [(site, values) for site, values in items if not idle(site)]
        items = running or items
    sites = [values for _, values in items]
    if depth and not sites and unbuilt is not None and unbuilt(usr):
        return []
    if not sites and depth < MAX_DEPTH and unrun is not None and unrun(usr):
        return []
    out = _at_sites(text, usr, items or [("", {})], passed, depth, unbuilt, unrun, idle,
                    hosted, chains)
    if not out and items and usr in hosted and depth < MAX_DEPTH:
        out = _at_sites(text, usr, [("", {})], passed, depth, unbuilt, unrun, idle, hosted,
                        chains)
    return out


def _rootless(texts: list[str]) -> list[str]:
    """``_expand``'s values without the marks of a handle's root or origin
    (``ROOT_MARK``, ``ORIGIN_MARKS``), for what is no call's namespace."""
    return [_plain(text) for text in texts]


def _at_sites(text: str, usr: str, items: list[tuple[str, dict[int, str]]],
              passed: dict[str, dict[str, dict[int, str]]], depth: int,
              unbuilt: Callable[[str], bool] | None, unrun: Callable[[str], bool] | None,
              idle: Callable[[str], bool] | None, hosted: Collection[str],
              chains: dict[str, list[frozenset[str]]] | None = None) -> list[str]:
    """``_expand``'s values of ``text`` with ``usr``'s placeholders filled at each of
    the call sites ``items`` (site, values by parameter index), then the rest; the
    sites each value went through to ``chains``, when given."""
    out: list[str] = []
    mark = f"{_SITE_OF}{usr}{_SITE_OF}"  # the site of this function's call, asked for
    for site, values in items:
        here = text.replace(mark, f"{_SITE_AT}{site}{_SITE_OF}") if mark in text else text
        def fill(found: re.Match[str], values: dict[int, str] = values) -> str:
            if found.group(1) != usr:
                return found.group(0)
            value = values.get(int(found.group(2)), "?")
            # a value that holds the function's own placeholder (a call it makes of
            # itself, directly or through a base method) stands for a chain of any
            # length: unknown (it expanded until MAX_VALUES made every value unknown)
            return "?" if usr in marked_usrs(value) else value
        inner: dict[str, list[frozenset[str]]] | None = {} if chains is not None else None
        for filled in _expand(_MARK.sub(fill, here), passed, depth + 1, unbuilt, unrun,
                              idle, hosted, inner):
            if filled not in out:
                out.append(filled)
            if chains is not None and inner is not None:
                chains.setdefault(filled, []).extend(
                    chain | {site} if site else chain
                    for chain in inner.get(filled, [frozenset()]))
            if len(out) > MAX_VALUES:  # no more work: the values of placeholders
                # multiplied (``a + b`` of two functions of many callers each) end here
                value = choose(_MARK.sub("?", text))
                if chains is not None:
                    chains.clear()
                    chains[value] = [frozenset()]
                return [value]
    return out


def _chain_conditions(chains: list[frozenset[str]],
                      site_under: dict[str, tuple[Condition, ...]]) -> tuple[Condition, ...]:
    """The conditions a call filled by each of ``chains`` (the call sites of one way of
    filling it) exists under: those of every site of a way, shared by all the ways."""
    shared: tuple[Condition, ...] | None = None
    for chain in chains:
        held = tuple(dict.fromkeys(c for site in sorted(chain)
                                   for c in site_under.get(site, ())))
        shared = held if shared is None else tuple(c for c in shared if c in held)
        if not shared:
            return ()
    return shared or ()


def _of_class_template(function: Cursor) -> bool:
    """Whether ``function`` is a constructor or method of a class template."""
    parent = function.semantic_parent
    return function.kind in (CursorKind.CONSTRUCTOR, CursorKind.CXX_METHOD) and (
        parent is not None and parent.kind == CursorKind.CLASS_TEMPLATE)
