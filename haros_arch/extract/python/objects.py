"""The static values the Python evaluator works with.

Strings are ``model.values.Value`` (unknown parts print as ``?``); numbers, booleans and
None are themselves; everything else is one of the small value classes here.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from ...model.conditions import Condition
from ...model.values import Unknown, Value, scalar_type
from .modules import ClassInfo, FunctionInfo, Module


@dataclass(frozen=True)
class Ref:
    """Something imported from outside the package, by qualified name."""

    qualname: str

    @property
    def key(self) -> tuple[str, str]:
        parts = self.qualname.split(".")
        return parts[0], parts[-1]


# the origin of the unknown text of a program's command-line argument: its index follows
# (``sys.argv[1]``: 1; ``rospy.myargv()[-1]``: -1), as ``PrimitiveCall.name_arg`` counts
PROGRAM_ARGUMENT = "program argument "


# the origin of the unknown text of an option of the program's command line that
# argparse parses (``args.limb`` of ``add_argument("-l", "--limb")``): its flags follow,
# separated by spaces, as ``PrimitiveCall.name_option`` keeps them
PROGRAM_OPTION = "program option "


@dataclass(frozen=True)
class ArgParser:
    """An ``argparse.ArgumentParser``: its options are the ``add_argument`` calls made on
    the same receiver in its module (``ProgramOptions``, once parsed)."""


@dataclass(frozen=True)
class ProgramOptions:
    """What ``parse_args`` gives: each option's value (by ``dest``) is the unknown text the
    launch file's arguments for the instance tell; ``options`` maps a ``dest`` to the
    option's flags, space separated."""

    options: tuple[tuple[str, str], ...]

    def value(self, dest: str) -> object:
        flags = dict(self.options).get(dest)
        if flags is None:
            return Unknown(f"option {dest}")
        return Value.unknown(f"{PROGRAM_OPTION}{flags}")


@dataclass(frozen=True)
class ProgramArgs:
    """A program's command-line arguments: ``sys.argv``, every word as given (after the
    user's arguments roslaunch adds its ``:=`` words, ros2 launch its ``--ros-args``), or
    what ``rospy.myargv()`` leaves of them (``stripped``: its ``:=`` words taken off)."""

    stripped: bool

    def item(self, index: object) -> object:
        """``args[index]``: the argument's unknown text, which the launch file's
        arguments for the instance tell (``graph``); from the end only of what rospy
        leaves (the last word as given is roslaunch's ``__log:=``)."""
        if isinstance(index, int) and not isinstance(index, bool) and (
                index > 0 or (index < 0 and self.stripped)):
            return Value.unknown(f"{PROGRAM_ARGUMENT}{index}")
        return Value.unknown("program argument")


@dataclass(frozen=True)
class ParamValue:
    """The value of a parameter read (``rospy.get_param('~topic', 'scan')``)."""

    name: str
    default: object = None


ELEMENT_OF = "an element of parameter "  # the origin of a ``ParamElement``'s unknown text
FIELD_OF = ", field "  # after it, the element's field


@dataclass(frozen=True)
class ParamElement:
    """An element of the list parameter ``name``: the variable of a loop over its value
    (``for step in self.get_parameter('steps').value``); a call it names is one call per
    element (``PrimitiveCall.name_each``), or per element's ``field`` (``src['topic']``
    of ``for src in rospy.get_param('~sources')``; ``.``: the element itself)."""

    name: str
    field: str = "."


TURN_OF = "a turn of a loop up to parameter "  # the origin of a ``ParamTurn``'s text
TURN_FROM = ", from "  # after it, the loop's first value


@dataclass(frozen=True)
class ParamTurn:
    """The variable of a counting loop up to an integer parameter's value (``for i in
    range(rospy.get_param('~waypoint_num'))``): a call named by it is one call per turn
    of the value the configuration gives ``name`` (``PrimitiveCall.name_each``
    ``COUNTED``), from ``start``; ``shift`` is a constant added to it (``i + 1``)."""

    name: str
    start: int = 0
    shift: int = 0
    length: bool = False  # up to the number of elements of the list ``name`` (``len(p)``)


@dataclass(frozen=True)
class ParamObject:
    """An rclpy ``Parameter`` object (from ``get_parameter`` / ``declare_parameter``)."""

    name: str
    default: object = None


@dataclass(frozen=True)
class NewParameter:
    """An rclpy ``Parameter(name, type, value)`` the code builds (to give to
    ``set_parameters``), kept in a variable: its name and the value expression's value."""

    name: Value
    value: object = None


@dataclass(frozen=True)
class ParameterClient:
    """An rclpy ``AsyncParameterClient`` for the parameters of the node ``remote``."""

    remote: Value


@dataclass(eq=False)
class NodeHandle:
    """An rclpy node made by ``rclpy.create_node`` or ``Node(...)``."""

    name: object = None


@dataclass(eq=False)
class Instance:
    cls: ClassInfo
    attrs: dict[str, object] = field(default_factory=dict)
    # an rclpy node: the name its __init__ gives it (``super().__init__('talker')``)
    node_name: str | None = None


@dataclass(frozen=True)
class BoundMethod:
    instance: Instance
    function: FunctionInfo


@dataclass(frozen=True)
class NodeMethod:
    """A method of an rclpy node: ``self.create_publisher`` in a ``Node`` subclass."""

    name: str
    # the node whose parameters a parameter client's method reads or writes
    remote: Value | None = None
    # the node it is a method of: an ``Instance`` of a Node subclass or a ``NodeHandle``
    owner: object = None


@dataclass(frozen=True)
class SuperInit:
    """``super().__init__`` or ``Node.__init__`` in a class."""


@dataclass(frozen=True)
class QoS:
    policies: tuple[tuple[str, Any], ...]

    def as_dict(self) -> dict[str, Any]:
        return dict(self.policies)


@dataclass(frozen=True)
class Seq:
    items: tuple[object, ...]


@dataclass(frozen=True)
class Record:
    """A dict literal whose keys are known strings (crane_x7's ``{"control":
    "/crane_x7/crane_x7_control", "joint": "crane_x7_wrist_joint"}``): an entry read with
    a known key is its value."""

    entries: tuple[tuple[str, object], ...]

    def entry(self, key: str) -> object:
        for name, value in self.entries:
            if name == key:
                return value
        return Unknown(f"entry {key}")


@dataclass(frozen=True)
class Alternatives:
    """A local that the two paths of an ``if`` leave different (``TwistMsg =
    TwistStamped`` if ``stamped``, else ``Twist``): each value with the conditions under
    which it holds. A call given it as an argument is one call per value, under its
    conditions (``PyVisitor._call``)."""

    options: tuple[tuple[object, tuple[Condition, ...]], ...]


MAX_ALTERNATIVES = 4  # values a local (or a helper's return) may hold per path


def options_under(value: object, under: Condition
                  ) -> tuple[tuple[object, tuple[Condition, ...]], ...]:
    """``value`` on a path under ``under``: each of its own options when it has several."""
    if isinstance(value, Alternatives):
        return tuple((each, (under, *conditions)) for each, conditions in value.options)
    return ((value, (under,)),)


def same_value(first: object, second: object) -> bool:
    """Whether two values of two paths are alike (a comparison that fails: not)."""
    try:
        return bool(first == second)
    except Exception:
        return False


def alternative(value: object) -> bool:
    """A value a call's argument can take per path: a message type or other imported
    name, a string, a number."""
    return isinstance(value, Ref | Value | int | float)


def returned_alternative(value: object) -> bool:
    """A value a helper may return per path (``Evaluator.returned``): an ``alternative``;
    a parameter's value (a call it names is named by the parameter on that path); a
    literal list of them (what a loop over the return walks on that path):
    joint_state_publisher's ``get_param(name, value)`` returns the private parameter,
    else the global one, else ``value``."""
    return alternative(value) or isinstance(value, ParamValue) or (
        isinstance(value, Seq) and all(alternative(item) for item in value.items))


@dataclass(frozen=True)
class ModuleRef:
    module: Module


@dataclass
class Frame:
    module: Module
    locals: dict[str, object] = field(default_factory=dict)
    instance: Instance | None = None
    depth: int = 0
    # the module's own top-level code: its imports and definitions are indexed already
    top: bool = False
    # the class whose method this frame runs (``super()`` starts after it)
    owner: ClassInfo | None = None


def text_of(value: object) -> Value:
    """A value as a string value, with ``?`` for what is not known."""
    if isinstance(value, Value):
        return value
    if isinstance(value, bool):
        return Value.of(str(value))
    if isinstance(value, int | float):
        return Value.of(repr(value))
    if isinstance(value, ParamValue):
        return Value.unknown(f"parameter {value.name}")
    if isinstance(value, ParamElement):
        field = "" if value.field == "." else f"{FIELD_OF}{value.field}"
        return Value.unknown(f"{ELEMENT_OF}{value.name}{field}")
    if isinstance(value, ParamTurn):
        return Value.unknown(f"{TURN_OF}{value.name}{TURN_FROM}{value.start}"
                             + (f"{value.shift:+d}" if value.shift else "")
                             + ("#" if value.length else ""))
    return Value.unknown(getattr(value, "origin", "") or type(value).__name__)


def param_type(value: object) -> str | None:
    """A parameter type from the Python value it is given (as the C++ extractor names them)."""
    if isinstance(value, bool | int | float):
        return scalar_type(value)
    if isinstance(value, Value):
        return "str"
    if isinstance(value, Seq):
        # rclpy types a list by its elements (Parameter.Type.from_parameter_value): a
        # list of one known scalar type is that type's array, as C++'s std::vector<T>
        # is T[]; an empty one, or one of elements not known or mixed, stays a list
        kinds = {param_type(item) for item in value.items}
        only = next(iter(kinds)) if len(kinds) == 1 else None
        return f"{only}[]" if only in ("bool", "int", "double", "str") else "list"
    return None


def plain_value(value: object) -> object:
    """A value as JSON data when it is fully known (a default in code), else None."""
    if isinstance(value, bool | int | float):
        return value
    if isinstance(value, Value):
        return value.literal
    if isinstance(value, Seq):
        items = [plain_value(item) for item in value.items]
        return None if any(item is None for item in items) else items
    return None
