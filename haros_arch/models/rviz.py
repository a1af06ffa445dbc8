"""What rviz subscribes to and publishes, read from the display configuration it is
started with (``rviz -d FILE``, ``rviz2 -d FILE``, ``--display-config FILE``).

rviz's own code knows no topic: each display of the configuration subscribes to the
topic its ``Topic`` property names (ROS 2: its ``Value``, with the display's QoS), each
tool publishes on its ``Topic``, and the frame manager listens to ``/tf`` and
``/tf_static``. A launched rviz whose configuration file is in the workspace takes these
calls beside its interface model's; the file is read as YAML, never run. A display or
tool is read only when it is enabled (a disabled group's displays are not). A display
class, tool or panel this table does not know may subscribe or publish anything: the
node is then partial, said with the class and the file. A panel of a plugin package it
knows (nav2_rviz_plugins' Navigation 2) adds its calls.

Facts from rviz's sources (ros-visualization/rviz noetic-devel ``src/rviz/default_plugin``
and rviz2 ``rviz_default_plugins``): each display's message type; the Map display also
subscribes ``<topic>_updates`` (map_msgs' OccupancyGridUpdate; ROS 2: its ``Update
Topic``); the Camera display also ``camera_info`` beside its image; the interactive
markers display subscribes ``<ns>/update`` and ``<ns>/update_full`` (ROS 1) and
publishes ``<ns>/feedback`` (ROS 2: subscribes ``<ns>/update``, publishes
``<ns>/feedback``, calls ``<ns>/get_interactive_markers``); the initial pose tool
publishes ``initialpose``, the goal tool ROS 1 ``/move_base_simple/goal`` and ROS 2
``goal_pose``, the point tool ``clicked_point``; ROS 2's robot model display subscribes
to its ``Description Topic`` when its ``Description Source`` is a topic; ROS 1's reads
the parameter its ``Robot Description`` names.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, replace
from typing import Any

import yaml

from .. import diagnostics as diag
from .. import safe_yaml
from ..diagnostics import Diagnostic
from ..launch.model import NodeDecl
from ..model.source import Node, PrimitiveCall
from ..plugins.hosts import transport_named
from ..workspace import Workspace
from .commands import program_words

RVIZ = {("rviz", "rviz"), ("rviz2", "rviz2")}
MAX_BYTES = 2_000_000  # a configuration larger than this is not read
# the last part of a display class (``rviz/LaserScan``, ``rviz_default_plugins/Map``) ->
# (package, message) of what it subscribes to; None for a display of no topic
_DISPLAYS: dict[str, tuple[str, str] | None] = {
    "Grid": None, "Axes": None, "Group": None, "TF": None, "RobotModel": None,
    "InteractiveMarkers": None, "Map": ("nav_msgs", "OccupancyGrid"),
    "LaserScan": ("sensor_msgs", "LaserScan"), "PointCloud": ("sensor_msgs", "PointCloud"),
    "PointCloud2": ("sensor_msgs", "PointCloud2"), "Image": ("sensor_msgs", "Image"),
    "Camera": ("sensor_msgs", "Image"), "Path": ("nav_msgs", "Path"),
    "Odometry": ("nav_msgs", "Odometry"), "Pose": ("geometry_msgs", "PoseStamped"),
    "PoseArray": ("geometry_msgs", "PoseArray"),
    "PoseWithCovariance": ("geometry_msgs", "PoseWithCovarianceStamped"),
    "Marker": ("visualization_msgs", "Marker"),
    "MarkerArray": ("visualization_msgs", "MarkerArray"),
    "Polygon": ("geometry_msgs", "PolygonStamped"), "Range": ("sensor_msgs", "Range"),
    "Temperature": ("sensor_msgs", "Temperature"),
    "Illuminance": ("sensor_msgs", "Illuminance"),
    "RelativeHumidity": ("sensor_msgs", "RelativeHumidity"),
    "FluidPressure": ("sensor_msgs", "FluidPressure"),
    "WrenchStamped": ("geometry_msgs", "WrenchStamped"),
    "Wrench": ("geometry_msgs", "WrenchStamped"), "Point": ("geometry_msgs", "PointStamped"),
    "PointStamped": ("geometry_msgs", "PointStamped"),
    "TwistStamped": ("geometry_msgs", "TwistStamped"),
    "AccelStamped": ("geometry_msgs", "AccelStamped"),
    "GridCells": ("nav_msgs", "GridCells"), "Effort": ("sensor_msgs", "JointState"),
    "Imu": ("sensor_msgs", "Imu"),
    "ParticleCloud": ("nav2_msgs", "ParticleCloud"),  # nav2_rviz_plugins' (amcl's particles)
    "DepthCloud": ("sensor_msgs", "Image"),  # ROS 1's: its topics are _depth_cloud's
}
# the packages whose display classes ``_DISPLAYS`` describes: rviz's own, and the one
# plugin package of a display there; another package's class of the same last name is
# another display (Autoware's ``rviz_plugins/Path`` shows an autoware_planning_msgs
# Path, not nav_msgs')
_RVIZ_OWNERS = frozenset(("rviz", "rviz_default_plugins"))
_DISPLAY_OWNERS: dict[str, frozenset[str]] = {
    "ParticleCloud": frozenset(("nav2_rviz_plugins",)),
    "DepthCloud": frozenset(("rviz",))}  # rviz_default_plugins' not read yet
# a tool -> (ROS 1 topic, ROS 2 topic, package, message) it publishes by default; None:
# a tool that publishes nothing
_TOOLS: dict[str, tuple[str, str, str, str] | None] = {
    "MoveCamera": None, "Interact": None, "Select": None, "FocusCamera": None,
    "Measure": None,
    "SetInitialPose": ("initialpose", "initialpose", "geometry_msgs",
                       "PoseWithCovarianceStamped"),
    "SetGoal": ("/move_base_simple/goal", "goal_pose", "geometry_msgs", "PoseStamped"),
    "PublishPoint": ("clicked_point", "clicked_point", "geometry_msgs", "PointStamped"),
    # nav2_rviz_plugins' goal tool hands the pose to its Navigation 2 panel
    # (goal_tool.cpp:44-49, GoalUpdater.setGoal), which sends the goal: it publishes nothing
    "GoalTool": None,
}


@dataclass(frozen=True)
class _Plugin:
    """A display of a plugin package, known by its whole class name: the topics it
    subscribes to, each named by a property (a path of property names, a sub-property
    under its category) with its default (ROS 1, ROS 2) when the file does not save it,
    and the message (package, name); with ``scene`` the planning scene service its
    ``Move Group Namespace`` puts the name in; with ``description`` the parameter its
    ``Robot Description`` names and that name with ``_semantic``; ``gaps`` what else it
    does that is not listed (ROS 1, ROS 2; None: nothing), which leaves rviz partial."""

    subscribes: tuple[tuple[tuple[str, ...], tuple[str, str], tuple[str, str]], ...] = ()
    scene: bool = False
    description: bool = False
    gaps: tuple[str | None, str | None] = (None, None)


# MoveIt's displays (moveit_ros_visualization; moveit noetic-devel 7c0343f0 and moveit2
# jazzy 4d841063): the planning scene display subscribes to its "Planning Scene Topic"
# (planning_scene_display.cpp:82 / :83, then startSceneMonitor at :382 / :404) and calls
# get_planning_scene in its "Move Group Namespace" (:383-387 / :405-409, the PSM's
# DEFAULT_PLANNING_SCENE_SERVICE); the trajectory visualisation subscribes to its
# "Trajectory Topic" (trajectory_visualization.cpp:71, :287 / :80, :299), under the
# category "Planned Path" in the motion planning display; the robot state display to its
# "Robot State Topic" (robot_state_display.cpp:72, :300 / :73, :308). ROS 1's RDFLoader
# reads the parameter "Robot Description" names and its "_semantic" (rdf_loader.cpp:67,
# :82); ROS 2's reads them through SynchronizedStringParameter (rdf_loader.cpp:73-80),
# which subscribes to a topic of that name when the parameter is empty
# (synchronized_string_parameter.cpp:50-94): not listed.
_ROS2_DESCRIPTION = ("its robot description comes from the parameter 'Robot Description' "
                     "names, or from a topic of that name when the parameter is empty "
                     "(moveit_ros_planning's SynchronizedStringParameter): not listed")
_SCENE_MONITOR = ("its planning scene monitor loads the robot model with its kinematics "
                  "solvers (plugins), whose parameter reads are not listed")
_SCENE = (("Planning Scene Topic",), ("move_group/monitored_planning_scene",
                                      "/monitored_planning_scene"),
          ("moveit_msgs", "PlanningScene"))
_TRAJECTORY = ("move_group/display_planned_path", "/display_planned_path")
_DISPLAY_TRAJECTORY = ("moveit_msgs", "DisplayTrajectory")
_PLUGINS: dict[str, _Plugin] = {
    "moveit_rviz_plugin/PlanningScene": _Plugin(
        (_SCENE,), scene=True, description=True, gaps=(_SCENE_MONITOR, _SCENE_MONITOR)),
    "moveit_rviz_plugin/MotionPlanning": _Plugin(
        (_SCENE, (("Planned Path", "Trajectory Topic"), _TRAJECTORY, _DISPLAY_TRAJECTORY)),
        scene=True, description=True,
        gaps=(("its planning frame's MoveGroupInterface, robot interaction markers and "
               "remote-control topics (moveit_ros_planning_interface, "
               "moveit_ros_robot_interaction) and " + _SCENE_MONITOR,) * 2)),
    "moveit_rviz_plugin/Trajectory": _Plugin(
        ((("Trajectory Topic",), _TRAJECTORY, _DISPLAY_TRAJECTORY),), description=True,
        gaps=(None, _ROS2_DESCRIPTION)),
    "moveit_rviz_plugin/RobotState": _Plugin(
        ((("Robot State Topic",), ("display_robot_state", "display_robot_state"),
          ("moveit_msgs", "DisplayRobotState")),), description=True,
        gaps=(None, _ROS2_DESCRIPTION)),
    # rtabmap_rviz_plugins (introlab/rtabmap_ros noetic-devel and ros2, aec4f91f): each a
    # MessageFilterDisplay of one message on its "Topic" (InfoDisplay.h:40 / :47,
    # MapGraphDisplay.h:56 / :62, MapCloudDisplay.h:76 / :103); the map cloud display
    # also downloads the map through rtabmap's services (its "Download namespace",
    # MapCloudDisplay.cpp:195; ROS 2 from a client node of its own, :100-101)
    # imu_tools' rviz_imu_plugin (noetic and humble): a message filter display of
    # sensor_msgs' Imu on its "Topic" (imu_display.h:62 / :59)
    "rviz_imu_plugin/Imu": _Plugin(((("Topic",), ("", ""), ("sensor_msgs", "Imu")),)),
    "rtabmap_rviz_plugins/Info": _Plugin(
        ((("Topic",), ("", ""), ("rtabmap_msgs", "Info")),)),
    "rtabmap_rviz_plugins/MapGraph": _Plugin(
        ((("Topic",), ("", ""), ("rtabmap_msgs", "MapGraph")),)),
    "rtabmap_rviz_plugins/MapCloud": _Plugin(
        ((("Topic",), ("", ""), ("rtabmap_msgs", "MapData")),),
        gaps=(("its map download services (its 'Download namespace') are not listed",) * 2)),
}
# panels of rviz itself, which make no ROS call
_PANELS = {"Displays", "Selection", "Tool Properties", "Views", "Time", "Help"}
# panels of plugin packages (ROS 2), by whole class name: the calls they make, each
# (kind, name, type), names relative to rviz's namespace. nav2_rviz_plugins' Navigation 2
# panel (navigation2 humble 3c3db59d6, jazzy f4108e5b1 and main a3a97043e alike,
# nav2_panel.cpp): a client node of its own in rviz's process (``__node:=
# rviz_navigation_dialog_action_client``, no namespace of its own) makes the two
# LifecycleManagerClients of lifecycle_manager_navigation and _localization
# (lifecycle_manager_client.cpp:33-43: ``<name>/manage_nodes``, ``<name>/is_active``),
# the action clients of navigate_to_pose, follow_waypoints and navigate_through_poses
# and the ``waypoints`` marker publisher; rviz's own node subscribes to the feedback and
# status of navigate_to_pose and navigate_through_poses and (jazzy on) declares
# ``base_frame``; its transform listener listens to /tf and /tf_static as rviz does
_MANAGE = "nav2_msgs/srv/ManageLifecycleNodes"
# ``rclcpp::QoS(1).transient_local()``, reliable by default
_LATCHED_ONE = {"depth": 1, "history": "keep_last", "reliability": "reliable",
                "durability": "transient_local"}
# kind, name, type, and the QoS of a publisher (None: the default profile) or the default
# of a parameter declaration
_PANEL_CALLS: dict[str, tuple[tuple[str, str, str, dict[str, Any] | None], ...]] = {
    "nav2_rviz_plugins/Navigation 2": (
        *((kind, f"lifecycle_manager_{which}/{service}", type_, None)
          for which in ("navigation", "localization")
          for kind, service, type_ in (("client", "manage_nodes", _MANAGE),
                                       ("client", "is_active", "std_srvs/srv/Trigger"))),
        ("action-client", "navigate_to_pose", "nav2_msgs/action/NavigateToPose", None),
        ("action-client", "follow_waypoints", "nav2_msgs/action/FollowWaypoints", None),
        ("action-client", "navigate_through_poses", "nav2_msgs/action/NavigateThroughPoses",
         None),
        ("publish", "waypoints", "visualization_msgs/msg/MarkerArray", _LATCHED_ONE),
        *(("subscribe", f"{action}/_action/feedback",
           f"nav2_msgs/action/{name}_FeedbackMessage", None)
          for action, name in (("navigate_to_pose", "NavigateToPose"),
                               ("navigate_through_poses", "NavigateThroughPoses"))),
        *(("subscribe", f"{action}/_action/status", "action_msgs/msg/GoalStatusArray", None)
          for action in ("navigate_to_pose", "navigate_through_poses")),
        ("declare", "base_frame", "str", {"default": "base_footprint"}),
    ),
    # its Selector panel (selector.cpp:26-39): a node of its own publishes the selected
    # plugin of each server, depth 1, reliable, transient local (main adds
    # path_handler_selector; listed for every release, as a missing publisher would say
    # more than an extra one)
    "nav2_rviz_plugins/Selector": tuple(
        ("publish", f"{server}_selector", "std_msgs/msg/String", _LATCHED_ONE)
        for server in ("controller", "planner", "goal_checker", "smoother",
                       "progress_checker", "path_handler")),
    # its Docking panel (docking_panel.cpp:167-290, jazzy and main): the dock_robot and
    # undock_robot action clients on a node of its own, and, on rviz's node, the
    # docking feedback and the two actions' status
    "nav2_rviz_plugins/Docking": (
        ("action-client", "dock_robot", "nav2_msgs/action/DockRobot", None),
        ("action-client", "undock_robot", "nav2_msgs/action/UndockRobot", None),
        ("subscribe", "dock_robot/_action/feedback",
         "nav2_msgs/action/DockRobot_FeedbackMessage", None),
        *(("subscribe", f"{action}/_action/status", "action_msgs/msg/GoalStatusArray", None)
          for action in ("dock_robot", "undock_robot")),
    ),
}
_DURABILITY = {"Volatile": "volatile", "Transient Local": "transient_local"}
_RELIABILITY = {"Reliable": "reliable", "Best Effort": "best_effort"}
_HISTORY = {"Keep Last": "keep_last", "Keep All": "keep_all"}


def config_file(decl: NodeDecl) -> str | None:
    """The display configuration an rviz declaration is started with, when it is a
    file that exists; None otherwise (no ``-d``, or a path not known statically)."""
    if (decl.package, decl.executable) not in RVIZ:
        return None
    words = program_words(decl.args)
    for i, word in enumerate(words):
        path = None
        if word in ("-d", "--display-config") and i + 1 < len(words):
            path = words[i + 1]
        elif word.startswith("--display-config="):
            path = word.partition("=")[2]
        if path and os.path.isabs(path) and os.path.isfile(path):
            return path
    return None


def with_displays(decl: NodeDecl, base: Node | None, workspace: Workspace,
                  found: list[Diagnostic]) -> Node | None:
    """``base`` (rviz's code or interface model) with the calls of the displays and
    tools of the configuration ``decl`` starts rviz with; None when it starts it with
    none that can be read (``base`` stands). What cannot be read is said in ``found``."""
    path = config_file(decl)
    if path is None:
        return None
    where = workspace.location(path)
    try:
        if os.path.getsize(path) > MAX_BYTES:
            found.append(diag.make("RVIZ_CONFIG_INVALID", where, path=path,
                                   detail=f"larger than {MAX_BYTES} bytes, not read"))
            return None
        with open(path, encoding="utf-8", errors="replace") as handle:
            text = handle.read()
        # the file as the launch gives it, its text replaced (nav2's ReplaceString)
        text = next((done for given, done in decl.rewritten_files.items()
                     if os.path.realpath(given) == os.path.realpath(path)), text)
        data = safe_yaml.load(text)
    except (OSError, yaml.YAMLError) as error:
        mark = getattr(error, "problem_mark", None)
        if mark is not None:
            where = workspace.location(path, mark.line + 1, mark.column + 1)
        found.append(diag.make("RVIZ_CONFIG_INVALID", where, path=path,
                               detail=str(error).splitlines()[0]))
        return None
    manager = data.get("Visualization Manager") if isinstance(data, dict) else None
    if not isinstance(manager, dict):
        found.append(diag.make("RVIZ_CONFIG_INVALID", where, path=path,
                               detail="no 'Visualization Manager' mapping"))
        return None
    ros2 = decl.ros_version == 2
    calls: list[PrimitiveCall] = [
        _config_call("subscribe", name, _type("tf2_msgs", "TFMessage", ros2), where)
        for name in ("/tf", "/tf_static")]
    unknown: list[str] = []
    gaps: list[tuple[str, str]] = []  # what displays known in part do beyond their calls
    _displays(manager.get("Displays"), ros2, where, calls, unknown, gaps)
    for tool in manager.get("Tools") or ():
        if isinstance(tool, dict):
            _tool(tool, ros2, where, calls, unknown)
    panels = data.get("Panels") if isinstance(data, dict) else None
    for panel in panels or ():
        cls = panel.get("Class") if isinstance(panel, dict) else None
        if not isinstance(cls, str) or cls.rpartition("/")[2] in _PANELS:
            continue
        if ros2 and cls in _PANEL_CALLS:
            calls.extend(_panel_call(kind, name, type_, extra, where)
                         for kind, name, type_, extra in _PANEL_CALLS[cls])
        else:
            unknown.append(f"panel {cls}")
    own = {(c.kind, c.name) for c in calls}
    kept = [c for c in (base.calls if base is not None else ())
            if (c.kind, c.name) not in own]
    reasons = [f"{what} of {os.path.basename(path)} is not known: it may subscribe or "
               "publish anything" for what in dict.fromkeys(unknown)] + [
        f"{what} of {os.path.basename(path)}: {why}" for what, why in dict.fromkeys(gaps)]
    node = replace(base, calls=[*kept, *calls]) if base is not None else Node(
        decl.package, decl.executable, "executable", "cpp", calls=calls,
        location=decl.location)
    node.completeness = "partial" if reasons else "model"
    node.completeness_reasons = reasons[:5]
    node.plugin_loads = []  # the displays and tools it loads are these
    node.model = (base.model if base is not None and base.model else "rviz") + (
        f" with the displays of {path}")
    return node


def _config_call(kind: Any, name: str, type_: str, where: Any,
                 qos: dict[str, Any] | None = None) -> PrimitiveCall:
    """A call of the configuration (links of origin ``config``), at its file."""
    return PrimitiveCall(kind, name, type_, qos=qos, location=where, origin="config")


def _panel_call(kind: str, name: str, type_: str, extra: dict[str, Any] | None,
                where: Any) -> PrimitiveCall:
    """A call of a panel of ``_PANEL_CALLS``: a publisher with its QoS, a declaration
    with its default."""
    if kind == "declare" and extra is not None:
        return replace(_config_call(kind, name, type_, where), has_default=True,
                       default=extra.get("default"))
    return _config_call(kind, name, type_, where, dict(extra) if extra else None)


def _type(package: str, name: str, ros2: bool) -> str:
    return f"{package}/msg/{name}" if ros2 else f"{package}/{name}"


def _topic(value: Any) -> tuple[str | None, dict[str, Any] | None]:
    """A property's topic and, in ROS 2, its QoS."""
    if isinstance(value, str):
        return value or None, None
    if not isinstance(value, dict) or not isinstance(value.get("Value"), str):
        return None, None
    qos: dict[str, Any] = {}
    if isinstance(value.get("Depth"), int):
        qos["depth"] = value["Depth"]
    for key, table, field in (("Durability Policy", _DURABILITY, "durability"),
                              ("Reliability Policy", _RELIABILITY, "reliability"),
                              ("History Policy", _HISTORY, "history")):
        if value.get(key) in table:
            qos[field] = table[value[key]]
    return value["Value"] or None, (qos or None)


def _displays(displays: Any, ros2: bool, where: Any, calls: list[PrimitiveCall],
              unknown: list[str], gaps: list[tuple[str, str]]) -> None:
    for display in displays or ():
        if not isinstance(display, dict) or display.get("Enabled") is False:
            continue
        cls = display.get("Class")
        if not isinstance(cls, str):
            continue
        kind = cls.rpartition("/")[2]
        if kind == "Group":
            _displays(display.get("Displays"), ros2, where, calls, unknown, gaps)
            continue
        if cls in _PLUGINS:
            _plugin(display, _PLUGINS[cls], ros2, where, calls)
            gap = _PLUGINS[cls].gaps[1 if ros2 else 0]
            if gap is not None:
                gaps.append((f"display {cls}", gap))
            continue
        if kind not in _DISPLAYS or cls.rpartition("/")[0] not in _DISPLAY_OWNERS.get(
                kind, _RVIZ_OWNERS):
            unknown.append(f"display {cls}")
            continue
        message = _DISPLAYS[kind]
        if kind == "DepthCloud":
            _depth_cloud(display, where, calls)
            continue
        if kind == "InteractiveMarkers":
            _markers(display, ros2, where, calls)
        elif kind == "RobotModel":
            _robot_model(display, ros2, where, calls)
        if message is None:
            continue
        # ROS 1 names the property after what it shows: "Marker Topic" (markers),
        # "Image Topic" (Image, Camera); ROS 2 calls each "Topic"
        key = next((k for k in ("Topic", "Image Topic", "Marker Topic") if k in display),
                   None)
        name, qos = _topic(display.get(key)) if key is not None else (None, None)
        if name is None:
            continue
        calls.append(_config_call("subscribe", name, _type(*message, ros2), where, qos))
        if kind == "Map":
            update, update_qos = _topic(display.get("Update Topic")) if ros2 else (
                name + "_updates", None)
            if update:
                calls.append(_config_call("subscribe", update, _type(
                    "map_msgs", "OccupancyGridUpdate", ros2), where, update_qos))
        elif kind == "Camera":
            calls.append(_config_call("subscribe", _camera_info(name),
                                      _type("sensor_msgs", "CameraInfo", ros2), where))


def _camera_info(image: str) -> str:
    """The camera_info topic beside an image topic (image_transport's
    ``getCameraInfoTopic``)."""
    return image.rpartition("/")[0] + "/camera_info" if "/" in image else "camera_info"


def _depth_cloud(display: dict[str, Any], where: Any, calls: list[PrimitiveCall]) -> None:
    """ROS 1 rviz's depth cloud display (depth_cloud_display.cpp:271-316): its depth
    map through image_transport with its transport hint (``raw``: the topic itself,
    else the transport's topic below it), the camera_info beside the depth map, and the
    color image when one is named, with its own hint."""
    for topic_key, hint_key in (("Depth Map Topic", "Depth Map Transport Hint"),
                                ("Color Image Topic", "Color Transport Hint")):
        name, _ = _topic(display.get(topic_key))
        if not name:
            continue
        hint = display.get(hint_key, "raw")
        hint = hint if isinstance(hint, str) and hint else "raw"
        row = transport_named(hint)
        calls.append(_config_call("subscribe", name if hint == "raw" else (
            name.rstrip("/") + "/" + hint), (row.types[0] if row else None) or "", where))
        if topic_key == "Depth Map Topic":
            calls.append(_config_call("subscribe", _camera_info(name),
                                      _type("sensor_msgs", "CameraInfo", False), where))


def _plugin(display: dict[str, Any], plugin: _Plugin, ros2: bool, where: Any,
            calls: list[PrimitiveCall]) -> None:
    """The calls of a display of ``_PLUGINS``: a property the file does not save has
    its default."""
    for path, default, message in plugin.subscribes:
        value: Any = display
        for key in path:
            value = value.get(key) if isinstance(value, dict) else None
        name, qos = _topic(value) if value is not None else (default[1 if ros2 else 0],
                                                               None)
        if name:
            calls.append(_config_call("subscribe", name, _type(*message, ros2), where, qos))
    if plugin.scene:
        space = display.get("Move Group Namespace", "")
        space = space.rstrip("/") + "/" if isinstance(space, str) and space else ""
        service = "moveit_msgs/srv/GetPlanningScene" if ros2 else "moveit_msgs/GetPlanningScene"
        calls.append(_config_call("client", space + "get_planning_scene", service, where))
    if plugin.description:
        param = display.get("Robot Description", "robot_description")
        if isinstance(param, str) and param:
            for name in (param, param + "_semantic"):
                calls.append(_config_call("read", name, "str", where))


def _markers(display: dict[str, Any], ros2: bool, where: Any,
             calls: list[PrimitiveCall]) -> None:
    if ros2:
        space = display.get("Interactive Markers Namespace")
        space, _ = _topic(space)
        if not space:
            return
        calls.append(_config_call("subscribe", space + "/update", _type(
            "visualization_msgs", "InteractiveMarkerUpdate", True), where))
        calls.append(_config_call("publish", space + "/feedback", _type(
            "visualization_msgs", "InteractiveMarkerFeedback", True), where))
        calls.append(_config_call("client", space + "/get_interactive_markers",
                                  "visualization_msgs/srv/GetInteractiveMarkers", where))
        return
    update, _ = _topic(display.get("Update Topic"))
    if not update or not update.endswith("/update"):
        return
    space = update[:-len("/update")]
    for name, message in ((update, "InteractiveMarkerUpdate"),
                          (space + "/update_full", "InteractiveMarkerInit")):
        calls.append(_config_call("subscribe", name,
                                  _type("visualization_msgs", message, False), where))
    calls.append(_config_call("publish", space + "/feedback", _type(
        "visualization_msgs", "InteractiveMarkerFeedback", False), where))


def _robot_model(display: dict[str, Any], ros2: bool, where: Any,
                 calls: list[PrimitiveCall]) -> None:
    if ros2:
        if display.get("Description Source", "Topic") != "Topic":
            return
        name, qos = _topic(display.get("Description Topic"))
        if name:
            calls.append(_config_call("subscribe", name, _type("std_msgs", "String", True),
                                      where, qos))
        return
    param = display.get("Robot Description", "robot_description")
    if isinstance(param, str) and param:
        calls.append(_config_call("read", param, "str", where))


def _tool(tool: dict[str, Any], ros2: bool, where: Any, calls: list[PrimitiveCall],
          unknown: list[str]) -> None:
    cls = tool.get("Class")
    if not isinstance(cls, str):
        return
    kind = cls.rpartition("/")[2]
    if kind not in _TOOLS:
        unknown.append(f"tool {cls}")
        return
    default = _TOOLS[kind]
    if default is None:
        return
    name, qos = _topic(tool.get("Topic"))
    calls.append(_config_call("publish", name or default[1 if ros2 else 0],
                              _type(default[2], default[3], ros2), where, qos))
