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
# the functions the glog stand-in's CHECK, PCHECK, LOG_ASSERT and CHECK_ERR expand to:
# each aborts the program when its argument is false. Not DCHECK's (``haros_dcheck``):
# a release build (NDEBUG, as ROS packages are built) never evaluates its argument, so
# a read in it is no required one
_CHECKS = frozenset({"haros_check"})


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
        if kind in (CursorKind.IF_STMT, CursorKind.WHILE_STMT):
            children = list(node.get_children())
            if children:
                self._condition(children[0])
            found = self.reader.required(node, children) if kind == CursorKind.IF_STMT else None
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
        elif kind == CursorKind.VAR_DECL:
            children = [c for c in node.get_children() if c.kind.is_expression()]
            if children:
                self._hold(node, children[-1])

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
            return {made: False} if made is not None else {}
        if kind == CursorKind.CALL_EXPR:
            made = key(expr)
            return {made: False} if made is not None else {}
        return {}

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


def _strip(expr: Cursor) -> Cursor:
    """``expr`` through implicit conversions and parentheses."""
    while expr.kind in _WRAPPERS:
        children = list(expr.get_children())
        if len(children) != 1:
            break
        expr = children[0]
    return expr
