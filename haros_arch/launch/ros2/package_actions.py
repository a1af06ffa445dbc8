"""Launch actions that installed packages add to ``ros2 launch``, as the readers know them:
rows of facts, never the packages' code.

ros_gz's actions (``ros_gz_bridge.actions.RosGzBridge``, ``ros_gz_sim.actions.GzServer``,
``GzSpawnModel``; the frontend tags ``<ros_gz_bridge>``, ``<gz_server>``,
``<gz_spawn_model>`` they expose) each include their package's launch file
(``ros_gz_bridge.launch.py``, ``gz_server.launch.py``, ``gz_spawn_model.launch.py``),
which starts one node: the bridge's ``bridge_node`` named ``bridge_name`` in
``namespace`` with the parameter ``config_file``, the server's ``gzserver`` with
``world_sdf_file`` / ``world_sdf_string``, the spawner's ``create`` with ``world``,
``file``, ``string`` and the pose. With ``use_composition`` the same node is a component
in a container (another process, the same interface), read as the node.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from . import entities as e


@dataclass(frozen=True)
class PackageAction:
    tag: str  # the frontend tag (``expose_action``)
    cls: str  # the Python class
    package: str
    executable: str
    name_arg: str | None  # the argument that names the node; None: the program's name
    namespace_arg: str | None
    params: tuple[tuple[str, str], ...]  # (node parameter, action argument)
    others: tuple[str, ...]  # arguments that change no name, parameter or interface
    required: tuple[str, ...] = ()  # arguments the action's parse demands


_CONTAINER = ("container_name", "create_own_container", "use_composition")
PACKAGE_ACTIONS: tuple[PackageAction, ...] = (
    # ros_gz_bridge/actions/ros_gz_bridge.py, launch/ros_gz_bridge.launch.py
    PackageAction("ros_gz_bridge", "RosGzBridge", "ros_gz_bridge", "bridge_node",
                  "bridge_name", "namespace", (("config_file", "config_file"),),
                  (*_CONTAINER, "use_respawn", "log_level"),
                  ("bridge_name", "config_file")),
    # ros_gz_sim/actions/gzserver.py, launch/gz_server.launch.py
    PackageAction("gz_server", "GzServer", "ros_gz_sim", "gzserver", None, None,
                  (("world_sdf_file", "world_sdf_file"),
                   ("world_sdf_string", "world_sdf_string")), _CONTAINER),
    # ros_gz_sim/actions/gz_spawn_model.py, launch/gz_spawn_model.launch.py
    PackageAction("gz_spawn_model", "GzSpawnModel", "ros_gz_sim", "create", None, None,
                  (("world", "world"), ("file", "file"), ("string", "model_string"),
                   ("topic", "topic"), ("name", "entity_name"),
                   ("allow_renaming", "allow_renaming"), ("x", "x"), ("y", "y"),
                   ("z", "z"), ("R", "roll"), ("P", "pitch"), ("Y", "yaw")), ()),
)
BY_TAG = {row.tag: row for row in PACKAGE_ACTIONS}
BY_CLASS = {row.cls: row for row in PACKAGE_ACTIONS}


def node_action(row: PackageAction, value: Callable[[str], e.Text | None]) -> e.NodeAction:
    """The node the action of ``row`` starts, given the text of each of its arguments
    (``value``: None when the action is not given it), as the frontend and the Python
    reader read them."""
    params: list[e.ParamEntry] = []
    for parameter, argument in row.params:
        given = value(argument)
        if given is not None:
            params.append(((parameter,), given))
    return e.NodeAction((row.package,), (row.executable,),
                        value(row.name_arg) if row.name_arg else None,
                        value(row.namespace_arg) if row.namespace_arg else None, params)
