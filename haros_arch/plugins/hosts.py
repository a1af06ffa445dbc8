"""Which host nodes load plugins, which of their parameters name them, and where the
plugins' calls go: data, like the API tables of the extractors.

A host is recognised by the package and executable a launch file starts. Each of its
``Slot`` rows says how the host's parameters name plugins:

- ``names``: the parameter holding the list of plugin names (nav2's ``planner_plugins``,
  a costmap's ``plugins``), or None when each plugin is named by ``type_of`` alone
  (move_base's ``base_global_planner``), or the special ``"*spawner"`` for controllers
  that controller_manager spawners name (their args), or ``"*exported"`` for every
  class the analysed packages export with one of ``bases`` that the deny and allow
  lists (``lists``) let through (mavros), or ``"*described"`` for the hardware plugins
  of the robot description a controller manager reads (``robot.attach.hardware``).
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
  ``"code"``: a node of its own when the class's code names the node it makes
  (``Node.rosname``), in the host's namespace, else its calls are the host's (a
  ros2_control hardware plugin).
- ``bases``: the export tags / base classes of the classes it loads (``nav_core``,
  ``nav2_core::GlobalPlanner``); these classes are extracted as plugin nodes.

A host may also create nodes of its own in its process (``Child``): nav2's planner server
makes the costmap node ``global_costmap`` in the namespace ``<its namespace>/global_costmap``,
itself the host of the costmap's layers. A ``Sources`` row says which plugin classes
subscribe to topics named by a parameter list (a costmap obstacle layer's
``observation_sources``: one subscription per source, on its ``topic``, of the type its
``data_type`` names), and their calls that read ``<layer>.?.<key>`` are one read per source.

Names are relative to the host's node (its private namespace); ROS 2 keys use ``.``.

An image_transport publisher or subscriber hosts transport plugins (``TRANSPORTS``, used by
``plugins.transports`` when the graph links a call the C++ API table marks).
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Slot:
    names: str | None
    type_of: str | None
    bases: tuple[str, ...]
    placement: str = "name"  # "name" | "node" | "code"
    prefix: str = ""  # put before the plugin name given to the plugin (ROS 1 costmaps)
    defaults: tuple[tuple[str, str], ...] = ()
    # the plugin name is the last segment of the class's lookup name (move_base's
    # planners: ``navfn/NavfnROS`` is initialised as ``NavfnROS``)
    name_from_class: bool = False
    # ``names`` is EXPORTED: the deny and allow lists (parameters holding glob patterns
    # matched against lookup names, case folded); allowed is what no deny pattern
    # matches, or an allow pattern does; an allow list alone denies the rest
    lists: tuple[str, str] | None = None
    # a node of its own named by its code: the regular expression that finds that name
    # in the class's sources (group 1), as the class's ``rosname``
    node_name: str | None = None
    # a ROS 1 costmap: without ``plugins`` it makes its layers from the pre-Hydro
    # parameters (``plugins.attach._pre_hydro``)
    pre_hydro: bool = False
    # ``names`` is one string of classes separated by white space, loaded with the
    # ``defaults`` (not instead of them), less those the ``disable`` parameter's string
    # names (MoveIt's move_group: ``capabilities``, ``disable_capabilities``)
    disable: str | None = None
    # parameters the host's loading code declares on the node of each plugin
    # (``placement="node"``), whatever the plugin's own code does
    declares: tuple[str, ...] = ()
    # the version of the host's package from which it loads these plugins; an older one
    # loads none (its code does the work itself); not known: it is taken to load them
    since: tuple[int, ...] | None = None
    # ``names`` is KEYED: the plugin names are the ``{name}`` parts of the parameters
    # set that ``keys`` matches (move_group's ``planning_pipelines/{name}/planning_plugin``);
    # each plugin's classes are those of ``type_of`` for that name
    keys: str | None = None
    # KEYED: ``keys`` is looked up in the host's private namespace and then in each of
    # its parents, the first found winning (roscpp's ``searchParam``)
    search: bool = False
    # the slot loads nothing when a parameter matching this ``keys``-like pattern is set
    # (move_group's pipeline of its own namespace, used only without
    # ``planning_pipelines/<name>/planning_plugin``)
    unless: str | None = None
    # the value of ``type_of`` is one string of classes separated by white space, each
    # loaded under the same plugin name (a pipeline's ``request_adapters``)
    words: bool = False
    # what the host passes the plugin where its code takes names from it, ``{name}`` the
    # plugin name (a MoveIt pipeline's planner gets the pipeline's namespace,
    # ``~planning_pipelines/{name}``); None: the plugin name itself
    given: str | None = None
    # the host's namespace (relative to its private one, ``{name}`` the plugin name) that
    # the plugin's private names move to: its code makes them on a handle the host gives
    # it, which the extraction took for ``~`` (a MoveIt pipeline's planner, given the
    # pipeline's namespace; OMPL's ``nh_("~")`` replaced by ``NodeHandle(ns)``)
    rebase: str | None = None
    # the place (``file:line``, as ``Node.plugin_loads`` says) where a plugin's code loads
    # the classes this slot attaches, from the host's parameters (the constraint samplers
    # MoveIt's OMPL planner loads with move_group's ``~constraint_samplers``): a plugin
    # loading there is not partial for it
    site: str | None = None
    # the key of a ``{name, type}`` mapping of ``names`` that gives the class
    # (move_group's ``sensors``: ``sensor_plugin``)
    type_key: str = "type"
    # ``names`` is EXPORTED: the packages known to export classes of ``bases``, whose
    # interface models give them where a package has no source here (mavros' own and
    # mavros_extras'); another package than the host's loads only where it is installed,
    # which nothing here says unless a package of the workspace depends on it
    exporters: tuple[str, ...] = ()
    # ``placement`` is "node": each plugin's node is made in the namespace of the host
    # node's full name (mavros' ``Plugin(uas, "imu")``: ``Node::make_shared("imu",
    # uas->get_fully_qualified_name())``), which the process's ``__ns`` rule, a launch
    # file's namespace for it, replaces (rcl applies it to every node of the process):
    # ``/mavros/imu`` either way for mavros' UAS node ``mavros`` started in ``/mavros``
    # or in ``/``
    beneath_host: bool = False
    # ``placement`` is "node": each plugin's node takes the process's global arguments
    # (mavros' plugins make their nodes with default options), so a launch ``name=``
    # (``__node``) renames every one of them to that name, as it does the process's own
    # nodes (mavros issues 1919, 2216: in a container each plugin node took its name)
    global_rules: bool = False
    # an element of ``names`` that is no mapping, or has no class, an empty one or one
    # starting with ``~``, loads nothing (MoveIt's octomap updaters,
    # occupancy_map_monitor.cpp:113-130)
    typed_only: bool = False
    # the class of a plugin whose ``type_of`` is not set is its plugin name (dwb's critics:
    # ``BaseObstacle``), completed as ``resolve`` says
    class_is_name: bool = False
    # how a class written short is completed (``PLUGIN_SLOTS``): this suffix added when
    # the class does not hold it, then, when it names no namespace, the first namespace
    # of the list parameter ``resolve[1]`` (default ``resolve[2]``) under which a class is
    # found (dwb's ``resolveCriticClassName``: ``Critic``, ``default_critic_namespaces``,
    # ``dwb_critics``)
    resolve: tuple[str, str, tuple[str, ...]] | None = None
    # a plugin's own slot (``PLUGIN_SLOTS``, ``prefix`` the outer plugin's name and a
    # dot): its plugins' names fill two unknown parts, the outer plugin's name the first
    # and theirs the next (``<plugin>.<critic>.scale``); a name of one unknown part is the
    # outer plugin's
    inner: bool = False
    # INNER: each plugin is given ``<outer>.<own>`` as its one name, so a name of one
    # unknown part is that whole (MPPI's critics: ``on_configure(parent, name_, name_ +
    # "." + name, ...)``, ``FollowPath.GoalCritic.cost_weight``)
    joined: bool = False
    # defaults the host loads only where a test of its code holds (``Test``): the
    # plugin's calls carry it as a source condition, which the graph decides from the
    # host's parameter
    default_if: tuple[Test, ...] = ()
    # where the host keeps the objects of the plugins it loads: the qualified name of the
    # function that gives that container and of the method of a plugin object that
    # returns the plugin's name (the name given to it: ``prefix`` and the plugin name).
    # The host's code adds each object it loads to the container through another class's
    # method (nav2's ``layered_costmap_->addPlugin(plugin)``, a ``push_back`` in
    # layered_costmap.cpp) and the name reaches the object through a base-class method
    # (``Layer::initialize(..., name, ...)`` keeps it in ``name_``), which the extraction
    # of one unit does not follow: this row says it. A loop of the host's code over that
    # container naming a call by that method (``PrimitiveCall.name_each`` ``LOADED``) makes
    # the call once per plugin of this slot (``graph.build.element_calls``)
    kept: tuple[str, str] | None = None


@dataclass(frozen=True)
class Test:
    """A test in the host's code that a default plugin ``plugin`` is loaded under:
    ``text`` as written at ``file``:``line`` of package ``package``, holding the value of
    the host's private parameter ``parameter`` read before it (move_base initialises its
    default ``rotate_recovery`` only with ``clearing_rotation_allowed_``)."""

    plugin: str
    text: str
    parameter: str
    package: str
    file: str
    line: int


@dataclass(frozen=True)
class Child:
    """A node the host's code creates in its own process, named ``name`` in the host's
    namespace plus ``namespace`` (``/ns/global_costmap/global_costmap``), whose node model
    and host row are those of ``package``/``executable`` (the standalone costmap node);
    it gets the parameter files of the host's process."""

    name: str
    namespace: str
    package: str
    executable: str


@dataclass(frozen=True)
class Host:
    package: str
    executables: tuple[str, ...]
    ros_version: int
    slots: tuple[Slot, ...]
    children: tuple[Child, ...] = ()


@dataclass(frozen=True)
class Sources:
    """Topics a plugin subscribes to, one per source its ``names`` parameter lists
    (separated by spaces), each on the topic ``topic`` gives (default: the source's
    name), of the type ``data_type`` names (``types``; ``default_type`` when not set).
    Keys are relative to the plugin (``{plugin}.observation_sources``) with ``{source}``
    for the source's name. A relative topic resolves in the node's namespace, or, from
    version ``parent_since`` of the plugin's package on, in the parent of that namespace
    (nav2's ``joinWithParentNamespace``)."""

    classes: tuple[str, ...]
    ros_version: int
    names: str
    topic: str
    data_type: str
    types: tuple[tuple[str, str], ...]
    default_type: str
    parent_since: tuple[int, ...] | None = None


SPAWNER = "*spawner"
# the classes of the ``<ros2_control><hardware><plugin>`` elements of the robot
# description the host reads (``robot.attach.hardware``): ros2_control's resource
# manager loads each (humble and jazzy resource_manager.cpp, ``load_and_initialize_
# components``) in the controller manager's process; what a class's code does with ROS
# (a node it makes, publishers) happens there
DESCRIBED = "*described"
HARDWARE_BASES = ("hardware_interface", "hardware_interface::SystemInterface",
                  "hardware_interface::ActuatorInterface",
                  "hardware_interface::SensorInterface")
EXPORTED = "*exported"  # every class exported with one of the slot's bases
KEYED = "*keyed"  # the plugin names are parts of parameter names (``Slot.keys``)

# Costmap2DROS keeps its layers in its LayeredCostmap's ``getPlugins()``, its filters in
# ``getFilters()`` (nav2_costmap_2d/src/costmap_2d_ros.cpp, layered_costmap.hpp); from 1.3
# it publishes each layer that is a CostmapLayer on the topic ``layer->getName()``
_NAV2_LAYER_NAME = "nav2_costmap_2d::Layer::getName"
_NAV2_COSTMAP = (Slot("plugins", "{name}.plugin", ("nav2_costmap_2d",
                                                    "nav2_costmap_2d::Layer"),
                      defaults=(("static_layer", "nav2_costmap_2d::StaticLayer"),
                                ("obstacle_layer", "nav2_costmap_2d::ObstacleLayer"),
                                ("inflation_layer", "nav2_costmap_2d::InflationLayer")),
                      kept=("nav2_costmap_2d::LayeredCostmap::getPlugins", _NAV2_LAYER_NAME)),
                 Slot("filters", "{name}.plugin", ("nav2_costmap_2d",
                                                    "nav2_costmap_2d::Layer"),
                      kept=("nav2_costmap_2d::LayeredCostmap::getFilters", _NAV2_LAYER_NAME)))


def _ros1_costmap(prefix: str) -> Slot:
    return Slot(f"{prefix}plugins", None, ("costmap_2d", "costmap_2d::Layer"),
                prefix=prefix, pre_hydro=True)


# MoveIt 1's move_group loads, besides its capabilities (moveit noetic-devel 7c0343f0, read
# in the source):
# - a planning pipeline per ``~planning_pipelines/<name>`` that sets ``planning_plugin``
#   (move_group.cpp:214-236), with the handle of that namespace (moveit_cpp.cpp:141-146);
#   none: one pipeline on ``~`` itself (:263-269, "deprecated Melodic behavior"). A
#   pipeline loads the planner of ``planning_plugin`` and the request adapters of the
#   string ``request_adapters`` (planning_pipeline.cpp:55-67), gives the planner the
#   pipeline's namespace (:121; OMPL makes its handle of it, ompl_planner_manager.cpp:110,
#   its names' unknown parts being groups, not the pipeline) and each adapter its handle
#   (:156); without
#   ``planning_plugin`` it takes the first class declared (:101-112), which depends on
#   what is installed: not modelled (the pipeline then loads nothing here);
# - a kinematics solver per group of the semantic description, the white-space separated
#   classes of ``robot_description_kinematics/<group>/kinematics_solver`` found by
#   ``searchParam`` from ``~`` (kinematics_plugin_loader.cpp:295-328), each initialised
#   with the group's name (:179);
# - the controller manager ``~moveit_controller_manager`` (trajectory_execution_manager.cpp:
#   147-172; not set, the only class declared, which depends on what is installed);
# - the sensor manager ``~moveit_sensor_manager`` (plan_with_sensing.cpp:87-104);
# - an octomap updater per entry of ``~sensors``, its class ``sensor_plugin``
#   (occupancy_map_monitor.cpp:106-148);
# - the constraint samplers of the string ``~constraint_samplers`` (none when not set),
#   which ConstraintSamplerManagerLoader loads for the OMPL planner and pick and place
#   (constraint_sampler_manager_loader.cpp:49-71, a handle on "~").
_MOVEIT_CORE = "moveit_core"
UNKNOWN_CLASS = "?"  # a default class that depends on what is installed
_MOVEIT1 = (
    Slot(KEYED, "planning_pipelines/{name}/planning_plugin",
         (_MOVEIT_CORE, "planning_interface::PlannerManager"),
         keys="planning_pipelines/{name}/planning_plugin", given="",
         rebase="planning_pipelines/{name}"),
    Slot(None, "planning_plugin", (_MOVEIT_CORE, "planning_interface::PlannerManager"),
         unless="planning_pipelines/{name}/planning_plugin",
         defaults=(("", UNKNOWN_CLASS),)),
    Slot(KEYED, "planning_pipelines/{name}/request_adapters",
         (_MOVEIT_CORE, "planning_request_adapter::PlanningRequestAdapter"),
         keys="planning_pipelines/{name}/planning_plugin", words=True,
         given="~planning_pipelines/{name}"),
    Slot(None, "request_adapters",
         (_MOVEIT_CORE, "planning_request_adapter::PlanningRequestAdapter"),
         unless="planning_pipelines/{name}/planning_plugin", words=True, given="~"),
    Slot(KEYED, "robot_description_kinematics/{name}/kinematics_solver",
         (_MOVEIT_CORE, "kinematics::KinematicsBase"),
         keys="robot_description_kinematics/{name}/kinematics_solver", search=True,
         words=True),
    Slot(None, "moveit_controller_manager",
         (_MOVEIT_CORE, "moveit_controller_manager::MoveItControllerManager")),
    Slot(None, "moveit_sensor_manager",
         (_MOVEIT_CORE, "moveit_sensor_manager::MoveItSensorManager")),
    Slot("sensors", None, ("moveit_ros_perception",
                           "occupancy_map_monitor::OccupancyMapUpdater"),
         type_key="sensor_plugin", typed_only=True),
    Slot(None, "constraint_samplers",
         (_MOVEIT_CORE, "constraint_samplers::ConstraintSamplerAllocator"), words=True,
         site="moveit_ros/planning/constraint_sampler_manager_loader/src/"
              "constraint_sampler_manager_loader.cpp:71"),
)


HOSTS: tuple[Host, ...] = (
    # ros2_control: controllers are lifecycle nodes of their own, named by the controller,
    # in the controller manager's namespace; a spawner names them, their class is
    # ``<name>.type`` of the manager or ``type`` of the controller's own parameters;
    # ControllerInterfaceBase::init, which the manager calls on each, declares
    # ``update_rate`` (Humble, Jazzy) and ``is_async``, ``thread_priority`` (Jazzy) there
    Host("controller_manager", ("ros2_control_node",), 2, (
        Slot(SPAWNER, "{name}.type", ("controller_interface",
                                      "controller_interface::ControllerInterface",
                                      "controller_interface::ChainableControllerInterface"),
             placement="node", declares=("update_rate", "is_async", "thread_priority")),
        Slot(DESCRIBED, None, HARDWARE_BASES, placement="code"))),
    # nav2's servers are hosts as executables and as components (the composed bringup,
    # nav2_bringup's default, loads ``nav2_planner::PlannerServer`` into a container);
    # the planner and controller servers make their costmap nodes in their constructor
    # (``Costmap2DROS("global_costmap", get_namespace(), ...)``)
    Host("nav2_planner", ("planner_server", "nav2_planner::PlannerServer"), 2, (
        Slot("planner_plugins", "{name}.plugin", ("nav2_core", "nav2_core::GlobalPlanner"),
             defaults=(("GridBased", "nav2_navfn_planner::NavfnPlanner"),)),),
         (Child("global_costmap", "global_costmap", "nav2_costmap_2d", "nav2_costmap_2d"),)),
    Host("nav2_controller", ("controller_server", "nav2_controller::ControllerServer"), 2, (
        Slot("controller_plugins", "{name}.plugin", ("nav2_core", "nav2_core::Controller"),
             defaults=(("FollowPath", "dwb_core::DWBLocalPlanner"),)),
        Slot("goal_checker_plugins", "{name}.plugin", ("nav2_core", "nav2_core::GoalChecker"),
             defaults=(("goal_checker", "nav2_controller::SimpleGoalChecker"),)),
        Slot("progress_checker_plugins", "{name}.plugin",
             ("nav2_core", "nav2_core::ProgressChecker"),
             defaults=(("progress_checker", "nav2_controller::SimpleProgressChecker"),)),
        Slot("progress_checker_plugin", "{name}.plugin",
             ("nav2_core", "nav2_core::ProgressChecker")),
        # path handlers from navigation2 1.5.0 (f3406e246, "Centralize path handler
        # logic in controller server"; parameter_handler.cpp's ``path_handler_plugins``)
        Slot("path_handler_plugins", "{name}.plugin", ("nav2_core", "nav2_core::PathHandler"),
             defaults=(("PathHandler", "nav2_controller::FeasiblePathHandler"),),
             since=(1, 5)),),
         (Child("local_costmap", "local_costmap", "nav2_costmap_2d", "nav2_costmap_2d"),)),
    # the behavior and smoother servers' defaults where their lists are not set
    # (behavior_server.cpp's and nav2_smoother.cpp's ``default_ids_``, the same from
    # Humble to 1.5)
    Host("nav2_behaviors", ("behavior_server", "behavior_server::BehaviorServer"), 2, (
        Slot("behavior_plugins", "{name}.plugin", ("nav2_core", "nav2_core::Behavior"),
             defaults=(("spin", "nav2_behaviors::Spin"), ("backup", "nav2_behaviors::BackUp"),
                       ("drive_on_heading", "nav2_behaviors::DriveOnHeading"),
                       ("wait", "nav2_behaviors::Wait"))),)),
    Host("nav2_smoother", ("smoother_server", "nav2_smoother::SmootherServer"), 2, (
        Slot("smoother_plugins", "{name}.plugin", ("nav2_core", "nav2_core::Smoother"),
             defaults=(("simple_smoother", "nav2_smoother::SimpleSmoother"),)),)),
    Host("nav2_waypoint_follower", ("waypoint_follower",
                                    "nav2_waypoint_follower::WaypointFollower"), 2, (
        # the loader's package is nav2_waypoint_follower from Humble to Jazzy (its
        # plugins.xml exported under that tag), nav2_core after
        # (not set: ``wait_at_waypoint``, WaitAtWaypoint; parameter_handler.cpp, and
        # waypoint_follower.cpp before it)
        Slot("waypoint_task_executor_plugin", "{name}.plugin",
             ("nav2_core", "nav2_waypoint_follower", "nav2_core::WaypointTaskExecutor"),
             defaults=(("wait_at_waypoint", "nav2_waypoint_follower::WaitAtWaypoint"),)),)),
    Host("nav2_costmap_2d", ("nav2_costmap_2d",), 2, _NAV2_COSTMAP),
    # bt_navigator loads its navigators by id (bt_navigator.cpp: ``navigators``, each
    # class from ``<id>.plugin``; the two defaults when the list is not set); a navigator
    # names its action and parameters by its ``getName()``, not by the id. From Iron
    # (1.2) on: Humble's (1.1.20, bt_navigator.cpp:125) builds its two navigators itself
    Host("nav2_bt_navigator", ("bt_navigator", "nav2_bt_navigator::BtNavigator"), 2, (
        Slot("navigators", "{name}.plugin", ("nav2_core", "nav2_core::NavigatorBase"),
             defaults=(("navigate_to_pose", "nav2_bt_navigator::NavigateToPoseNavigator"),
                       ("navigate_through_poses",
                        "nav2_bt_navigator::NavigateThroughPosesNavigator")),
             since=(1, 2)),)),
    # move_base: planners named by their class (initialised with the class's short
    # name), recovery behaviours and costmap layers by {name, type} lists; a layer is
    # initialised with the name ``<costmap>/<layer>``
    Host("move_base", ("move_base",), 1, (
        Slot(None, "base_global_planner", ("nav_core", "nav_core::BaseGlobalPlanner"),
             defaults=(("", "navfn/NavfnROS"),), name_from_class=True),
        Slot(None, "base_local_planner", ("nav_core", "nav_core::BaseLocalPlanner"),
             defaults=(("", "base_local_planner/TrajectoryPlannerROS"),),
             name_from_class=True),
        # without ``recovery_behaviors`` (move_base.cpp, loadDefaultRecoveryBehaviors,
        # noetic-devel 9ad6441): two ClearCostmapRecovery and one RotateRecovery, the
        # rotation initialised only with ``clearing_rotation_allowed`` (default true)
        Slot("recovery_behaviors", None, ("nav_core", "nav_core::RecoveryBehavior"),
             defaults=(("conservative_reset", "clear_costmap_recovery/ClearCostmapRecovery"),
                       ("rotate_recovery", "rotate_recovery/RotateRecovery"),
                       ("aggressive_reset", "clear_costmap_recovery/ClearCostmapRecovery")),
             default_if=(Test("rotate_recovery", "clearing_rotation_allowed_",
                              "~clearing_rotation_allowed", "move_base",
                              "move_base/src/move_base.cpp", 1121),)),
        _ros1_costmap("global_costmap/"),
        _ros1_costmap("local_costmap/"))),
    Host("costmap_2d", ("costmap_2d_node",), 1, (_ros1_costmap("costmap/"),)),
    # MoveIt 2's move_group (moveit_ros/move_group/src/move_group.cpp,
    # configureCapabilities): DEFAULT_CAPABILITIES, plus the classes of its
    # ``capabilities`` string, less those of ``disable_capabilities``; a capability makes
    # its calls on move_group's node (``context_->moveit_cpp_->getNode()``)
    Host("moveit_ros_move_group", ("move_group",), 2, (
        Slot("capabilities", None, ("moveit_ros_move_group",
                                    "move_group::MoveGroupCapability"),
             defaults=tuple((name, name) for name in (
                 "move_group/LoadGeometryFromFileService",
                 "move_group/SaveGeometryToFileService", "move_group/GetUrdfService",
                 "move_group/MoveGroupCartesianPathService",
                 "move_group/MoveGroupKinematicsService",
                 "move_group/MoveGroupExecuteTrajectoryAction",
                 "move_group/MoveGroupMoveAction", "move_group/MoveGroupPlanService",
                 "move_group/MoveGroupQueryPlannersService",
                 "move_group/MoveGroupStateValidationService",
                 "move_group/MoveGroupGetPlanningSceneService",
                 "move_group/ApplyPlanningSceneService", "move_group/ClearOctomapService")),
             disable="disable_capabilities"),)),
    # MoveIt 1's move_group (moveit noetic-devel 7c0343f0, move_group.cpp:57-69
    # DEFAULT_CAPABILITIES, :136-141 ``~capabilities`` split on spaces, :157-163
    # ``~disable_capabilities``, :165-180 each loaded and initialised); a capability
    # makes its calls on handles of move_group's process (move_group_capability.h:60,
    # 97-98: ``~`` and the node's namespace). MoveGroupPickPlaceAction is
    # moveit_ros_manipulation's (pick_place_capability_plugin_description.xml)
    Host("moveit_ros_move_group", ("move_group",), 1, (
        Slot("capabilities", None, ("moveit_ros_move_group",
                                    "move_group::MoveGroupCapability"),
             defaults=tuple((name, name) for name in (
                 "move_group/MoveGroupCartesianPathService",
                 "move_group/MoveGroupKinematicsService",
                 "move_group/MoveGroupExecuteTrajectoryAction",
                 "move_group/MoveGroupMoveAction", "move_group/MoveGroupPickPlaceAction",
                 "move_group/MoveGroupPlanService",
                 "move_group/MoveGroupQueryPlannersService",
                 "move_group/MoveGroupStateValidationService",
                 "move_group/MoveGroupGetPlanningSceneService",
                 "move_group/ApplyPlanningSceneService", "move_group/ClearOctomapService")),
             disable="disable_capabilities"),
        *_MOVEIT1)),
    # mavros (mavros/src/lib/mavros.cpp, mavros_uas.cpp) loads every class its plugin
    # loader declares unless its lists say otherwise; ROS 1 plugins make their calls on
    # the mavros node through handles their code names (``~imu``); a ROS 2 plugin is a
    # node of its own, ``Plugin(uas, "imu")`` (plugin.hpp: Node::make_shared(subnode,
    # uas's full name)), beneath the UAS node unless the process has a namespace;
    # before mavros 0.18 (2016) the ROS 1 plugins' base was
    # ``mavplugin::MavRosPlugin`` (mavros.cpp: ``plugin_loader("mavros", ...)``)
    Host("mavros", ("mavros_node",), 1, (
        Slot(EXPORTED, None, ("mavros", "mavros::plugin::PluginBase",
                              "mavplugin::MavRosPlugin"),
             lists=("plugin_blacklist", "plugin_whitelist"),
             exporters=("mavros", "mavros_extras")),)),
    Host("mavros", ("mavros_node",), 2, (
        Slot(EXPORTED, None, ("mavros", "mavros::plugin::PluginFactory"), placement="node",
             lists=("plugin_denylist", "plugin_allowlist"),
             exporters=("mavros", "mavros_extras"), beneath_host=True, global_rules=True,
             node_name=r'\b(?:Plugin|MissionBase)\s*\(\s*uas_?\s*,\s*"([^"\\]+)"'),)),
)


SOURCES: tuple[Sources, ...] = (
    # nav2_costmap_2d/plugins/obstacle_layer.cpp (VoxelLayer runs its onInitialize)
    Sources(("nav2_costmap_2d::ObstacleLayer", "nav2_costmap_2d::VoxelLayer"), 2,
            "{plugin}.observation_sources", "{plugin}.{source}.topic",
            "{plugin}.{source}.data_type",
            (("LaserScan", "sensor_msgs/msg/LaserScan"),
             ("PointCloud2", "sensor_msgs/msg/PointCloud2")), "LaserScan", (1, 4)),
    # costmap_2d/plugins/obstacle_layer.cpp: NodeHandle("~/" + name), a global handle
    # subscribes
    Sources(("costmap_2d::ObstacleLayer", "costmap_2d::VoxelLayer"), 1,
            "{plugin}/observation_sources", "{plugin}/{source}/topic",
            "{plugin}/{source}/data_type",
            (("LaserScan", "sensor_msgs/LaserScan"), ("PointCloud", "sensor_msgs/PointCloud"),
             ("PointCloud2", "sensor_msgs/PointCloud2")), "PointCloud"),
)


# plugin classes whose code runs another exported class's (their base class's
# onInitialize), which their own sources do not hold: voxel_layer.cpp calls
# ObstacleLayer::onInitialize (nav2 and ROS 1 costmap_2d)
EXTENDS: dict[str, str] = {
    "nav2_costmap_2d::VoxelLayer": "nav2_costmap_2d::ObstacleLayer",
    "costmap_2d::VoxelLayer": "costmap_2d::ObstacleLayer",
}


@dataclass(frozen=True)
class RunsAs:
    """A base class no package exports, whose code an exported class of its package runs
    and adds no ROS call to: ``model_class``, whose interface model shows what the base
    does (its calls made outside that class's own files); the calls of a kind in
    ``typed`` are typed by the base's template argument."""
    model_class: str
    typed: tuple[str, ...] = ()
    # the name the model's class gives the calls its ``getName()`` names (nav2's
    # NavigateToPoseNavigator serves ``navigate_to_pose``): a derived class's own
    # ``getName()`` names them (``?`` when its text does not tell it)
    named: str | None = None


# a workspace class derived from one of these, its package without source here, runs the
# base's code: nav2_behaviors' TimedBehavior<ActionT>::configure serves ActionT under the
# plugin's name, makes the cmd_vel publisher and reads the behavior server's frames and
# rates (timed_behavior.hpp), and Wait adds only its onRun / onCycleUpdate
RUNS_AS: dict[str, RunsAs] = {
    "nav2_behaviors::TimedBehavior": RunsAs("nav2_behaviors::Wait", ("action-server",)),
    # nav2_core's BehaviorTreeNavigator<ActionT>::on_configure builds the behaviour tree
    # action server (nav2_behavior_tree's BtActionServer: ActionT served as getName(),
    # the tree server's parameters, the tree log publisher); NavigateToPoseNavigator's
    # own files add its goal subscription and parameters, left out
    "nav2_core::BehaviorTreeNavigator": RunsAs(
        "nav2_bt_navigator::NavigateToPoseNavigator", ("action-server",), "navigate_to_pose"),
}


# lookup-name prefixes that are not the package exporting the class (pluginlib's
# convention is ``pkg/Name``), with the packages that do: MoveIt's capabilities are
# ``move_group/...``, exported by moveit_ros_move_group
# (default_capabilities_plugin_description.xml) and, MoveIt 1's pick and place, by
# moveit_ros_manipulation (pick_place_capability_plugin_description.xml); perception_pcl's
# nodelets are ``pcl/VoxelGrid``, ..., exported by pcl_ros (plugins/nodelet/*.xml);
# ros2_control's mock hardware is ``mock_components/GenericSystem`` (humble also
# ``fake_components/GenericSystem``), exported by hardware_interface
# (mock_components_plugin_description.xml, fake_components_plugin_description.xml);
# ROS 1 ros_controllers' trajectory controllers are ``effort_controllers/
# JointTrajectoryController`` and the same under position_controllers,
# velocity_controllers, pos_vel_controllers and pos_vel_acc_controllers, exported by
# joint_trajectory_controller (ros_control_plugins.xml); the gripper action controllers
# are ``position_controllers/GripperActionController`` and the same under
# effort_controllers, exported by ros2_controllers' gripper_controllers
# (ros_control_plugins.xml) and ROS 1's gripper_action_controller
# (ros_control_plugins.xml), and ros2_controllers' parallel gripper is
# ``parallel_gripper_action_controller/GripperActionController``, exported by
# parallel_gripper_controller (ros_control_plugins.xml);
# MoveIt 1's plugins are named by
# their namespaces: ``ompl_interface/OMPLPlanner`` (moveit_planners_ompl),
# ``default_planner_request_adapters/...`` (moveit_ros_planning), the kinematics solvers
# ``kdl_kinematics_plugin/...`` and the like (moveit_kinematics), the octomap updaters
# ``occupancy_map_monitor/...`` (moveit_ros_perception)
_TRAJECTORY = ("joint_trajectory_controller",)
_GRIPPER = ("gripper_controllers", "gripper_action_controller")
LOOKUP_PACKAGES: dict[str, tuple[str, ...]] = {
    "move_group": ("moveit_ros_move_group", "moveit_ros_manipulation"),
    "pcl": ("pcl_ros",),
    "ompl_interface": ("moveit_planners_ompl",),
    "default_planner_request_adapters": ("moveit_ros_planning",),
    **{kind: ("moveit_kinematics",) for kind in (
        "kdl_kinematics_plugin", "lma_kinematics_plugin", "srv_kinematics_plugin",
        "cached_ik_kinematics_plugin")},
    "occupancy_map_monitor": ("moveit_ros_perception",),
    "mock_components": ("hardware_interface",),
    "fake_components": ("hardware_interface",),
    "parallel_gripper_action_controller": ("parallel_gripper_controller",),
    "mppi": ("nav2_mppi_controller",),  # its critics, mppi::critics::GoalCritic
    "solver_plugins": ("slam_toolbox",),  # its solvers, solver_plugins::CeresSolver
    **{kind: _TRAJECTORY for kind in ("velocity_controllers", "pos_vel_controllers",
                                      "pos_vel_acc_controllers")},
    **{kind: _TRAJECTORY + _GRIPPER for kind in ("position_controllers",
                                                 "effort_controllers")}}


def sources_of(cls: str, ros_version: int) -> Sources | None:
    """The ``Sources`` row of a plugin class (lookup name or C++ type), if any."""
    cls = cls.strip().lstrip(":")
    return next((row for row in SOURCES
                 if cls in row.classes and row.ros_version == ros_version), None)


def host_of(package: str, executable: str, ros_version: int) -> Host | None:
    """The host row for a node started as ``package``/``executable``, if it is one."""
    for host in HOSTS:
        if (host.package == package and executable in host.executables
                and host.ros_version == ros_version):
            return host
    return None


# ROS 1 ros_control: a ControllerManager lives inside a robot's hardware node or Gazebo's
# gazebo_ros_control, not in a node of its own; its spawners name the controllers (see
# ``attach.ros1_controllers``), each loaded with the handle ``<manager namespace>/<name>``
# and the class ``<name>/type`` there
ROS1_CONTROLLER_BASES = ("controller_interface", "controller_interface::ControllerBase")


# classes that any node's own code loads by the value of a parameter its code names (a
# call marked ``PrimitiveCall.loads`` with one of these export tags: the ROS package
# filters' FilterChain, whose filters are ``<filters plugin=...>`` exports of base
# filters::FilterBase<T>), attached by ``attach.chains`` wherever such a node runs: a
# filter's calls go to the node, its name put where its code builds names from it
# (ROS 1 ``NodeHandle("~" + getName())``; ROS 2 its parameters, below
# ``<prefix>filterN.params``)
CHAINS: tuple[str, ...] = ("filters",)


def node_name_patterns() -> dict[str, str]:
    """Base class (or export tag) → the pattern that finds a plugin node's name in its
    class's sources, for the hosts whose plugins are nodes named by their code."""
    return {base: slot.node_name for host in HOSTS for slot in host.slots
            if slot.node_name for base in slot.bases if "::" in base}


# plugin classes that load plugins of their own from their host's parameters, named
# relative to the plugin (``{plugin}``: the name the host gives it): each slot's plugins
# make their calls on the host, their names' first unknown part the plugin's name and the
# next the inner plugin's (``attach._inner``); ``site``: the file of the loading code (any
# line), whose load then hides nothing.
# dwb_core's DWBLocalPlanner (navigation2 humble to main, dwb_local_planner.cpp
# ``loadCritics``): ``<plugin>.critics`` lists the critics, each's class is
# ``<plugin>.<critic>.class`` or the critic's name, completed by
# ``resolveCriticClassName``; ``TrajectoryCritic::initialize(node, critic, plugin, ...)``
# names their parameters ``<plugin>.<critic>.<key>``. nav2_mppi_controller's
# MPPIController (critic_manager.cpp ``loadCritics``, humble to main): ``<plugin>.critics``
# lists the critics, each's class ``mppi::critics::<critic>`` (``getFullName``), configured
# with ``<plugin>.<critic>`` as its name, under which it reads its parameters
PLUGIN_SLOTS: dict[str, tuple[Slot, ...]] = {
    "dwb_core::DWBLocalPlanner": (
        # (the base alone: dwb_plugins exports other classes under dwb_core's tag too,
        # the goal checkers, which no dwb ClassLoader loads)
        Slot("{plugin}.critics", "{plugin}.{name}.class",
             ("dwb_core::TrajectoryCritic",), class_is_name=True,
             resolve=("Critic", "{plugin}.default_critic_namespaces", ("dwb_critics",)),
             site="dwb_core/src/dwb_local_planner.cpp", inner=True),),
    "nav2_mppi_controller::MPPIController": (
        # (its ClassLoader's export tag, the package's own: ``ClassLoader<CriticFunction>(
        # "nav2_mppi_controller", "mppi::critics::CriticFunction")``)
        Slot("{plugin}.critics", None, ("nav2_mppi_controller", "mppi::critics::CriticFunction"),
             class_is_name=True, resolve=("", "", ("mppi::critics",)),
             site="nav2_mppi_controller/src/critic_manager.cpp", inner=True, joined=True),),
}


def _base_groups() -> list[tuple[str, ...]]:
    """The export tags and base classes of each slot (one ``ClassLoader`` each)."""
    return [ROS1_CONTROLLER_BASES, *((tag,) for tag in CHAINS),
            *(slot.bases for host in HOSTS for slot in host.slots),
            *(slot.bases for slots in PLUGIN_SLOTS.values() for slot in slots)]


def hosted_class(tag: str, base: str) -> bool:
    """Whether some slot loads a class exported under ``tag`` with the base class
    ``base``: pluginlib's ``ClassLoader(tag, base)`` finds only the classes exported
    under its own tag (a slot's tags are its entries without ``::``, else the first
    namespace of its classes), of its base (a slot naming no class takes any)."""
    base = base.replace(" ", "").lstrip(":")
    for group in _base_groups():
        classes = [b.lstrip(":") for b in group if "::" in b]
        tags = [b for b in group if "::" not in b] or [c.split("::", 1)[0] for c in classes]
        if tag in tags and (not classes or base in classes):
            return True
    return False


def hosted_tag(tag: str) -> bool:
    """Whether some slot loads classes exported under ``tag``."""
    return any(tag in ([b for b in group if "::" not in b] or [
        b.lstrip(":").split("::", 1)[0] for b in group]) for group in _base_groups())


# -- image_transport ---------------------------------------------------------------------


@dataclass(frozen=True)
class Transport:
    """An image_transport plugin (``image_transport/<name>_pub`` / ``_sub``, exported by
    ``package``). A publisher of the base topic ``b`` loads every transport plugin
    installed and publishes ``b/<name>`` through it (raw: ``b`` itself), of the type
    ``types`` gives (ROS 1, ROS 2; None: no plugin for that version); a subscriber loads
    one, and subscribes ``b/<name>``. ``common``: a transport of the
    image_transport_plugins metapackage, installed with the usual ROS installs, so
    published under the condition that its package is installed when the workspace does
    not have it; another transport is published only when its package is found."""

    name: str
    package: str
    types: tuple[str | None, str | None]
    common: bool = False
    # ROS 1: the plugin runs a dynamic_reconfigure server on the handle of its topic
    # (``reconfigure_server_`` made with ``this->nh()``, SimplePublisherPlugin's
    # ``NodeHandle(transport_topic)``): ``<topic>/set_parameters`` and its two topics
    reconfigure: bool = False
    # the parameters the publisher plugin reads: ROS 1 its dynamic_reconfigure config's
    # (``cfg/*Publisher.cfg``, read under ``<topic>/``), ROS 2 those it declares as
    # ``<base>.<name>.<parameter>`` (the base relative to the node's namespace, ``/`` as
    # ``.``), and, when ``unscoped``, as the deprecated ``<base>.<parameter>`` too
    parameters: tuple[tuple[str, ...], tuple[str, ...]] = ((), ())
    unscoped: bool = False


# image_common (noetic-devel, jazzy, rolling): Publisher loads each ``*_pub`` class of the
# image_transport loader; SimplePublisherPlugin::getTopicToAdvertise is
# ``base + "/" + getTransportName()``, RawPublisher's the base. image_transport_plugins
# noetic-devel: compressed, compressedDepth, theora; rolling (and jazzy, from Feb 2024)
# also zstd. ffmpeg_image_transport is a package of its own (ros-misc-utilities).
TRANSPORTS: tuple[Transport, ...] = (
    Transport("raw", "image_transport", ("sensor_msgs/Image", "sensor_msgs/msg/Image")),
    Transport("compressed", "compressed_image_transport",
              ("sensor_msgs/CompressedImage", "sensor_msgs/msg/CompressedImage"), True, True,
              (("enable", "format", "jpeg_quality", "jpeg_progressive", "jpeg_optimize",
                "jpeg_restart_interval", "png_level"),
               ("format", "png_level", "jpeg_quality", "tiff.res_unit", "tiff.xdpi",
                "tiff.ydpi")), True),
    Transport("compressedDepth", "compressed_depth_image_transport",
              ("sensor_msgs/CompressedImage", "sensor_msgs/msg/CompressedImage"), True, True,
              (("enable", "format", "depth_max", "depth_quantization", "png_level"),
               ("format", "depth_max", "depth_quantization", "png_level")), True),
    Transport("theora", "theora_image_transport",
              ("theora_image_transport/Packet", "theora_image_transport/msg/Packet"), True,
              True, (("enable", "optimize_for", "target_bitrate", "quality",
                      "keyframe_frequency"),
                     ("optimize_for", "target_bitrate", "quality", "keyframe_frequency")),
              True),
    Transport("zstd", "zstd_image_transport", (None, "sensor_msgs/msg/CompressedImage"), True,
              parameters=((), ("zstd_level",))),
    Transport("ffmpeg", "ffmpeg_image_transport",
              ("ffmpeg_image_transport_msgs/FFMPEGPacket",
               "ffmpeg_image_transport_msgs/msg/FFMPEGPacket")),
)


def transport_named(name: str | None) -> Transport | None:
    """The row of ``TRANSPORTS`` of a transport's name (``raw``, ``compressed``), if any."""
    return next((t for t in TRANSPORTS if t.name == name), None)

# the parameters that choose transports: a ROS 1 publisher skips the transports listed
# in ``<resolved base>/disable_pub_plugins`` (publisher.cpp, getParam on the node's
# handle); a ROS 2 one loads only those of ``<base>.enable_pub_plugins`` (the base
# relative to the node's namespace, ``/`` as ``.``; declared with every transport as
# its default); entries are ``image_transport/<name>``. A subscriber's TransportHints
# read the node's private ``image_transport`` (default ``raw``).
DISABLE_PUB_PLUGINS = "disable_pub_plugins"
ENABLE_PUB_PLUGINS = "enable_pub_plugins"
TRANSPORT_PARAM = "image_transport"


# -- BehaviorTree.CPP navigators -----------------------------------------------------------


@dataclass(frozen=True)
class TreeHost:
    """A node whose ROS calls are mostly made by the BehaviorTree.CPP nodes of the trees
    it runs (``plugins.behavior_trees``): the BT plugin libraries it loads (those of the
    ``builtin`` packages always, plus the library names of the ``libraries`` parameter)
    and the tree files it runs (``trees``: parameter, and the default as a path in a
    package's share folder). Each tree tag makes the calls of the class registered under
    its ID (``BT_REGISTER_NODES``), on the host's node."""

    package: str
    executables: tuple[str, ...]
    libraries: str
    builtin: tuple[str, ...]
    # (parameter, share package, share path of the default; "" "": no default)
    trees: tuple[tuple[str, str, str], ...]
    # the parameter listing the host's navigators, and the navigators (id, class) whose
    # trees ``trees`` names: another navigator runs trees of its own, not read
    navigators: tuple[str, tuple[tuple[str, str], ...]] | None = None
    # the class of the navigator that runs each tree of ``trees`` (in order; "" for a
    # tree the host runs itself): a navigator the list leaves out runs none of its trees
    tree_navigators: tuple[str, ...] = ()


# nav2_bt_navigator (bt_navigator.cpp: BT_BUILTIN_PLUGINS, the libraries of
# nav2_behavior_tree, plus ``plugin_lib_names``; Humble and Iron list the same libraries
# as the parameter's default); navigators/navigate_to_pose.cpp and
# navigate_through_poses.cpp: the default trees in nav2_bt_navigator's share folder
TREE_HOSTS: tuple[TreeHost, ...] = (
    TreeHost("nav2_bt_navigator", ("bt_navigator", "nav2_bt_navigator::BtNavigator"),
             "plugin_lib_names", ("nav2_behavior_tree",), (
                 ("default_nav_to_pose_bt_xml", "nav2_bt_navigator",
                  "behavior_trees/navigate_to_pose_w_replanning_and_recovery.xml"),
                 ("default_nav_through_poses_bt_xml", "nav2_bt_navigator",
                  "behavior_trees/navigate_through_poses_w_replanning_and_recovery.xml")),
             ("navigators", (("navigate_to_pose", "nav2_bt_navigator::NavigateToPoseNavigator"),
                             ("navigate_through_poses",
                              "nav2_bt_navigator::NavigateThroughPosesNavigator"))),
             ("nav2_bt_navigator::NavigateToPoseNavigator",
              "nav2_bt_navigator::NavigateThroughPosesNavigator")),
    # PlanSys2's BT action executor (plansys2_bt_actions/src/plansys2_bt_actions/
    # BTAction.cpp): the libraries of ``plugins``, the tree of ``bt_xml_file`` (no
    # default), the node itself on the blackboard
    TreeHost("plansys2_bt_actions", ("bt_action_node",), "plugins", (),
             (("bt_xml_file", "", ""),)),
)


def tree_host_of(package: str, executable: str, ros_version: int) -> TreeHost | None:
    """The tree host row for a node started as ``package``/``executable``, if any."""
    if ros_version != 2:
        return None
    return next((host for host in TREE_HOSTS
                 if host.package == package and executable in host.executables), None)
