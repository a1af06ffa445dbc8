"""webots_ros2_driver's launch actions (Cyberbotics' Webots simulator), as the static
Python interpreter knows them: rows of ``python_api.API``, never the package's code.
Facts from webots_ros2_driver (webots_controller.py, webots_launcher.py,
wait_for_controller_connection.py, src/Driver.cpp):

- ``WebotsController(robot_name=..., namespace=..., parameters=[...], remappings=[...])``
  runs the package's ``driver`` program for the robot of that name (its
  ``webots-controller`` script): one node, named after the robot (``Driver.cpp`` names
  it ``wb_robot_get_name()``, each of `` -.)(`` made ``_``), in ``namespace``, given the
  parameters (dictionaries as ``-p``, files as ``--params-file``) and remappings as a
  ``Node`` is. Without ``robot_name`` the robot is the one whose controller is
  ``<extern>``, which the world file tells: the program's own name then.
- ``WebotsLauncher(world=..., ros2_supervisor=...)`` starts the simulator, no ROS node;
  with ``ros2_supervisor`` its ``_supervisor`` attribute is the ``Ros2SupervisorLauncher``
  node the launch file adds: ``ros2_supervisor.py`` (whose code names its node
  ``Ros2Supervisor``) in the namespace ``Ros2Supervisor``, its ``clock`` remapped to
  ``/clock``.
- ``WaitForControllerConnection(target_driver=..., nodes_to_start=[...])`` starts the
  actions once the driver says it is connected to Webots (an ``OnProcessIO`` handler on
  the driver's output): they run later, under that event.
"""

from __future__ import annotations

import ast
from typing import TYPE_CHECKING, Any

from . import entities as e
from .python_methods import Args, Builder, Kwargs, arg

if TYPE_CHECKING:
    from .python import Interpreter

PACKAGE = "webots_ros2_driver"
_NOT_IN_NAMES = " -.)("  # what Driver.cpp turns into ``_`` in the robot's name


def _built(i: Interpreter, k: Kwargs, n: ast.AST, row: str = "Node", **given: Any) -> Any:
    """The action the interpreter's own row ``row`` builds, with the keywords ``given``
    and the action's ``condition``."""
    kwargs = {key: value for key, value in given.items() if value is not None}
    if k.get("condition") is not None:
        kwargs["condition"] = k["condition"]
    return i.api[row](i, [], kwargs, n)


def webots_controller(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    robot = k.get("robot_name")
    if isinstance(robot, str):
        robot = "".join("_" if c in _NOT_IN_NAMES else c for c in robot) or None
    return _built(i, k, n, package=PACKAGE, executable="driver", name=robot,
                 namespace=k.get("namespace") or None, parameters=k.get("parameters"),
                 remappings=k.get("remappings"))


def supervisor(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    return _built(i, k, n, package=PACKAGE, executable="ros2_supervisor.py",
                 name="Ros2Supervisor", namespace="Ros2Supervisor",
                 remappings=[("/Ros2Supervisor/clock", "/clock")])


def webots_launcher(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    world = k.get("world")
    process = _built(i, k, n, "ExecuteProcess",
                     cmd=["webots", *([world] if world is not None else [])])
    wanted = k.get("ros2_supervisor", False)
    if isinstance(process, e.Process) and wanted not in (False, None, 0, ""):
        process.members["_supervisor"] = supervisor(i, [], {}, n)
    return process


def wait_for_connection(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    started = arg(a, k, 1, "nodes_to_start")
    later = i.actions_of(started, n) if started is not None else []
    return e.Delayed(later, "on event: the Webots controller connects", "event",
                     location=i.where(n))


WEBOTS: dict[str, Builder] = {
    "WebotsController": webots_controller, "WebotsLauncher": webots_launcher,
    "Ros2SupervisorLauncher": supervisor, "WaitForControllerConnection": wait_for_connection,
}
