"""robotnik_common's launch argument helpers (Robotnik's ROS 2 robots and simulations), as
the static Python interpreter knows them: rows of ``python_api.API`` and of its methods,
never robotnik_common's code.

``ExtendedArgument(name, default_value, description, use_env=True, environment=None)``
holds one argument (its environment variable ``NAME`` upper-cased unless given);
``AddArgumentParser(ld)`` collects them with ``add_arg``, and ``process_arg()`` adds to
``ld`` one ``DeclareLaunchArgument`` each, whose default is the environment variable with
the given default (or the default alone without ``use_env``), and returns ``{name:
LaunchConfiguration(name)}``. ``add_launch_args(ld, [(name, description, default), ...])``
does the same for tuples, always through the upper-cased environment variable.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from ...model.values import Unknown
from .python_methods import Args, Builder, Kwargs, Method, arg
from .python_values import LaunchDescription, derived

if TYPE_CHECKING:
    from .python import Interpreter


@dataclass(frozen=True)
class ExtendedArgument:
    name: str
    default_value: Any
    description: Any
    use_env: Any
    environment: str


@dataclass
class ArgumentParser:
    """``AddArgumentParser(ld)``: the arguments given to ``add_arg``, in order."""

    description: LaunchDescription
    arguments: list[ExtendedArgument] = field(default_factory=list)


def extended_argument(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    name = arg(a, k, 0, "name")
    if not isinstance(name, str):
        return i.unsupported(n, "ExtendedArgument with a name not known statically")
    environment = arg(a, k, 4, "environment")
    return ExtendedArgument(name, arg(a, k, 1, "default_value"), arg(a, k, 2, "description"),
                            arg(a, k, 3, "use_env", default=True),
                            environment if environment else name.upper())


def argument_parser(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    ld = arg(a, k, 0, "ld")
    if not isinstance(ld, LaunchDescription):
        return i.unsupported(n, "AddArgumentParser of a launch description not known "
                                "statically")
    return ArgumentParser(ld)


def _declare(i: Interpreter, ld: LaunchDescription, name: str, description: Any,
             default: Any, environment: str | None, n: ast.AST) -> Any:
    """One argument declared in ``ld`` (its default read from ``environment`` first when
    one is named); its ``LaunchConfiguration``."""
    if environment is not None:
        default = i.api["EnvironmentVariable"](i, [environment], {"default_value": default},
                                               n)
    ld.actions.append(i.api["DeclareLaunchArgument"](
        i, [name], {"description": description, "default_value": default}, n))
    return i.api["LaunchConfiguration"](i, [name], {}, n)


def m_add_arg(i: Interpreter, owner: Any, a: Args, k: Kwargs, n: ast.AST) -> Any:
    if not isinstance(owner, ArgumentParser) or not isinstance(
            arg(a, k, 0, "arg"), ExtendedArgument):
        return _other(i, owner, "add_arg", n)
    owner.arguments.append(arg(a, k, 0, "arg"))
    return None


def m_process_arg(i: Interpreter, owner: Any, a: Args, k: Kwargs, n: ast.AST) -> Any:
    if not isinstance(owner, ArgumentParser):
        return _other(i, owner, "process_arg", n)
    params: dict[str, Any] = {}
    for argument in owner.arguments:
        if not isinstance(argument.use_env, bool):
            return i.unsupported(n, f"ExtendedArgument {argument.name}: use_env not known "
                                    "statically")
        params[argument.name] = _declare(
            i, owner.description, argument.name, argument.description,
            argument.default_value, argument.environment if argument.use_env else None, n)
    return params


def add_launch_args(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    ld, rows = arg(a, k, 0, "ld"), arg(a, k, 1, "params")
    if not isinstance(ld, LaunchDescription) or not isinstance(rows, (list, tuple)) or not all(
            isinstance(r, (list, tuple)) and len(r) >= 3 and isinstance(r[0], str)
            for r in rows):
        return i.unsupported(n, "add_launch_args of values not known statically")
    return {row[0]: _declare(i, ld, row[0], row[1], row[2], row[0].upper(), n)
            for row in rows}


ROBOTNIK_COMMON: dict[str, Builder] = {
    "ExtendedArgument": extended_argument, "AddArgumentParser": argument_parser,
    "add_launch_args": add_launch_args,
}
ROBOTNIK_METHODS: dict[str, Method] = {"add_arg": m_add_arg, "process_arg": m_process_arg}


def _other(i: Interpreter, owner: Any, name: str, n: ast.AST) -> Unknown:
    """A method of this name on another value (isaac_ros_launch_utils'
    ``ArgumentContainer.add_arg``, its module not in the workspace): not interpreted,
    said once, not again on a value already said unknown where it was made."""
    if isinstance(owner, Unknown) and owner.kind == "unsupported":
        return derived(owner, f"method .{name}() of a value not known statically")
    return i.unsupported(n, f"method .{name}() is not interpreted")
