"""Values of the static Python interpreter, its bounds, and how they become launch text.

``Unknown`` is a value we do not know; ``Lazy`` a string with substitutions or unknown parts
(a ``Text``, computed when the action runs); ``Ref`` a module or an imported name;
``Func`` a function of the interpreted file; ``ReadOnlyFile`` what ``open()`` gives.
"""

from __future__ import annotations

import ast
import functools
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import PurePosixPath
from typing import Any

from ...evaluate.operations import Limits
from ...model.location import Location
from ...model.values import Unknown
from . import entities as e

MAX_SOURCE = 512 * 1024
MAX_NODES = 100_000
MAX_DEPTH = 100
MAX_STEPS = 200_000
MAX_CALL_DEPTH = 40
MAX_SIZE = 100_000  # items of a container or characters of a string
# the one evaluator's operations, with this reader's size bound
LIMITS = Limits(length=MAX_SIZE, steps=MAX_STEPS)
MAX_READ = 1024 * 1024  # bytes of a file read by open() / yaml.safe_load


class Budget(Exception):
    """A bound was reached: interpretation stops."""


class Unsupported(Exception):
    """A construct outside the subset, where a value cannot stand for it."""


class _Flow(Exception):
    """return / break / continue, as control flow of the interpreted code."""


class _Return(_Flow):
    def __init__(self, value: Any) -> None:
        self.value = value


class _Break(_Flow):
    pass


class _Continue(_Flow):
    pass


class _Stop(_Flow):
    """``sys.exit()`` / ``exit()`` / a ``raise`` no ``try`` of the interpreted code
    catches: the launch file stops there (``what``: the statement, said ``where`` it is,
    in the file of the function that runs it, when it is reached under no test not
    known)."""

    def __init__(self, what: str, where: Location) -> None:
        self.what = what
        self.where = where


class Raised(Exception):
    """A builtin exception the interpreted code raises (``int("camera")``) inside a
    ``try`` whose handler catches it: the interpreter goes on in that handler, as Python
    does (``Interpreter.failed``)."""

    def __init__(self, name: str) -> None:
        self.name = name


class Guard(str):
    """The text of a Python test not known statically that the code at hand runs under,
    and which run of a test of the file this is (``run``, counted by ``Expressions.guard``):
    the same test run again (a loop's next item, another call of its function) may come
    out otherwise, so what two runs make is not under one condition, though its text is
    the same."""

    run: int
    test: int | None  # the ``if`` test it comes from (``id`` of its node), if one

    def __new__(cls, text: str, run: int, test: int | None = None) -> Guard:
        made = super().__new__(cls, text)
        made.run = run
        made.test = test
        return made


def conjunction(tests: Iterable[str]) -> str:
    """The text of Python tests that all hold, joined by ``and``: one that is an ``or``
    (or a conditional expression, a lambda) in parentheses when there are several, as
    Python would read it otherwise (``not (a or b) and (c or d)``, not ``... and c or
    d``)."""
    texts = list(tests)
    if len(texts) == 1:
        return texts[0]
    return " and ".join(f"({text})" if _loose(text) else text for text in texts)


@functools.lru_cache(maxsize=1024)
def _loose(text: str) -> bool:
    """Whether ``text`` binds more loosely than ``and`` (a text that is no expression,
    ``for x in items``, is taken as written)."""
    try:
        node = ast.parse(text, mode="eval").body
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return False
    return (isinstance(node, ast.BoolOp) and isinstance(node.op, ast.Or)) or isinstance(
        node, (ast.IfExp, ast.Lambda, ast.NamedExpr))


def derived(owner: Unknown, origin: str) -> Unknown:
    """The result of a method not interpreted of the unknown ``owner``: of one made by a
    construct said not interpreted where it was made, of that kind and place too, so
    that nothing made of it says so again: the calls chained on a
    ``MoveItConfigsBuilder`` of a package not known statically were said at every
    second one (the result of a method of a said value was a plain unknown, and a method
    of that was said), and the ``.to_dict()`` of its configs given as a node's
    parameters once more at each node."""
    if owner.kind == "unsupported":
        return Unknown(origin, "unsupported", where=owner.where)
    return Unknown(origin)


@dataclass(frozen=True)
class InstalledPackages(Unknown):
    """ament_index_python's ``get_packages_with_prefixes()``: every package installed
    where the launch file runs, by name, with its prefix. Not known here, but ``name in
    it`` is ``has_resource('packages', name)`` (``Interpreter.compare_values``)."""


@dataclass(frozen=True)
class Lazy:
    """A string with substitutions or unknown parts, computed when the action runs."""

    text: e.Text


@dataclass(eq=False)
class XacroDocument:
    """What ``xacro.process_file(path, mappings=...)`` returns: never processed here; its
    ``toxml()`` is the output of the ``xacro`` command line it stands for. Or what
    ``xacro.parse(open(path))`` returns (``path``): the file as it is, a ``cat`` command,
    until ``xacro.process_doc(doc, mappings=...)`` processes it in place."""

    command: e.Text
    path: Any = None


@dataclass(frozen=True)
class Ref:
    """A module or a name imported from one: ``launch_ros.actions.Node``."""

    qualified: str


@dataclass(eq=False)
class Module:
    """A Python file of the workspace that the launch file imports by its name from a
    folder it put on ``sys.path``: its module-level names, as interpreted here."""

    name: str
    path: str
    names: dict[str, Any]


@dataclass
class Func:
    node: ast.FunctionDef | ast.Lambda
    closure: dict[str, Any]


@dataclass(eq=False)
class ActionClass:
    """A class the interpreted code defines on a launch action (``class
    DeclareArmDescription(DeclareLaunchArgument)``) with a constructor at most: calling it
    builds ``base`` (a ``Ref`` of the API or another such class) with what the
    constructor hands to ``super().__init__``."""

    name: str
    base: Any
    init: Func | None


@dataclass(eq=False)
class SubstitutionClass:
    """A class the interpreted code defines on launch's ``Substitution`` (with its own
    ``perform``, not interpreted): an object of it is a substitution whose value is not
    known, but launch performs it where the action using it runs, and it performs the
    substitutions its constructor is given (create3_sim's and turtlebot4_simulator's
    ``OffsetParser(LaunchConfiguration('x'), 0.157)``)."""

    name: str


@dataclass(eq=False)
class PlainClass:
    """A class of the interpreted code that is no launch action (vrx_gz's ``Model``,
    whose methods build its bridges and nodes; a ``@dataclass`` ``Bridge``; an ``Enum``):
    calling it makes an ``Instance``, its methods run when called. ``methods``: name ->
    (kind: method, static, class or property; function); ``attributes``: the names its
    body sets (an Enum's members); ``fields``: a dataclass's fields in order with their
    defaults (``UNSET`` for none), None for a class that is no dataclass."""

    name: str
    methods: dict[str, tuple[str, Func]] = field(default_factory=dict)
    attributes: dict[str, Any] = field(default_factory=dict)
    fields: list[tuple[str, Any]] | None = None
    enum: bool = False


@dataclass(eq=False)
class Instance:
    """An object of a ``PlainClass``: the attributes its constructor and methods set."""

    cls: PlainClass
    attributes: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class EnumMember:
    """A member of an ``Enum`` class of the interpreted code (``BridgeDirection.GZ_TO_ROS``):
    itself, equal to no other value, with its ``name`` and ``value``."""

    cls: str
    name: str
    value: Any


@dataclass(eq=False)
class Method:
    """A function of a ``PlainClass`` bound to what it gets first: the instance, or the
    class for a classmethod."""

    func: Func
    owner: Any


OUTER = "__outer__"  # a function's names declared ``global`` / ``nonlocal``: their scopes


def write_outer(env: dict[str, Any]) -> None:
    """The names a function declared ``global`` / ``nonlocal`` take, in their own
    scopes, the values the function gave them so far: when it returns, and before it
    calls a function, which may read them there (Python writes them there at once)."""
    for name, scope in env.get(OUTER, {}).items():
        if name in env:
            scope[name] = env[name]


def read_outer(env: dict[str, Any]) -> None:
    """After a call: the names the function declared ``global`` / ``nonlocal`` as the
    callee may have left them in their scopes."""
    for name, scope in env.get(OUTER, {}).items():
        if name in scope:
            env[name] = scope[name]


UNSET = object()  # a dataclass field with no default


@dataclass(eq=False)
class FieldFactory:
    """A dataclass field's ``field(default_factory=...)``: called for each instance."""

    func: Any


@dataclass(eq=False)
class Constructing:
    """``self`` in an ``ActionClass``'s constructor: the attributes it sets, and the
    action its base built once ``super().__init__`` ran."""

    cls: ActionClass
    attributes: dict[str, Any] = field(default_factory=dict)
    built: Any = None


@dataclass(frozen=True)
class SuperOf:
    """``super()`` in an ``ActionClass``'s constructor."""

    instance: Constructing


@dataclass(frozen=True)
class ReadOnlyFile:
    """What ``open(path)`` gives: only ``read()`` and ``yaml.safe_load`` use it."""

    path: str


@dataclass(eq=False)
class Record:
    """An object of a known helper library whose attributes are data the launch file
    reads and changes in place (moveit_configs_utils' ``MoveItConfigs``: a dataclass of
    dicts); ``facts`` are what its rows know of it that the file cannot read."""

    cls: str
    attributes: dict[str, Any]
    facts: dict[str, Any] = field(default_factory=dict)


@dataclass
class LaunchDescription:
    actions: list[Any] = field(default_factory=list)


class DefaultDict(dict[Any, Any]):
    """``collections.defaultdict(factory)``: a dict whose lookup of a key it lacks
    stores what calling ``factory`` (an interpreted value: ``list``, a lambda) gives
    (``Interpreter.eval_Subscript``); a plain dict to everything else."""

    def __init__(self, factory: Any, *args: Any) -> None:
        super().__init__(*args)
        self.factory = factory


@dataclass(frozen=True)
class Context:
    """The ``context`` an ``OpaqueFunction`` receives: reads the runner's scope.
    ``assigned``: the launch configurations the function sets
    (``context.launch_configurations["rate"] = ...``), which it reads back and the
    actions after it see. ``configuration(name)``: how the scope holds a configuration,
    ``("set", None)`` (performed as a ``LaunchConfiguration``), ``("value", v)`` (one
    that is no text: launch_ros' ``global_params``), ``("unset", None)`` or
    ``("unknown", None)`` (an action not seen may have set it); None for a context the
    launch file made itself."""

    perform: Callable[[e.Text], Any]
    assigned: dict[str, Any] = field(default_factory=dict, compare=False)
    configuration: Callable[[str], tuple[str, Any]] | None = field(default=None,
                                                                  compare=False)

    def held(self, name: Any) -> tuple[str, Any]:
        """How the configuration ``name`` is held for a read: ``("value", v)`` for one
        the function set or launch_ros' ``global_params``, else ``configuration``'s
        state (``("set", None)`` when it cannot tell: performed as a
        ``LaunchConfiguration``)."""
        if not isinstance(name, str):
            return "set", None
        if name in self.assigned:
            return "value", self.assigned[name]
        return self.configuration(name) if self.configuration is not None else ("set", None)


_KNOWN_ROOTS = ("launch", "launch_ros", "launch_xml", "launch_yaml", "os", "ament_index_python",
                "nav2_common", "builtins", "pathlib", "yaml", "xacro", "copy", "launch_pal",
                "controller_manager", "robotnik_common", "moveit_configs_utils",
                "launch_param_builder", "itertools", "collections", "tempfile", "json",
                "typing",
                # their launch actions (package_actions)
                "ros_gz_bridge", "ros_gz_sim")
# the modules of a package whose launch actions the API's rows are (python_webots); the
# package's other modules are read where the workspace holds them
_KNOWN_MODULES = ("webots_ros2_driver.webots_launcher",
                  "webots_ros2_driver.webots_controller",
                  "webots_ros2_driver.wait_for_controller_connection")


def _known_module(qualified: str) -> bool:
    return qualified.split(".")[0] in _KNOWN_ROOTS or any(
        qualified == module or qualified.startswith(module + ".") for module in _KNOWN_MODULES)


def _source(node: ast.AST) -> str:
    try:
        text = ast.unparse(node)
    except Exception:
        text = "?"
    return text if len(text) <= 200 else text[:197] + "..."


def _load(target: ast.expr) -> ast.expr:
    copy = ast.parse(ast.unparse(target), mode="eval").body
    return ast.copy_location(copy, target)


def _hashable(value: Any) -> Any:
    if isinstance(value, list):
        return tuple(_hashable(v) for v in value)
    if isinstance(value, dict):
        return Unknown("dict key")
    if _opaque(value) or isinstance(value, slice):  # a substitution, an unknown: the
        return value  # lookup says what it cannot; a slice is no key
    try:
        hash(value)
    except TypeError:  # a value of the interpreter's own (a method not called, ...)
        return Unknown("dict key not known statically")
    return value


def open_keys(keys: Iterable[Any]) -> bool:
    """Whether one of ``keys`` (a dict's) is not known statically, wholly or in part (an
    item set under ``payload[sensor.name()]`` or ``payload['thrust_' + name]``): a key
    not among a dict's known ones may be that one, so a lookup of it is not known."""
    stack = list(keys)
    while stack:
        key = stack.pop()
        if isinstance(key, tuple):
            stack.extend(key)
        elif _opaque(key):
            return True
    return False


def _opaque(value: Any) -> bool:
    return isinstance(value, (Unknown, Lazy, e.Subst, e.Cond, e.Action))


def launch_object(value: Any) -> bool:
    """An object of launch's API (a condition, a substitution, an action): none of their
    classes defines ``__bool__`` or ``__len__``, so Python takes each as true, unevaluated.
    A string with substitutions (``Lazy``, a ``str`` when it runs) is not one."""
    return isinstance(value, (e.Subst, e.Cond, e.Action))


# launch's class of a substitution only one call makes here, by its module's path
_PYTHON_CLASS: dict[type, str] = {
    e.Var: "launch.substitutions.launch_configuration.LaunchConfiguration",
    e.Env: "launch.substitutions.environment_variable.EnvironmentVariable",
    e.Command: "launch.substitutions.command.Command",
    e.Eval: "launch.substitutions.python_expression.PythonExpression",
    e.Literal: "launch.substitutions.text_substitution.TextSubstitution",
    e.DeclareArg: "launch.actions.declare_launch_argument.DeclareLaunchArgument",
}


def object_text(value: Any) -> Lazy | None:
    """Python's ``str()`` and ``repr()`` of an object of launch's API (a substitution, a
    condition, an action; not a ``pathlib`` path): no class of launch or launch_ros
    defines ``__str__`` or ``__repr__`` for them, so it is ``object``'s,
    ``<module.Class object at 0x...>``, never the value the substitution stands for (nor
    a path); its address is not known here. None for any other value."""
    if not launch_object(value) or (isinstance(value, e.PathJoin)
                                    and value.python == e.PATHLIB):
        return None
    name = value.python if isinstance(value, e.PathJoin) else _PYTHON_CLASS.get(type(value))
    address = e.Opaque("str() / repr() of a launch object is Python's object text with its "
                       "address, not the value it stands for")
    if not name:
        return Lazy(("<", e.Opaque("the class of a launch object (its str() or repr())"),
                     " object at ", address, ">"))
    return Lazy((f"<{name} object at ", address, ">"))


ENV_UNSET = "environment variable "  # the origin ``os.environ`` / ``os.getenv`` give one


def env_unset(values: Iterable[Any]) -> tuple[str, ...]:
    """The environment variables (``environment variable NAME``) that ``values`` are
    unknown through, when that is their only unknown: an unset variable's read (a
    ``Lazy`` of its ``Opaque``, said where it was read) or a value computed from such
    reads alone (``env_unknown``); () when any value is unknown for another cause, or
    none is unknown."""
    causes: list[str] = []
    for value in values:
        if isinstance(value, Lazy):
            for part in value.text:
                if isinstance(part, e.Opaque) and not part.report and (
                        part.origin.startswith(ENV_UNSET)):
                    causes.append(part.origin)
                elif not isinstance(part, str):
                    return ()
        elif isinstance(value, Unknown):
            if not value.causes or not all(c.startswith(ENV_UNSET) for c in value.causes):
                return ()
            causes.extend(value.causes)
    return tuple(dict.fromkeys(causes))


def said_unknown(what: str, values: Iterable[Any]) -> Unknown | None:
    """What Python computes from a value a construct not interpreted made (kind
    ``unsupported``, said where it was made): unknown, said there only, so that its uses
    say no more (``'robot_' + str(int(subprocess.check_output(...)) + 1)``, ``str(i)``
    of the item of a loop over such a value, ``range()`` of one); None when no value
    is one."""
    for value in values:
        if isinstance(value, Unknown) and value.kind == "unsupported":
            return Unknown(f"{what} of {value.origin}", "unsupported", causes=value.causes,
                           where=value.where)
        if isinstance(value, Lazy):
            # a text of such values (``'robot_' + str(...)``, a path joined of them):
            # said where each was made
            made = _said_parts(value.text)
            if made is not None:
                return Unknown(f"{what} of {made.origin}", "unsupported")
    return None


def _said_parts(text: e.Text) -> e.Opaque | None:
    """The first part of ``text`` said not known where it was made, when every part is
    known text or such a part (through path joins: ``os.path.join(folder, said)``);
    None when another part is not known, or none is."""
    first: e.Opaque | None = None
    for part in text:
        if isinstance(part, str):
            continue
        if isinstance(part, e.Opaque) and not part.report:
            first = first or part
            continue
        if isinstance(part, e.PathJoin):
            for piece in part.parts:
                if all(isinstance(x, str) for x in piece):
                    continue
                made = _said_parts(piece)
                if made is None:
                    return None
                first = first or made
            continue
        return None
    return first


def derived_unknown(what: str, values: Iterable[Any], where: Location | None
                    ) -> Unknown | None:
    """What Python computes from ``values`` when one is already said not known: unknown
    only through unset environment variables (``env_unknown``, said where they were
    read), or through a value a construct not interpreted made (``said_unknown``); None
    when neither, and the caller says why it is not known."""
    values = list(values)
    causes = env_unset(values)
    if causes:
        return env_unknown(what, causes, where)
    return said_unknown(what, values)


def env_unknown(what: str, causes: tuple[str, ...], where: Location | None) -> Unknown:
    """What Python computes from values unknown only through unset environment
    variables (``int(os.environ['DRONE_ID'])``, ``count > 0``): unknown, and said where
    the variables were read (LAUNCH_UNKNOWN_VALUE), so its uses say no more, as those of
    a construct said not interpreted (kind ``unsupported``); ``causes`` names them."""
    return Unknown(f"{what} of {', '.join(causes)}", "unsupported", causes=causes,
                   where=where)


def is_lazy(value: Any) -> bool:
    return isinstance(value, (Lazy, e.Subst, Unknown))


def is_stringy(value: Any) -> bool:
    return isinstance(value, (str, Lazy, e.Subst, Unknown))


def _text_of(value: Any) -> e.Text:
    return to_text(value)


def to_text(value: Any) -> e.Text:
    """A launch text (str / substitution / list of them) as our ``Text``."""
    if isinstance(value, str):
        return (value,)
    if isinstance(value, PurePosixPath):  # pathlib.Path(...) of known parts
        return (str(value),)
    if isinstance(value, Lazy):
        return value.text
    if isinstance(value, e.Literal):  # its text, the value launch performs it to
        return value.text
    if isinstance(value, e.Subst):
        return (value,)
    if isinstance(value, (list, tuple)):
        return e.text(*(to_text(v) for v in value))
    if isinstance(value, dict):
        # launch's normalisation iterates what it is given: a dict gives its keys
        # (space-ros' ``arguments=["-topic", robot_description]``, the parameter dict
        # ``{"robot_description": ...}``, is the word ``robot_description``); a key that
        # is neither text nor a substitution is its TypeError
        if all(isinstance(key, str) or is_lazy(key) for key in value):
            return e.text(*(to_text(key) for key in value))
        return (e.Opaque("a dict whose keys are not all text or substitutions is used "
                         "where launch takes text or substitutions: ros2 launch stops "
                         "with a TypeError", refused=True),)
    if isinstance(value, bool):
        return (str(value).lower(),)
    if isinstance(value, (int, float)):
        return (str(value),)
    if isinstance(value, Unknown):
        # one made by a construct not interpreted was said where it was made, once;
        # its uses say no more
        return (e.Opaque(value.origin, report=value.kind != "unsupported"),)
    if isinstance(value, e.ParamFile):
        return (e.FileRef(value),)
    if isinstance(value, e.Action):  # launch's normalisation raises a TypeError on it
        what = (f"DeclareLaunchArgument('{value.name}')" if isinstance(value, e.DeclareArg)
                else f"a {type(value).__name__} action")
        return (e.Opaque(f"{what} is used where launch takes text or substitutions: "
                         "ros2 launch stops with a TypeError", refused=True),)
    return (e.Opaque(f"{type(value).__name__} value"),)


PLAIN = (str, int, float, bool, type(None))


def printable(value: Any, path: bool = True) -> bool:
    """Whether Python's text of ``value`` is known: a plain value (``str``, ``int``,
    ``float``, ``bool``, ``None``; a path where ``path``), or a list, tuple or dict of
    plain values, nested. A substitution, a path or any object of ours inside one is not
    (its text would be our object's, not what the launch file makes). Walks at most
    ``LIMITS.length`` items; past that the text is too long anyway and the bounded
    ``str`` / ``repr`` refuse it."""
    if isinstance(value, PLAIN) or (path and isinstance(value, PurePosixPath)):
        return True
    stack = [value]
    seen = 0
    while stack and seen <= LIMITS.length:
        item = stack.pop()
        seen += 1
        if isinstance(item, dict):
            stack.extend(item.keys())
            stack.extend(item.values())
        elif isinstance(item, (list, tuple)):
            stack.extend(item)
        elif not isinstance(item, PLAIN):
            return False
    return True


def concat(parts: list[Any]) -> Any:
    """Join strings, substitutions and unknowns: a str when all parts are known."""
    out: list[str | e.Subst] = []
    for part in parts:
        if isinstance(part, (int, float)) and not isinstance(part, bool):
            out.append(str(part))
        elif isinstance(part, (str, Lazy, e.Subst, Unknown, PurePosixPath)):
            out.extend(to_text(part))
        else:
            out.append(e.Opaque(f"{type(part).__name__} in a string"))
    if all(isinstance(p, str) for p in out):
        return "".join(p for p in out if isinstance(p, str))
    return Lazy(tuple(out))
