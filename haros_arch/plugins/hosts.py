"""Which host nodes load plugins, which of their parameters name them, and where the
plugins' calls go: data, like the API tables of the extractors.

A host is recognised by the package and executable a launch file starts. Each of its
``Slot`` rows says how the host's parameters name plugins:

- ``names``: the parameter holding the list of plugin names (nav2's ``planner_plugins``,
  a costmap's ``plugins``), or None when each plugin is named by ``type_of`` alone
  (move_base's ``base_global_planner``), or the special ``"*spawner"`` for controllers
  that controller_manager spawners name (their args).
- ``type_of``: the parameter giving one plugin's class, with ``{name}`` for the plugin
  name (``{name}.plugin``, ``{name}/type``); None when ``names`` holds ``{name, type}``
  mappings (move_base's ``recovery_behaviors``, ROS 1 costmap ``plugins``) or the class
  itself.
- ``defaults``: the plugin names the host uses when the list parameter is not set (nav2
  declares defaults: ``GridBased``, ``FollowPath``, ...), with their default classes.
- ``placement``: ``"node"`` when each plugin is a ROS node of its own named by the plugin
  name in the host's namespace (ros2_control controllers); ``"name"`` when the plugin's
  calls are made on the host node and its code builds its names from the plugin name the
  host passes it (``name + ".tolerance"``, ``NodeHandle("~/" + name)``): an unknown
  first part of such a name is that plugin name, prefixed with ``prefix``.
- ``bases``: the export tags / base classes of the classes it loads (``nav_core``,
  ``nav2_core::GlobalPlanner``); these classes are extracted as plugin nodes.

Names are relative to the host's node (its private namespace); ROS 2 keys use ``.``.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Slot:
    names: str | None
    type_of: str | None
    bases: tuple[str, ...]
    placement: str = "name"  # "name" | "node"
    prefix: str = ""  # put before the plugin name given to the plugin (ROS 1 costmaps)
    defaults: tuple[tuple[str, str], ...] = ()
    # the plugin name is the last segment of the class's lookup name (move_base's
    # planners: ``navfn/NavfnROS`` is initialised as ``NavfnROS``)
    name_from_class: bool = False


@dataclass(frozen=True)
class Host:
    package: str
    executables: tuple[str, ...]
    ros_version: int
    slots: tuple[Slot, ...]


SPAWNER = "*spawner"

_NAV2_COSTMAP = (Slot("plugins", "{name}.plugin", ("nav2_costmap_2d",
                                                    "nav2_costmap_2d::Layer")),
                 Slot("filters", "{name}.plugin", ("nav2_costmap_2d",
                                                    "nav2_costmap_2d::Layer")))


def _ros1_costmap(prefix: str) -> Slot:
    return Slot(f"{prefix}plugins", None, ("costmap_2d", "costmap_2d::Layer"),
                prefix=prefix)


HOSTS: tuple[Host, ...] = (
    # ros2_control: controllers are lifecycle nodes of their own, named by the controller,
    # in the controller manager's namespace; a spawner names them, their class is
    # ``<name>.type`` of the manager or ``type`` of the controller's own parameters
    Host("controller_manager", ("ros2_control_node",), 2, (
        Slot(SPAWNER, "{name}.type", ("controller_interface",
                                      "controller_interface::ControllerInterface",
                                      "controller_interface::ChainableControllerInterface"),
             placement="node"),)),
    # ros_control: controllers use the handle ``<manager namespace>/<name>``
    Host("controller_manager", ("controller_manager",), 1, (
        Slot(SPAWNER, "{name}/type", ("controller_interface",
                                      "controller_interface::ControllerBase"),
             placement="node"),)),
    Host("nav2_planner", ("planner_server",), 2, (
        Slot("planner_plugins", "{name}.plugin", ("nav2_core", "nav2_core::GlobalPlanner"),
             defaults=(("GridBased", "nav2_navfn_planner::NavfnPlanner"),)),)),
    Host("nav2_controller", ("controller_server",), 2, (
        Slot("controller_plugins", "{name}.plugin", ("nav2_core", "nav2_core::Controller"),
             defaults=(("FollowPath", "dwb_core::DWBLocalPlanner"),)),
        Slot("goal_checker_plugins", "{name}.plugin", ("nav2_core", "nav2_core::GoalChecker"),
             defaults=(("goal_checker", "nav2_controller::SimpleGoalChecker"),)),
        Slot("progress_checker_plugins", "{name}.plugin",
             ("nav2_core", "nav2_core::ProgressChecker"),
             defaults=(("progress_checker", "nav2_controller::SimpleProgressChecker"),)),
        Slot("progress_checker_plugin", "{name}.plugin",
             ("nav2_core", "nav2_core::ProgressChecker")),)),
    Host("nav2_behaviors", ("behavior_server",), 2, (
        Slot("behavior_plugins", "{name}.plugin", ("nav2_core", "nav2_core::Behavior")),)),
    Host("nav2_smoother", ("smoother_server",), 2, (
        Slot("smoother_plugins", "{name}.plugin", ("nav2_core", "nav2_core::Smoother")),)),
    Host("nav2_waypoint_follower", ("waypoint_follower",), 2, (
        Slot("waypoint_task_executor_plugin", "{name}.plugin",
             ("nav2_core", "nav2_core::WaypointTaskExecutor")),)),
    Host("nav2_costmap_2d", ("nav2_costmap_2d",), 2, _NAV2_COSTMAP),
    # move_base: planners named by their class (initialised with the class's short
    # name), recovery behaviours and costmap layers by {name, type} lists; a layer is
    # initialised with the name ``<costmap>/<layer>``
    Host("move_base", ("move_base",), 1, (
        Slot(None, "base_global_planner", ("nav_core", "nav_core::BaseGlobalPlanner"),
             defaults=(("", "navfn/NavfnROS"),), name_from_class=True),
        Slot(None, "base_local_planner", ("nav_core", "nav_core::BaseLocalPlanner"),
             defaults=(("", "base_local_planner/TrajectoryPlannerROS"),),
             name_from_class=True),
        Slot("recovery_behaviors", None, ("nav_core", "nav_core::RecoveryBehavior")),
        _ros1_costmap("global_costmap/"),
        _ros1_costmap("local_costmap/"))),
    Host("costmap_2d", ("costmap_2d_node",), 1, (_ros1_costmap("costmap/"),)),
)


def host_of(package: str, executable: str, ros_version: int) -> Host | None:
    """The host row for a node started as ``package``/``executable``, if it is one."""
    for host in HOSTS:
        if (host.package == package and executable in host.executables
                and host.ros_version == ros_version):
            return host
    return None


def plugin_bases() -> frozenset[str]:
    """Export tags and base classes of every class some host loads."""
    return frozenset(base for host in HOSTS for slot in host.slots for base in slot.bases)
