"""launch_pal's argument helpers (PAL Robotics' TIAGo, PMB2, ARI launch files), as the
static Python interpreter knows them: rows of ``python_api.API``, never launch_pal's code.

``read_launch_argument(name, context)`` is ``perform_substitutions(context,
[LaunchConfiguration(name)])`` (arg_utils.py); ``get_robot_name(default)`` declares
``robot_name`` with that default (robot_utils.py, ``'pmb2'`` unless given). The other
``robot_utils`` helpers (``get_arm(robot)``, ``get_end_effector(robot)``, ...) declare
one argument each, its default and choices by the robot (``ROBOT_ARGUMENTS``, launch_pal
0.22.1's table: TIAGo's launch files read ``arm``, ``end_effector`` and ``ft_sensor`` back
to name their parameter files); for a robot the table has not, launch_pal raises
ValueError and the launch file does not load, which is said. The action classes are built
with the interpreter's own rows, as launch_pal's code builds them.
"""

from __future__ import annotations

import ast
from typing import TYPE_CHECKING, Any

from ...model.values import Unknown
from .python_methods import Args, Builder, Kwargs, arg

if TYPE_CHECKING:
    from .python import Interpreter


def read_launch_argument(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    config = i.api["LaunchConfiguration"](i, [arg(a, k, 0, "arg_name")], {}, n)
    return i.api["perform_substitutions"](i, [arg(a, k, 1, "context"), [config]], {}, n)


def get_robot_name(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    default = arg(a, k, 0, "default_robot_name", default="pmb2")
    return i.api["DeclareLaunchArgument"](i, ["robot_name"], {"default_value": default}, n)


# launch_pal's robot_utils (0.22.1, ca87370): helper -> (argument, {robot: (default,
# choices)}); the helpers are deprecated there for its robot_arguments module
ROBOT_ARGUMENTS: dict[str, tuple[str, dict[str, tuple[str, tuple[str, ...]]]]] = {
    "get_wheel_model": ("wheel_model", {
        robot: ("moog", ("nadia", "moog")) for robot in ("pmb2", "tiago")}),
    "get_laser_model": ("laser_model", {
        **{robot: ("sick-571", ("no-laser", "sick-571", "sick-561", "sick-551", "hokuyo"))
           for robot in ("pmb2", "tiago", "pmb3", "omni_base")},
        "ari": ("ydlidar-tg15", ("no-laser", "sick-571", "ydlidar-tg15", "ydlidar-tg30"))}),
    "get_courier_rgbd_sensors": ("courier_rgbd_sensors", {
        "pmb2": ("False", ("True", "False"))}),
    "get_arm": ("arm", {"tiago": ("tiago-arm", ("no-arm", "tiago-arm"))}),
    "get_wrist_model": ("wrist_model", {
        "tiago": ("wrist-2010", ("wrist-2010", "wrist-2017"))}),
    "get_end_effector": ("end_effector", {
        "tiago": ("pal-gripper", ("pal-gripper", "pal-hey5", "custom", "no-end-effector",
                                  "robotiq-2f-85", "robotiq-2f-140")),
        "ari": ("no-hand", ("ari-hand", "no-hand", "no-end-effector"))}),
    "get_ft_sensor": ("ft_sensor", {"tiago": ("schunk-ft", ("schunk-ft", "no-ft-sensor"))}),
    "get_camera_model": ("camera_model", {
        "tiago": ("orbbec-astra", ("no-camera", "orbbec-astra", "orbbec-astra-pro",
                                   "asus-xtion")),
        "pmb3": ("realsense-d435", ("realsense-d435",)),
        "ari": ("realsense-d435", ("raspi", "realsense-d435"))}),
    "get_robot_model": ("robot_model", {"ari": ("v2", ("v1", "v2"))}),
}


def _robot_argument(helper: str) -> Builder:
    """``helper(robot)``: the declaration of its argument for ``robot`` (a robot not
    known statically: the default all the table's robots share, else not known)."""
    argument, robots = ROBOT_ARGUMENTS[helper]

    def declare(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
        robot = arg(a, k, 0, "robot")
        if isinstance(robot, str) and robot not in robots:
            return i.unsupported(n, f"{helper}({robot!r}) raises ValueError in launch_pal: "
                                    f"the robot has no argument {argument}")
        if isinstance(robot, str):
            default: Any = robots[robot][0]
        else:
            defaults = {value for value, _choices in robots.values()}
            default = defaults.pop() if len(defaults) == 1 else Unknown(
                f"the default of {argument} for a robot not known statically", "unknown")
        return i.api["DeclareLaunchArgument"](i, [argument], {"default_value": default}, n)

    return declare


LAUNCH_PAL: dict[str, Builder] = {
    "read_launch_argument": read_launch_argument, "get_robot_name": get_robot_name,
    **{helper: _robot_argument(helper) for helper in ROBOT_ARGUMENTS},
}
