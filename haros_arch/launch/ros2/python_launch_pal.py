"""launch_pal's argument helpers (PAL Robotics' TIAGo, PMB2, ARI launch files), as the
static Python interpreter knows them: rows of ``python_api.API``, never launch_pal's code.

``read_launch_argument(name, context)`` is ``perform_substitutions(context,
[LaunchConfiguration(name)])`` (arg_utils.py); ``get_robot_name(default)`` declares
``robot_name`` with that default (robot_utils.py, ``'pmb2'`` unless given). The other
``robot_utils`` helpers (``get_arm(robot)``, ...) choose their declaration by the robot
from launch_pal's own table and stay calls not interpreted. The action classes are built
with the interpreter's own rows, as launch_pal's code builds them.
"""

from __future__ import annotations

import ast
from typing import TYPE_CHECKING, Any

from .python_methods import Args, Builder, Kwargs, arg

if TYPE_CHECKING:
    from .python import Interpreter


def read_launch_argument(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    config = i.api["LaunchConfiguration"](i, [arg(a, k, 0, "arg_name")], {}, n)
    return i.api["perform_substitutions"](i, [arg(a, k, 1, "context"), [config]], {}, n)


def get_robot_name(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    default = arg(a, k, 0, "default_robot_name", default="pmb2")
    return i.api["DeclareLaunchArgument"](i, ["robot_name"], {"default_value": default}, n)


LAUNCH_PAL: dict[str, Builder] = {
    "read_launch_argument": read_launch_argument, "get_robot_name": get_robot_name,
}
