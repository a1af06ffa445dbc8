"""The conditions a function's calls carry from the places that call it.

A function of the node's files (a free function or a method, not a constructor, which
``visitor.CallFinder._constructed_under`` and ``_built_under`` cover) runs only where
something calls it: when every call site in the node's files shares a source condition
(motoman's ``JointTrajectoryInterface::init(connection)`` calls the single-group
``init(connection, joint_names)`` only in the ``else`` of ``if (getJointGroups(...))``),
the calls the function makes exist only under it. Each translation unit says, as facts
(``links.Fact``), where it calls such functions and under what conditions
(``SITE_UNDER``), which it uses otherwise than by a call (``REFERENCED``: a callback, a
function pointer, a virtual method a class we do not read may call) and which base
methods a virtual method overrides (``BASES``: a call of one may run it); the node's
result joins them (``shared``). A function no file calls, or called from one place with
no condition, gives none."""

from __future__ import annotations

import json
import os
import re
from collections.abc import Callable, Collection, Iterable

from clang.cindex import Cursor, CursorKind, SourceLocation, conf

from ...model.conditions import EACH_STATEMENT, Condition
from .cache import conditions_of_text, conditions_text
from .call_sites import CallSites, callee_of
from .conditions import ConditionReader
from .cursors import children_in

Fact = tuple[str, int, str, str]
# the index of a fact: the site (``file:offset``, a newline, the USR of the function
# that holds the call) calls the function under the source conditions of the value
SITE_UNDER = -6
# the function is used otherwise than called (its address taken, a virtual method of a
# class the node's files do not define): it may run anywhere
REFERENCED = -7
# the function is a virtual method overriding the methods whose USRs the value holds,
# one per line: a call of one of those may run it
BASES = -8
# the unit declares the function and the parse left errors in code that names it: a
# call of it may be hidden there
HIDDEN = -9
# the function (of the workspace's files, a free function or a non-virtual method that
# ``eligible`` takes, no ``main``: ``runs_when_called``) holds a string or handle
# parameter the unit made a placeholder of, or one of the unit's ROS calls: its code runs
# only where the node's files call or use it (``links.never_run``)
RUNS_WHEN_CALLED = -12
# the fact's USR is a name the unit's code writes where clang keeps only the overloads
# it may be (``OVERLOADED_DECL_REF``: a call in a template that depends on its parameters,
# ``&f`` of an overloaded ``f``) or a member reference whose object's type depends on a
# template parameter (``obj.f(x)``): any function of that name may run there
OVERLOADED = -13
# the fact's USR is a class a variable outside functions names (a plugin's or a
# component's export, ``PLUGINLIB_EXPORT_CLASS(C, Base)``; a global object): a loader or
# any code may run its methods
NAMED_CLASS = -14
# the fact's USR is a function template a specialisation of which the unit calls or
# names (``getParameter<int>(...)``): its code runs where that one does (a call's facts
# say the specialisation, ``SITE_UNDER``, ``REFERENCED``)
INSTANTIATED = -19
INDICES = frozenset({SITE_UNDER, REFERENCED, BASES, HIDDEN, RUNS_WHEN_CALLED, OVERLOADED,
                     NAMED_CLASS, INSTANTIATED})
_CLASSES = frozenset({CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL,
                      CursorKind.CLASS_TEMPLATE})
_CONTAINERS = frozenset({
    CursorKind.NAMESPACE, CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL,
    CursorKind.LINKAGE_SPEC, CursorKind.UNEXPOSED_DECL,
})
_KINDS = frozenset({CursorKind.FUNCTION_DECL, CursorKind.CXX_METHOD})
_REFERENCES = frozenset({CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR})
_NAMES = _REFERENCES | {CursorKind.OVERLOADED_DECL_REF}  # what ``site_facts`` reads
MAX_DEPTH = 8
# the conditions of a site not carried: a loop's (a call named by each element of a
# list the loop walks is made once per element, the loop no condition of it: navigation2's
# collision monitor configures a Polygon per name of ``polygon_names``) and a ``try``
# block's (its body runs unless something fails)
NOT_CARRIED = frozenset({"for", "while", "do", EACH_STATEMENT, "try"})
VIRTUAL = "\x01"  # marks a call that may dispatch to an override, while sites are read


def eligible(function: Cursor) -> bool:
    """Whether the calls ``function`` makes can take its call sites' conditions: a
    free function or method that is no template nor a class template's member, no
    operator (library code calls those: ``std::for_each`` a functor's ``operator()``)."""
    if function.kind not in _KINDS or function.spelling.startswith("operator"):
        return False
    parent = function.semantic_parent
    return parent is None or parent.kind not in (
        CursorKind.CLASS_TEMPLATE, CursorKind.CLASS_TEMPLATE_PARTIAL_SPECIALIZATION)


def site_facts(functions: list[Cursor], sites: CallSites, reader: ConditionReader,
               owned: Callable[[str], bool], enter: Callable[[Cursor], None],
               walked: Callable[[Cursor], tuple[list[Cursor], list[Cursor]] | None]
               = lambda function: None, variables: Iterable[Cursor] = (),
               declared: str | None = None, holding: Iterable[Cursor] = (),
               source_of: Callable[[str], bytes | None] | None = None) -> list[Fact]:
    """The unit's facts (``SITE_UNDER``, ``REFERENCED``, ``BASES``) over the eligible
    functions of the workspace's files it calls or defines; ``enter`` readies
    ``reader`` for a function's body; ``walked`` gives a function's calls (among other
    nodes) and its references to declarations, each in preorder, when a walk of the
    unit kept them (else its nodes are walked here); ``variables``, the unit's variables
    outside functions, use each function they name (a call there runs before ``main``,
    a function's address in a table runs anywhere: ``REFERENCED``); ``declared``, the
    header of the names the unit declared permissively (a base class there may hide a
    virtual method its subclass's method overrides); ``holding``, the functions whose
    bodies hold the unit's ROS calls (``RUNS_WHEN_CALLED`` where ``runs_when_called``);
    ``source_of``, a file's bytes by name (``_meta_named``)."""
    # whether a declaration is an eligible function of the workspace's files, by the
    # node (one per cursor of the unit, kept with its answer: many references and
    # calls name the same declaration)
    known: dict[int, tuple[Cursor, bool]] = {}

    def ours(cursor: Cursor | None) -> bool:
        if cursor is None or cursor.kind not in _KINDS:  # no function ``eligible`` takes
            return False
        found = known.get(id(cursor))
        if found is None:
            where = cursor.location.file
            found = known[id(cursor)] = (
                cursor, where is not None and owned(where.name) and eligible(cursor))
        return found[1]

    facts: list[Fact] = []
    calls: dict[str, int] = {}
    refs: dict[str, int] = {}
    overloaded: set[str] = set()
    instantiated: set[str] = set()  # the function templates of the specialisations named
    by_caller: dict[tuple[str, int], tuple[Cursor, dict[tuple[str, int], str]]] = {}
    site_names: dict[tuple[str, int], str] = {}  # each call's place as its facts name it
    def built(cursor: Cursor) -> bool:
        """Whether a callee is the constructor of a class of the workspace's files (not
        a class template's): its class is built there, and the calls its constructor
        makes through the methods it calls exist under the conditions of the
        constructions (``shared``)."""
        if cursor.kind != CursorKind.CONSTRUCTOR:
            return False
        found = known.get(id(cursor))
        if found is None:
            where = cursor.location.file
            parent = cursor.semantic_parent
            found = known[id(cursor)] = (cursor, where is not None and owned(where.name) and (
                parent is None or parent.kind not in (
                    CursorKind.CLASS_TEMPLATE,
                    CursorKind.CLASS_TEMPLATE_PARTIAL_SPECIALIZATION)))
        return found[1]

    for function in functions:
        kept = walked(function)
        if kept is None:
            every = list(function.walk_preorder())
            nodes: Iterable[Cursor] = every
            references: Iterable[Cursor] = [n for n in every if n.kind in _NAMES]
        else:
            nodes, references = kept
        for node in references:
            if node.kind == CursorKind.OVERLOADED_DECL_REF:
                overloaded.add(node.spelling)
                continue
            target = node.referenced
            if target is None and node.kind == CursorKind.MEMBER_REF_EXPR:
                # ``reader.read`` on a ``reader`` whose type depends on a template
                # parameter: clang keeps neither the member nor its name
                overloaded.add(node.spelling or _last_word(node))
                continue
            if target is not None and ours(target):
                usr = target.canonical.get_usr()
                if usr:
                    refs[usr] = refs.get(usr, 0) + 1
                instantiated.add(_template_usr(target))
        for node in nodes:
            if node.kind == CursorKind.CALL_EXPR:
                callee = callee_of(node)
                if callee is None or not (ours(callee) or built(callee)):
                    continue
                usr = callee.canonical.get_usr()
                if not usr:
                    continue
                calls[usr] = calls.get(usr, 0) + 1
                instantiated.add(_template_usr(callee))
                place = _place(node)
                site_names[place] = site_of(node.location)
                # a virtual method called unqualified may run an override instead
                virtual = callee.kind == CursorKind.CXX_METHOD and (
                    callee.is_virtual_method()) and not qualified_call(node)
                # (two calls may start at one place, ``Driver().start(nh)``: the
                # constructor's and the method's, one per line)
                at = by_caller.setdefault(_place(function), (function, {}))[1]
                marked = usr + (VIRTUAL if virtual else "")
                held = at.get(place)
                at[place] = marked if held is None or held == marked else (
                    f"{held}\n{marked}" if marked not in held.split("\n") else held)
    for function, wanted in by_caller.values():
        # the function holding the calls; a constructor too, whose sites are none where
        # no file of the node builds it (``shared``)
        caller = function.canonical.get_usr() if eligible(function) or (
            function.kind == CursorKind.CONSTRUCTOR) else ""
        for place, (usrs, under) in _conditions(function, wanted, reader, enter).items():
            text = conditions_text(under) if under is not None else ""
            for usr in usrs.split("\n"):
                called, virtual = usr.removesuffix(VIRTUAL), usr.endswith(VIRTUAL)
                facts.append((called, SITE_UNDER, text,
                              f"{site_names[place]}\n{caller}\n{'v' if virtual else ''}"))
    used: set[str] = set()  # named in a variable's initialiser outside functions
    classes: set[str] = set()  # named in a variable's type or initialiser there
    for variable in variables:
        for node in variable.walk_preorder():
            if node.kind == CursorKind.OVERLOADED_DECL_REF:
                overloaded.add(node.spelling)
            elif node.kind == CursorKind.TYPE_REF and node.referenced is not None and (
                    node.referenced.kind in _CLASSES):
                classes.add(node.referenced.canonical.get_usr())
            elif node.kind in _REFERENCES and ours(node.referenced):
                used.add(node.referenced.canonical.get_usr())
    # a function used otherwise than by the calls seen (``&C::callback``) may run anywhere
    facts.extend((usr, REFERENCED, "", "") for usr, count in refs.items()
                 if count > calls.get(usr, 0))
    facts.extend((usr, REFERENCED, "", "") for usr in sorted(used) if usr)
    facts.extend((name, OVERLOADED, "", "") for name in sorted(overloaded) if name)
    facts.extend((usr, NAMED_CLASS, "", "") for usr in sorted(classes) if usr)
    facts.extend((usr, INSTANTIATED, "", "") for usr in sorted(instantiated) if usr)
    # a placeholder's function that runs only when called (``RUNS_WHEN_CALLED``); a
    # function template's (abb_robot_cpp_utilities' ``getParameter``, instantiated
    # explicitly in its .cpp) too, its name with it (its USR spells it ``@FT@``)
    for usr, (function, _bases) in sites.overrides.items():
        where = function.location.file
        if where is None or not owned(where.name):
            continue
        if function.kind == CursorKind.FUNCTION_TEMPLATE and _free_template(function):
            facts.append((usr, RUNS_WHEN_CALLED, function.spelling, ""))
        elif runs_when_called(function, declared):
            facts.append((usr, RUNS_WHEN_CALLED, "", ""))
    # so does a function that holds one of the unit's ROS calls (``holding``): where
    # nothing of the node calls or uses it, those calls are never made
    # (``links.NodeFacts.never_run``: Fast-Planner's ``ObjPredictor::init()``),
    # and one that calls such functions: what it calls runs where it does
    for function in (*holding, *(function for function, _ in by_caller.values())):
        where = function.location.file
        usr = function.canonical.get_usr()
        if usr and where is not None and owned(where.name) and (
                runs_when_called(function, declared)):
            facts.append((usr, RUNS_WHEN_CALLED, "", ""))
    # a name the code writes where Qt's meta-object system calls it by its text
    # (``SLOT(updateTopic())``, ``invokeMethod(obj, "refresh")``): any function of that
    # name may run there, as an overloaded name's may
    facts.extend((name, OVERLOADED, "", "") for name in sorted(_meta_named(
        {function.location.file.name for function in functions
         if function.location.file is not None}, source_of)) if name not in overloaded)
    for function in functions:
        if function.kind != CursorKind.CXX_METHOD or not function.is_virtual_method() or (
            not eligible(function)
        ):
            continue
        usr = function.canonical.get_usr()
        bases = _overridden(function, owned)
        if usr:
            facts.append((usr, BASES, "\n".join(bases), "") if bases is not None
                         else (usr, REFERENCED, "", ""))
    return list(dict.fromkeys(facts))


def runs_when_called(function: Cursor, declared: str | None) -> bool:
    """Whether ``function``'s code runs only where something calls it or names it: a
    free function or a non-virtual method that ``eligible`` takes (no ``main``, no C
    function, which a loader may find by its symbol), of a class whose bases are all
    read (a method that looks non-virtual may override a virtual one of a base the
    parse could not read)."""
    if not eligible(function) or function.spelling == "main":
        return False
    if function.kind == CursorKind.FUNCTION_DECL:
        return "#" in (function.canonical.get_usr() or "")  # a C function's has no types
    return not function.is_virtual_method() and _bases_read(function.semantic_parent, declared)


# the functions a string names for Qt's meta-object system to call by name
_META = re.compile(rb"\b(?:SLOT|SIGNAL|Q_SLOT|Q_SIGNAL)\s*\(\s*([A-Za-z_]\w*)"
                   rb"|\binvokeMethod\s*\([^;]*?\"([A-Za-z_]\w*)\"")


def _meta_named(files: Iterable[str], source_of: Callable[[str], bytes | None] | None
                ) -> set[str]:
    """The names ``files`` hand Qt's meta-object system as text (``_META``)."""
    found: set[str] = set()
    if source_of is None:
        return found
    for name in files:
        data = source_of(name)
        if data is None or (b"SLOT" not in data and b"SIGNAL" not in data
                            and b"invokeMethod" not in data):
            continue
        for match in _META.finditer(data):
            found.add((match.group(1) or match.group(2)).decode())
    return found


def _template_usr(function: Cursor) -> str:
    """The USR of the function template ``function`` specialises, else ``""``."""
    template = conf.lib.clang_getSpecializedCursorTemplate(function)
    if template is None or template.kind != CursorKind.FUNCTION_TEMPLATE:
        return ""
    return template.canonical.get_usr() or ""


def _free_template(function: Cursor) -> bool:
    """Whether the function template ``function`` is a namespace's (a free function's
    template, not a member's: no virtual dispatch nor class template around it)."""
    parent = function.semantic_parent
    return parent is None or parent.kind in (
        CursorKind.NAMESPACE, CursorKind.TRANSLATION_UNIT, CursorKind.LINKAGE_SPEC)


def _bases_read(cls: Cursor | None, declared: str | None, depth: int = 0) -> bool:
    """Whether every base class of ``cls`` (transitively) is defined as written, none
    unknown or declared permissively (``declared``): a method that looks non-virtual
    may override a virtual one of a base the parse could not read."""
    if cls is None or depth > MAX_DEPTH:
        return False
    for base in cls.get_children():
        if base.kind != CursorKind.CXX_BASE_SPECIFIER:
            continue
        decl = base.type.get_canonical().get_declaration()
        definition = decl.get_definition() if decl.kind != CursorKind.NO_DECL_FOUND else None
        where = definition.location.file if definition is not None else None
        if where is None or where.name == declared or not _bases_read(
                definition, declared, depth + 1):
            return False
    return True


def _last_word(node: Cursor) -> str:
    """The last identifier written in ``node`` (a member reference's member)."""
    words = [t.spelling for t in node.get_tokens() if t.kind.name == "IDENTIFIER"]
    return words[-1] if words else ""


def hidden_facts(root: Cursor, owned: Callable[[str], bool],
                 errors: list[tuple[set[str], tuple[str, int] | None]]) -> list[Fact]:
    """``HIDDEN`` facts: the eligible functions of the workspace's files this unit
    declares whose names are among the words of the code where the parse left an error
    that can hide a statement (``errors``: each error's words, with its place when it
    is outside the functions, the words of its line; a function declared on that line
    is no call there: ``void MotionCtrl::init()`` with ``MotionCtrl`` unknown)."""
    declared: list[tuple[str, str, tuple[str, int]]] = []
    stack = [root]
    while stack:
        parent = stack.pop()
        for cursor in children_in(parent, owned):
            if cursor.kind in _CONTAINERS:
                stack.append(cursor)
            elif cursor.kind in _KINDS:
                where = cursor.location
                place = (os.path.abspath(where.file.name) if where.file else "", where.line)
                usr = cursor.canonical.get_usr() if eligible(cursor) else ""
                declared.append((cursor.spelling, usr, place))
    at: dict[tuple[str, int], set[str]] = {}
    for name, _usr, place in declared:
        at.setdefault(place, set()).add(name)
    words: set[str] = set()
    for found, spot in errors:
        words |= found - at.get(spot, set()) if spot is not None else found
    return list(dict.fromkeys((usr, HIDDEN, "", "") for name, usr, _ in declared
                              if usr and name in words))


def qualified_call(call: Cursor) -> bool:
    """Whether the call names its method with a class (``Base::init(...)``): no
    virtual dispatch then."""
    for child in call.get_children():
        if child.kind == CursorKind.UNEXPOSED_EXPR:
            child = next(iter(child.get_children()), child)
        if child.kind in _REFERENCES:
            return any(c.kind in (CursorKind.TYPE_REF, CursorKind.NAMESPACE_REF,
                                  CursorKind.TEMPLATE_REF) for c in child.get_children())
        break
    return False


def site_of(location: SourceLocation) -> str:
    """A call site as facts name it: its file, line and column (not its offset: an edit
    that changes a line's length leaves the sites below it, and so the unit's result,
    as they were)."""
    return f"{location.file.name if location.file else ''}:{location.line}:{location.column}"


def _place(cursor: Cursor) -> tuple[str, int]:
    where = cursor.location
    return (where.file.name if where.file else "", where.offset)


def _conditions(function: Cursor, wanted: dict[tuple[str, int], str],
                reader: ConditionReader, enter: Callable[[Cursor], None]
                ) -> dict[tuple[str, int], tuple[str, tuple[Condition, ...] | None]]:
    """The callee's USR (the callees', one per line, of calls that start at one place)
    and the source conditions of each wanted call in ``function`` (None: not met in the
    walk, so unknown)."""
    enter(function)
    found: dict[tuple[str, int], tuple[str, tuple[Condition, ...] | None]] = {
        place: (usr, None) for place, usr in wanted.items()}
    stack: list[tuple[Cursor, tuple[Condition, ...]]] = [
        (child, ()) for child in reversed(list(function.get_children()))
        if child.kind != CursorKind.PARM_DECL]
    left = len(found)  # the wanted calls not met yet: the walk ends when none is left
    # the wanted calls' offsets in each file: a statement or expression of the
    # function's file whose text holds none is not walked into (mav_control_rw's CVXGEN
    # check_factorization: 6,500 lines of assignments and ifs before its one call, each
    # if's condition read)
    offsets: dict[str, list[int]] = {}
    for name, offset in wanted:
        offsets.setdefault(name, []).append(offset)
    start = function.extent.start
    own = start.file.name if start.file is not None else None
    mine = offsets.get(own, []) if own is not None else []
    whole = own is None or len(mine) != len(wanted)  # a call in another file: walk all
    while stack and left:
        node, conditions = stack.pop()
        if node.kind == CursorKind.CALL_EXPR:
            place = _place(node)
            if place in wanted and found[place][1] is None:
                found[place] = (wanted[place], tuple(
                    c for c in conditions
                    if c.kind == "source" and c.statement not in NOT_CARRIED))
                left -= 1
        if not whole and not _holds(node, own, mine):
            continue
        stack.extend(reader.below(node, conditions))
    return found


def _holds(node: Cursor, name: str | None, offsets: list[int]) -> bool:
    """Whether the text of ``node`` holds one of ``offsets`` of the file
    ``name`` (sorted or not); True when its text is not all in that file (a macro's)."""
    extent = node.extent
    start, end = extent.start, extent.end
    if start.file is None or end.file is None or start.file.name != name or (
            end.file.name != name):
        return True
    low, high = start.offset, end.offset
    return any(low <= offset <= high for offset in offsets)


def _overridden(method: Cursor, owned: Callable[[str], bool],
                depth: int = 0) -> list[str] | None:
    """The USRs of the virtual methods of ``method``'s base classes (transitively) that
    it overrides (same name and parameter types); None when a base class cannot be
    read or is not of the workspace's files (its own code, or a host's, may call
    the method)."""
    parent = method.semantic_parent
    if parent is None or depth > MAX_DEPTH:
        return None
    types = [p.type.get_canonical().spelling for p in method.get_children()
             if p.kind == CursorKind.PARM_DECL]
    return _overridden_in(parent, method.spelling, types, owned, depth)


def _overridden_in(cls: Cursor, name: str, types: list[str], owned: Callable[[str], bool],
                   depth: int) -> list[str] | None:
    """The overridden methods (``_overridden``) found in the bases of ``cls``."""
    if depth > MAX_DEPTH:
        return None
    found: list[str] = []
    for base in cls.get_children():
        if base.kind != CursorKind.CXX_BASE_SPECIFIER:
            continue
        decl = base.type.get_canonical().get_declaration()
        decl = decl.get_definition() or decl
        if decl.kind == CursorKind.NO_DECL_FOUND:
            return None
        hit = False
        for other in decl.get_children():
            if other.kind == CursorKind.CXX_METHOD and other.spelling == name and (
                other.is_virtual_method()
            ) and [p.type.get_canonical().spelling for p in other.get_children()
                   if p.kind == CursorKind.PARM_DECL] == types:
                where = other.location.file
                if where is None or not owned(where.name):
                    return None
                found.append(other.canonical.get_usr())
                deeper = _overridden(other, owned, depth + 1)
                if deeper is None:
                    return None
                found.extend(deeper)
                hit = True
                break
        if not hit:
            deeper = _overridden_in(decl, name, types, owned, depth + 1)
            if deeper is None:
                return None
            found.extend(deeper)
    return found


def shared(facts: Iterable[Fact], unseen: Collection[str],
           unbuilt: Callable[[str], bool] = lambda usr: False,
           unseen_construction: Callable[[str], bool] = lambda usr: False,
           never: Callable[[str], bool] = lambda usr: False,
           ) -> dict[str, tuple[Condition, ...]]:
    """Function USR -> the source conditions every call of it in the node's files is
    made under, with those its calling function is called under in turn (a base
    method's calls count too, as they may run an override). None for a function with
    no call seen, used otherwise, one a unit declares and names where the parse left an
    error (``HIDDEN``: a call of it may be hidden; any, ``*`` in ``unseen``, when a
    unit was not read), or with one site unconditional. A site in a constructor no file
    of the node calls (``unbuilt``, ``links.constructor_unbuilt``) is none: humble
    controller_manager's ``subscribe_to_robot_description_topic()``, under ``if
    (robot_description.empty())`` in the constructor ros2_control_node builds and under
    another condition in one it never builds. A site in a constructor is under the
    conditions the constructions of its class share in turn (its sites are constructions,
    ``SITE_UNDER`` facts too; none when ``unseen_construction`` says the parse may hide
    one): OrbbecSDK_ROS2's driver builds its ``OBLidarNode`` only ``if (device_type_ ==
    "lidar")``, and the lidar's publishers are made by ``setupTopics()``, which its
    constructor calls. Nor is a site in a function the node never runs (``never``,
    ``links.never_run``)."""
    sites: dict[str, dict[str, tuple[tuple[Condition, ...] | None, str, bool]]] = {}
    referenced: set[str] = set()
    bases: dict[str, list[str]] = {}
    hidden: set[str] = set()
    for usr, index, value, site in facts:
        if index == HIDDEN:
            hidden.add(usr)
        elif index == SITE_UNDER:
            place, _, rest = site.partition("\n")
            caller, _, virtual = rest.partition("\n")
            try:
                under = conditions_of_text(value) if value else None
            except (ValueError, TypeError, KeyError, json.JSONDecodeError):
                under = None
            sites.setdefault(usr, {})[place] = (under, caller, virtual == "v")
        elif index == REFERENCED:
            referenced.add(usr)
        elif index == BASES:
            bases[usr] = [b for b in value.split("\n") if b]
    memo: dict[str, tuple[Condition, ...]] = {}

    def of(usr: str, active: frozenset[str]) -> tuple[Condition, ...]:
        if usr in memo:
            return memo[usr]
        every = [usr, *bases.get(usr, [])]
        if "*" in unseen or len(active) > MAX_DEPTH or unseen_construction(usr) or (
            any(u in referenced or u in hidden for u in every)
        ):
            return ()
        # its own calls, and those of the methods it overrides that may dispatch to it
        # (a constructor whose class a file of the node builds, its own file too, is
        # built: those constructions are its sites)
        found_sites = [(under, caller) for u in every
                       for under, caller, virtual in sites.get(u, {}).values()
                       if (u == usr or virtual) and not (
                           caller and unbuilt(caller) and not sites.get(caller))
                       and not (caller and never(caller))]
        if not found_sites:
            return ()
        result: tuple[Condition, ...] | None = None
        for under, caller in found_sites:
            if under is None:
                result = ()
                break
            outer = of(caller, active | {usr}) if caller and caller not in active else ()
            held = (*outer, *(c for c in under if c not in outer))
            result = held if result is None else tuple(c for c in result if c in held)
            if not result:
                break
        memo[usr] = result or ()
        return memo[usr]

    out: dict[str, tuple[Condition, ...]] = {}
    for usr in list(sites) + list(bases):
        found = of(usr, frozenset())
        if found:
            out[usr] = found
    return out
