"""Source conditions: the control statements a call sits in.

``branches(node)`` answers, for one statement, which of its children run under which
extra conditions; the visitor stacks them on the way down, so a call carries one
``Condition`` per enclosing ``if`` / ``else`` / loop / ``switch`` / ``try`` / ``catch``,
and one for the branch of a ``?:`` or the right side of ``&&`` / ``||`` it is on
(``if`` with the text of what is tested, ``else`` when it runs if that is false).
A call in a loop's or an ``if``'s own condition runs at least once, so it has none of
them. A call in an ``else`` branch gets statement ``else`` with the text of its
``if``; a ``try`` block's condition has empty text; a ``catch`` block's text is its
exception declaration; a ``switch``'s is its value against the ``case`` labels the
call follows (``mode == 1``; after ``default:``, ``mode != 1 && mode != 2``). Condition
texts are taken from the source as written (macros unexpanded), whitespace collapsed.
A condition in ``main(argc, argv)`` says so (``program_args``): its ``argc`` / ``argv``
are the program's arguments, which the graph can decide from a launch file's ``args``,
as it can the local that keeps what rclcpp leaves of them (``args_left``).
"""

from __future__ import annotations

import dataclasses
import re
from collections.abc import Callable
from typing import TypeVar

from clang.cindex import Cursor, CursorKind, SourceLocation

from ...ctext import function_macros
from ...model.conditions import Condition
from ...model.location import Location
from .expressions import ros_init, strip

Branch = tuple[Cursor, tuple[Condition, ...]]
_Rest = TypeVar("_Rest")
_LOOPS = {CursorKind.FOR_STMT: "for", CursorKind.CXX_FOR_RANGE_STMT: "for",
          CursorKind.WHILE_STMT: "while"}
_LABELS = (CursorKind.CASE_STMT, CursorKind.DEFAULT_STMT)
# the kinds ``branches`` gives conditions to children of; any other node's children run
# under its own conditions
_CONTROL = frozenset({
    CursorKind.IF_STMT, *_LOOPS, CursorKind.DO_STMT, CursorKind.SWITCH_STMT,
    CursorKind.CXX_TRY_STMT, CursorKind.CONDITIONAL_OPERATOR, CursorKind.BINARY_OPERATOR,
    CursorKind.CXX_CATCH_STMT, CursorKind.COMPOUND_STMT})
# what a block's statements after ``if (TEST) return;`` run under starts again at a label
# (a ``goto``, or a ``case`` reached by the switch, jumps there)
_JUMPED_TO = frozenset({*_LABELS, CursorKind.LABEL_STMT})
# a test of whether a parameter is set (``nh.hasParam("x")``, ``!nh.getParam("x", v)``,
# ``node->get_parameter("x", v)``): when its failing side aborts, the parameter is required
_PRESENCE = re.compile(
    r"\b(?:hasParam|getParam|getParamCached|has_parameter|get_parameter|has_param|get_param"
    r"|param::get|param::has)\s*[<(]")
# an error logged by the client library's macros
_ERROR_LOG = re.compile(r"\b(?:ROS|RCLCPP)_(?:ERROR|FATAL)\w*\s*\(")
# a returned value that says the function failed (``return false;``, ``return -1;``,
# ``return CallbackReturn::ERROR;``, ``return EXIT_FAILURE;``, ``return nullptr;``);
# any other value, or none, is a function done early on purpose
_FAILED = re.compile(
    r"^(?:false|-\s*\d+|nullptr|NULL|\w*(?:::)?\w*EXIT_FAILURE)$|\b(?:ERROR|FAILURE|Error"
    r"|Failure|FAILED|Failed)\b")
_SPACE = re.compile(r"\s+")
# a counting loop's header over literal bounds, as ``_parens`` reads it: ``int i = 1; i <
# 10; i++`` (a variable declared with a literal start, ``<``, ``<=`` or ``!=`` a literal
# end, a step of one up)
_COUNTING = re.compile(
    r"^(?:[\w:]+\s+)+(?P<var>[A-Za-z_]\w*)\s*=\s*(?P<start>\d+)[uUlL]*\s*;"
    r"\s*(?P=var)\s*(?P<op><=|<|!=)\s*(?P<end>\d+)[uUlL]*\s*;"
    r"\s*(?:\+\+\s*(?P=var)|(?P=var)\s*\+\+|(?P=var)\s*\+=\s*1)$")
# the most turns of a counting loop read one by one (``CallFinder._emit_one``)
MAX_TURNS = 16
# a counting loop up to a variable or member (``for (int i = 0; i < waypoint_num_; ++i)``)
_COUNTING_TO = re.compile(
    r"^(?:[\w:]+\s+)+(?P<var>[A-Za-z_]\w*)\s*=\s*(?P<start>\d+)[uUlL]*\s*;"
    r"\s*(?P=var)\s*(?P<op><=|<)\s*(?P<end>[A-Za-z_][\w.]*(?:->[A-Za-z_]\w*)*)\s*;"
    r"\s*(?:\+\+\s*(?P=var)|(?P=var)\s*\+\+|(?P=var)\s*\+=\s*1)$")
# ``!node->has_parameter(name)``, ``!this->has_parameter("x")``, ``!has_parameter(x)``
_NOT_DECLARED = re.compile(
    r"!\s*(?:[A-Za-z_][\w:]*\s*(?:\(\s*\))?\s*(?:->|\.)\s*)*has_parameter\s*\(\s*(.+?)\s*\)")
_DECLARED = re.compile(_NOT_DECLARED.pattern.removeprefix("!\\s*"))
_ELSE = re.compile(r"\belse\b")
_SHORT_CIRCUIT = re.compile(r"^\s*(&&|\|\||\band\b|\bor\b)\s*$")
# a handler that catches what rclcpp throws for a parameter that is not set (its
# exceptions, std::exception, or anything)
_CATCHES_FAILURE = re.compile(
    r"^\s*\.\.\.\s*$|\bstd::(?:exception|runtime_error)\b|\brclcpp::exceptions::"
    r"|\bParameter\w*Exception\b")


class ConditionReader:
    """Turns control statements into conditions, reading their text from the source."""

    def __init__(self, source: dict[str, bytes], where: Callable[[Cursor], Location]) -> None:
        self.source = source
        self.where = where
        self.in_main = False  # the function walked is main(argc, argv)
        # the extent (file, first and end offsets) of main's ``ros::init(argc, argv, ..)``
        # when it is a statement of main's body: a statement before it runs before it,
        # one after it after it (``Condition.after_init``)
        self._init: tuple[str, int, int] | None = None
        # main's local that holds the arguments the client library leaves (``args_left``)
        self.args_left: str | None = None
        # the locals a tested expression names that hold a parameter's value, in the
        # function read (``Condition.parameters``)
        self.held: Callable[[Cursor], tuple[tuple[str, str], ...]] | None = None
        # the constants a tested expression names, with their values (``Condition.
        # constants``)
        self.constants: Callable[[Cursor], tuple[tuple[str, int | bool], ...]] | None = None
        # the names a tested expression uses that hold each element of a list parameter
        # (``Condition.elements``)
        self.elements: Callable[[Cursor], tuple[tuple[str, str, str], ...]] | None = None
        # the ``try`` conditions whose handlers catch a parameter's failure: a read in the
        # block is prepared for the parameter not being set (``PrimitiveCall.tested``)
        self.handled: set[Condition] = set()
        # the branches of each control statement read so far, by the statement and the
        # reading it was read in (``enter``'s ``key``): the walks of a unit read the same
        # function again (its calls, then each call site's conditions)
        self._read: dict[tuple[int, int, object], list[Branch]] = {}
        # the counting loops over literal bounds read (``_counting``): each one's
        # variable and the values it takes in turn
        self.counted: dict[Condition, tuple[tuple[str, int], tuple[int, ...]]] = {}
        # and those up to a variable or member (``_counting``): each one's variable, its
        # first value, whether the bound is its last, and the bound's expression
        self.counted_to: dict[Condition, tuple[tuple[str, int], int, bool, Cursor]] = {}
        self._reading: tuple[int, object] | None = None

    def below(self, node: Cursor, conditions: tuple[Condition, ...]) -> list[Branch]:
        """The children of ``node``, each with the conditions it runs under inside code
        that runs under ``conditions`` (``branches``), last first: what a walk pushes on
        its stack to visit them in order."""
        if node.kind not in _CONTROL:
            return [(child, conditions) for child in reversed(list(node.get_children()))]
        if self._reading is None:
            branches = self.branches(node)
        else:
            key = (id(node), *self._reading)
            found = self._read.get(key)
            if found is None:
                found = self._read[key] = self.branches(node)
            branches = found
        return [(child, conditions + extra) for child, extra in reversed(branches)]

    def branches(self, node: Cursor) -> list[Branch]:
        kind = node.kind
        children = list(node.get_children())
        if kind == CursorKind.IF_STMT:
            return self._if(node, children)
        if kind in _LOOPS and children:
            loop = self._condition(node, _LOOPS[kind], self._tested(
                node, "for" if kind == CursorKind.CXX_FOR_RANGE_STMT
                else _LOOPS[kind]))
            if kind == CursorKind.FOR_STMT:
                self._counting(loop, children)
            return [(c, ()) for c in children[:-1]] + [(children[-1], (loop,))]
        if kind == CursorKind.DO_STMT and children:
            text = (self._parens(children[0].extent.end)
                    if self._written(node.extent.start, "do")
                    else self._tested(node, "do", "while"))
            return [(children[0], (self._condition(node, "do", text),)),
                    *((c, ()) for c in children[1:])]
        if kind == CursorKind.SWITCH_STMT and children:
            switch = self._condition(node, "switch", self._tested(node, "switch"),
                                     children[-2] if len(children) >= 2 else None)
            return [(c, ()) for c in children[:-1]] + self._switch_body(children[-1], switch)
        if kind == CursorKind.CXX_TRY_STMT and children:
            attempt = self._condition(node, "try", "")
            if any(c.kind == CursorKind.CXX_CATCH_STMT and _CATCHES_FAILURE.search(
                    self._parens(c.extent.start)) and _goes_on(c) for c in children[1:]):
                self.handled.add(attempt)
            return [(children[0], (attempt,)), *((c, ()) for c in children[1:])]
        if kind == CursorKind.CONDITIONAL_OPERATOR and len(children) == 3:
            text = self._text(children[0])
            return [(children[0], ()),
                    (children[1], (self._condition(node, "if", text, children[0]),)),
                    (children[2], (self._condition(node, "else", text, children[0]),))]
        if kind == CursorKind.BINARY_OPERATOR and len(children) == 2:
            operator = self._between(children[0], children[1], _SHORT_CIRCUIT)
            if operator:  # ``a && f()`` calls f if a; ``a || f()`` calls it if not a
                statement = "if" if operator in ("&&", "and") else "else"
                text = self._text(children[0])
                return [(children[0], ()),
                        (children[1], (self._condition(node, statement, text, children[0]),))]
        if kind == CursorKind.CXX_CATCH_STMT and children:
            catch = self._condition(node, "catch", self._parens(node.extent.start))
            return [(c, (catch,)) for c in children]
        if kind == CursorKind.COMPOUND_STMT:
            return self._block(children)
        return [(c, ()) for c in children]

    def _counting(self, loop: Condition, children: list[Cursor]) -> None:
        """Note ``loop`` in ``counted`` when it is a counting loop over literal bounds
        that runs its body at least once (``for (int i = 1; i < 10; i++)``): its
        variable and each value it takes, none when it takes more than ``MAX_TURNS``.
        Such a loop is no condition of what its body makes."""
        found = _COUNTING.match(loop.text)
        if found is None:
            self._counting_to(loop, children)
            return
        if not children or children[0].kind != CursorKind.DECL_STMT:
            return
        declared = [c for c in children[0].get_children() if c.kind == CursorKind.VAR_DECL]
        if len(declared) != 1 or declared[0].spelling != found.group("var"):
            return
        start, end = int(found.group("start")), int(found.group("end"))
        end += 1 if found.group("op") == "<=" else 0
        if end <= start:
            return  # never runs, or (``!=`` from above) never stops
        from .values import key_of  # (values reads no conditions)

        turns = tuple(range(start, end)) if end - start <= MAX_TURNS else ()
        self.counted[loop] = (key_of(declared[0]), turns)

    def _counting_to(self, loop: Condition, children: list[Cursor]) -> None:
        """Note ``loop`` in ``counted_to`` when it counts up by one from a literal to a
        variable or member (``for (int i = 0; i < waypoint_num_; i++)``), its bound's
        expression the right side of its test."""
        found = _COUNTING_TO.match(loop.text)
        if found is None or len(children) < 3 or children[0].kind != CursorKind.DECL_STMT:
            return
        declared = [c for c in children[0].get_children() if c.kind == CursorKind.VAR_DECL]
        test = children[1]
        sides = list(test.get_children()) if test.kind == CursorKind.BINARY_OPERATOR else []
        if len(declared) != 1 or declared[0].spelling != found.group("var") or len(sides) != 2:
            return
        from .values import key_of  # (values reads no conditions)

        self.counted_to[loop] = (key_of(declared[0]), int(found.group("start")),
                                 found.group("op") == "<=", sides[1])

    def _block(self, children: list[Cursor]) -> list[Branch]:
        """The statements of a block, each under what the ones before it decided: after
        ``if (TEST) return;`` (or ``continue``, ``break``) the rest of the block runs only
        when TEST is false, ``else`` TEST; after ``if (TEST) {...} else return;`` only when
        it is true. A side that fails (``return false``, an error value, ``throw``, an
        exit) adds nothing: what follows is the function's work when it succeeds, as
        ``if (!init()) { ROS_ERROR(..); return false; }`` means."""
        out: list[Branch] = []
        extra: tuple[Condition, ...] = ()
        for i, child in enumerate(children):
            if child.kind in _JUMPED_TO:
                extra = ()
            out.append((child, extra))
            if child.kind == CursorKind.IF_STMT:
                extra += self._after_if(child, children[i + 1:])
        return out

    def _sides(self, node: Cursor, children: list[Cursor]
               ) -> tuple[int, bool, str, Cursor] | None:
        """Of an ``if`` statement with its children: the index of its ``then`` branch,
        whether it has an ``else``, the text it tests and the tested expression."""
        if len(children) < 2:
            return None
        has_else = len(children) >= 3 and self._between(children[-2], children[-1], _ELSE) == "else"
        then = len(children) - (2 if has_else else 1)
        return then, has_else, self._tested(node, "if"), children[then - 1]

    def _after_if(self, node: Cursor, rest: list[Cursor]) -> tuple[Condition, ...]:
        """The condition the statements after the ``if`` ``node`` in its block run
        under: its ``else`` when its ``then`` side leaves the block without failing and its
        ``else`` side (if any) does not leave; its ``if`` the other way round; none
        otherwise, or when the test guards what the function does once
        (``_guards_first_time``)."""
        children = list(node.get_children())
        sides = self._sides(node, children)
        if sides is None:
            return ()
        then, has_else, text, tested = sides
        first = self._leaves(children[then])
        second = self._leaves(children[-1]) if has_else else None
        if first == "done" and second is None:
            if not has_else and self._guards_first_time(tested, rest):
                return ()
            return (self._condition(node, "else", text, tested),)
        if second == "done" and first is None:
            return (self._condition(node, "if", text, tested),)
        return ()

    def _leaves(self, statement: Cursor) -> str | None:
        """Whether ``statement`` always leaves its block, and how: ``"failed"`` by
        ``throw``, an exit, or with an error logged (``ROS_ERROR(..); return;``);
        ``"false"`` by a return from ``main`` or of a failure value (``return false;``,
        which may also mean "not done here": move_base's ``loadRecoveryBehaviors``,
        whose caller then loads the defaults); ``"done"`` by another ``return``,
        ``continue`` or ``break``; None when it may go on."""
        kind = statement.kind
        if kind == CursorKind.COMPOUND_STMT:
            inner = list(statement.get_children())
            if not inner:
                return None
            last = self._leaves(inner[-1])
            if last in ("done", "false") and (any(_exits(s) for s in inner[:-1])
                                              or _ERROR_LOG.search(self._text(statement))):
                return "failed"  # ``ros::shutdown(); return;``, ``ROS_ERROR(..); return;``
            return last
        if kind == CursorKind.RETURN_STMT:
            if self.in_main:
                return "false"
            value = list(statement.get_children())
            return "false" if value and _FAILED.search(self._text(value[0])) else "done"
        if kind in (CursorKind.CONTINUE_STMT, CursorKind.BREAK_STMT):
            return "done"
        if kind == CursorKind.IF_STMT:
            children = list(statement.get_children())
            sides = self._sides(statement, children)
            if sides is None or not sides[1]:
                return None
            both = (self._leaves(children[sides[0]]), self._leaves(children[-1]))
            if None in both:
                return None
            return "failed" if "failed" in both else "false" if "false" in both else "done"
        if _exits(statement):
            return "failed"
        return None

    def _guards_first_time(self, tested: Cursor, rest: list[Cursor]) -> bool:
        """Whether ``if (TEST) return;`` guards what the function does only once, or
        not again for the same input: TEST reads a member the rest of the block sets
        (``if (initialized_) { ROS_WARN(..); return; }`` before ``initialized_ = true``;
        navigation2's ``if (!always_reload_bt_ && current_bt_file_or_id_ == file_or_id)
        return true;`` before ``current_bt_file_or_id_ = file_or_id``). The first run
        goes past it, so what follows is made."""
        from .members import member_of
        from .writes import writes_in

        members = {member_of(node) for node in tested.walk_preorder()
                   if node.kind == CursorKind.MEMBER_REF_EXPR}
        flag = _flag(strip(tested))
        members = {m for m in members | {flag} if m is not None
                   and m.kind == CursorKind.FIELD_DECL}
        if not members:
            return False
        return any(write.whole and member_of(write.target) in members
                   for statement in rest for write in writes_in(statement, self.source))

    def required(self, node: Cursor, children: list[Cursor], presence: bool = True
                 ) -> tuple[str, Cursor] | None:
        """The side of the ``if`` ``node`` (with its children) that a parameter's
        presence test makes required (``_required``), with the tested expression;
        ``presence`` False: whatever it tests (a count of failed reads, which the
        caller follows to the reads)."""
        sides = self._sides(node, children)
        side = self._required(children, sides, presence) if sides is not None else None
        return (side, sides[3]) if side is not None and sides is not None else None

    def _required(self, children: list[Cursor], sides: tuple[int, bool, str, Cursor],
                  presence: bool = True) -> str | None:
        """Which side of an ``if`` (its children and ``_sides``) a parameter's presence
        test makes required: ``"if"`` when the ``else`` side fails (``if
        (nh.hasParam("x")) {..} else { ROS_ERROR(..); return false; }``), ``"else"`` when
        the ``then`` side does; None otherwise. Code on that side runs whenever the
        function goes on, so it is under no condition of the test. Failing is throwing,
        exiting or logging an error: a bare ``return false;`` may be a fallback the
        caller takes."""
        then, has_else, text, _ = sides
        if presence and not _PRESENCE.search(text):
            return None
        if has_else and self._leaves(children[-1]) == "failed":
            return "if"
        if self._leaves(children[then]) == "failed":
            return "else"
        return None

    def _if(self, node: Cursor, children: list[Cursor]) -> list[Branch]:
        sides = self._sides(node, children)
        if sides is None:
            return [(c, ()) for c in children]
        then, has_else, text, tested = sides
        required = self._required(children, sides)
        out: list[Branch] = [(c, ()) for c in children[:then]]
        first = required == "if" or self._first_time(tested, children[then])
        out.append((children[then], () if first else (self._condition(node, "if", text,
                                                                      tested),)))
        if has_else:
            out.append((children[-1], () if required == "else" else (
                self._condition(node, "else", text, tested),)))
        return out

    def _first_time(self, tested: Cursor, then: Cursor) -> bool:
        """Whether an ``if`` is a lazy initialisation, ``if (!initialized_) { ...;
        initialized_ = true; }`` (or ``!isInitialized()``, a method that returns the
        member): its block runs the first time the function does (ROS 1 planners'
        ``initialize``, which their host calls once), so what it makes is made."""
        from .members import _negates, member_of
        from .writes import writes_in

        test = strip(tested)
        if test.kind != CursorKind.UNARY_OPERATOR or not _negates(test, self.source):
            return False
        operands = list(test.get_children())
        flag = _flag(strip(operands[0])) if len(operands) == 1 else None
        if flag is None:
            return False
        for write in writes_in(then, self.source):
            if write.whole and write.value is not None and _true(write.value) \
                    and member_of(write.target) == flag:
                return True
        return False

    def _switch_body(self, body: Cursor, switch: Condition) -> list[Branch]:
        """Statements of a switch body, each under one condition: the switch's value
        equal to the ``case`` labels it follows (``mode == 1``), or, after ``default:``,
        different from every other label (``mode != 1 && mode != 2``)."""
        if body.kind != CursorKind.COMPOUND_STMT:
            return [(body, (switch,))]
        groups: list[tuple[Cursor, list[str], Cursor]] = []  # (first label, texts, stmt)
        for statement in body.get_children():
            if statement.kind not in _LABELS:
                groups.append((statement, [], statement))
                continue
            texts: list[str] = []
            start = statement
            while statement.kind in _LABELS:
                inner = list(statement.get_children())
                if statement.kind == CursorKind.CASE_STMT:
                    texts.append(self._text(inner[0]) if inner else "?")
                else:
                    texts.append("default")
                if not inner:
                    break
                statement = inner[-1]
            groups.append((start, texts, statement))
        labels = [t for _, texts, _ in groups for t in texts if t != "default"]
        value = switch.text
        out: list[Branch] = []
        condition = switch
        for start, texts, statement in groups:
            if texts:
                if "default" in texts:
                    text = " && ".join(f"{value} != {t}" for t in labels) or "default"
                else:
                    text = " || ".join(f"{value} == {t}" for t in texts)
                condition = dataclasses.replace(self._condition(start, "switch", text),
                                                parameters=switch.parameters,
                                                elements=switch.elements)
            if statement.kind not in _LABELS:
                out.append((statement, (condition,)))
        return out

    # -- text -------------------------------------------------------------------------

    def _condition(self, node: Cursor, statement: str, text: str,
                   tested: Cursor | None = None) -> Condition:
        held = self.held(tested) if tested is not None and self.held is not None else ()
        constants = self.constants(tested) if tested is not None and (
            self.constants is not None) else ()
        elements = self.elements(tested) if tested is not None and (
            self.elements is not None) else ()
        return Condition(text, "source", statement, self.where(node), self.in_main,
                         self.args_left if self.in_main else None, held or None,
                         constants=constants or None, elements=elements or None,
                         after_init=self._after_init(node) if self.in_main else None)

    def _after_init(self, node: Cursor) -> bool | None:
        """Whether main's statement ``node`` runs after main's ``ros::init`` (True),
        before it (False), or neither is known (None: no such call in main's body)."""
        start = node.extent.start
        if self._init is None or start.file is None or start.file.name != self._init[0]:
            return None
        if start.offset >= self._init[2]:
            return True
        return False if node.extent.end.offset <= self._init[1] else None

    def choice(self, node: Cursor, statement: str, test: Cursor) -> Condition:
        """The condition of a side of the ``?:`` ``node`` whose test is ``test``: ``if``
        its text for the first, ``else`` for the second, as ``branches`` gives them."""
        return self._condition(node, statement, self._text(test), test)

    def enter(self, function: Cursor, arguments_left: frozenset[str],
              held: Callable[[Cursor], tuple[tuple[str, str], ...]] | None = None,
              constants: Callable[[Cursor], tuple[tuple[str, int | bool], ...]] | None = None,
              elements: Callable[[Cursor], tuple[tuple[str, str, str], ...]] | None = None,
              key: object = None) -> None:
        """Read the conditions of ``function`` next: whether it is ``main(argc, argv)``,
        and its local initialised by a call of ``arguments_left`` (rclcpp's
        ``init_and_remove_ros_arguments``), when it has one such local; ``held`` tells
        the locals of a tested expression that hold a parameter's value, ``constants``
        the constants it names with their values, ``elements`` the names that hold each
        element of a list parameter in turn. ``key``: what ``held``, ``constants`` and
        ``elements`` answer from (the function's scope of the unit), so that a statement
        read again in the same reading gives the branches read before; None: read anew."""
        self._reading = None if key is None else (id(function), key)
        self.held = held
        self.constants = constants
        self.elements = elements
        params = [c.spelling for c in function.get_children()
                  if c.kind == CursorKind.PARM_DECL]
        self.in_main = function.spelling == "main" and params[:2] == ["argc", "argv"]
        self.args_left = None
        self._init = None
        if not self.in_main:
            return
        call = ros_init(function)
        start = call.extent.start if call is not None else None
        if call is not None and start is not None and start.file is not None:
            self._init = start.file.name, start.offset, call.extent.end.offset
        found = {node.spelling for node in function.walk_preorder()
                 if node.kind == CursorKind.VAR_DECL and any(
                     call.kind == CursorKind.CALL_EXPR and call.spelling in arguments_left
                     for call in node.walk_preorder())}
        self.args_left = found.pop() if len(found) == 1 else None

    def _bytes(self, node_file: object) -> bytes | None:
        name = getattr(node_file, "name", None)
        return self.source.get(name) if name else None

    def _parens(self, start: object) -> str:
        """The text inside the first balanced parentheses after source position ``start``."""
        text = self._bytes(getattr(start, "file", None))
        offset = getattr(start, "offset", 0)
        if text is None:
            return "?"
        begin = text.find(b"(", offset)
        inner = _balanced(text, begin) if begin >= 0 else None
        return "?" if inner is None else _clean(inner)

    def _written(self, start: object, keyword: str) -> bool:
        """Whether the statement at ``start`` is written there, ``keyword`` first (not
        made by a macro invoked there)."""
        text = self._bytes(getattr(start, "file", None))
        offset = getattr(start, "offset", 0)
        return text is not None and re.match(
            keyword.encode() + rb"\b", text[offset:offset + len(keyword) + 1]) is not None

    def _tested(self, node: Cursor, keyword: str, tests: str | None = None) -> str:
        """What the statement ``node``, ``keyword`` (``if``, ``while``, ``for``,
        ``switch``), tests, as written. A statement a function-like macro's expansion
        makes starts, for the parse, at the macro's name: its test is then read off the
        macro's ``#define`` the parse expanded there, in the file or a header of the
        workspace, each parameter the invocation's argument (``#define
        INIT_IF_NEEDED(v, val) if (!v) v = val;`` called as ``INIT_IF_NEEDED(listener,
        ...)`` tests ``!listener``, not the invocation's arguments, riptide_autonomy's
        UwrtBtNode.cpp); ``?`` when that definition is not read (a header outside the
        workspace) or makes more than one such statement. ``tests``: the word the test
        follows when not ``keyword`` (``while`` of a ``do``)."""
        start = node.extent.start
        text = self._bytes(getattr(start, "file", None))
        offset = getattr(start, "offset", 0)
        if text is None:
            return "?"
        if self._written(start, keyword):
            return self._parens(start)
        invocation = _INVOCATION.match(text, offset)
        if invocation is None:
            return "?"
        arguments = _balanced(text, invocation.end() - 1)
        definition = self._definition(node, text, invocation.group(1))
        if arguments is None or definition is None:
            return "?"
        parameters, body = definition
        found = list(re.finditer(rb"\b" + (tests or keyword).encode() + rb"\s*\(", body))
        inner = _balanced(body, found[0].end() - 1) if len(found) == 1 else None
        given = _split_arguments(arguments)
        if inner is None or (len(given) != len(parameters) and (
                not parameters or parameters[-1] != b"...")):
            return "?"
        values = dict(zip(parameters, given, strict=False))
        if parameters and parameters[-1] == b"...":
            values[b"__VA_ARGS__"] = b", ".join(given[len(parameters) - 1:])
        return _clean(re.sub(rb"\b[A-Za-z_]\w*\b",
                             lambda m: values.get(m.group(0), m.group(0)).strip(), inner))

    def _definition(self, node: Cursor, text: bytes, name: bytes
                    ) -> tuple[list[bytes], bytes] | None:
        """The parameters and body of the function-like macro ``name`` whose expansion
        makes ``node`` (its invocation starts ``node``, in the file of ``text``): the
        definition the parse expanded there (its macro definition, with the detailed
        preprocessing record), in whichever file of the workspace holds it; without it,
        the only one ``text`` holds."""
        defined = _expanded_definition(node)
        if defined is not None:
            header = self._bytes(defined.file)
            found = [(p, b) for at, p, b in function_macros(header, name)
                     if at == defined.offset] if header is not None else []
        else:
            found = [(p, b) for _, p, b in function_macros(text, name)]
        return found[0] if len(found) == 1 else None

    def text(self, node: Cursor) -> str:
        """The source text of ``node``, whitespace collapsed (as conditions are); ``?``
        when it is not in one file read."""
        return self._text(node)

    def declared_anyway(self, conditions: tuple[Condition, ...], name: Cursor
                        ) -> tuple[Condition, ...]:
        """``conditions`` of an rclcpp parameter declaration named by ``name`` without
        a test that the node has not declared that parameter yet (``if
        (!node->has_parameter(name)) node->declare_parameter(name, value)``: nav2's
        ``declare_parameter_if_not_declared``). rclcpp throws on a second declaration;
        the test only spares that, and after the statement the parameter is declared
        either way, so it is no condition of the declaration."""
        written = None
        kept = []
        for condition in conditions:
            # ``if (!has_parameter(n)) declare``, or after ``if (has_parameter(n)) return
            # get_parameter(n);`` (navigation2's ``declare_or_get_parameter``): ``else``
            found = _NOT_DECLARED.fullmatch(condition.text) if (
                condition.statement == "if") else _DECLARED.fullmatch(condition.text) if (
                condition.statement == "else") else None
            if found is not None:
                written = self._text(name) if written is None else written
                if found.group(1) == written:
                    continue
            kept.append(condition)
        return tuple(kept) if len(kept) < len(conditions) else conditions

    def _text(self, node: Cursor) -> str:
        start, end = node.extent.start, node.extent.end
        text = self._bytes(start.file)
        if text is None or end.file is None or end.file.name != start.file.name:
            return "?"
        return _clean(text[start.offset:end.offset])

    def _between(self, first: Cursor, second: Cursor, pattern: re.Pattern[str]) -> str:
        """What ``pattern`` finds in the source text between two sibling nodes, or ""."""
        end, start = first.extent.end, second.extent.start
        text = self._bytes(end.file)
        if text is None or start.file is None or start.file.name != end.file.name:
            return ""
        between = text[end.offset:start.offset].decode("utf-8", "replace")
        found = pattern.search(between)
        return found.group(found.lastindex or 0) if found else ""


def _flag(expr: Cursor) -> Cursor | None:
    """The boolean member ``expr`` reads: the member itself, or a method without
    arguments whose body is ``return member;``."""
    from .members import member_of

    if expr.kind == CursorKind.CALL_EXPR:
        method = expr.referenced
        if list(expr.get_arguments()) or method is None \
                or method.kind != CursorKind.CXX_METHOD:
            return None
        body = method.get_definition()
        statements = [] if body is None else [
            c for c in body.get_children() if c.kind == CursorKind.COMPOUND_STMT]
        inner = list(statements[0].get_children()) if statements else []
        if len(inner) != 1 or inner[0].kind != CursorKind.RETURN_STMT:
            return None
        returned = list(inner[0].get_children())
        expr = strip(returned[0]) if len(returned) == 1 else expr
        if expr.kind == CursorKind.CALL_EXPR:
            return None
    found = member_of(expr)
    if found is None or found.kind != CursorKind.FIELD_DECL or found.type.spelling != "bool":
        return None
    return found


def _true(value: Cursor) -> bool:
    value = strip(value)
    return value.kind == CursorKind.CXX_BOOL_LITERAL_EXPR and any(
        t.spelling == "true" for t in value.get_tokens())


# a function-like macro's invocation: its name and opening parenthesis
_INVOCATION = re.compile(rb"([A-Za-z_]\w*)\s*\(")


def _balanced(text: bytes, begin: int) -> bytes | None:
    """The text inside the balanced parentheses opening at ``begin`` (strings and
    character literals skipped), or None when they do not close."""
    depth, i, quote = 0, begin, 0
    while i < len(text):
        char = text[i]
        if quote:
            if char == 0x5C:  # backslash
                i += 1
            elif char == quote:
                quote = 0
        elif char in (0x22, 0x27):  # " '
            quote = char
        elif char == 0x28:
            depth += 1
        elif char == 0x29:
            depth -= 1
            if depth == 0:
                return text[begin + 1:i]
        i += 1
    return None


def _split_arguments(text: bytes) -> list[bytes]:
    """A macro invocation's arguments: ``text`` split at its commas outside parentheses
    and strings (brackets, braces and template angle brackets do not group them for the
    preprocessor)."""
    parts, depth, quote, last = [], 0, 0, 0
    i = 0
    while i < len(text):
        char = text[i]
        if quote:
            if char == 0x5C:
                i += 1
            elif char == quote:
                quote = 0
        elif char in (0x22, 0x27):
            quote = char
        elif char == 0x28:
            depth += 1
        elif char == 0x29:
            depth -= 1
        elif char == 0x2C and depth == 0:
            parts.append(text[last:i].strip())
            last = i + 1
        i += 1
    parts.append(text[last:].strip())
    return parts if parts != [b""] else []


def _expanded_definition(node: Cursor) -> SourceLocation | None:
    """Where the macro whose invocation starts ``node`` is defined (its name), by the
    parse; None when the parse says no macro is invoked there."""
    try:
        at = Cursor.from_location(node.translation_unit, node.extent.start)
        if at is None or at.kind != CursorKind.MACRO_INSTANTIATION:
            return None
        defined = at.referenced
    except (ValueError, TypeError, AttributeError):
        return None
    if defined is None or defined.kind != CursorKind.MACRO_DEFINITION:
        return None
    return defined.location if defined.location.file is not None else None


def _clean(raw: bytes) -> str:
    return _SPACE.sub(" ", raw.decode("utf-8", "replace")).strip()


# what ends a handler other than by going on after the ``try``
_LEAVES = frozenset({CursorKind.CXX_THROW_EXPR, CursorKind.RETURN_STMT})
_EXITS = frozenset({"exit", "abort", "_exit", "quick_exit", "terminate", "shutdown"})


def _exits(statement: Cursor) -> bool:
    """Whether ``statement`` is a ``throw`` or a call that ends the program or its ROS
    node (``exit(1)``, ``abort()``, ``ros::shutdown()``)."""
    while statement.kind == CursorKind.UNEXPOSED_EXPR:
        inner = list(statement.get_children())
        if len(inner) != 1:
            return False
        statement = inner[0]
    return statement.kind == CursorKind.CXX_THROW_EXPR or (
        statement.kind == CursorKind.CALL_EXPR and statement.spelling in _EXITS)


def _goes_on(handler: Cursor) -> bool:
    """Whether a ``catch`` block lets the code go on after its ``try`` (no ``throw``,
    ``return`` or exit in it): then the failure it catches is handled, as navigation2's
    ``catch (const std::exception &) {}`` around a deprecated parameter's read; one that
    rethrows or returns false makes the failure the caller's."""
    return not any(node.kind in _LEAVES or (
        node.kind == CursorKind.CALL_EXPR and node.spelling in _EXITS)
        for node in handler.walk_preorder())



def fewest(alternatives: list[tuple[tuple[Condition, ...], _Rest]]
           ) -> list[tuple[tuple[Condition, ...], _Rest]]:
    """Of the ways one call is made (its conditions, and what else it is made with),
    those no other one covers, in the order given: conditions that hold all of
    another's hold only where that one does, and the call is made there anyway; two
    made with the same rest that differ only in an ``if`` and its ``else`` (the same
    test at the same place) are one, under their common part."""
    work = list(alternatives)
    changed = True
    while changed and len(work) > 1:
        changed = False
        for i, (one, rest) in enumerate(work):
            for j, (other, other_rest) in enumerate(work):
                if i == j:
                    continue
                if set(other) <= set(one) and (set(other) < set(one) or j < i):
                    del work[i]  # ``one`` is covered
                    changed = True
                    break
                common = _branches_of(one, other) if rest == other_rest else None
                if common is not None:
                    work[min(i, j)] = (common, rest)
                    del work[max(i, j)]
                    changed = True
                    break
            if changed:
                break
    return work


def _branches_of(one: tuple[Condition, ...], other: tuple[Condition, ...]
                 ) -> tuple[Condition, ...] | None:
    """``one`` less the one condition in which it differs from ``other``, when that is
    an ``if`` in one and its ``else`` in the other; else None."""
    if len(one) != len(other):
        return None
    differ = [i for i, (a, b) in enumerate(zip(one, other, strict=True)) if a != b]
    if len(differ) != 1:
        return None
    a, b = one[differ[0]], other[differ[0]]
    if {a.statement, b.statement} != {"if", "else"} or (a.text, a.location) != (
            b.text, b.location):
        return None
    return (*one[:differ[0]], *one[differ[0] + 1:])

