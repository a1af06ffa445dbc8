"""Calls whose result the code tests: ``if (nh.getParam("x", v))``, ``!nh.hasParam(..)``.

A parameter read that returns whether the parameter was there, and whose result is a
condition, is handled when the parameter is absent (``PrimitiveCall.tested``). The
visitor shows this class every node of a function on its way down (parents before
children); it records the calls in a condition: of an ``if``, ``while`` or ``do``, of
``?:``, an operand of ``!``, ``&&`` or ``||``, and a ``bool`` variable initialised or
assigned from a call that is then one of those (``bool ok = nh.getParam(..); if (!ok)``),
a member too, tested in the same function (laser_filters' ``using_filter_chain_deprecated_ =
private_nh_.hasParam("filter_chain"); if (using_filter_chain_deprecated_)``), and a string
a read wrote and then tested for being empty: in the same function, or in any function of
the unit for a global, a static or a member (``unit_tested``).
"""

from __future__ import annotations

import re

from clang.cindex import Cursor, CursorKind, StorageClass

from .conditions import ConditionReader
from .values import emptiness_test, strip

Key = tuple[str, int, int]
_WRAPPERS = (CursorKind.UNEXPOSED_EXPR, CursorKind.PAREN_EXPR)
# a logical operator of a test: for the value a missing parameter gives it, ``&`` and
# ``|`` of two truth values are ``&&`` and ``||`` (they only evaluate both sides:
# base_local_planner's ``if (nh.hasParam("pdist_scale") & !nh.hasParam("path_distance_
# bias"))``); conditions.py's own pattern keeps to the short-circuiting ones
_LOGICAL = re.compile(r"^\s*(&&|\|\||&|\||\band\b|\bor\b|\bbitand\b|\bbitor\b)\s*$")
_OR = frozenset({"||", "or", "|", "bitor"})
_ASSIGN = re.compile(r"^\s*=\s*$")
_EQUALS = re.compile(r"^\s*(==|!=)\s*$")
_NOT = re.compile(r"^\s*(!|\bnot\b)")
# a compound assignment that gathers failed reads into a count or a flag: ``+=`` and
# ``|=`` make it true (non-zero) with any operand that is, ``&=`` false with any false one
_GATHER = re.compile(r"^\s*(\+=|\|=|&=|\bor_eq\b|\band_eq\b)\s*$")
_COMPARE = re.compile(r"^\s*(==|!=|>=|<=|>|<)\s*$")
# a comparison of a count with a number that says whether it is non-zero (``n > 0``,
# ``n != 0``, ``n >= 1``; ``n == 0`` says it is zero), by operator and number, the count
# on the left
_NONZERO = {(">", 0): True, ("!=", 0): True, (">=", 1): True,
            ("==", 0): False, ("<=", 0): False, ("<", 1): False}
_MIRROR = {">": "<", "<": ">", ">=": "<=", "<=": ">=", "==": "==", "!=": "!="}
# the functions the glog stand-in's CHECK, PCHECK, LOG_ASSERT and CHECK_ERR expand to:
# each aborts the program when its argument is false. Not DCHECK's (``haros_dcheck``):
# a release build (NDEBUG, as ROS packages are built) never evaluates its argument, so
# a read in it is no required one
_CHECKS = frozenset({"haros_check"})
# library functions that end the process when their last argument, a count of failed
# reads, is not zero: rosparam_shortcuts' ``shutdownIfError([parent_name, ]error_count)``
# (``ros::shutdown(); exit(0)``), by (namespace, name)
EXITS = frozenset({("rosparam_shortcuts", "shutdownIfError")})


def key(cursor: Cursor) -> Key | None:
    start, end = cursor.extent.start, cursor.extent.end
    if start.file is None:
        return None
    return start.file.name, start.offset, end.offset


class TestedCalls:
    """The calls of one function whose result is tested."""

    def __init__(self, reader: ConditionReader) -> None:
        self.reader = reader
        self.keys: set[Key] = set()
        self._results: dict[Key, Key] = {}  # a bool variable -> the call it holds
        # a variable -> the calls it was passed to before (``getParam("x", topic)``)
        self._passed: dict[Key, list[Key]] = {}
        # the same for a variable that outlives the function (a global, a static, a
        # member), and those of them tested for being empty here: a test in another
        # function of the unit handles the read's absence too (``unit_tested``)
        self.lasting_passed: dict[Key, list[Key]] = {}
        self.lasting_tested: set[Key] = set()
        # the calls tested whose absence takes the side that fails (``if
        # (!nh.getParam("x", x)) { ROS_ERROR(..); return false; }``): the parameter is
        # required, its absence not handled
        self.required: set[Key] = set()
        # a variable that counts or flags the reads that found nothing (depthai_examples'
        # ``badParams += !pnh.getParam("x", x);`` before ``if (badParams > 0) throw``,
        # ``ok &= nh.getParam(..)``, ``if (!nh.getParam(..)) ++missing;``) -> the calls
        # whose absence decides it, each with whether it is then true (non-zero)
        self._markers: dict[Key, dict[Key, bool]] = {}

    def visit(self, node: Cursor) -> None:
        kind = node.kind
        if kind == CursorKind.CALL_EXPR:
            self._pass(node)
            if node.spelling in _CHECKS:
                # glog's CHECK(nh.getParam("x", x)) aborts the program when the read
                # finds nothing: the parameter is required (Kimera-VIO-ROS' log_gt_data)
                given = list(node.get_arguments())
                if given:
                    self.required.update(k for k, v in self._when_absent(given[0]).items()
                                         if not v)
            elif _exits_when_nonzero(node):
                # ``error += !get(..); shutdownIfError("x", error);``: each get the count
                # gathers is required (mobipick's pick-and-place poses)
                given = list(node.get_arguments())
                if given:
                    self.required.update(k for k, v in self._when_absent(given[-1]).items()
                                         if v)
        if kind in (CursorKind.IF_STMT, CursorKind.WHILE_STMT):
            children = list(node.get_children())
            if children:
                self._condition(children[0])
            found = None
            if kind == CursorKind.IF_STMT:
                sides = self.reader._sides(node, children)
                if sides is not None:
                    self._marked_sides(children, sides[0], sides[1])
                # a test of a count of failed reads names no read: the failing side it
                # takes makes them required all the same
                found = self.reader.required(node, children) or (self.reader.required(
                    node, children, presence=False) if sides is not None
                    and self._marks(sides[3]) else None)
            if found is not None:
                side, tested = found
                fails = side != "if"  # the test's value that takes the failing side
                self.required.update(k for k, v in self._when_absent(tested).items()
                                     if v == fails)
        elif kind == CursorKind.DO_STMT:
            children = list(node.get_children())
            if len(children) == 2:
                self._condition(children[1])
        elif kind == CursorKind.CONDITIONAL_OPERATOR:
            children = list(node.get_children())
            if len(children) == 3:
                self._condition(children[0])
        elif kind == CursorKind.UNARY_OPERATOR:
            if self._is_not(node):
                for child in node.get_children():
                    self._condition(child)
        elif kind == CursorKind.BINARY_OPERATOR:
            children = list(node.get_children())
            if len(children) == 2:
                if self.reader._between(children[0], children[1], _LOGICAL):
                    self._condition(children[0])
                    self._condition(children[1])
                elif self.reader._between(children[0], children[1], _ASSIGN):
                    self._hold(children[0].referenced, children[1])
                    self._assign_marker(children[0], children[1])
        elif kind == CursorKind.COMPOUND_ASSIGNMENT_OPERATOR:
            children = list(node.get_children())
            operator = self.reader._between(children[0], children[1], _GATHER) if len(
                children) == 2 else ""
            if operator:
                self._gather(children[0], children[1], operator not in ("&=", "and_eq"))
        elif kind == CursorKind.VAR_DECL:
            children = [c for c in node.get_children() if c.kind.is_expression()]
            if children:
                self._hold(node, children[-1])
                held = key(node)
                if held is not None:
                    self._markers[held] = self._when_absent(children[-1])

    def _variable(self, expr: Cursor) -> Key | None:
        """The local or member a written expression names."""
        expr = _strip(expr)
        variable = expr.referenced if expr.kind in (
            CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR) else None
        if variable is None or variable.kind not in (CursorKind.VAR_DECL,
                                                     CursorKind.FIELD_DECL):
            return None
        return key(variable)

    def _gather(self, target: Cursor, value: Cursor, truthy: bool) -> None:
        """``target += value`` (``|=``: ``truthy``) or ``&=``: the calls whose absence
        makes ``value`` true (false for ``&=``) make the variable so."""
        held = self._variable(target)
        if held is None:
            return
        marks = self._markers.setdefault(held, {})
        marks.update({k: v for k, v in self._when_absent(value).items() if v == truthy})

    def _assign_marker(self, target: Cursor, value: Cursor) -> None:
        """``ok = ok && nh.getParam(..)``, ``failed = failed || !nh.getParam(..)``:
        gathered as ``&=`` and ``|=``; another value replaces what the variable held."""
        held = self._variable(target)
        if held is None:
            return
        inner = _strip(value)
        sides = list(inner.get_children()) if inner.kind == CursorKind.BINARY_OPERATOR else []
        operator = self.reader._between(sides[0], sides[1], _LOGICAL) if len(sides) == 2 else ""
        itself = [s for s in sides if self._variable(s) == held]
        if operator and len(itself) == 1:
            other = sides[1] if itself[0] == sides[0] else sides[0]
            self._gather(target, other, operator in _OR)
            return
        self._markers[held] = self._when_absent(value)

    def _marked_sides(self, children: list[Cursor], then_at: int, has_else: bool) -> None:
        """``if (!nh.getParam("x", x)) { ROS_ERROR(..); ++missing; }``: the side of an
        ``if`` (its children, the index of its ``then`` side, whether it has an
        ``else``) that a read's absence takes marks what it writes there: ``++n``,
        ``n++``, ``n += 1``, ``failed = true``, ``ok = false``."""
        absent = self._when_absent(children[then_at - 1])
        then = children[then_at]
        other = children[-1] if has_else else None
        for made, value in absent.items():
            side = then if value else other
            if side is None:
                continue
            statements = list(side.get_children()) if side.kind == CursorKind.COMPOUND_STMT \
                else [side]
            for statement in statements:
                written = self._mark_written(statement)
                if written is not None:
                    self._markers.setdefault(written[0], {})[made] = written[1]

    def _mark_written(self, statement: Cursor) -> tuple[Key, bool] | None:
        """The variable a statement marks and whether it makes it true (non-zero)."""
        statement = _strip(statement)
        children = list(statement.get_children())
        if statement.kind == CursorKind.UNARY_OPERATOR and len(children) == 1:
            tokens = [t.spelling for t in statement.get_tokens()]
            held = self._variable(children[0])
            return (held, True) if held is not None and "++" in tokens else None
        if len(children) != 2:
            return None
        held = self._variable(children[0])
        literal = _literal(children[1])
        if held is None or literal is None:
            return None
        if statement.kind == CursorKind.COMPOUND_ASSIGNMENT_OPERATOR:
            operator = self.reader._between(children[0], children[1], _GATHER)
            return (held, True) if operator in ("+=", "|=", "or_eq") and literal else None
        if statement.kind == CursorKind.BINARY_OPERATOR and self.reader._between(
                children[0], children[1], _ASSIGN):
            return held, bool(literal)
        return None

    def _marks(self, tested: Cursor) -> bool:
        """Whether an ``if``'s test reads a variable that marks failed reads."""
        for node in tested.walk_preorder():
            held = self._variable(node) if node.kind in (
                CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR) else None
            if held is not None and self._markers.get(held):
                return True
        return False

    def _when_absent(self, expr: Cursor) -> dict[Key, bool]:
        """The calls of a tested expression whose absence (the call false) decides its
        value, each with that value: ``!a || !b`` is true when ``a`` is false, ``a &&
        b`` false; ``a || b`` depends on ``b`` then."""
        expr = _strip(expr)
        kind = expr.kind
        if kind == CursorKind.UNARY_OPERATOR and self._is_not(expr):
            inner = list(expr.get_children())
            return {k: not v for k, v in self._when_absent(inner[0]).items()} if len(
                inner) == 1 else {}
        if kind == CursorKind.BINARY_OPERATOR:
            sides = list(expr.get_children())
            if len(sides) != 2:
                return {}
            operator = self.reader._between(sides[0], sides[1], _LOGICAL)
            if operator:
                decided = operator in _OR  # the value an operand decides
                return {k: v for side in sides for k, v in self._when_absent(side).items()
                        if v == decided}
            counted = self._count_test(sides)
            if counted is not None:
                return counted
            literals = [s for s in sides if _strip(s).kind == CursorKind.CXX_BOOL_LITERAL_EXPR]
            between = self.reader._between(sides[0], sides[1], _EQUALS)
            if len(literals) != 1 or not between:
                return {}
            other = sides[1] if literals[0] == sides[0] else sides[0]
            true = any(t.spelling == "true" for t in _strip(literals[0]).get_tokens())
            keep = true == (between == "==")  # ``x == true``, ``x != false``
            return {k: v if keep else not v for k, v in self._when_absent(other).items()}
        if kind in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR):
            variable = expr.referenced
            held = key(variable) if variable is not None else None
            made = self._results.get(held) if held is not None else None
            if made is not None:
                return {made: False}
            return dict(self._markers.get(held, {})) if held is not None else {}
        if kind == CursorKind.CALL_EXPR:
            made = key(expr)
            return {made: False} if made is not None else {}
        return {}

    def _count_test(self, sides: list[Cursor]) -> dict[Key, bool] | None:
        """A comparison of a variable that marks failed reads with a number that says
        whether it is non-zero (``badParams > 0``, ``0 != missing``): the marks, their
        values turned as the test turns them; None for another expression."""
        numbers = [_literal(s) for s in sides]
        if numbers.count(None) != 1 or any(isinstance(n, bool) for n in numbers):
            return None
        at = numbers.index(None)
        held = self._variable(sides[at])
        if held is None or held not in self._markers:
            return None
        operator = self.reader._between(sides[0], sides[1], _COMPARE)
        if not operator:
            return None
        operator = operator if at == 0 else _MIRROR[operator]
        number = numbers[1 - at]
        nonzero = _NONZERO.get((operator, number)) if isinstance(number, int) else None
        if nonzero is None:
            return None
        return {k: v if nonzero else not v for k, v in self._markers[held].items()}

    def _is_not(self, node: Cursor) -> bool:
        text = self.reader._bytes(node.extent.start.file)
        if text is None:
            return False
        offset = node.extent.start.offset
        return bool(_NOT.match(text[offset:offset + 4].decode("utf-8", "replace")))

    def _hold(self, variable: Cursor | None, value: Cursor) -> None:
        call = _unwrap(value)
        if variable is None or call is None or variable.kind not in (
                CursorKind.VAR_DECL, CursorKind.FIELD_DECL):
            return
        held, made = key(variable), key(call)
        if held is not None and made is not None:
            self._results[held] = made

    def _pass(self, call: Cursor) -> None:
        made = key(call)
        if made is None:
            return
        for arg in call.get_arguments():
            arg = strip(arg)
            variable = arg.referenced if arg.kind in (
                CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR) else None
            if variable is None or variable.kind not in (
                    CursorKind.VAR_DECL, CursorKind.FIELD_DECL):
                continue
            held = key(variable)
            if held is None:
                continue
            if variable.kind == CursorKind.VAR_DECL:
                self._passed.setdefault(held, []).append(made)
            if _lasting(variable):
                self.lasting_passed.setdefault(held, []).append(made)

    def _condition(self, expr: Cursor) -> None:
        found = emptiness_test(expr)
        if found is not None:
            # ``getParam("topic", topic); if (!topic.empty())``: a string a read wrote,
            # tested for being empty, the absence handled (uuv_assistants'
            # message_to_tf: an optional topic, subscribed only when given)
            subject = strip(found[0])
            variable = subject.referenced if subject.kind in (
                CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR) else None
            held = key(variable) if variable is not None else None
            if held is not None:
                self.keys.update(self._passed.get(held, ()))
                if _lasting(variable):
                    self.lasting_tested.add(held)
            return
        if expr.kind == CursorKind.VAR_DECL:  # if (bool ok = nh.getParam(..))
            children = [c for c in expr.get_children() if c.kind.is_expression()]
            expr = children[-1] if children else expr
        call = _unwrap(expr)
        if call is None:
            return
        if call.kind in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR):
            variable = call.referenced
            held = key(variable) if variable is not None else None
            if held is not None and held in self._results:
                self.keys.add(self._results[held])
            return
        made = key(call)
        if made is not None:
            self.keys.add(made)


def _lasting(variable: Cursor) -> bool:
    """Whether a variable outlives the function that uses it: a member, a global or
    namespace-scope variable, a static local."""
    if variable.kind == CursorKind.FIELD_DECL:
        return True
    if variable.kind != CursorKind.VAR_DECL:
        return False
    parent = variable.semantic_parent
    return (parent is not None and parent.kind in (
        CursorKind.TRANSLATION_UNIT, CursorKind.NAMESPACE, CursorKind.CLASS_DECL,
        CursorKind.STRUCT_DECL)) or variable.storage_class == StorageClass.STATIC


def unit_tested(passed: dict[Key, list[Key]], tested: set[Key]) -> set[Key]:
    """The calls of the unit that wrote a variable outliving its function which some
    function of the unit tests for being empty (message_to_tf's ``g_position_frame_id``,
    read in main, tested where the transforms are sent)."""
    return {made for held in tested for made in passed.get(held, ())}


def _unwrap(expr: Cursor) -> Cursor | None:
    """The call (or variable reference) an expression is, through implicit conversions,
    parentheses and a comparison with ``true`` / ``false`` (kobuki's
    ``if (nh.getParam(..) == true)``)."""
    for _ in range(8):
        if expr.kind in (CursorKind.CALL_EXPR, CursorKind.DECL_REF_EXPR,
                         CursorKind.MEMBER_REF_EXPR):
            return expr
        if expr.kind == CursorKind.BINARY_OPERATOR:
            sides = list(expr.get_children())
            others = [s for s in sides if _strip(s).kind != CursorKind.CXX_BOOL_LITERAL_EXPR]
            if len(sides) != 2 or len(others) != 1:
                return None
            expr = others[0]
            continue
        if expr.kind not in _WRAPPERS:
            return None
        children = list(expr.get_children())
        if len(children) != 1:
            # a call clang could not resolve stays an unexposed expression
            return expr if expr.kind == CursorKind.UNEXPOSED_EXPR and children else None
        expr = children[0]
    return None


def _literal(expr: Cursor) -> int | bool | None:
    """The value of an integer or ``bool`` literal (``1``, ``true``); None for
    another expression."""
    expr = _strip(expr)
    if expr.kind == CursorKind.CXX_BOOL_LITERAL_EXPR:
        return any(t.spelling == "true" for t in expr.get_tokens())
    if expr.kind != CursorKind.INTEGER_LITERAL:
        return None
    tokens = [t.spelling for t in expr.get_tokens()]
    try:
        return int(tokens[0].rstrip("uUlL"), 0) if tokens else None
    except ValueError:
        return None


def _strip(expr: Cursor) -> Cursor:
    """``expr`` through implicit conversions and parentheses."""
    while expr.kind in _WRAPPERS:
        children = list(expr.get_children())
        if len(children) != 1:
            break
        expr = children[0]
    return expr


def _exits_when_nonzero(call: Cursor) -> bool:
    """Whether a call is of a library function of ``EXITS`` (by its declaration's
    namespace, not by its name alone)."""
    if call.spelling not in {name for _, name in EXITS}:
        return False
    function = call.referenced
    parent = function.semantic_parent if function is not None else None
    return parent is not None and (parent.spelling, call.spelling) in EXITS
