"""The walk over a node's Python modules that finds ROS primitive calls.

Every function and method is walked once as an entry, with its parameters unknown, and
again wherever it is called in the package (``helper('scan')``, ``self.setup()``,
``Talker()`` runs ``__init__``) with the call's arguments bound, a few calls deep; a
function that is walked at one of its call sites does not count as an entry, so its
calls carry the caller's values and conditions. Statements are dispatched by node type
(one method per kind, one fallback), and calls are matched against the API tables.
A ``for`` loop over a known list, tuple or ``range`` of at most ``MAX_UNROLL`` items
(``MAX_UNROLL_OUTER`` for a loop inside no other unrolled one) is walked once per item,
so ``for side in ['left', 'right']`` gives one call per side.
"""

from __future__ import annotations

import ast
import dataclasses
import functools
import re
import sys
from collections.abc import Callable, Iterator

from ... import diagnostics as diag
from ...diagnostics import Diagnostic
from ...model.conditions import EACH_STATEMENT, PARAMETER_VALUE, Condition
from ...model.location import Location
from ...model.source import JOINED, PrimitiveCall, counted_mark
from ...model.values import Unknown, Value
from ...shell import MAX_WORDS, commands, split_words
from . import rclpy, rospy
from .api import Arg, PyFunction
from .conditions import condition, is_main_guard, name_test, source_text, tested_text
from .modules import ClassInfo, FunctionInfo, Loader, Module, add_import, api_modules, last_name
from .msg_types import ros_type
from .objects import (
    ELEMENT_OF,
    FIELD_OF,
    MAX_ALTERNATIVES,
    PROGRAM_ARGUMENT,
    PROGRAM_OPTION,
    TURN_FROM,
    TURN_OF,
    Alternatives,
    BoundMethod,
    Frame,
    Instance,
    NodeHandle,
    NodeMethod,
    ParamElement,
    ParamTurn,
    ParamValue,
    QoS,
    Record,
    Ref,
    Seq,
    SuperInit,
    alternative,
    options_under,
    param_type,
    plain_value,
    same_value,
    text_of,
)
from .qos import as_profile, with_policy
from .reach import Reach, imports_ros
from .scopes import COPIES as _COPIES
from .scopes import MAX_UNROLL, MAX_UNROLL_OUTER
from .specials import (
    dynamic_descriptor,
    evaluate,
    is_none,
    param_name,
    special_calls,
    type_only,
)
from .values import (
    MAX_CALL_DEPTH,
    NODE_NAME,
    RESOLVED,
    Evaluator,
    argument,
    in_namespace,
    literal_name,
    own_name,
    search_start,
    searched_name,
    unknown_params,
)

Conditions = tuple[Condition, ...]
MAX_STEPS = 200_000
_PARAM_KINDS = ("read", "write", "declare")
_CONVERSIONS = frozenset({"int", "float", "str", "bool"})
# a handler's exception type that catches a parameter read's failure (rospy's KeyError,
# rclpy's ParameterNotDeclaredException / ParameterUninitializedException, Exception)
_EXITS = frozenset({"exit", "_exit", "abort", "signal_shutdown", "shutdown"})
# the program of qt_gui that runs one plugin alone (``main(argv, standalone=...)``)
_QT_GUI_MAINS = frozenset({"rqt_gui.main.Main", "qt_gui.main.Main"})


def _goes_on(handler: ast.ExceptHandler) -> bool:
    """Whether an ``except`` block lets the code go on after its ``try`` (no ``raise``,
    ``return`` or exit in it): the failure it catches is then handled."""
    for node in ast.walk(handler):
        if isinstance(node, ast.Raise | ast.Return):
            return False
        if isinstance(node, ast.Call) and last_name(node.func) in _EXITS:
            return False
    return True


_CATCHES_FAILURE = re.compile(
    r"\b(?:KeyError|LookupError|Exception|BaseException|ParameterNotDeclaredException"
    r"|ParameterUninitializedException)\b")


class Walker:
    def __init__(self, loader: Loader) -> None:
        self.loader = loader
        self.evaluator = Evaluator(loader)
        self.calls: list[PrimitiveCall] = []
        self.diagnostics: list[Diagnostic] = []
        self._limit_reported = False
        # the ``if`` statement walked last, with its two conditions (``_block``)
        self._tested_if: tuple[ast.If, Condition, Condition] | None = None
        self._unrolled = 0  # unrolled loops the walk is in
        # the functions inlined, innermost last, each with whether it cannot reach a ROS
        # call (``Reach``; nor, then, can what it calls): the loops of such a function
        # are walked once, not unrolled (``_loop``)
        self._inlining: list[tuple[ast.AST | None, bool]] = [(None, False)]
        # the variables of the unrolled loops the walk is in, by frame: each holds one
        # known item per walk of the body (``_decided``)
        self._loop_names: list[tuple[int, frozenset[str]]] = []
        # the parameters of each function inlined at a call, by its frame, that its body
        # never assigns: each holds the call's argument all through it (``_decided``)
        self._fixed: dict[int, frozenset[str]] = {}
        # the ``if`` walked last whose test the walk decided, and the side it took
        self._decided_if: tuple[ast.If, list[ast.stmt]] | None = None
        self.rosname: str | None = None
        self.namespace: str | None = None
        self.anonymous = False
        # every fully known node name the code gives, in walk order, and where
        self.names: list[str] = []
        self.names_at: list[Location] = []
        # the names given to rclpy nodes (each a node of the process), in walk order, and
        # the names each Node subclass was given (for methods walked without a caller)
        self.rclpy_names: list[str] = []
        self._class_names: dict[int, list[str]] = {}
        # the ROS packages the node's package depends on whose code is not read, and
        # the classes of them said built (``_unseen_class``)
        self.unseen_packages: frozenset[str] = frozenset()
        # those of them the node's package.xml names (``_package_of_module``)
        self.unseen_dependencies: frozenset[str] = frozenset()
        self._classes_said: dict[str, tuple[Location, str]] = {}
        # classes built of Python packages neither the workspace holds nor a dependency
        # names (``_unseen_class``): ROS code when the program makes no node itself
        self._classes_elsewhere: dict[str, Location] = {}
        # the first call of each top-level module the reader finds nowhere and no list
        # knows as a library, in a ROS 1 program (``_unread_module``): where, what
        self._modules_elsewhere: dict[str, tuple[Location, str]] = {}
        self._ros_init = False  # rclpy.init() is called
        self._gui_plugin = False  # rqt_gui runs a plugin alone (``_standalone_plugin``)
        self._launches_said: set[Location] = set()  # where roslaunch runs (PY_LAUNCHES)
        self._imports_said: set[Location] = set()  # PY_DYNAMIC_IMPORT
        self._functions_said: set[Location] = set()  # PY_FUNCTION_UNSEEN
        # the cuts of the walk under way (``_collect``) and those said (PY_CALL_DEPTH)
        self._cuts: list[Diagnostic] = []
        self._cuts_said: set[Location] = set()
        self._reach = Reach()
        # the classes the walk constructs, and those they derive from (ids)
        self._constructed: set[int] = set()
        self.steps = 0
        self._inlined: set[int] = set()
        self._active: set[int] = set()
        self._nested: list[FunctionInfo] = []
        self._used_classes: list[ClassInfo] = []
        self.main: set[str] = set()
        # where the program starts: the function a console_scripts entry point names
        # (``main`` of ``pkg.module:main``), "" for a script Python runs whole, None when
        # not known (``_unreached``)
        self.entry: str | None = None
        # the calls whose result is a condition (ids of their ast.Call nodes)
        self._tested: set[int] = set()
        # the ``try`` conditions whose handlers catch a parameter's failure (KeyError,
        # rclpy's exceptions, Exception or anything): a read there is prepared for it
        self._handled: set[Condition] = set()
        # reads whose value the code converts (``int(rospy.get_param('~baud', '500000'))``):
        # any value the conversion takes will do, so the read has no type of its own
        self._converted: set[int] = set()
        # imports whose module only tells where it is (``__import__(pkg).__path__``)
        self._located: set[int] = set()
        # the conditions under which each QoS profile held by a local or an attribute of
        # ``self`` was made (``_qos_assigned``)
        self._qos_made: dict[tuple[int, str], Conditions] = {}

    # -- entries ------------------------------------------------------------------------

    def run(self, modules: list[Module]) -> None:
        self.main = {m.path for m in modules}
        entries: list[tuple[FunctionInfo, list[PrimitiveCall], list[Diagnostic]]] = []
        for module in modules:
            calls, cuts = self._collect(lambda m=module: self._block(
                m.tree.body, Frame(m, top=True), ()))
            self.calls.extend(calls)
            self._said_cuts(cuts)
        done: set[int] = set()
        queue: list[FunctionInfo] = []
        unreached = self._unreached(modules)
        for module in modules:
            queue.extend(info for info in module.functions.values()
                         if id(info.node) not in unreached)
            for cls in module.classes.values():
                queue.extend(cls.methods.values())
        # the methods of the classes of other modules the walk builds, not yet named
        pending: list[FunctionInfo] = []
        while queue or self._nested or self._used_classes or pending:
            if not queue:
                if self._nested:
                    queue.append(self._nested.pop(0))
                elif self._used_classes:
                    pending.extend(self._used_classes.pop(0).methods.values())
                else:
                    named = self._named(done)
                    queue = [info for info in pending if self._reachable(info, named)]
                    if not queue:
                        break
                    pending = [info for info in pending if info not in queue]
                continue
            info = queue.pop(0)
            if id(info.node) in done:
                continue
            done.add(id(info.node))
            entries.append((info, *self._collect(lambda i=info: self._entry(i))))
        self._unseen_said()
        unbuilt = self._unbuilt(modules)
        for info, calls, cuts in entries:
            if id(info.node) not in self._inlined and (info.cls is None
                                                       or id(info.cls) not in unbuilt):
                self.calls.extend(calls)
                self._said_cuts(cuts)

    def _unreached(self, modules: list[Module]) -> set[int]:
        """The module functions of the executable's modules (ids) that no code its entry
        (``entry``) reaches calls or names: not walked, so their calls are not the
        node's (sailbot's ``trigger_error_transition(node)``, which nothing calls, makes
        no ``change_state`` client). Reached: the module's own statements (a script's,
        ``if __name__ == '__main__':`` with them), the entry function, every class's
        code, each function decorated (a decorator may keep it), and, in turn, every
        function whose name any of these uses, as a call or as a value (handed to a
        thread, a timer, a dict of handlers, a string ``getattr`` may look up); every
        module read that is not the executable's counts whole. None when the entry is
        not known or when code looks names up in a way not read (``globals()``,
        ``eval``, ``getattr`` of a computed name, ``sys.modules``): any may run."""
        if self.entry is None or any(_looks_up_names(m.tree)
                                     for m in self.loader.modules.values() if m is not None):
            return set()
        functions = {id(info.node): info for module in modules
                     for info in module.functions.values()}
        named = {self.entry.split(".")[0]} if self.entry else set()
        for module in self.loader.modules.values():
            if module is not None:
                named |= _attribute_names(module.tree, set(functions)
                                          if module in modules else set(), variables=True)
        unreached = set(functions)
        grown = True
        while grown:
            grown = False
            for key in list(unreached):
                info = functions[key]
                if info.node.name in named or info.node.decorator_list:
                    unreached.discard(key)
                    named |= _attribute_names(info.node, set(), variables=True)
                    grown = True
        return unreached

    def _named(self, done: set[int]) -> set[str]:
        """The attribute names (and identifier strings, for ``getattr``) the code may use:
        in every module read, outside the methods of classes of other modules that the
        walk has not run (``done``: walked as entries; ``_inlined``: at call sites)."""
        named: set[str] = set()
        for module in self.loader.modules.values():
            if module is None:
                continue
            walked = module.path in self.main
            skipped = set() if walked else {
                id(method.node) for cls in module.classes.values()
                for method in cls.methods.values()
                if id(method.node) not in done and id(method.node) not in self._inlined}
            named |= _attribute_names(module.tree, skipped)
        return named

    def _reachable(self, info: FunctionInfo, named: set[str]) -> bool:
        """Whether a method of a class of another module the walk builds may run: a
        special method, one whose name the code uses, or any of a class with a base the
        walk cannot read (whose code may call it: ``threading.Thread.run``). The others
        (intera_interface's ``RobotEnable.enable``, a publisher of ``robot/set_super_enable``,
        in a node that builds a RobotEnable to read its state) are never called."""
        name = info.node.name
        if name.startswith("__") or name in named or info.cls is None:
            return True
        ev = self.evaluator
        return any(not isinstance(base, ClassInfo) and not (
                       isinstance(written, ast.Name) and written.id == "object")
                   for cls in ev.mro(info.cls)
                   for written, base in zip(cls.node.bases, ev.bases(cls), strict=True))

    def _unbuilt(self, modules: list[Module]) -> set[int]:
        """The node classes of the executable's modules that nothing it runs constructs,
        when it makes its node(s) otherwise (a module with a class per node whose
        ``main()`` builds one): they are no node of the process and make no call, as a
        C++ class the node never builds; their names are dropped (a node class the code
        may build out of our sight keeps its calls where nothing else names the node)."""
        ev = self.evaluator
        unbuilt = {id(cls) for module in modules for cls in module.classes.values()
                   if id(cls) not in self._constructed and ev.is_node_class(cls)}
        theirs = {name for key in unbuilt for name in self._class_names.get(key, ())}
        others = {name for key, names in self._class_names.items() if key not in unbuilt
                  for name in names}
        dropped = theirs - others
        kept = [i for i, name in enumerate(self.names) if name not in dropped]
        if not unbuilt or not kept:
            return set()
        self.names_at = [self.names_at[i] for i in kept]
        self.names = [self.names[i] for i in kept]
        self.rclpy_names = [name for name in self.rclpy_names if name not in dropped]
        if self.rosname in dropped:
            self.rosname, self.namespace = self.names[0], None
        return unbuilt

    def _collect(self, walk: object) -> tuple[list[PrimitiveCall], list[Diagnostic]]:
        """The calls of one walk, and its cuts (``_cut``): kept or dropped together."""
        saved, self.calls = self.calls, []
        saved_cuts, self._cuts = self._cuts, []
        try:
            walk()  # type: ignore[operator]
            return self.calls, self._cuts
        finally:
            self.calls, self._cuts = saved, saved_cuts

    def _said_cuts(self, cuts: list[Diagnostic]) -> None:
        for cut in cuts:
            if cut.location not in self._cuts_said:
                self._cuts_said.add(cut.location)
                self.diagnostics.append(cut)

    def _entry(self, info: FunctionInfo) -> None:
        instance = self.evaluator.new(info.cls) if info.cls is not None else None
        frame = Frame(info.module, unknown_params(info), instance, owner=info.cls)
        self._active.add(id(info.node))
        try:
            self._block(info.node.body, frame, ())
        finally:
            self._active.discard(id(info.node))

    # -- statements ---------------------------------------------------------------------

    def _block(self, body: list[ast.stmt], frame: Frame, conds: Conditions) -> None:
        """The statements of ``body`` in turn; after ``if test: return`` (``continue``,
        ``break``) the rest runs under ``else`` test, after ``if test: ... else:
        return`` under test, unless that side fails (``raise``, an exit, an error logged,
        ``return False``): the rest is then the function's work when it succeeds; nor
        when the test guards what the method does once (``_guards_first_time``)."""
        for index, statement in enumerate(body):
            self.steps += 1
            limit = f"{MAX_STEPS} statements walked" if self.steps > MAX_STEPS else \
                self.evaluator.limited
            if limit is not None:
                if not self._limit_reported:
                    self._limit_reported = True
                    if imports_ros(self.loader, self.unseen_packages):
                        self.diagnostics.append(diag.make(
                            "PY_TOO_COMPLEX", self._where(frame, statement), limit=limit))
                return
            handler = getattr(self, "_" + type(statement).__name__, self._statement)
            handler(statement, frame, conds)
            if isinstance(statement, ast.If) and self._decided_if is not None and (
                    self._decided_if[0] is statement):
                if _leaves(self._decided_if[1]) is not None:
                    return  # the side taken leaves: the rest does not run
                continue
            if isinstance(statement, ast.If) and self._tested_if is not None and (
                    self._tested_if[0] is statement):
                _, yes, no = self._tested_if
                first, second = _leaves(statement.body), _leaves(statement.orelse)
                if first == "done" and second is None:
                    if statement.orelse or not _guards_first_time(
                            statement.test, body[index + 1:], frame.module.tree):
                        conds = (*conds, no)
                elif second == "done" and first is None:
                    conds = (*conds, yes)

    def _statement(self, statement: ast.stmt, frame: Frame, conds: Conditions) -> None:
        """Fallback: the calls in the statement's expressions, in source order."""
        for child in ast.iter_child_nodes(statement):
            if isinstance(child, ast.expr):
                self._expr(child, frame, conds)

    def _Assign(self, statement: ast.Assign | ast.AnnAssign | ast.AugAssign, frame: Frame,
                conds: Conditions) -> None:
        before = len(self.calls)
        if statement.value is not None:
            self._expr(statement.value, frame, conds)
        self._stored(statement, frame, self.calls[before:])
        self.evaluator.assign(statement, frame)
        self._choice_assigned(statement, frame)
        targets = _targets(statement)
        for target in targets:
            self._qos_assigned(target, frame, conds)

    def _choice_assigned(self, statement: ast.stmt, frame: Frame) -> None:
        """``x = A if test else B`` with a test not known statically: the local holds
        both values, each under its side of the test, as after ``if test: x = A else:
        x = B`` (webots_ros2's ``state_topic = '/state' if old else
        '/controller_state'``)."""
        if not (isinstance(statement, ast.Assign) and len(statement.targets) == 1
                and isinstance(statement.targets[0], ast.Name)
                and isinstance(statement.value, ast.IfExp)):
            return
        name, choice = statement.targets[0].id, statement.value
        ev = self.evaluator
        if not isinstance(frame.locals.get(name), Unknown) or not isinstance(
                ev.eval(choice.test, frame), Unknown):
            return  # the evaluator decided the test
        text = self._text(frame, choice.test)
        where = self._where(frame, choice)
        options = (*options_under(ev.eval(choice.body, frame), condition("if", text, where)),
                   *options_under(ev.eval(choice.orelse, frame), condition("else", text, where)))
        if len(options) <= MAX_ALTERNATIVES and all(alternative(v) for v, _ in options):
            frame.locals[name] = Alternatives(options)

    def _qos_assigned(self, target: ast.expr, frame: Frame, conds: Conditions) -> None:
        """Where a QoS profile is bound to a local or an attribute of ``self``, and its
        policies set after (``qos.durability = ...``): a policy set under a condition
        the profile was not made under may not be set, so it is unknown, as a C++
        setter that may not run leaves its field."""
        ev = self.evaluator
        if isinstance(target, ast.Attribute) and (target.attr == "depth"
                                                  or target.attr in rclpy.POLICIES):
            holder = as_profile(ev.eval(target.value, frame))
            key = self._holder(target.value, frame)
            made = self._qos_made.get(key) if key is not None else None
            if holder is not None and any(c not in (made or ()) for c in conds):
                unset = with_policy(holder, target.attr, None)
                if unset is not None:
                    ev.bind(target.value, unset, frame)
            return
        key = self._holder(target, frame)
        if key is not None and as_profile(ev.eval(target, frame)) is not None:
            self._qos_made[key] = conds

    @staticmethod
    def _holder(expr: ast.expr, frame: Frame) -> tuple[int, str] | None:
        """A local (in its frame) or an attribute of ``self`` (of its instance)."""
        if isinstance(expr, ast.Name):
            return id(frame), expr.id
        if isinstance(expr, ast.Attribute) and isinstance(expr.value, ast.Name) \
                and expr.value.id == "self" and frame.instance is not None:
            return id(frame.instance), expr.attr
        return None

    def _stored(self, statement: ast.Assign | ast.AnnAssign | ast.AugAssign, frame: Frame,
                made: list[PrimitiveCall]) -> None:
        """``self.x = self.get_parameter("x").value`` (rospy's ``get_param``, a
        ``declare_parameter(..).value``): the read names the member it stores into
        (``PrimitiveCall.variable``), as the C++ extraction does, so a condition over
        ``self.x`` is decided from the parameter, when this is the member's one
        assignment in its file and the statement's one read, written in it."""
        targets = _targets(statement)
        if isinstance(statement, ast.AugAssign) or len(targets) != 1:
            return
        member = _self_member(targets[0])
        last = getattr(statement, "end_lineno", None) or statement.lineno
        reads = [c for c in made if c.kind in ("read", "declare")]
        if member is None or len(reads) != 1 or not (
            statement.lineno <= reads[0].location.line <= last
            and reads[0].location.file == self._where(frame, statement).file
        ):
            return
        at = (reads[0].location.line, reads[0].location.column - 1)
        if not _read_as_is(statement.value, at):
            return
        if reads[0].kind == "read" and member in _mapping_members(frame.module):
            # the value is used as a dict (``self.x.items()``): whatever type its default
            # has, the node reads a dict (AutoRally's autorally_controller.py reads
            # ``get_param("~chassisCommandProirities", [])``, then sorts its ``items()``)
            reads[0].type = "dict"
        elif reads[0].kind == "read" and reads[0].type == "str" and reads[0].default == "" \
                and member in _iterated_members(frame.module):
            # an empty text as the default of a value the code walks element by element
            # (``for c in sorted(self.joints)``) stands for "none": rospy's read has no
            # type, and the node reads a list (rbx1's dynamixel_joint_state_publisher.py
            # reads ``get_param(namespace + '/joints', '')``, the launch file loads a list)
            reads[0].type = "list"
        if _member_writes(frame.module).get(member) == 1:
            # rclpy's ``declare_parameter`` / ``get_parameter`` give the Parameter, whose
            # ``.value`` a condition reads (``self.origin_param.value == 'auto'``)
            reads[0].variable = member + PARAMETER_VALUE if (
                isinstance(statement.value, ast.Call) and isinstance(
                    statement.value.func, ast.Attribute)
                and statement.value.func.attr in _PARAMETER_OBJECTS) else member

    _AnnAssign = _Assign
    _AugAssign = _Assign

    def _If(self, statement: ast.If, frame: Frame, conds: Conditions) -> None:
        self._test(statement.test)
        self._expr(statement.test, frame, conds)
        if is_main_guard(statement.test):
            self._block(statement.body, frame, conds)
            self._block(statement.orelse, frame, conds)
            return
        decided = self._decided(statement.test, frame)
        self._tested_if = self._decided_if = None
        if decided is not None:  # one side runs, under no condition of the test
            side = statement.body if decided else statement.orelse
            self._block(side, frame, conds)
            self._decided_if = (statement, side)
            return
        text = tested_text(frame.module.lines, statement.test,
                           lambda arg: literal_name(self.evaluator.eval(arg, frame)))
        where = self._where(frame, statement)
        held = self._held(statement.test, frame)
        yes, no = condition("if", text, where, held), condition("else", text, where, held)
        # a presence test whose absent side fails: the other side runs whenever the
        # function goes on (the parameter is required)
        required = None if _PRESENCE.search(text) is None else (
            "if" if _leaves(statement.orelse) == "failed" else
            "else" if _leaves(statement.body) == "failed" else None)
        if required is None and _first_time_if(statement, frame.module.tree):
            required = "if"  # a lazy initialisation: its block runs the first time
        # the locals, and the attributes of ``self`` (interbotix_xs_modules' core: ``if
        # self.robot_name is None: self.robot_name = robot_model``, with ``robot_name`` an
        # option argparse parses), each path sets: both, joined after
        attrs = frame.instance.attrs if frame.instance is not None else {}
        before, attrs_before = dict(frame.locals), dict(attrs)
        self._block(statement.body, frame, conds if required == "if" else (*conds, yes))
        taken, attrs_taken = dict(frame.locals), dict(attrs)
        frame.locals.clear()  # the other path starts from what was before the if
        frame.locals.update(before)
        attrs.clear()
        attrs.update(attrs_before)
        if statement.orelse:
            self._block(statement.orelse, frame, conds if required == "else" else (*conds, no))
        other, attrs_other = dict(frame.locals), dict(attrs)
        frame.locals.clear()
        frame.locals.update(_joined(before, taken, other, yes, no))
        attrs.clear()
        attrs.update(_joined(attrs_before, attrs_taken, attrs_other, yes, no))
        self._tested_if = (statement, yes, no)

    def _decided(self, test: ast.expr, frame: Frame) -> bool | None:
        """The value of an ``if``'s test over the variables of the unrolled loops the walk
        is in, which hold one known item per walk of the body, and literals alone
        (``for side in ['left', 'right']: if side == 'skip': continue``): decided for
        that item, as a C++ test over constants is (``Condition.constants``); so is one
        over the parameters of a function inlined at a call that its body never assigns
        and that the call gives a literal (fetchit_challenge's ``SchunkMachineServer(
        is_simulated=True)``, whose ``__init__`` makes the simulation's publishers ``if
        is_simulated:`` and the real machine's otherwise). None for any other test, or
        one whose value is not known. A test of ``__name__`` against a name the module
        cannot have is decided too (``name_test``)."""
        named = name_test(test, frame.module.path)
        if named is not None:
            return named
        names = {name for at, given in self._loop_names if at == id(frame) for name in given}
        names |= {name for name in self._fixed.get(id(frame), ())
                  if name in frame.locals and _literal(frame.locals[name])}
        names |= {node.id for node in ast.walk(test) if isinstance(node, ast.Name)
                  and node.id not in frame.locals and node.id not in names
                  and self._computed_global(node.id, frame.module)}
        if not names:
            return None
        for node in ast.walk(test):
            if (isinstance(node, ast.Name) and node.id not in names) or not isinstance(
                    node, ast.Name | ast.Constant | ast.Compare | ast.BoolOp | ast.UnaryOp
                    | ast.cmpop | ast.boolop | ast.unaryop | ast.expr_context | ast.Tuple
                    | ast.List):
                return None
        if not any(isinstance(node, ast.Name) for node in ast.walk(test)):
            return None  # a test of literals alone (``if False:``) is the code's own
        value = self.evaluator.eval(test, frame)
        plain = value.literal if isinstance(value, Value) else value
        return bool(plain) if isinstance(plain, bool | int | float | str) else None

    def _computed_global(self, name: str, module: Module) -> bool:
        """Whether ``name`` is a global the module computes once at its top level, to a
        known literal, and no function rebinds (``global``): carla ros-bridge's
        ``ROS_VERSION = roscomp.get_ros_version()``, from the distribution's
        ROS_VERSION, tested in its nodes' methods (``if ROS_VERSION == 1:``), which
        hold the same value there. Not one written as a literal (``DEBUG = False``: the
        code's own switch, kept as a condition), nor one assigned again
        (``_rebound_globals``); the caller leaves out the frame's locals."""
        written = module.constants.get(name)
        if written is None or (isinstance(written, ast.Constant | ast.UnaryOp)
                               and name not in module.import_guarded):
            # (but a flag a ROS import guard sets is what running as a node makes it:
            # kyubic_ros' dashboard's ``ROS_AVAILABLE``, ``modules._ros_import_guard``)
            return False
        rebound = _rebound_globals(module.tree)
        if name in rebound:
            return False
        value = self.evaluator.eval(ast.Name(id=name, ctx=ast.Load()), Frame(module))
        plain = value.literal if isinstance(value, Value) else value
        return isinstance(plain, bool | int | float | str)

    def _held(self, test: ast.expr, frame: Frame) -> tuple[tuple[str, str], ...] | None:
        """What ``test`` reads that holds a parameter's value, as the graph decides a
        condition by (``Condition.parameters``): each local whose value here is a
        parameter read's (``num_agents = self.get_parameter('num_agent').value``, then
        ``if num_agents == 2``), and each read written in the test itself
        (``if self.get_parameter('kb_teleop').value``, ``if rospy.get_param('~x', 1)``),
        by its source text; with the parameter named as its read call is. A member of
        ``self`` is not one (its read names it: ``PrimitiveCall.variable``)."""
        found: dict[str, str] = {}
        stack: list[ast.AST] = [test]
        while stack:
            node = stack.pop()
            if isinstance(node, ast.Name) and node.id in frame.locals:
                value = frame.locals[node.id]
                key = node.id
            elif isinstance(node, ast.Call | ast.Attribute) and _self_member(node) is None:
                value = self.evaluator.eval(node, frame)
                key = self._text(frame, node)
            else:
                stack.extend(ast.iter_child_nodes(node))
                continue
            if isinstance(value, ParamValue) and "?" not in value.name:
                version = frame.module.version
                found[key] = param_name(Value.of(value.name)) if version == 2 else value.name
            elif not isinstance(node, ast.Name):
                stack.extend(ast.iter_child_nodes(node))
        return tuple(sorted(found.items())) or None

    def _For(self, statement: ast.For | ast.AsyncFor, frame: Frame, conds: Conditions) -> None:
        self._expr(statement.iter, frame, conds)
        self._loop(statement.target, statement.iter, frame, self._where(frame, statement),
                   lambda loop: self._block(statement.body, frame, (*conds, *loop)),
                   whole=not _leaves_early(statement.body),
                   builds=self._inlining[-1][1] and _builds(statement, self._inlining[-1][0]),
                   uses_item=_names_target(statement.body, statement.target)
                   or _stores(statement.body))
        self._block(statement.orelse, frame, conds)

    def _loop(self, target: ast.expr, over: ast.expr, frame: Frame, where: Location,
              body: Callable[[tuple[Condition, ...]], None], whole: bool = True,
              builds: bool = False, uses_item: bool = True) -> None:
        """Walk a loop's body (``body(loop conditions)``) once per item of a known, short
        sequence (unrolled), else once with the variable unknown; over a list
        parameter's value, or a dict parameter's ``values()`` / ``items()``, once with
        the variable its element (``ParamElement``; an entry's key is unknown). An
        unrolled loop over items that are there, whose body runs ``whole`` (no
        ``break``, ``return`` or ``raise`` of its own), runs it for each for sure: no
        condition (as a C++ loop over a list parameter's elements).

        In a function that cannot reach a ROS call (``_inlining``) a loop is walked once,
        unless it ``builds`` a container item by item (``_builds``: a list of topic
        names a helper appends to): a loop there names no call, and walking it once per
        item, in each call of the function, made a driver's device code (probing each
        baud rate of each port, reading each message) exhaust the walk before the
        node's own code (ethzasl_xsens_driver's MTDevice: 4 of its 23 calls found).

        A loop whose body never names its variable and stores nothing itself (``for _
        in range(200): self.run()``: no assignment, no container changed in place)
        differs from turn to turn only by what the functions it calls leave to the next
        turn: it is unrolled until a turn makes the very calls the turn before made, the
        later turns being walks of the same (quadruped_ctrl's simulator calls its
        ``run()`` 200 times in its reset, which exhausted the walk: the node was
        partial); a counter a turn advances (``i += 1``), a list it fills, still gives
        one walk per turn."""
        ev = self.evaluator
        if id(over) not in ev.fixed:
            walked = ev.eval(over, frame)
            if isinstance(walked, Alternatives):
                self._loop_per_value(target, over, frame, where, body, walked, whole, builds)
                return
        text = f"{self._text(frame, target)} in {self._text(frame, over)}"
        loop: tuple[Condition, ...] = (condition("for", text, where),)
        items = None if self._inlining[-1][1] and not builds else ev.iteration(
            over, frame, MAX_UNROLL if self._unrolled else MAX_UNROLL_OUTER)
        if items and whole:
            loop = ()
        if items is None:
            element = self._element_loop(target, over, frame)
            if element is not None:
                # a loop over a list parameter's value: a call named by its variable is
                # one call per element the configuration gives it (the graph expands it,
                # and the loop, "for each", is then no condition of those calls)
                loop = (condition(EACH_STATEMENT, text, where),)
                items = (element,)
        # a loop over a known, short sequence is unrolled: one walk of the body per item
        self._unrolled += 1 if items else 0
        if items:
            self._loop_names.append((id(frame), frozenset(
                n.id for n in ast.walk(target) if isinstance(n, ast.Name))))
        try:
            previous: list[PrimitiveCall] | None = None
            for item in items if items else (Unknown("loop variable"),):
                start = len(self.calls)
                ev.bind(target, item, frame)
                body(loop)
                if not uses_item:
                    turn = self.calls[start:]
                    if turn == previous:
                        break
                    previous = turn
        finally:
            self._unrolled -= 1 if items else 0
            if items:
                self._loop_names.pop()
        if items:  # after the loop its variable is unknown to the rest of the walk
            ev.bind(target, Unknown("loop variable"), frame)

    def _loop_per_value(self, target: ast.expr, over: ast.expr, frame: Frame,
                        where: Location, body: Callable[[tuple[Condition, ...]], None],
                        walked: Alternatives, whole: bool, builds: bool) -> None:
        """A loop over what differs per path (a local an ``if`` set, a helper's return,
        ``Alternatives``): the loop once per value, under its path's conditions, as a
        call given such a value is one call per value; a literal empty list on a path
        (a helper's default) walks nothing there (joint_state_publisher's ``for source
        in get_param("source_list", [])``: per element of ``~source_list`` where it is
        set, else of ``source_list``; the subscription was ``?``)."""
        ev = self.evaluator
        try:
            for value, under in walked.options:
                if isinstance(value, Seq) and not value.items:
                    continue
                ev.fixed[id(over)] = value
                self._loop(target, over, frame, where, _under(body, under), whole, builds)
        finally:
            ev.fixed.pop(id(over), None)

    def _element_loop(self, target: ast.expr, over: ast.expr, frame: Frame) -> object:
        """What a loop's variable holds when the loop is over a parameter's elements:
        ``ParamElement`` (``for x in p``, ``for x in p.values()``), a key unknown and
        the element (``for k, x in p.items()``); else None."""
        ev = self.evaluator
        turn = self._turn_loop(target, over, frame)
        if turn is not None:
            return turn
        while isinstance(over, ast.Call) and isinstance(over.func, ast.Name) \
                and over.func.id in _COPIES and len(over.args) == 1 and not over.keywords \
                and isinstance(ev.eval(over.func, frame), Unknown):
            # ``sorted(p)``, ``list(p)``, ...: the elements of ``p`` in an order of their
            # own (rbx1's dynamixel_joint_state_publisher.py: ``for controller in
            # sorted(self.joints)``)
            over = over.args[0]
        walked = ev.eval(over, frame)
        if isinstance(walked, ParamValue):
            return ParamElement(walked.name) if isinstance(target, ast.Name) else None
        if not (isinstance(over, ast.Call) and isinstance(over.func, ast.Attribute)
                and over.func.attr in ("items", "values") and not over.args):
            return None
        owner = ev.eval(over.func.value, frame)
        if not isinstance(owner, ParamValue):
            return None
        if over.func.attr == "values":
            return ParamElement(owner.name) if isinstance(target, ast.Name) else None
        if isinstance(target, ast.Tuple) and len(target.elts) == 2 and isinstance(
                target.elts[1], ast.Name):
            return Seq((Unknown("loop variable"), ParamElement(owner.name)))
        return None

    def _turn_loop(self, target: ast.expr, over: ast.expr, frame: Frame) -> ParamTurn | None:
        """``ParamTurn`` of a loop ``for i in range(n)`` (or ``range(k, n)``, ``k`` a
        literal integer) where ``n`` holds a parameter's value, or is ``len(p)`` of a list
        parameter's value ``p`` (tauv's thrusters subscribe ``f'vehicle/thrusters/{i}/
        target_thrust'`` for ``i in range(len(self._thruster_channels))``); else None."""
        if not (isinstance(target, ast.Name) and isinstance(over, ast.Call)
                and isinstance(over.func, ast.Name) and over.func.id == "range"
                and 1 <= len(over.args) <= 2 and not over.keywords
                and not any(isinstance(a, ast.Starred) for a in over.args)):
            return None
        start = 0
        if len(over.args) == 2:
            first = over.args[0]
            if not (isinstance(first, ast.Constant) and type(first.value) is int
                    and first.value >= 0):
                return None
            start = first.value
        last = over.args[-1]
        counted = last.args[0] if (
            isinstance(last, ast.Call) and isinstance(last.func, ast.Name)
            and last.func.id == "len" and len(last.args) == 1 and not last.keywords
            and not isinstance(last.args[0], ast.Starred)
            and isinstance(self.evaluator.eval(last.func, frame), Unknown)) else None
        bound = self.evaluator.eval(counted if counted is not None else last, frame)
        return ParamTurn(bound.name, start, length=counted is not None) if isinstance(
            bound, ParamValue) else None

    _AsyncFor = _For

    def _While(self, statement: ast.While, frame: Frame, conds: Conditions) -> None:
        self._test(statement.test)
        self._expr(statement.test, frame, conds)
        if self._entered(statement.test, frame):
            # its first turn runs whenever the loop is reached (a retry loop, ``loaded =
            # False`` then ``while not loaded:``): what it makes, under no condition of it
            self._block(statement.body, frame, conds)
        else:
            loop = condition("while", self._text(frame, statement.test),
                             self._where(frame, statement))
            self._block(statement.body, frame, (*conds, loop))
        self._block(statement.orelse, frame, conds)

    def _entered(self, test: ast.expr, frame: Frame) -> bool:
        """Whether a ``while`` loop's test holds where the walk reaches the loop: a test
        of the function's locals alone (and literals; ``not``, ``and`` / ``or``,
        comparisons), each holding a literal the walk knows there (rosbridge_suite's
        rosbridge_tcp: ``loaded = False`` then ``while not loaded:``, its node built in
        the body). Not a test of a global, a member or a call, nor of a local not known
        there (a branch's, a call's value): false then, the loop kept as a condition."""
        names = {node.id for node in ast.walk(test) if isinstance(node, ast.Name)}
        if not names or any(name not in frame.locals or not _literal(frame.locals[name])
                            for name in names):
            return False
        for node in ast.walk(test):
            if not isinstance(node, ast.Name | ast.Constant | ast.Compare | ast.BoolOp
                              | ast.UnaryOp | ast.cmpop | ast.boolop | ast.unaryop
                              | ast.expr_context):
                return False
        value = self.evaluator.eval(test, frame)
        plain = value.literal if isinstance(value, Value) else value
        return isinstance(plain, bool | int | float | str) and bool(plain)

    def _Try(self, statement: ast.Try, frame: Frame, conds: Conditions) -> None:
        attempt = condition("try", "", self._where(frame, statement))
        if any((handler.type is None or _CATCHES_FAILURE.search(
                self._text(frame, handler.type))) and _goes_on(handler)
               for handler in statement.handlers):
            self._handled.add(attempt)
        self._block(statement.body, frame, (*conds, attempt))
        tried = _state(frame)
        for handler in statement.handlers:
            text = self._text(frame, handler.type) if handler.type is not None else ""
            caught = condition("except", text, self._where(frame, handler))
            self._block(handler.body, frame, (*conds, caught))
        _fallen_back(frame, tried)
        self._block(statement.orelse, frame, (*conds, attempt))
        self._block(statement.finalbody, frame, conds)

    _TryStar = _Try

    def _With(self, statement: ast.With | ast.AsyncWith, frame: Frame,
              conds: Conditions) -> None:
        for item in statement.items:
            self._expr(item.context_expr, frame, conds)
            if item.optional_vars is not None:
                self.evaluator.bind(item.optional_vars,
                                    self.evaluator.eval(item.context_expr, frame), frame)
        self._block(statement.body, frame, conds)

    _AsyncWith = _With

    def _Match(self, statement: ast.Match, frame: Frame, conds: Conditions) -> None:
        self._expr(statement.subject, frame, conds)
        match = condition("match", self._text(frame, statement.subject),
                          self._where(frame, statement))
        for case in statement.cases:
            label = condition("case", self._text(frame, case.pattern),
                              self._where(frame, case.pattern))
            self._block(case.body, frame, (*conds, match, label))

    def _FunctionDef(self, statement: ast.FunctionDef | ast.AsyncFunctionDef, frame: Frame,
                     conds: Conditions) -> None:
        if frame.top:
            return
        owner = frame.instance.cls if frame.instance is not None else None
        info = FunctionInfo(statement, frame.module, None, frame.locals)
        if owner is not None:
            frame.locals.setdefault("self", frame.instance)
        frame.locals[statement.name] = info
        if all(n.node is not statement for n in self._nested):
            self._nested.append(info)

    _AsyncFunctionDef = _FunctionDef

    def _ClassDef(self, statement: ast.ClassDef, frame: Frame, conds: Conditions) -> None:
        """A class statement runs its body once, where it is (Python builds the class
        then): its own statements, not the functions it defines, are walked
        in a namespace of their own (mbzirc2020's parser_c2 reads ``~UGV_data`` in its
        class body, ``ugv_file = rospy.get_param('~UGV_data')``: no read was seen, and
        the launch file's parameter was a false parameter-set-not-read); a class it
        defines runs its own body in turn."""
        own = [s for s in statement.body if not isinstance(
            s, ast.FunctionDef | ast.AsyncFunctionDef)]
        if any(not _is_docstring(s) for s in own):
            self._block(own, Frame(frame.module, depth=frame.depth), conds)

    def _Import(self, statement: ast.Import | ast.ImportFrom, frame: Frame,
                conds: Conditions) -> None:
        if frame.top:
            return
        imports: dict[str, str] = {}
        local: dict[str, tuple[str, str | None]] = {}
        add_import(frame.module, self.loader, statement, imports, local)
        for name, qualname in imports.items():
            frame.locals[name] = Ref(qualname)
        for name in local:
            frame.module.local_imports.setdefault(name, local[name])

    _ImportFrom = _Import

    # -- calls --------------------------------------------------------------------------

    def _test(self, expr: ast.expr) -> None:
        """Note the call ``expr`` is (through ``not``): its result is a condition."""
        while isinstance(expr, ast.UnaryOp) and isinstance(expr.op, ast.Not):
            expr = expr.operand
        if isinstance(expr, ast.Call):
            self._tested.add(id(expr))

    def _expr(self, expr: ast.expr, frame: Frame, conds: Conditions) -> None:
        assigned = self._setattr(expr, frame) if isinstance(expr, ast.Call) else None
        if assigned is not None:
            self._Assign(assigned, frame, conds)
            return
        for node in ast.walk(expr):  # operands of ``x if c else y``, ``and`` / ``or``, ``not``
            if isinstance(node, ast.IfExp):
                self._test(node.test)
            elif isinstance(node, ast.BoolOp):
                for value in node.values:
                    self._test(value)
            elif isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.Not):
                self._test(node.operand)
            elif isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and (
                node.func.id in _CONVERSIONS and len(node.args) == 1 and not node.keywords
                and isinstance(node.args[0], ast.Call)
            ):
                self._converted.add(id(node.args[0]))
            elif isinstance(node, ast.Attribute) and node.attr in _MODULE_PLACE and (
                    isinstance(node.value, ast.Call)):
                self._located.add(id(node.value))
        calls: list[ast.Call] = []
        comprehensions: list[_Comprehension] = []
        _outside_comprehensions(expr, calls, comprehensions)
        calls.sort(key=lambda c: (c.lineno, c.col_offset))
        for call in calls:
            self._call(call, frame, conds)
        for made in comprehensions:
            self._comprehension(made, frame, conds)

    def _comprehension(self, made: _Comprehension, frame: Frame, conds: Conditions) -> None:
        """A list, set, dict or generator comprehension walked as the ``for`` loops it
        is (``[rospy.Publisher(t + '/cmd', ...) for t in topics]``: one call per element
        of the list parameter ``topics``), each ``if`` of it a condition; its variables
        are its own, as in Python 3."""
        parts = [made.key, made.value] if isinstance(made, ast.DictComp) else [made.elt]
        names = {n.id for gen in made.generators for n in ast.walk(gen.target)
                 if isinstance(n, ast.Name)}
        saved = {name: frame.locals[name] for name in names if name in frame.locals}

        def level(index: int, inner: Conditions) -> None:
            if index == len(made.generators):
                for part in parts:
                    self._expr(part, frame, inner)
                return
            gen = made.generators[index]
            if index:  # the first one's iterable is the enclosing scope's
                self._expr(gen.iter, frame, inner)

            def body(loop: tuple[Condition, ...]) -> None:
                tests = (*inner, *loop)
                for test in gen.ifs:
                    self._test(test)
                    self._expr(test, frame, tests)
                    tests = (*tests, condition("if", self._text(frame, test),
                                               self._where(frame, test)))
                level(index + 1, tests)

            self._loop(gen.target, gen.iter, frame, self._where(frame, made), body)

        try:
            level(0, conds)
        finally:
            for name in names:
                if name in saved:
                    frame.locals[name] = saved[name]
                else:
                    frame.locals.pop(name, None)

    def _call(self, call: ast.Call, frame: Frame, conds: Conditions) -> None:
        self._changed_in_place(call, frame)
        for arg in (*call.args, *(k.value for k in call.keywords)):
            for part in ast.walk(arg):  # the local itself or in an expression: prefix + x
                held = frame.locals.get(part.id) if isinstance(part, ast.Name) else None
                if isinstance(held, Alternatives) and isinstance(part, ast.Name):
                    # a local the paths of an if left different: one call per value
                    try:
                        for value, under in held.options:
                            frame.locals[part.id] = value
                            self._call(call, frame, (*conds, *under))
                    finally:
                        frame.locals[part.id] = held
                    return
                member = _self_member(part) if isinstance(part, ast.expr) and (
                    frame.instance is not None) else None
                attrs = frame.instance.attrs if frame.instance is not None else {}
                kept = attrs.get(member) if member is not None else None
                if member is not None and isinstance(kept, Alternatives):
                    # an attribute of ``self`` the paths of an if left different, as a
                    # local (``_If``)
                    try:
                        for value, under in kept.options:
                            attrs[member] = value
                            self._call(call, frame, (*conds, *under))
                    finally:
                        attrs[member] = kept
                    return
                if isinstance(part, ast.Call) and id(part) not in self.evaluator.fixed \
                        and isinstance(self.evaluator.callee(part.func, frame),
                                       FunctionInfo | BoundMethod):
                    # a helper that returns a value per path (``Evaluator.returned``),
                    # called in the argument: one call per value, as for a local
                    given = self.evaluator.eval(part, frame)
                    if isinstance(given, Alternatives):
                        try:
                            for value, under in given.options:
                                self.evaluator.fixed[id(part)] = value
                                self._call(call, frame, (*conds, *under))
                        finally:
                            self.evaluator.fixed.pop(id(part), None)
                        return
        ev = self.evaluator
        target = ev.callee(call.func, frame)
        version = frame.module.version
        plugin = self._standalone_plugin(call, frame)
        if plugin is not None:
            # rqt_gui's ``Main().main(standalone='pkg.module.Class')``: the program
            # builds that plugin class (with a context the walk does not know)
            target, self._gui_plugin = plugin, True
            call = ast.copy_location(ast.Call(func=call.func, args=[], keywords=[]), call)
        if isinstance(call.func, ast.Name) and call.func.id == "__import__" \
                and isinstance(target, Unknown):
            self._dynamic_import("__import__", call, frame)
        if isinstance(target, SuperInit):
            if frame.instance is not None and ev.is_node_class(frame.instance.cls):
                node_spec = rclpy.NODE_NAMES[("rclpy", "Node")]
                name = self._node_name(node_spec, call, frame, 2)
                self._logger_services(node_spec, call, frame, conds, name)
                if ev.is_lifecycle_class(frame.instance.cls):
                    for kind, service, type_ in rclpy.LIFECYCLE_CALLS:
                        self._add(PrimitiveCall(kind, service, type_, conditions=conds,
                                                location=self._where(frame, call),
                                                node_name=name))
                if name is not None:
                    frame.instance.node_name = name
                    given = self._class_names.setdefault(id(frame.instance.cls), [])
                    if name not in given:
                        given.append(name)
        elif isinstance(target, Ref):
            names = rospy.NODE_NAMES if version == 1 else rclpy.NODE_NAMES
            rows = rospy.ROWS if version == 1 else rclpy.ROWS
            if target.key in names:
                name = self._node_name(names[target.key], call, frame, version)
                self._logger_services(names[target.key], call, frame, conds, name)
            elif target.key in rows:
                spec = rows[target.key]
                start = len(self.calls)
                self._record(spec, call, frame, conds, version)
                if spec.owner is not None:
                    self._made_on(self.calls[start:], evaluate(ev, argument(
                        call, spec.owner), frame))
            elif target.qualname in _IMPORTERS:
                self._dynamic_import(target.qualname, call, frame)
            elif target.qualname in _RUNS_TARGET:
                self._runs_target(_RUNS_TARGET[target.qualname], call, frame, conds)
            elif target.qualname in _SUBPROCESSES and self._runs_ros_tool(call, frame):
                where = self._where(frame, call)
                if where not in self._launches_said:
                    self._launches_said.add(where)
                    self.diagnostics.append(diag.make(
                        "PY_RUNS_ROS_TOOL", where, call=target.qualname))
            elif target.qualname.split(".")[0] == "roslaunch" and (
                    target.key[1] in _LAUNCHERS):
                where = self._where(frame, call)
                if where not in self._launches_said:  # a function walked twice: once
                    self._launches_said.add(where)
                    self.diagnostics.append(diag.make(
                        "PY_LAUNCHES", where, call=target.qualname))
            else:
                self._unseen_class(target, call, frame)
                self._unseen_function(target, call, frame)
        elif isinstance(target, NodeMethod) and target.name in rclpy.NODE_METHODS:
            start = len(self.calls)
            self._record(rclpy.NODE_METHODS[target.name], call, frame, conds, 2)
            self._made_on(self.calls[start:], target.owner)
            if target.remote is not None:
                for made in self.calls[start:]:
                    made.name = _remote(target.remote, made.name)
        elif isinstance(target, FunctionInfo | BoundMethod):
            self._classes_handed(call, frame)
            self._inline(target, call, frame, conds)
        elif isinstance(target, Unknown) and not (
                isinstance(call.func, ast.Name) and call.func.id in _TAKE_CLASSES):
            self._classes_handed(call, frame)
        elif isinstance(target, ClassInfo):
            init = ev.method(target, "__init__")
            self._constructed.update(id(c) for c in ev.mro(target))
            # a class of ours derived from one of an unread ROS package (Interbotix's
            # XSArmRobot(InterbotixManipulatorXS), whose base makes the node and its
            # publishers and clients): building it builds the base, unseen
            for used in ev.mro(target):
                for base in ev.bases(used):
                    if isinstance(base, Ref):
                        self._unseen_class(base, call, frame, base=True)
            self._use_class(target)
            if init is not None:
                self._inline(BoundMethod(ev.new(target), init), call, frame, conds)

    def _use_class(self, target: ClassInfo) -> None:
        """The methods of a class the program builds, and those it inherits, walked
        (rosserial_arduino's SerialClient runs rosserial_python's, whose run() sets up
        the device's topics)."""
        for used in self.evaluator.mro(target):
            if used.module.path not in self.main and used not in self._used_classes:
                self._used_classes.append(used)

    def _classes_handed(self, call: ast.Call, frame: Frame) -> None:
        """A class of the workspace given, as a value, to a function of the workspace
        or to a callee the walk does not know may be built where the walk does not
        follow it (nova's python_control2:
        ``PythonControl(node).with_hardware("arm", QCMDHardware)`` keeps the class in a
        ``DeferredConstructor``, which runs ``self.cls.__init__(instance, ...)`` once the
        node spins; QCMDHardware declares ``hardware.<name>.can_id``): it counts as
        built, its methods walked as those of a class the program builds, with what
        its code does not know left ``?``."""
        for given in (*call.args, *(k.value for k in call.keywords)):
            if isinstance(given, ast.Starred):
                given = given.value
            if not isinstance(given, ast.Name | ast.Attribute):
                continue
            value = self.evaluator.eval(given, frame)
            if isinstance(value, ClassInfo):
                self._constructed.update(id(c) for c in self.evaluator.mro(value))
                self._use_class(value)

    def _setattr(self, call: ast.Call, frame: Frame) -> ast.Assign | None:
        """The builtin ``setattr(obj, name, value)`` with a name known statically, as the
        assignment ``obj.<name> = value`` it is (vortex-auv's joystick interface: ``for
        param in ['pose', 'joy', ...]: setattr(self, param + '_topic',
        self.get_parameter(f'topics.{param}').value)``, then ``create_subscription(Joy,
        self.joy_topic, ...)``); None for any other call, or a name not known."""
        if not (isinstance(call.func, ast.Name) and call.func.id == "setattr"
                and len(call.args) == 3 and not call.keywords
                and not any(isinstance(a, ast.Starred) for a in call.args)
                and call.func.id not in frame.locals):
            return None
        builtin = self.evaluator.callee(call.func, frame)  # not a function of the code's
        if builtin is not None and not (isinstance(builtin, Unknown)
                                        and builtin.origin == "setattr"):
            return None
        name = self.evaluator.eval(call.args[1], frame)
        if not (isinstance(name, Value) and name.is_known and name.text.isidentifier()):
            return None
        target = ast.copy_location(ast.Attribute(
            value=call.args[0], attr=name.text, ctx=ast.Store()), call)
        return ast.copy_location(ast.Assign(targets=[target], value=call.args[2]), call)

    def _standalone_plugin(self, call: ast.Call, frame: Frame) -> ClassInfo | Ref | None:
        """The plugin class ``Main.main(argv, standalone='pkg.module.Class')`` of
        qt_gui (rqt_gui's ``Main``) runs alone: an rqt plugin's own program (bwi's
        level_selector script). Its class in a module of the workspace, else the class
        by name (a package not read: ``_unseen_class`` says so)."""
        if not (isinstance(call.func, ast.Attribute) and call.func.attr == "main"):
            return None
        owner = self.evaluator.eval(call.func.value, frame)
        if not (isinstance(owner, Unknown) and owner.origin in _QT_GUI_MAINS):
            return None
        given = argument(call, Arg(1, "standalone"))
        text = text_of(evaluate(self.evaluator, given, frame)) if given is not None else None
        if text is None or not text.is_known or "." not in (text.text or ""):
            return None
        module_name, _, name = str(text.text).rpartition(".")
        path = self.loader.resolve_import(frame.module.path, 0, module_name)
        module = self.loader.load(path) if path is not None else None
        found = module.classes.get(name) if module is not None else None
        return found if found is not None else Ref(str(text.text))

    def _changed_in_place(self, call: ast.Call, frame: Frame) -> None:
        """A list or dict a local or an attribute of ``self`` holds, changed by one of its
        methods (``self.sides.append('right')``): the value the walk knows is changed
        too (an item appended, inserted or a list extended by one known), else unknown
        from here on: a loop over it no longer runs over the items it had."""
        func = call.func
        if not (isinstance(func, ast.Attribute) and func.attr in _IN_PLACE):
            return
        holder = func.value
        if not (isinstance(holder, ast.Name) or (
                isinstance(holder, ast.Attribute) and isinstance(holder.value, ast.Name)
                and holder.value.id == "self")):
            return
        ev = self.evaluator
        value = ev.eval(holder, frame)
        if not isinstance(value, Seq | Record):
            return
        changed = None if call.keywords else _changed(
            value, func.attr, [ev.eval(arg, frame) for arg in call.args])
        ev.bind(holder, changed if changed is not None else Unknown(
            f"{self._text(frame, holder)} changed in place"), frame)

    def _inline(self, func: FunctionInfo | BoundMethod, call: ast.Call, frame: Frame,
                conds: Conditions) -> None:
        info = func.function if isinstance(func, BoundMethod) else func
        if id(info.node) in self._active:
            return  # recursion: the calls it makes are those being walked
        if frame.depth >= MAX_CALL_DEPTH:
            self._cut(info, call, frame)
            return
        inner = self.evaluator.call_frame(func, call, frame)
        self._inlined.add(id(info.node))
        self._active.add(id(info.node))
        self._inlining.append((info.node, not self._reach.may_call_ros(
            info, self.loader.modules.values())))
        self._fixed[id(inner)] = _unassigned_parameters(info.node)
        try:
            self._block(info.node.body, inner, conds)
        finally:
            self._active.discard(id(info.node))
            self._inlining.pop()
            self._fixed.pop(id(inner), None)

    def _runs_target(self, where: tuple[Arg, Arg, Arg], call: ast.Call, frame: Frame,
                     conds: Conditions) -> None:
        """A thread (``threading.Thread(target=f, args=(a,), kwargs={...})``, a
        ``threading.Timer``, a ``multiprocessing.Process``, ``_thread.start_new_thread``)
        runs its function with the arguments it is given: the function is walked as that
        call, here, as a call written in the code is. A method of ``self`` so run then
        sees the attributes the object has (svea's interfaces start their node's
        subscribers in ``Thread(target=self._init_and_spin_ros)``, named by the vehicle
        name their constructor was given); walked only as an entry, it saw an object of
        unknown attributes. A function not known (a lambda, a parameter) is not followed."""
        given = argument(call, where[0])
        if given is None:
            return
        func = self.evaluator.callee(given, frame)
        if not isinstance(func, FunctionInfo | BoundMethod):
            return
        values, keywords = argument(call, where[1]), argument(call, where[2])
        args: list[ast.expr] = []
        if isinstance(values, ast.Tuple | ast.List):
            args = list(values.elts)
        elif values is not None and not (isinstance(values, ast.Constant)
                                         and values.value is None):
            args = [ast.Starred(value=values, ctx=ast.Load())]
        named: list[ast.keyword] = []
        if isinstance(keywords, ast.Dict) and all(
                isinstance(k, ast.Constant) and isinstance(k.value, str) and k.value.isidentifier()
                for k in keywords.keys):
            named = [ast.keyword(arg=k.value, value=v)  # type: ignore[union-attr]
                     for k, v in zip(keywords.keys, keywords.values, strict=True)]
        elif keywords is not None and not (isinstance(keywords, ast.Constant)
                                           and keywords.value is None):
            named = [ast.keyword(arg=None, value=keywords)]
        run = ast.copy_location(ast.Call(func=given, args=args, keywords=named), call)
        self._inline(func, run, frame, conds)

    def _cut(self, info: FunctionInfo, call: ast.Call, frame: Frame) -> None:
        """A call ``MAX_CALL_DEPTH`` calls deep is not followed: its function is walked
        as an entry only (its parameters, and the object it is called on, not known),
        so the calls it makes on what it is given (carla's actors, five calls down from
        the bridge, publish through the node passed to them) can be lost. Said
        (``PY_CALL_DEPTH``), and the node is partial, when its code may reach a ROS
        call (``Reach``); a helper that cannot is cut silently. Said with the walk's
        calls: not for an entry walk whose calls are dropped (its function was walked
        where it is called, from a lower depth)."""
        if self._reach.may_call_ros(info, self.loader.modules.values()):
            self._cuts.append(diag.make("PY_CALL_DEPTH", self._where(frame, call),
                                        call=info.qualname, depth=MAX_CALL_DEPTH))

    def _logger_services(self, spec: object, call: ast.Call, frame: Frame, conds: Conditions,
                         name: str | None) -> None:
        """``enable_logger_service=True``: the node serves its logger levels."""
        flag = argument(call, getattr(spec, "logger_service", None))
        if flag is None or self.evaluator.eval(flag, frame) is not True:
            return
        for service, kind in rclpy.LOGGER_SERVICES:
            self._add(PrimitiveCall("server", service, kind, conditions=conds,
                                    location=self._where(frame, call), node_name=name))

    def _made_on(self, calls: list[PrimitiveCall], owner: object) -> None:
        """The calls are made on the rclpy node ``owner``: they carry its name."""
        name: str | None = None
        if isinstance(owner, Instance):
            known = self._class_names.get(id(owner.cls), [])
            name = owner.node_name or (known[0] if len(known) == 1 else None)
        elif isinstance(owner, NodeHandle):
            name = text_of(owner.name).text if owner.name is not None else None
        if name is not None and "?" not in name:
            for made in calls:
                made.node_name = name

    def _node_name(self, spec: object, call: ast.Call, frame: Frame,
                   version: int) -> str | None:
        """Record a name the code gives a node; the node's is the first fully known one
        (or the first, when none is), and every other known name is kept in ``names``.
        The name, when fully known."""
        ev = self.evaluator
        name_expr = argument(call, getattr(spec, "name", None))
        if name_expr is None:
            return None
        name = text_of(ev.eval(name_expr, frame)).text
        if "?" not in name and name not in self.names:
            self.names.append(name)
            self.names_at.append(self._where(frame, call))
        if "?" not in name and version == 2 and name not in self.rclpy_names:
            self.rclpy_names.append(name)
        if self.rosname is None or ("?" in self.rosname and "?" not in name):
            self.rosname, self.namespace, self.anonymous = name, None, False
            ns_expr = argument(call, getattr(spec, "namespace", None))
            if ns_expr is not None:
                self.namespace = text_of(ev.eval(ns_expr, frame)).text
            anon_expr = argument(call, getattr(spec, "anonymous", None))
            if anon_expr is not None:
                self.anonymous = ev.eval(anon_expr, frame) is True
        return None if "?" in name else name

    def _record(self, spec: PyFunction, call: ast.Call, frame: Frame, conds: Conditions,
                version: int) -> None:
        ev = self.evaluator
        where = self._where(frame, call)
        base = PrimitiveCall(spec.kind, "?", conditions=conds, location=where)
        if spec.fixed_type:
            base.type = spec.fixed_type
        elif spec.type is not None:
            base.type = self._type(argument(call, spec.type), frame, version,
                                   spec.kind.startswith("action"))
        if spec.queue is not None:
            given = argument(call, spec.queue)
            queue = evaluate(ev, given, frame)
            base.queue_size = queue if isinstance(queue, int) and not isinstance(
                queue, bool) else None
            # none given (nor maybe through *args / **kwargs), or None written
            base.queue_size_missing = (given is None and not any(
                isinstance(a, ast.Starred) for a in call.args) and all(
                k.arg is not None for k in call.keywords)) or (
                isinstance(given, ast.Constant) and given.value is None)
        if spec.latch is not None:
            base.latch = evaluate(ev, argument(call, spec.latch), frame) is True
        base.latch = base.latch or spec.fixed_latch
        if spec.qos is not None:
            base.qos = ev.qos(evaluate(ev, argument(call, spec.qos), frame))
        elif spec.fixed_qos is not None:
            base.qos = dict(rclpy.PRESETS[spec.fixed_qos])
        if base.qos is not None and isinstance(base.qos.get("depth"), int):
            base.queue_size = base.qos["depth"]
        if spec.callback is not None:
            base.callback = self._callback(argument(call, spec.callback), frame)
        if spec.special:
            for made in special_calls(ev, spec, call, frame, base, version):
                self._add(made)
            return
        if spec.fixed_name is not None:
            base.name = spec.fixed_name
        elif spec.name is not None:
            value = evaluate(ev, argument(call, spec.name), frame)
            self._set_name(base, value, version)
        if spec.value is not None:
            value_expr = argument(call, spec.value)
            declared_type = type_only(value_expr) if spec.kind == "declare" else None
            value = evaluate(ev, value_expr, frame)
            base.type = param_type(value)
            if declared_type is not None:
                # declare_parameter('port', Parameter.Type.STRING): a type, no value
                base.type = declared_type
            elif spec.kind == "declare" and (value_expr is None or is_none(value_expr)) and (
                    dynamic_descriptor(argument(call, Arg(2, "descriptor"))) is not None):
                # declare_parameter(name, [None,] descriptor=ParameterDescriptor(..)):
                # rclpy's get_parameter of it, unset, returns a NOT_SET parameter (value
                # None) when the descriptor says dynamic_typing=True, and raises for a
                # statically typed one, as any other descriptor declares
                base.has_default = dynamic_descriptor(
                    argument(call, Arg(2, "descriptor"))) is True
            elif spec.kind == "declare" and value_expr is None and argument(
                    call, Arg(2, "descriptor")) is None:
                # declare_parameter(name): rclpy (node.py, humble to rolling) passes the
                # name alone to declare_parameters, which declares it dynamically typed
                # (the deprecated form), so a get of it unset returns it, value None,
                # as it does for declare_parameter(name, None)
                base.has_default = True
            elif value_expr is not None and spec.kind in ("read", "declare"):
                base.has_default = True
                base.default = plain_value(value)
            if spec.kind == "declare":
                ev.declared[base.name.removeprefix("~")] = value
        if spec.kind == "read" and (id(call) in self._converted
                                    or id(call) in _converted_locals(frame.module.tree)):
            base.type = None
        base.searched = spec.search or base.searched
        if spec.search and base.name:  # rospy.search_param: from the node's own name up
            base.name = search_start(base.name)
        base.tested = (spec.tests and id(call) in self._tested) or (
            spec.kind in ("read", "declare") and not base.has_default
            and any(c in self._handled for c in conds))
        base.deletes = spec.deletes
        self._add(base)

    def _set_name(self, call: PrimitiveCall, value: object, version: int) -> None:
        ev = self.evaluator
        resolved = _resolved(value)
        if resolved is not None:
            value, call.handle_namespace = resolved
        text = text_of(value)
        if isinstance(value, ParamValue):
            call.name_param = param_name(Value.of(value.name)) if version == 2 else value.name
            default = value.default if value.default is not None else ev.declared.get(
                value.name.removeprefix("~"))
            if isinstance(default, Value) and default.is_known:
                call.name_default = default.text
        elif isinstance(value, ParamElement):
            call.name_param = param_name(Value.of(value.name)) if version == 2 else value.name
            call.name_each = value.field
        else:
            params = [p.origin for p in text.parts if isinstance(p, Unknown)]
            if len(params) == 1 and params[0].startswith(ELEMENT_OF):
                # an element with text around it (``f"/{robot}/cmd_vel"``): one call
                # per element too, the element in the place of the ``?``
                name, _, field = params[0].removeprefix(ELEMENT_OF).partition(FIELD_OF)
                call.name_param = param_name(Value.of(name)) if version == 2 else name
                call.name_each = field or "."
            elif len(params) == 1 and params[0].startswith(TURN_OF):
                # a counting loop's variable up to a parameter (``'~waypoint%d_x' % i``):
                # one call per turn of the value the configuration gives it
                name, _, start = params[0].removeprefix(TURN_OF).partition(TURN_FROM)
                call.name_param = param_name(Value.of(name)) if version == 2 else name
                turn = re.fullmatch(r"(\d+)([+-]\d+)?(#?)", start)
                if turn is not None:
                    first, shift, length = turn.groups("0")
                    call.name_each = counted_mark(int(first), False, int(shift),
                                                  length == "#")
            elif len(params) == 1 and params[0].startswith(PROGRAM_ARGUMENT):
                # a command-line argument with text around it (``sys.argv[1] + "/out"``):
                # the graph puts the instance's argument in the place of the ``?``
                call.name_arg = int(params[0].removeprefix(PROGRAM_ARGUMENT))
            elif len(params) == 1 and params[0].startswith(PROGRAM_OPTION):
                # an option argparse parses (``"/robot/limb/" + args.limb``): the value the
                # instance's arguments give it
                call.name_option = params[0].removeprefix(PROGRAM_OPTION)
                call.name_option_default = ev.option_defaults.get(call.name_option)
            elif params and all(p.startswith("parameter ") for p in params):
                # one parameter's value with text around it (``"/" + ns + "/cmd"``), or
                # several, each in the place of its ``?`` (``ns + "/" + topic``); values
                # with no text between them are one ``?`` (``"/" + robot_id + model``),
                # each after the first a JOINED entry, as the C++ side makes them
                filled: list[list[str | None]] = []
                after_unknown = False
                for part in text.parts:
                    if not isinstance(part, Unknown):
                        after_unknown = False
                        continue
                    name = part.origin.removeprefix("parameter ")
                    default = ev.param_defaults.get(name)
                    filled.append([param_name(Value.of(name)) if version == 2 else name,
                                   default.text if isinstance(default, Value)
                                   and default.is_known else None,
                                   *([JOINED] if after_unknown else [])])
                    after_unknown = True
                call.name_param, call.name_default = filled[0][0], filled[0][1]
                call.name_more = filled[1:] or None
                text = Value(tuple(part for i, part in enumerate(text.parts) if not (
                    i and isinstance(part, Unknown) and isinstance(text.parts[i - 1],
                                                                   Unknown))))
        found = searched_name(text)
        if found is not None:  # get_param(search_param('x')): the parameter found
            call.name, call.searched = found, True
            return
        text = own_name(in_namespace(text, version))
        # rclpy's get_name() elsewhere in a name (``f"/{self.get_name()}/x"``): the node's
        # name without its namespace, which the graph puts in its place per instance; the
        # first ``?`` when nothing else fills the others (``f"/{self.get_name()}/{key}"``)
        unknowns = [p.origin for p in text.parts if isinstance(p, Unknown)]
        named_self = version == 2 and unknowns[:1] == [NODE_NAME] and (
            len(unknowns) == 1 or (call.name_param is None and call.name_arg is None
                                   and call.name_option is None and call.name_each is None))
        if version == 2 and call.kind in _PARAM_KINDS:
            call.name = param_name(text)
        elif text.text.startswith("~/"):  # f"{get_name()}/x": the private name ~x
            call.name = "~" + text.text[2:]
        else:  # get_name() is "~": only as the start of a name is it the node's name
            call.name = (text.text[:1] + text.text[1:].replace("~", "?")) or "?"
        if call.name_more and call.name.count("?") != 1 + sum(
                entry[2:] != [JOINED] for entry in call.name_more):
            call.name_param = call.name_default = call.name_more = None  # not one each
        call.name_self = named_self and call.name.count("?") == len(unknowns)
        # rospy's fully qualified name inside a name (``"/debug" + rospy.get_name()``; at
        # its start, followed by ``/``, it is ``~``): the graph puts the instance's, as
        # rospy makes it canonical (``"/" + get_name()`` has no ``//``; rcl refuses one)
        call.name_full = version == 1 and call.name.count("?") == 1 and (
            unknowns == [NODE_NAME] and call.name_param is None and call.name_arg is None
            and call.name_option is None)

    def _type(self, expr: ast.expr | None, frame: Frame, version: int,
              action: bool) -> str | None:
        if expr is None:
            return None
        value = self.evaluator.eval(expr, frame)
        if isinstance(value, Ref):
            return ros_type(value.qualname, version, action) or "?"
        return "?"

    def _callback(self, expr: ast.expr | None, frame: Frame) -> str | None:
        if expr is None or isinstance(expr, ast.Lambda):
            return None
        value = self.evaluator.eval(expr, frame)
        if isinstance(value, BoundMethod):
            return f"{value.instance.cls.name}.{value.function.node.name}"
        if isinstance(value, FunctionInfo):
            return value.qualname
        if isinstance(expr, ast.Attribute) and isinstance(value, Unknown):
            return expr.attr
        return None

    def _unseen_class(self, target: Ref, call: ast.Call, frame: Frame,
                      base: bool = False) -> None:
        """Say where the node builds an object of a class of a ROS package its own
        package depends on whose code is not read (an installed package:
        nav2_simple_commander's ``BasicNavigator()``, a node with a dozen action
        clients; ``smach_ros.IntrospectionServer``): it may communicate under names we
        cannot see (``PY_CLASS_UNSEEN``), so the node is partial. Not a message,
        service or action, nor a class of a module the API tables model or of a
        package known to make no ROS call (``NOT_CLIENTS``). A base of a class of ours
        (``base``) from a Python package that neither the workspace holds nor a
        dependency names is kept for ``PY_NODE_UNSEEN``."""
        if target.key == ("rclpy", "init"):
            self._ros_init = True
        parts = target.qualname.split(".")
        if len(parts) < 2 or not parts[-1][:1].isupper() \
                or parts[0] in _MODELLED or target.qualname in self._classes_said \
                or any(part in ("msg", "srv", "action", "cfg") for part in parts[1:-1]):
            return  # (``cfg``: dynamic_reconfigure's configuration classes, built)
        package = self._package_of_module(parts[0])
        if package is not None:
            self._classes_said[target.qualname] = (self._where(frame, call), package)
        elif base and target.qualname not in self._classes_elsewhere and _foreign(parts[0]):
            self._classes_elsewhere[target.qualname] = self._where(frame, call)
        elif not base:
            self._unread_module(target, call, frame)

    def _unseen_function(self, target: Ref, call: ast.Call, frame: Frame) -> None:
        """Say where the node hands itself to a function whose code is not read
        (``PY_FUNCTION_UNSEEN``: ``setup_publishers(self)`` of a module named after a
        package of the workspace that the loader does not find, or of an installed ROS
        package, by the rule a class's is, ``_package_of_module``): with the node, the
        function can make any publisher, subscription, client or parameter read, so
        the node is partial. What counts as the node (``_node_given``): an rclpy node,
        or in ROS 1, whose node is the process's, an object rospy (or an API the tables
        model) made. Not a function of a message, service, action or ``cfg`` module,
        the standard library, a client library or a library known to make no ROS call
        (``_foreign``)."""
        parts = target.qualname.split(".")
        if len(parts) < 2 or parts[-1][:1].isupper() or parts[0] in _MODELLED or any(
                part in ("msg", "srv", "action", "cfg") for part in parts[1:-1]):
            return
        package = self._package_of_module(parts[0])
        if package is None:
            self._unread_module(target, call, frame)
        given = self._node_given(call, frame) if package is not None else None
        where = self._where(frame, call)
        if given is None or package is None or where in self._functions_said:
            return
        self._functions_said.add(where)  # a function walked twice: once
        self.diagnostics.append(diag.make("PY_FUNCTION_UNSEEN", where,
                                          function=target.qualname, package=package,
                                          given=given))

    def _unread_module(self, target: Ref, call: ast.Call, frame: Frame) -> None:
        """Keep the first call of a ROS 1 program into a module whose code is not read
        and that no list knows (``PY_MODULE_UNSEEN``): its top-level module is not the
        standard library's, a client library, a package known to make no ROS call or a
        pip library (``_foreign``), nor a ROS package the tool knows of
        (``_package_of_module``, said as such), and the reader finds it nowhere in the
        workspace. rospy's node is the process's, so that code can read parameters,
        publish and subscribe without being given anything: mobiman's training node
        calls openai_ros' ``StartOpenAI_ROS_Environment(name)``, an undeclared ROS
        package cloned beside the workspace, whose environment reads 80 parameters the
        launch file sets. An rclpy node is no one's but its holder's: in ROS 2 only a
        function given the node counts (``PY_FUNCTION_UNSEEN``). Not roslaunch, whose
        launching calls are said by their own rule (``PY_LAUNCHES``) and whose other
        functions (``rlutil.get_or_generate_uuid``) make no ROS call of a node."""
        module = target.qualname.split(".", 1)[0]
        if frame.module.version != 1 or module in self._modules_elsewhere or (
                module == "roslaunch") or (
                not _foreign(module)) or self.loader.resolve_import(
                    frame.module.path, 0, module) is not None:
            return
        self._modules_elsewhere[module] = (self._where(frame, call), target.qualname)

    def _node_given(self, call: ast.Call, frame: Frame) -> str | None:
        """The first argument of ``call`` that is the node, as written: an rclpy node
        (an object of a ``Node`` subclass, ``self`` in one, or ``rclpy.create_node``'s),
        or an object a row of the ROS 1 API tables makes (``rospy.Publisher``,
        ``actionlib.SimpleActionClient``: rospy's node is the process's, and code given
        its objects is ROS code); None when none is. A publisher an rclpy node made
        is not the node: a function given it can only publish on it."""
        ev = self.evaluator
        for expr in [*call.args, *(k.value for k in call.keywords)]:
            if isinstance(expr, ast.Starred):
                continue
            value = ev.eval(expr, frame)
            if isinstance(value, NodeHandle) or (
                    isinstance(value, Instance) and ev.is_node_class(value.cls)) or (
                    isinstance(value, Unknown) and frame.module.version == 1
                    and Ref(value.origin).key in rospy.ROWS
                    and value.origin.rsplit(".", 1)[-1][:1].isupper()):
                return self._text(frame, expr)
        return None

    def _runs_ros_tool(self, call: ast.Call, frame: Frame) -> bool:
        """Whether a subprocess call's command (a list's words, or a string's) starts
        nodes or plays a bag (``_starts_nodes``: Doosan's dmodel.py writes an rviz
        configuration and runs ``['rosrun', 'rviz', 'rviz', '-d', path]``;
        spencer_bagfile_tools' play.py runs ``rosbag play`` with the remaps it was
        given), also when a terminal or a shell runs it (``shell.commands``: the PX4 offboard
        example's processes.py opens ``gnome-terminal --tab -- bash -c
        'MicroXRCEAgent udp4 -p 8888; exec bash'``)."""
        given = call.args[0] if call.args else next(
            (k.value for k in call.keywords if k.arg == "args"), None)
        if given is None or isinstance(given, ast.Starred):
            return False
        value = self.evaluator.eval(given, frame)
        if isinstance(value, Seq):
            words = [text_of(item).text.strip() for item in value.items[:MAX_WORDS]]
            if len(words) == 1:
                words = split_words(words[0])
        else:
            words = split_words(text_of(value).text if value is not None else "")
        return any(_starts_nodes([w.rsplit("/", 1)[-1] if i == 0 else w
                                  for i, w in enumerate(" ".join(command).split()[:3])])
                   for command in commands(words))

    def _dynamic_import(self, function: str, call: ast.Call, frame: Frame) -> None:
        """Say where the program imports a module whose name it computes at run time
        (FlexBE's onboard engine imports each behavior it is sent, ``__import__("tmp_%d"
        % msg.behavior_checksum)``, and runs it; a plugin chosen by a parameter): that
        code is not read, and what it communicates may be missing
        (``PY_DYNAMIC_IMPORT``), so the node is partial. A module of messages, services
        or actions (``import_module(pkg + ".msg")``) runs no ROS call, and a name known
        here is an import as any other."""
        first = call.args[0] if call.args else next(
            (k.value for k in call.keywords if k.arg == "name"), None)
        if first is None or id(call) in self._located:
            # an import asked only where its package is (FlexBE's behavior library:
            # ``__import__(entry["package"]).__path__[-1]``) runs no more than the
            # package's ``__init__``
            return
        name = text_of(self.evaluator.eval(first, frame))
        if name.is_known or name.text.endswith((".msg", ".srv", ".action")) or (
                _loaded_module(first, frame.module.tree)) or (
                _interface_module(first, frame.module.tree)):
            return
        where = self._where(frame, call)
        if where not in self._imports_said:  # a function walked twice: once
            self._imports_said.add(where)
            self.diagnostics.append(diag.make(
                "PY_DYNAMIC_IMPORT", where, call=function, name=name.text))

    def _unseen_said(self) -> None:
        """``PY_CLASS_UNSEEN`` where the executable makes a ROS node of its own, starts
        rclpy (``rclpy.init()``, then ``BasicNavigator()``, a node) or makes ROS calls
        (on a node the unseen class made: Interbotix's xsarm_robot.py subscribes on
        ``self.core.get_node()``): a script that does none of these (a generator of
        launch files, an installer) runs no such class as part of a ROS program.
        ``PY_NODE_UNSEEN`` where a program of the client library makes no node in the
        code read yet builds a class of a Python package not in the workspace: that
        class makes the node (pepper_sensors_py's camera.py builds PepperCam, a NaoqiCam
        of naoqi_sensors_py's module ``naoqi_sensors``, which calls init_node and reads
        the camera's parameters)."""
        no_node = self.rosname is None and not self.names
        if no_node and any(
                m is not None and m.client_version for m in self.loader.modules.values()):
            for cls, where in self._classes_elsewhere.items():
                self.diagnostics.append(diag.make("PY_NODE_UNSEEN", where, cls=cls,
                                                  module=cls.split(".", 1)[0]))
        if no_node and not self._ros_init and not self._gui_plugin and not self.calls:
            return
        for cls, (where, package) in self._classes_said.items():
            self.diagnostics.append(diag.make("PY_CLASS_UNSEEN", where, cls=cls,
                                              package=package))
        if not no_node:
            for module, (where, call) in self._modules_elsewhere.items():
                self.diagnostics.append(diag.make("PY_MODULE_UNSEEN", where, call=call,
                                                  module=module))
        self._subclasses_said()

    def _subclasses_said(self) -> None:
        """``PY_DYNAMIC_CLASSES`` where code of the program asks a class for its
        subclasses (``cls.__subclasses__()``), which it then builds by the list it gets
        at run time (kalman_supervisor builds every ``Module`` and ``State`` so, and each
        opens its topics): which classes run, and what they communicate, is not read.
        Not where the class is named and none of the classes so listed may make a ROS
        call (``Reach.subclasses_may_call_ros``: uuv_simulator's path generators)."""
        for module in list(self.loader.modules.values()):
            if module is None:
                continue
            for node in ast.walk(module.tree):
                if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
                        and node.func.attr == "__subclasses__" and (
                            not isinstance(node.func.value, (ast.Name, ast.Attribute))
                            or self._reach.subclasses_may_call_ros(
                                last_name(node.func.value) or "", self.loader)):
                    self.diagnostics.append(diag.make(
                        "PY_DYNAMIC_CLASSES", self.loader.location(
                            module.path, node.lineno, node.col_offset + 1),
                        call=ast.unparse(node.func)))
                    break

    def _package_of_module(self, module: str) -> str | None:
        """The unread ROS package whose Python code the top-level module ``module`` is:
        the package of that name, else a dependency of the node's package whose name
        the module's begins with, then ``_`` (a package's setup.py installs modules of
        any name: mas_common_robotics' mcr_manipulation_pose_selector installs
        ``mcr_manipulation_pose_selector_ros``), the longest such name, when the
        module may be ROS code (``_foreign``). Also a package of the workspace (the
        node's own too) that names a module the loader did not find in its sources
        (object_recognition_ros' setup.py sets ``package_dir`` where the reader does
        not look): that code is not read either. None for any other module."""
        if module in self.unseen_packages:
            return module
        if module in getattr(self.loader.workspace, "packages", {}) and _foreign(module):
            return module
        named = [name for name in self.unseen_dependencies if module.startswith(name + "_")]
        return max(named, key=len) if named and _foreign(module) else None

    def _add(self, call: PrimitiveCall) -> None:
        self.calls.append(call)

    # -- text and places ----------------------------------------------------------------

    def _text(self, frame: Frame, node: ast.AST) -> str:
        return source_text(frame.module.lines, node)

    def _where(self, frame: Frame, node: ast.AST) -> Location:
        return self.loader.location(frame.module.path, getattr(node, "lineno", 0),
                                    getattr(node, "col_offset", -1) + 1)


# the functions that run a command, and the commands that start ROS nodes: the ROS
# tools, and the agents that put the topics of a micro-ROS or XRCE-DDS client (PX4's
# uxrce_dds_client, a microcontroller) on the ROS 2 graph
_SUBPROCESSES = frozenset({"subprocess.call", "subprocess.check_call", "subprocess.run",
                           "subprocess.Popen", "subprocess.check_output", "os.system"})
_ROS_TOOLS = frozenset({"rosrun", "roslaunch", "rqt_bag", "MicroXRCEAgent",
                        "micro-ros-agent", "micro_ros_agent"})
def _starts_nodes(words: list[str]) -> bool:
    """Whether a command line's first words start ROS nodes or publish: rosrun,
    roslaunch, rqt_bag, ``rosbag play`` (not ``rosbag info`` or ``record``, which
    publish nothing), ``ros2 run``, ``ros2 launch``, ``ros2 bag play``."""
    first = words[0] if words else ""
    second = words[1] if len(words) > 1 else ""
    if first in _ROS_TOOLS:
        return True
    if first == "rosbag":
        return second == "play"
    if first == "ros2":
        return second in ("run", "launch") or (
            second == "bag" and len(words) > 2 and words[2] == "play")
    return False


# a module's attributes that tell where it is
_MODULE_PLACE = frozenset({"__path__", "__file__"})


_INTERFACE_KINDS = frozenset({"msg", "srv", "action"})


def _interface_module(expr: ast.expr, tree: ast.Module) -> bool:
    """Whether the module name ``expr`` computes ends with a parameter of its function
    that every call of that function in the module gives as ``"msg"``, ``"srv"`` or
    ``"action"`` (joy_teleop's ``get_interface_type(type_name, interface_type)``, which
    imports ``package + "." + interface_type`` and is called with each): a module of
    interfaces, which runs no ROS call."""
    last = expr
    while isinstance(last, ast.BinOp) and isinstance(last.op, ast.Add):
        last = last.right
    if not isinstance(last, ast.Name):
        return False
    for function in ast.walk(tree):
        if not isinstance(function, ast.FunctionDef | ast.AsyncFunctionDef) or not any(
                node is expr for node in ast.walk(function)):
            continue
        names = [a.arg for a in function.args.args]
        if last.id not in names:
            return False
        index = names.index(last.id)
        given = [call for call in ast.walk(tree) if isinstance(call, ast.Call)
                 and isinstance(call.func, ast.Name) and call.func.id == function.name]
        values = [call.args[index] if index < len(call.args) else next(
            (k.value for k in call.keywords if k.arg == last.id), None) for call in given]
        return bool(values) and all(
            isinstance(v, ast.Constant) and v.value in _INTERFACE_KINDS for v in values)
    return False


def _loaded_module(expr: ast.expr, tree: ast.Module) -> bool:
    """Whether the module name ``expr`` computes is that of a class's module or of its
    package (``".".join(service_type.__module__.split(".")[:-1])``, carla's
    ros_compatibility getting a service's request class): a module already imported,
    whose import runs nothing new. ``expr`` holds ``__module__``, or is a local of a
    function every assignment of which does."""
    if _of_module(expr):
        return True
    if not isinstance(expr, ast.Name):
        return False
    for function in ast.walk(tree):
        if isinstance(function, ast.FunctionDef | ast.AsyncFunctionDef) and any(
                node is expr for node in ast.walk(function)):
            values = [node.value for node in ast.walk(function) if isinstance(node, ast.Assign)
                      and any(isinstance(t, ast.Name) and t.id == expr.id
                              for t in node.targets)]
            return bool(values) and all(_of_module(v) for v in values)
    return False


def _of_module(expr: ast.expr) -> bool:
    return any(isinstance(node, ast.Attribute) and node.attr == "__module__"
               for node in ast.walk(expr))


# the functions that import a module by its name (the first argument)
# what runs a function it is given with arguments it is given (``_runs_target``): where
# the function, its positional arguments and its keyword arguments are given
_RUNS_TARGET: dict[str, tuple[Arg, Arg, Arg]] = {
    "threading.Thread": (Arg(1, "target"), Arg(3, "args"), Arg(4, "kwargs")),
    "multiprocessing.Process": (Arg(1, "target"), Arg(3, "args"), Arg(4, "kwargs")),
    "threading.Timer": (Arg(1, "function"), Arg(2, "args"), Arg(3, "kwargs")),
    "_thread.start_new_thread": (Arg(0, None), Arg(1, None), Arg(2, None)),
    "thread.start_new_thread": (Arg(0, None), Arg(1, None), Arg(2, None)),
}

_IMPORTERS = frozenset({"importlib.import_module", "importlib.__import__",
                        "runpy.run_module"})


# roslaunch's entry points that start the nodes of launch files in the calling process
_LAUNCHERS = frozenset({"main", "ROSLaunchParent", "ROSLaunch", "ROSLaunchRunner"})


_IDENTIFIER = re.compile(r"[A-Za-z_]\w*")
# rclpy's node methods that give a Parameter, not its value
_PARAMETER_OBJECTS = frozenset({"declare_parameter", "get_parameter"})


# what looks a function up by a name the code computes: ``globals()[name]``, ``eval``
_LOOKUPS = frozenset({"globals", "locals", "vars", "eval", "exec", "__import__", "__dict__",
                      "importlib", "inspect", "modules"})


def _looks_up_names(tree: ast.AST) -> bool:
    """Whether ``tree`` may reach a function by a name it computes: a name of
    ``_LOOKUPS`` (``sys.modules``, ``module.__dict__``), or ``getattr`` of a name not
    written out on anything but ``self`` or ``cls``."""
    for node in ast.walk(tree):
        if (isinstance(node, ast.Name) and node.id in _LOOKUPS) or (
                isinstance(node, ast.Attribute) and node.attr in _LOOKUPS) or (
                isinstance(node, ast.alias) and node.name.split(".")[0] in _LOOKUPS):
            return True
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and (
                node.func.id == "getattr") and len(node.args) >= 2 and not (
                isinstance(node.args[1], ast.Constant)) and not (
                isinstance(node.args[0], ast.Name) and node.args[0].id in ("self", "cls")):
            return True
    return False


def _attribute_names(tree: ast.AST, skipped: set[int], variables: bool = False) -> set[str]:
    """The attribute names ``tree`` uses and the identifiers its strings hold, outside
    the function definitions whose ids are ``skipped``; with ``variables``, the
    variables it names and the names it imports too, and the decorators and default
    values of the functions skipped (which run where the function is defined)."""
    found: set[str] = set()
    stack = [tree]
    while stack:
        node = stack.pop()
        if id(node) in skipped:
            if variables and isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
                stack.extend([*node.decorator_list, *node.args.defaults,
                              *(d for d in node.args.kw_defaults if d is not None)])
            continue
        if isinstance(node, ast.Attribute):
            found.add(node.attr)
        elif variables and isinstance(node, ast.Name):
            found.add(node.id)
        elif variables and isinstance(node, ast.alias):
            found.update(part for part in (*node.name.split("."), node.asname) if part)
        elif isinstance(node, ast.Constant) and isinstance(node.value, str) and (
                _IDENTIFIER.fullmatch(node.value)):
            found.add(node.value)
        stack.extend(ast.iter_child_nodes(node))
    return found


def _targets(node: ast.AST) -> list[ast.expr]:
    """The targets of an assignment (``=``, annotated, augmented); none of any other
    node."""
    if isinstance(node, ast.Assign):
        return node.targets
    return [node.target] if isinstance(node, ast.AnnAssign | ast.AugAssign) else []


def _self_member(target: ast.expr) -> str | None:
    """``x`` of the assignment target ``self.x``."""
    if (isinstance(target, ast.Attribute) and isinstance(target.value, ast.Name)
            and target.value.id == "self"):
        return target.attr
    return None


def _read_as_is(value: ast.expr | None, read: tuple[int, int] | None = None) -> bool:
    """Whether an assigned value is a call's result as it is: a chain of attributes and
    method calls on a name (``self.get_parameter("x").value``,
    ``.get_parameter_value().bool_value``, ``rospy.get_param("~x", 1)``) whose calls take
    no call's result, not a value computed from one (``float(..)``, ``x * 1000``). The
    read itself (the call at ``read``: line, column from 0), a method called on a name,
    may take calls' results: they make its name, default or descriptor, not its value
    (``self.declare_parameter('origin', 'auto', descriptor=ParameterDescriptor(..))``,
    marti_common's initialize_origin)."""
    while isinstance(value, ast.Attribute | ast.Call):
        if isinstance(value, ast.Call):
            own = read is not None and (value.lineno, value.col_offset) == read and (
                isinstance(value.func, ast.Attribute)
                and isinstance(value.func.value, ast.Name))
            if not own and any(isinstance(node, ast.Call) for argument in (
                    *value.args, *(k.value for k in value.keywords))
                   for node in ast.walk(argument)):
                return False
            value = value.func
        else:
            value = value.value
    return isinstance(value, ast.Name)


def _member_writes(module: Module) -> dict[str, int]:
    """How many statements of the module assign each ``self.<member>``."""
    if module.member_writes is None:
        found: dict[str, int] = {}
        for node in ast.walk(module.tree):
            targets: list[ast.expr] = []
            if isinstance(node, ast.Assign):
                targets = [t for target in node.targets for t in (
                    target.elts if isinstance(target, ast.Tuple | ast.List) else [target])]
            elif isinstance(node, ast.AnnAssign | ast.AugAssign):
                targets = [node.target]
            for target in targets:
                member = _self_member(target)
                if member is not None:
                    found[member] = found.get(member, 0) + 1
        module.member_writes = found
    return module.member_writes


_MAPPING_METHODS = frozenset({"items", "keys", "values", "iteritems", "iterkeys",
                              "itervalues"})


def _mapping_members(module: Module) -> set[str]:
    """The ``self.<member>`` of the module that some code uses as a dict: a call of a
    dict's own method on it (``self.x.items()``)."""
    if module.mapping_members is None:
        module.mapping_members = {
            member for node in ast.walk(module.tree)
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
            and node.func.attr in _MAPPING_METHODS
            and (member := _self_member(node.func.value)) is not None}
    return module.mapping_members


# builtins whose one argument the code walks element by element (``sorted(self.x)``)
_ITERATING = frozenset({"sorted", "enumerate", "reversed", "list", "tuple", "set"})


def _iterated_members(module: Module) -> set[str]:
    """The ``self.<member>`` of the module that some code walks element by element: the
    iterable of a ``for`` or a comprehension, as it is or as the argument of ``sorted``,
    ``enumerate``, ``reversed``, ``list``, ``tuple`` or ``set``."""
    if module.iterated_members is None:
        walked = [node.iter for node in ast.walk(module.tree)
                  if isinstance(node, ast.For | ast.AsyncFor | ast.comprehension)]
        walked += [node.args[0] for node in ast.walk(module.tree)
                   if isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
                   and node.func.id in _ITERATING and len(node.args) == 1]
        module.iterated_members = {
            member for value in walked if (member := _self_member(value)) is not None}
    return module.iterated_members


def _resolved(value: object) -> tuple[Value, str | None] | None:
    """A name that begins with ``rospy.resolve_name(name)``: the name as written, and,
    when ``/...`` follows it (``resolve_name('mux') + '/select'``), that name as the
    namespace the rest is in, which the graph remaps first (``handle_namespace``: rospy
    gives the name resolved and remapped, ``mux:=input_vel_mux`` makes it
    ``/input_vel_mux/select``). None for any other value."""
    if not isinstance(value, Value) or not value.parts:
        return None
    first = value.parts[0]
    if not isinstance(first, Unknown) or not first.origin.startswith(RESOLVED):
        return None
    written = first.origin.removeprefix(RESOLVED)
    rest = value.parts[1:]
    under = bool(rest) and isinstance(rest[0], str) and rest[0].startswith("/") and (
        rest[0].strip("/"))
    return Value.of(written, *rest), (written if under else None)


def _remote(remote: Value, name: str) -> str:
    """A parameter of another node: ``~x`` of node ``board`` is ``board/x``."""
    node = remote.text.rstrip("/")
    return f"{node}/{name.removeprefix('~')}" if node else name


_Comprehension = ast.ListComp | ast.SetComp | ast.DictComp | ast.GeneratorExp


# the methods that change a list, dict or set in place
_IN_PLACE = frozenset({"append", "extend", "insert", "remove", "pop", "clear", "sort",
                       "reverse", "update", "setdefault", "popitem", "add", "discard"})


def _changed(value: Seq | Record, method: str, args: list[object]) -> Seq | None:
    """A list after ``append`` / ``extend`` / ``insert`` with arguments it can take;
    None for every other change (the value is then unknown)."""
    if not isinstance(value, Seq):
        return None
    if method == "append" and len(args) == 1:
        return Seq((*value.items, args[0]))
    if method == "extend" and len(args) == 1 and isinstance(args[0], Seq):
        return Seq((*value.items, *args[0].items))
    if method == "insert" and len(args) == 2 and isinstance(args[0], int) and not isinstance(
            args[0], bool):
        items = list(value.items)
        items.insert(args[0], args[1])
        return Seq(tuple(items))
    return None


# a test of whether a parameter is set (``rospy.has_param('~x')``, ``self.has_parameter(
# 'x')``): when its absent side fails, the parameter is required
_PRESENCE = re.compile(r"\b(?:has_param|has_parameter)\s*\(")
# what logs an error: rospy's ``logerr`` / ``logfatal`` (and their variants), a logger's
# ``error`` / ``fatal`` (``self.get_logger().error(..)``)
_ERROR_LOGS = frozenset({"logerr", "logfatal", "logerr_throttle", "logfatal_throttle",
                         "logerr_once", "logfatal_once", "logerr_throttle_identical"})


def _leaves(body: list[ast.stmt]) -> str | None:
    """Whether a block always leaves the one around it, and how: ``"failed"`` by
    ``raise``, an exit, or with an error logged; ``"false"`` by ``return False``, a
    negative number or a nonzero integer; ``"done"`` by another ``return``,
    ``continue`` or ``break``; None when it may go on (as ``ConditionReader._leaves``
    tells for C++)."""
    if not body:
        return None
    last = body[-1]
    found: str | None = None
    if isinstance(last, ast.Raise):
        return "failed"
    if isinstance(last, ast.Return):
        value = last.value
        # ``return False``, a negative number, or a nonzero exit status (a script's
        # ``main`` returning 1 to ``sys.exit(main())``: baxter_tools' calibrate_arm.py)
        failed = (isinstance(value, ast.Constant) and (value.value is False or (
            type(value.value) is int and value.value != 0))) or (
            isinstance(value, ast.UnaryOp) and isinstance(value.op, ast.USub)
            and isinstance(value.operand, ast.Constant))
        found = "false" if failed else "done"
    elif isinstance(last, ast.Continue | ast.Break):
        found = "done"
    elif isinstance(last, ast.Expr) and _exits(last.value):
        return "failed"
    elif isinstance(last, ast.If):
        both = (_leaves(last.body), _leaves(last.orelse))
        if None in both:
            return None
        found = "failed" if "failed" in both else "false" if "false" in both else "done"
    if found in ("done", "false") and any(
            isinstance(s, ast.Expr) and (_exits(s.value) or _logs_error(s.value))
            for s in body[:-1]):
        return "failed"
    return found


def _called(expr: ast.expr) -> str:
    return last_name(expr.func) if isinstance(expr, ast.Call) else ""


def _exits(expr: ast.expr) -> bool:
    """``sys.exit(1)``, ``exit()``, ``rospy.signal_shutdown(..)``, ``rclpy.shutdown()``."""
    return _called(expr) in _EXITS or _called(expr) == "quit"


def _logs_error(expr: ast.expr) -> bool:
    name = _called(expr)
    if name in _ERROR_LOGS:
        return True
    if name not in ("error", "fatal") or not isinstance(expr, ast.Call):
        return False
    owner = expr.func.value if isinstance(expr.func, ast.Attribute) else None
    return _called(owner) == "get_logger" if isinstance(owner, ast.Call) else (
        isinstance(owner, ast.Name | ast.Attribute) and "log" in (
            owner.id if isinstance(owner, ast.Name) else owner.attr).lower())


def _guards_first_time(test: ast.expr, rest: list[ast.stmt], module: ast.AST) -> bool:
    """Whether ``if TEST: return`` guards what the method does only once: TEST reads a
    member of ``self`` that the rest of the block assigns (``if self._initialized:
    return`` before ``self._initialized = True``), and that the rest of the module
    assigns literals alone (its first value, ``self._initialized = False``). The first
    run goes past it, so what follows is made (``ConditionReader._guards_first_time``
    for C++). A member the module may set to a value of its own (uuv_simulator's
    thruster manager: ``self.configuration_matrix = numpy.array(tam)`` when ``~tam`` is
    given, then ``update_tam`` returns before its transform listener) is no such flag."""
    return _first_time_guard(test, tuple(rest), module)


@functools.lru_cache(maxsize=4096)
def _first_time_guard(test: ast.expr, rest: tuple[ast.stmt, ...], module: ast.AST) -> bool:
    """``_guards_first_time``, once per ``if`` (a loop or a method inlined at each call
    walks the same one again: ethzasl_xsens_driver's MTDevice, whose every read tests
    ``self`` flags, asked it 16,871 times, each walking the whole module)."""
    members = {member for node in ast.walk(test) if isinstance(node, ast.Attribute)
               and (member := _self_member(node)) is not None}
    if not members:
        return False
    writes = [write for member in members for write in _self_writes(module).get(member, ())]
    if not writes:
        return False
    inside = {id(node) for statement in rest for node in ast.walk(statement)}
    assigned = False
    for node, constant in writes:
        if id(node) in inside:
            assigned = True
        elif not constant:
            return False
    return assigned


@functools.lru_cache(maxsize=64)
def _self_writes(module: ast.AST) -> dict[str, list[tuple[ast.AST, bool]]]:
    """Each member of ``self`` a module's tree assigns, also in part (``self.x = ...``,
    ``self.x += ...``, ``self.x, y = ...``, ``self.x[k] = ...``: ``_member_writes``
    counts the whole ones) -> the assignments, each with whether its value is a
    literal."""
    writes: dict[str, list[tuple[ast.AST, bool]]] = {}
    for node in ast.walk(module):
        members = {member for target in _targets(node) for t in ast.walk(target)
                   if isinstance(t, ast.Attribute) and (member := _self_member(t)) is not None}
        constant = isinstance(getattr(node, "value", None), ast.Constant)
        for member in members:
            writes.setdefault(member, []).append((node, constant))
    return writes


@functools.lru_cache(maxsize=256)
def _rebound_globals(tree: ast.Module) -> frozenset[str]:
    """The names a module's functions declare ``global`` (and so may rebind), and those
    its top level assigns more than once or other than by a plain assignment."""
    found: set[str] = set()
    assigned: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Global):
            found.update(node.names)
    for statement in tree.body:
        targets: list[ast.expr] = []
        if isinstance(statement, ast.Assign):
            targets = list(statement.targets)
        elif isinstance(statement, ast.AnnAssign | ast.AugAssign):
            targets = [statement.target]
            if isinstance(statement, ast.AugAssign) and isinstance(statement.target, ast.Name):
                found.add(statement.target.id)
        for target in targets:
            for node in ast.walk(target):
                if isinstance(node, ast.Name):
                    if node.id in assigned:
                        found.add(node.id)
                    assigned.add(node.id)
    return frozenset(found)


@functools.lru_cache(maxsize=4096)
def _first_time_if(statement: ast.If, module: ast.AST) -> bool:
    """Whether an ``if`` without ``else`` tests a member of ``self`` for being unset
    (``self.pub is None``, ``self.pub == None``, ``not self.ready``) that the module
    sets, outside the block, only to ``None``, ``False``, ``0`` or ``''`` (its first
    value, in ``__init__``), on ``self`` alone: the block runs the first time the code
    reaches it, a lazy initialisation (ethzasl_xsens_driver's ``if self.imu_pub is
    None: self.imu_pub = rospy.Publisher(...)``), so what it makes is made there, as
    C++'s ``if (!initialized_)`` (``ConditionReader._first_time``)."""
    if statement.orelse:
        return False
    test = statement.test
    if isinstance(test, ast.UnaryOp) and isinstance(test.op, ast.Not):
        member = _self_member(test.operand)
    elif isinstance(test, ast.Compare) and len(test.ops) == 1 and isinstance(
            test.ops[0], ast.Is | ast.Eq) and isinstance(test.comparators[0], ast.Constant) \
            and test.comparators[0].value is None:
        member = _self_member(test.left)
    else:
        return False
    if member is None:
        return False
    inside = {id(node) for statement_ in statement.body for node in ast.walk(statement_)}
    outside = [node for node, _ in _self_writes(module).get(member, ())
               if id(node) not in inside]
    if not outside or any(
            not isinstance(node, ast.Assign) or not isinstance(node.value, ast.Constant)
            or node.value.value not in (None, False, 0, "") for node in outside):
        return False
    # (another object's ``x.<member> = ...`` may set it too: not told here)
    return not any(
        isinstance(t, ast.Attribute) and t.attr == member and _self_member(t) is None
        for node in ast.walk(module) if isinstance(node, ast.Assign | ast.AnnAssign)
        for target in _targets(node) for t in ast.walk(target))


@functools.lru_cache(maxsize=4096)
def _builds(loop: ast.For | ast.AsyncFor, function: ast.AST | None) -> bool:
    """Whether a loop of ``function`` (None: none inlined) builds, item by item, a value
    that outlives the call: its body (not a function or class it defines) changes a
    container in place (``names.append(x)``, ``_IN_PLACE``), assigns an item (``d[k] =
    v``) or augments a value (``text += x``) of an object's attribute
    (``self.topics.append``), or of a name the function is given, declares global or
    nonlocal, or stores in an object (``self.topics = names``). A local the function
    only returns is not: what a call returns is evaluated on its own (``values``)."""
    roots: list[ast.expr] = []
    stack: list[ast.AST] = [*loop.body, *loop.orelse]
    while stack:
        node = stack.pop()
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef | ast.Lambda):
            continue
        if isinstance(node, ast.AugAssign):
            roots.append(node.target)
        elif isinstance(node, ast.Assign | ast.AnnAssign):
            roots += [t.value for target in _targets(node)
                      for t in ast.walk(target) if isinstance(t, ast.Subscript)]
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and (
                node.func.attr in _IN_PLACE):
            roots.append(node.func.value)
        stack.extend(ast.iter_child_nodes(node))
    if not roots:
        return False
    names: set[str] = set()
    for root in roots:
        while isinstance(root, ast.Subscript):
            root = root.value
        if not isinstance(root, ast.Name):
            return True  # an attribute, or a value not told
        names.add(root.id)
    return function is None or bool(names & _kept_names(function))


@functools.lru_cache(maxsize=1024)
def _kept_names(function: ast.AST) -> frozenset[str]:
    """The names whose values outlive a call of ``function``: its parameters, those it
    declares global or nonlocal, and those it reads in a value it stores in an object
    (an assignment to an attribute or an item, a container of an attribute changed in
    place)."""
    kept: set[str] = set()
    args = getattr(function, "args", None)
    if isinstance(args, ast.arguments):
        kept.update(a.arg for a in (*args.posonlyargs, *args.args, *args.kwonlyargs))
        kept.update(a.arg for a in (args.vararg, args.kwarg) if a is not None)
    for node in ast.walk(function):
        if isinstance(node, ast.Global | ast.Nonlocal):
            kept.update(node.names)
        stored: list[ast.AST] = []
        if isinstance(node, ast.Assign | ast.AnnAssign | ast.AugAssign):
            if node.value is not None and any(
                    isinstance(t, ast.Attribute | ast.Subscript)
                    for target in _targets(node) for t in ast.walk(target)):
                stored.append(node.value)
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and (
                node.func.attr in _IN_PLACE) and not isinstance(node.func.value, ast.Name):
            stored += [*node.args, *(k.value for k in node.keywords)]
        kept.update(n.id for value in stored for n in ast.walk(value)
                    if isinstance(n, ast.Name))
    return frozenset(kept)


def _names_target(body: list[ast.stmt], target: ast.expr) -> bool:
    """Whether a loop's body names any variable its target binds (read, written or
    deleted, in a function or comprehension it defines too)."""
    names = {n.id for n in ast.walk(target) if isinstance(n, ast.Name)}
    if not names or any(isinstance(n, ast.Attribute | ast.Subscript) for n in ast.walk(target)):
        return True  # an attribute or an item as target: the turn stores the item
    return any(isinstance(n, ast.Name) and n.id in names
               for statement in body for n in ast.walk(statement))


@functools.lru_cache(maxsize=256)
def _converted_locals(tree: ast.Module) -> frozenset[int]:
    """The calls (ids) whose value a function (or the module's own code) keeps in a
    local it assigns once and uses only where any type will do: converted (``int(x)``,
    ``str(x)``, ``float(x)``, ``bool(x)``) or formatted (``'{}'.format(x)``, ``'%s' %
    x``, ``f'{x}'``), or, in a function or a script's ``if __name__ == '__main__':``, not
    at all. A parameter read so has no type of its own, as one converted where it is
    read (mbzirc2020's c3_starter reads ``~ground_id`` with the
    default ``'0'`` and uses ``int(ground_id)``: the launch file's integer 0 is as good;
    mobiman's plot_ocs2_log.py never uses its ``mpc_flag``)."""
    found: set[int] = set()
    scopes: list[ast.AST] = [tree, *(n for n in ast.walk(tree)
                                     if isinstance(n, ast.FunctionDef | ast.AsyncFunctionDef))]
    scripted = {id(n) for guard in tree.body if isinstance(guard, ast.If)
                and is_main_guard(guard.test) for statement in guard.body
                for n in ast.walk(statement)}
    for scope in scopes:
        nodes = list(_scope_nodes(scope))
        stores: dict[str, list[ast.AST]] = {}
        for node in nodes:
            if isinstance(node, ast.Name) and not isinstance(node.ctx, ast.Load):
                stores.setdefault(node.id, []).append(node)
            elif isinstance(node, ast.arg):
                stores.setdefault(node.arg, []).append(node)
        agnostic = {id(child) for node in nodes for child in _typeless_uses(node)}
        for node in nodes:
            if not (isinstance(node, ast.Assign) and len(node.targets) == 1
                    and isinstance(node.targets[0], ast.Name)
                    and isinstance(node.value, ast.Call)):
                continue
            name = node.targets[0].id
            loads = [n for n in ast.walk(scope) if isinstance(n, ast.Name)
                     and n.id == name and isinstance(n.ctx, ast.Load)]
            # (a module's own global may be used by a module that imports it, unless
            # the script's ``if __name__ == '__main__':`` assigns it)
            if len(stores.get(name, ())) == 1 and (
                    loads or scope is not tree or id(node) in scripted) and all(
                    id(n) in agnostic for n in loads):
                found.add(id(node.value))
    return frozenset(found)


def _scope_nodes(scope: ast.AST) -> Iterator[ast.AST]:
    """The nodes of a function's (or module's) own code, not of a function or class it
    defines."""
    stack = list(ast.iter_child_nodes(scope))
    while stack:
        node = stack.pop()
        yield node
        if not isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef
                          | ast.Lambda):
            stack.extend(ast.iter_child_nodes(node))


def _typeless_uses(node: ast.AST) -> Iterator[ast.AST]:
    """The values ``node`` uses where any type will do (``_converted_locals``)."""
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) \
            and node.func.id in _CONVERSIONS and len(node.args) == 1 and not node.keywords:
        yield node.args[0]
    elif isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
            and node.func.attr == "format" and isinstance(node.func.value, ast.Constant) \
            and isinstance(node.func.value.value, str):
        yield from (*node.args, *(k.value for k in node.keywords))
    elif isinstance(node, ast.BinOp) and isinstance(node.op, ast.Mod) \
            and isinstance(node.left, ast.Constant) and isinstance(node.left.value, str):
        yield from (node.right.elts if isinstance(node.right, ast.Tuple) else [node.right])
    elif isinstance(node, ast.FormattedValue) and node.format_spec is None:
        yield node.value


def _is_docstring(statement: ast.stmt) -> bool:
    return isinstance(statement, ast.Expr) and isinstance(statement.value, ast.Constant)


def _stores(body: list[ast.stmt]) -> bool:
    """Whether a loop's body, as written (its callees aside, and nested loops'
    variables, which it binds afresh each turn), stores a value a later turn may see:
    an assignment, a deletion, a ``with ... as``, an import, a global or nonlocal
    declaration, a container changed in place (``names.append(x)``)."""
    for statement in body:
        for node in ast.walk(statement):
            if isinstance(node, ast.Assign | ast.AugAssign | ast.AnnAssign | ast.NamedExpr
                          | ast.Delete | ast.Import | ast.ImportFrom | ast.Global
                          | ast.Nonlocal | ast.FunctionDef | ast.AsyncFunctionDef
                          | ast.ClassDef):
                return True
            if isinstance(node, ast.withitem) and node.optional_vars is not None:
                return True
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
                    and node.func.attr in _IN_PLACE:
                return True
    return False


def _leaves_early(body: list[ast.stmt]) -> bool:
    """Whether a loop's body holds a ``break`` of its own, a ``return`` or a ``raise``
    (not inside a function or class it defines): its later items may not run."""
    stack: list[ast.AST] = list(body)
    while stack:
        node = stack.pop()
        if isinstance(node, ast.Return | ast.Raise):
            return True
        if isinstance(node, ast.Break):
            return True
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef | ast.Lambda):
            continue
        if isinstance(node, ast.For | ast.AsyncFor | ast.While):
            # a break there is that loop's; a return or raise leaves this one too
            stack.extend(n for n in ast.walk(node) if isinstance(n, ast.Return | ast.Raise))
            stack.extend(node.orelse)
            continue
        stack.extend(ast.iter_child_nodes(node))
    return False


def _outside_comprehensions(expr: ast.AST, calls: list[ast.Call],
                            comprehensions: list[_Comprehension]) -> None:
    """The calls of ``expr`` outside its comprehensions (the first iterable of one is
    outside: the enclosing scope evaluates it), and its outermost comprehensions."""
    if isinstance(expr, _Comprehension):
        comprehensions.append(expr)
        _outside_comprehensions(expr.generators[0].iter, calls, comprehensions)
        return
    if isinstance(expr, ast.Call):
        calls.append(expr)
    for child in ast.iter_child_nodes(expr):
        _outside_comprehensions(child, calls, comprehensions)


_UNSET = object()


def _state(frame: Frame) -> tuple[dict[str, object], dict[str, object]]:
    """A frame's locals and its instance's attributes, as they are."""
    return dict(frame.locals), dict(frame.instance.attrs) if frame.instance is not None else {}


def _fallen_back(frame: Frame, tried: tuple[dict[str, object], dict[str, object]]) -> None:
    """After a ``try``'s handlers: a local or attribute of ``self`` that the block set
    from a parameter read (``self._prefix = rospy.get_param("~vehicle_prefix")``) and a
    handler set again (``self._prefix = ""``) is the parameter's value, the handler's
    constant its default: the handler runs when the read fails, the parameter not set
    (autorally's controller: its topics were named by the handler's "" alone)."""
    holders = [(frame.locals, tried[0])]
    if frame.instance is not None:
        holders.append((frame.instance.attrs, tried[1]))
    for now, then in holders:
        for name, value in then.items():
            handled = now.get(name, _UNSET)
            if handled is value or not _from_parameter(value):
                continue
            if isinstance(value, ParamValue) and value.default is None and (
                    isinstance(handled, int | float) or (
                        isinstance(handled, Value) and handled.is_known)):
                value = dataclasses.replace(value, default=handled)
            now[name] = value


def _from_parameter(value: object) -> bool:
    """A parameter's value, or a text holding one (``"/" + prefix``)."""
    return isinstance(value, ParamValue) or (isinstance(value, Value) and any(
        isinstance(part, Unknown) and part.origin.startswith("parameter ")
        for part in value.parts))


def _under(body: Callable[[tuple[Condition, ...]], None], under: tuple[Condition, ...]
           ) -> Callable[[tuple[Condition, ...]], None]:
    """A loop's body walked under ``under`` too."""
    return lambda loop: body((*under, *loop))


def _joined(before: dict[str, object], taken: dict[str, object], other: dict[str, object],
            yes: Condition, no: Condition) -> dict[str, object]:
    """The locals after an ``if``: those both paths leave alike as they are; an imported
    name, a string or a number the paths set differently as ``Alternatives`` (each value
    under its path's condition); a QoS profile with the policies they set differently
    unknown; anything else as a walk in order had left it (the ``else`` path's value
    where it set one, else the ``if`` path's)."""
    joined: dict[str, object] = {}
    for name in dict.fromkeys([*taken, *other]):
        first, second = taken.get(name, _UNSET), other.get(name, _UNSET)
        if first is second or same_value(first, second):
            joined[name] = first
            continue
        options = (*options_under(first, yes), *options_under(second, no))
        if len(options) <= MAX_ALTERNATIVES and all(
                alternative(value) for value, _ in options):
            joined[name] = Alternatives(options)
            continue
        if isinstance(first, QoS) and isinstance(second, QoS):
            # a profile the paths set differently: what they do not agree on is unknown
            one, two = first.as_dict(), second.as_dict()
            joined[name] = QoS(tuple((key, value if two.get(key) == value else None)
                                     for key, value in one.items()))
            continue
        kept = second if second is not before.get(name, _UNSET) else first
        if kept is not _UNSET:
            joined[name] = kept
    return joined


# the standard library's modules of the Pythons ROS distributions run (3.8, Noetic's
# and Foxy's, on) that later releases removed, which ``sys.stdlib_module_names`` of the
# Python running this tool (3.10 or later) may lack: 3.10 removed formatter, parser and
# symbol, 3.11 binhex, 3.12 asynchat, asyncore, distutils, imp and smtpd (PEP 632, the
# deprecations of 3.4-3.6), 3.13 PEP 594's dead batteries and lib2to3; 3.9 removed
# dummy_threading and _dummy_thread. A Noetic node's ``from distutils.version import
# LooseVersion`` is the standard library's, whatever Python reads it.
REMOVED_STDLIB = frozenset({
    "_dummy_thread", "dummy_threading", "formatter", "parser", "symbol", "binhex",
    "asynchat", "asyncore", "distutils", "imp", "smtpd", "aifc", "audioop", "cgi", "cgitb",
    "chunk", "crypt", "imghdr", "mailcap", "msilib", "nis", "nntplib", "ossaudiodev",
    "pipes", "sndhdr", "spwd", "sunau", "telnetlib", "uu", "xdrlib", "lib2to3"})


def _foreign(module: str) -> bool:
    """Whether the top-level module ``module``, which the workspace does not hold, may be
    ROS code: not the standard library's (of this Python, or one a ROS distribution
    runs: ``REMOVED_STDLIB``), a client library or module the API tables read, nor a
    package known to make no ROS call (``NOT_CLIENTS``)."""
    from . import NOT_CLIENTS  # (the package reads this module)

    return module not in sys.stdlib_module_names and module not in REMOVED_STDLIB and (
        module not in NOT_CLIENTS) and module not in api_modules()


# builtins given a class that they never build
_TAKE_CLASSES = frozenset({"isinstance", "issubclass", "super", "type", "getattr", "hasattr",
                           "setattr", "delattr", "vars", "dir", "id", "repr", "str", "print",
                           "hash", "callable"})


# the packages whose classes the API tables model (by their first module name)
_MODELLED = frozenset(key[0] for table in (rospy.ROWS, rclpy.ROWS, rospy.NODE_NAMES,
                                           rclpy.NODE_NAMES) for key in table)


def _literal(value: object) -> bool:
    """Whether a walked value is a literal the walk knows: a number, a bool, None or a
    fully known string."""
    return value is None or isinstance(value, bool | int | float) or (
        isinstance(value, Value) and value.literal is not None)


def _unassigned_parameters(function: ast.AST) -> frozenset[str]:
    """The named parameters of ``function`` (not ``*args`` / ``**kwargs``) that nothing
    in its body assigns, deletes or declares ``global`` / ``nonlocal`` (a nested
    function's too: kept out to be safe)."""
    args = getattr(function, "args", None)
    if not isinstance(args, ast.arguments):
        return frozenset()
    names = {a.arg for a in (*args.posonlyargs, *args.args, *args.kwonlyargs)}
    for node in ast.walk(function):
        if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store | ast.Del):
            names.discard(node.id)
        elif isinstance(node, ast.Global | ast.Nonlocal):
            names.difference_update(node.names)
        elif isinstance(node, ast.ExceptHandler) and node.name:
            names.discard(node.name)
        elif isinstance(node, ast.alias):
            names.discard((node.asname or node.name).partition(".")[0])
        elif isinstance(node, ast.arg) and node not in (
                *args.posonlyargs, *args.args, *args.kwonlyargs):
            names.discard(node.arg)  # a nested function's or lambda's own parameter
    return frozenset(names)
