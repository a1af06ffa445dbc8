"""rviz started with a display configuration (``-d FILE``): its enabled displays
subscribe, its tools publish, read from the file (never run). husky_viz's robot.rviz and
navigation2's nav2_default_view.rviz are the shapes."""

from __future__ import annotations

from pathlib import Path

from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl
from haros_arch.model import Configuration, Node, PrimitiveCall
from haros_arch.workspace import Workspace

ROS1 = """\
Panels:
  - Class: rviz/Displays
Visualization Manager:
  Displays:
    - Class: rviz/Grid
      Enabled: true
    - Class: rviz/RobotModel
      Enabled: true
      Robot Description: robot_description
    - Class: rviz/Group
      Enabled: true
      Displays:
        - Class: rviz/LaserScan
          Enabled: true
          Topic: /front/scan
        - Class: rviz/Map
          Enabled: true
          Topic: /map
        - Class: rviz/Image
          Enabled: true
          Image Topic: /camera/image_raw
        - Class: rviz/MarkerArray
          Enabled: true
          Marker Topic: /planner/markers
        - Class: rviz/Image
          Enabled: true
          Image Topic: ""
    - Class: rviz/Group
      Enabled: false
      Displays:
        - Class: rviz/Path
          Enabled: true
          Topic: /move_base/NavfnROS/plan
    - Class: rviz/InteractiveMarkers
      Enabled: true
      Update Topic: /twist_marker_server/update
  Tools:
    - Class: rviz/Interact
    - Class: rviz/SetGoal
      Topic: /move_base_simple/goal
"""

ROS2 = """\
Visualization Manager:
  Displays:
    - Class: rviz_default_plugins/Map
      Enabled: true
      Topic:
        Value: map
        Depth: 1
        Durability Policy: Transient Local
        Reliability Policy: Reliable
      Update Topic:
        Value: map_updates
    - Class: nav2_rviz_plugins/ParticleFilter
      Enabled: true
      Topic:
        Value: particle_cloud
  Tools:
    - Class: rviz_default_plugins/SetInitialPose
      Topic:
        Value: initialpose
"""


def _graph(tmp_path: Path, text: str, ros_version: int, publishers=()):
    config_file = tmp_path / "view.rviz"
    config_file.write_text(text)
    rviz = ("rviz", "rviz") if ros_version == 1 else ("rviz2", "rviz2")
    decl = NodeDecl("/rviz", *rviz, args=f"-d {config_file}")
    decl.ros_version = ros_version
    model = Node(*rviz, calls=[PrimitiveCall("subscribe", "/tf", "tf2_msgs/TFMessage")],
                 completeness="partial", completeness_reasons=["display code"])
    model.model = "rviz model"
    decls = [decl]
    nodes = {model.name: model}
    for topic, message in publishers:
        pub = NodeDecl("/driver", "drv", "driver")
        pub.ros_version = ros_version
        decls.append(pub)
        nodes["drv/driver"] = Node("drv", "driver",
                                   calls=[PrimitiveCall("publish", topic, message)])
    launch = LaunchModel(nodes=decls)
    return build(Configuration("c"), launch, Workspace(root=str(tmp_path)), nodes)


def test_ros1_enabled_displays_subscribe_and_tools_publish(tmp_path: Path) -> None:
    config = _graph(tmp_path, ROS1, 1, [("/front/scan", "sensor_msgs/LaserScan")])
    rviz = next(n for n in config.nodes if n.name == "/rviz")
    links = sorted((link.kind, link.resource.name, link.type) for link in rviz.links)
    assert links == sorted([
        ("subscribe", "/tf", "tf2_msgs/TFMessage"),
        ("subscribe", "/tf_static", "tf2_msgs/TFMessage"),
        ("read", "/robot_description", "str"),
        ("subscribe", "/front/scan", "sensor_msgs/LaserScan"),
        ("subscribe", "/map", "nav_msgs/OccupancyGrid"),
        ("subscribe", "/map_updates", "map_msgs/OccupancyGridUpdate"),
        # ROS 1's image display names its property "Image Topic", markers "Marker
        # Topic"; a display with an empty topic subscribes to nothing
        ("subscribe", "/camera/image_raw", "sensor_msgs/Image"),
        ("subscribe", "/planner/markers", "visualization_msgs/MarkerArray"),
        # the disabled group's path display subscribes to nothing
        ("subscribe", "/twist_marker_server/update",
         "visualization_msgs/InteractiveMarkerUpdate"),
        ("subscribe", "/twist_marker_server/update_full",
         "visualization_msgs/InteractiveMarkerInit"),
        ("publish", "/twist_marker_server/feedback",
         "visualization_msgs/InteractiveMarkerFeedback"),
        ("publish", "/move_base_simple/goal", "geometry_msgs/PoseStamped")])
    assert {link.origin for link in rviz.links} == {"config"}
    assert rviz.is_complete  # every class is known: the model's display gaps are these
    scan = config.topic("/front/scan")
    assert sorted(link.node.name for link in scan.links) == ["/driver", "/rviz"]


def test_ros2_displays_take_their_qos_and_an_unknown_class_makes_rviz_partial(
        tmp_path: Path) -> None:
    config = _graph(tmp_path, ROS2, 2)
    rviz = next(n for n in config.nodes if n.name == "/rviz")
    by_name = {link.resource.name: link for link in rviz.links}
    assert by_name["/map"].type == "nav_msgs/msg/OccupancyGrid"
    assert by_name["/map"].qos == {"depth": 1, "durability": "transient_local",
                                   "reliability": "reliable"}
    assert by_name["/map_updates"].type == "map_msgs/msg/OccupancyGridUpdate"
    assert by_name["/initialpose"].kind == "publish"
    assert "/particle_cloud" not in by_name
    assert not rviz.is_complete
    assert rviz.completeness_reasons == [
        "display nav2_rviz_plugins/ParticleFilter of view.rviz is not known: it may "
        "subscribe or publish anything"]


def test_a_configuration_that_is_no_yaml_is_said_and_rviz_keeps_its_model(
        tmp_path: Path) -> None:
    config = _graph(tmp_path, "Visualization Manager: [\n", 1)
    rviz = next(n for n in config.nodes if n.name == "/rviz")
    assert [link.resource.name for link in rviz.links] == ["/tf"]
    (said,) = [d for d in config.diagnostics if d.code == "RVIZ_CONFIG_INVALID"]
    assert said.location.file.endswith("view.rviz") and said.location.line == 2


MOVEIT1 = """\
Visualization Manager:
  Displays:
    - Class: moveit_rviz_plugin/MotionPlanning
      Enabled: true
      Move Group Namespace: ""
      Planned Path:
        Trajectory Topic: move_group/display_planned_path
      Planning Scene Topic: move_group/monitored_planning_scene
      Robot Description: robot_description
    - Class: moveit_rviz_plugin/Trajectory
      Enabled: true
      Robot Description: arm_description
    - Class: rtabmap_rviz_plugins/Info
      Enabled: true
      Topic: /rtabmap/info
  Tools:
    - Class: nav2_rviz_plugins/GoalTool
"""


def test_moveit_displays_subscribe_to_what_their_properties_name(tmp_path: Path) -> None:
    """MoveIt's motion planning display subscribes to its planning scene and planned
    path topics, calls get_planning_scene in its move group namespace and reads the
    robot description and its semantic part; what its planning frame does is not
    listed, so rviz stays partial, saying so. The trajectory display takes its topic's
    default when the file does not save it, and is whole in ROS 1."""
    config = _graph(tmp_path, MOVEIT1, 1, [("/move_group/display_planned_path",
                                            "moveit_msgs/DisplayTrajectory")])
    rviz = next(n for n in config.nodes if n.name == "/rviz")
    links = {(link.kind, link.resource.name, link.type) for link in rviz.links}
    assert {("subscribe", "/move_group/monitored_planning_scene",
             "moveit_msgs/PlanningScene"),
            ("subscribe", "/move_group/display_planned_path",
             "moveit_msgs/DisplayTrajectory"),
            ("client", "/get_planning_scene", "moveit_msgs/GetPlanningScene"),
            ("read", "/robot_description", "str"),
            ("read", "/robot_description_semantic", "str"),
            ("read", "/arm_description", "str"),
            ("read", "/arm_description_semantic", "str"),
            ("subscribe", "/rtabmap/info", "rtabmap_msgs/Info")} <= links
    assert not any(kind == "publish" for kind, _, _ in links)  # nav2's goal tool: none
    assert not rviz.is_complete
    (reason,) = rviz.completeness_reasons
    assert reason.startswith("display moveit_rviz_plugin/MotionPlanning of view.rviz: "
                             "its planning frame's MoveGroupInterface")
    path = config.topic("/move_group/display_planned_path")  # two displays subscribe
    assert sorted(link.node.name for link in path.links) == ["/driver", "/rviz", "/rviz"]


def test_ros2_moveit_trajectory_display_is_partial_for_its_description_topic(
        tmp_path: Path) -> None:
    text = """\
Visualization Manager:
  Displays:
    - Class: moveit_rviz_plugin/Trajectory
      Enabled: true
      Trajectory Topic: /display_planned_path
    - Class: moveit_rviz_plugin/PlanningScene
      Enabled: true
      Move Group Namespace: /arm
"""
    config = _graph(tmp_path, text, 2)
    rviz = next(n for n in config.nodes if n.name == "/rviz")
    links = {(link.kind, link.resource.name, link.type) for link in rviz.links}
    assert {("subscribe", "/display_planned_path", "moveit_msgs/msg/DisplayTrajectory"),
            ("subscribe", "/monitored_planning_scene", "moveit_msgs/msg/PlanningScene"),
            ("client", "/arm/get_planning_scene", "moveit_msgs/srv/GetPlanningScene"),
            } <= links
    assert [r.partition(":")[0] for r in rviz.completeness_reasons] == [
        "display moveit_rviz_plugin/Trajectory of view.rviz",
        "display moveit_rviz_plugin/PlanningScene of view.rviz"]


AUTOWARE_PATH = """\
Visualization Manager:
  Displays:
    - Class: rviz_plugins/Path
      Enabled: true
      Topic:
        Depth: 5
        Value: /planning/path
    - Class: rviz_default_plugins/Path
      Enabled: true
      Topic:
        Depth: 5
        Value: /planning/nav_path
    - Class: nav2_rviz_plugins/ParticleCloud
      Enabled: true
      Topic:
        Depth: 5
        Value: /particle_cloud
"""


def test_a_display_of_another_package_with_a_known_name_is_another_display(
        tmp_path: Path) -> None:
    """Autoware's autoware.rviz shows its planner's path with ``rviz_plugins/Path``
    (autoware_planning_rviz_plugin's display of an autoware_planning_msgs Path). It was
    taken for rviz's own Path display, so rviz subscribed to the planner's path as a
    nav_msgs Path: a false topic-type-mismatch error against the planner."""
    config = _graph(tmp_path, AUTOWARE_PATH, 2)
    rviz = next(n for n in config.nodes if n.name == "/rviz")
    by_name = {link.resource.name: link for link in rviz.links}
    assert "/planning/path" not in by_name
    assert by_name["/planning/nav_path"].type == "nav_msgs/msg/Path"
    assert by_name["/particle_cloud"].type == "nav2_msgs/msg/ParticleCloud"
    assert rviz.completeness_reasons == [
        "display rviz_plugins/Path of view.rviz is not known: it may subscribe or publish "
        "anything"]


NAV2_PANEL = """\
Panels:
  - Class: rviz_common/Displays
  - Class: nav2_rviz_plugins/Navigation 2
    Name: Navigation 2
Visualization Manager:
  Displays:
    - Class: rviz_default_plugins/Map
      Enabled: true
      Topic:
        Value: /map
  Tools:
    - Class: nav2_rviz_plugins/GoalTool
"""


def test_nav2_panel_calls_nav2_and_leaves_rviz_whole(tmp_path: Path) -> None:
    """nav2_default_view.rviz's Navigation 2 panel (nav2_panel.cpp): the lifecycle
    managers' services, the three navigation actions, the waypoint markers, the actions'
    feedback and status; a panel not in the table still leaves rviz partial."""
    config = _graph(tmp_path, NAV2_PANEL, 2)
    rviz = next(n for n in config.nodes if n.name == "/rviz")
    links = {(link.kind, link.resource.name, link.type) for link in rviz.links}
    assert {("client", "/lifecycle_manager_navigation/manage_nodes",
             "nav2_msgs/srv/ManageLifecycleNodes"),
            ("client", "/lifecycle_manager_localization/is_active", "std_srvs/srv/Trigger"),
            ("action-client", "/navigate_to_pose", "nav2_msgs/action/NavigateToPose"),
            ("action-client", "/follow_waypoints", "nav2_msgs/action/FollowWaypoints"),
            ("publish", "/waypoints", "visualization_msgs/msg/MarkerArray"),
            ("subscribe", "/navigate_through_poses/_action/status",
             "action_msgs/msg/GoalStatusArray")} <= links
    assert rviz.is_complete, rviz.completeness_reasons
    panels = tmp_path / "panels"
    panels.mkdir()
    config = _graph(panels, NAV2_PANEL.replace(
        "  - Class: rviz_common/Displays\n",
        "  - Class: nav2_rviz_plugins/Selector\n  - Class: nav2_rviz_plugins/Docking\n"), 2)
    rviz = next(n for n in config.nodes if n.name == "/rviz")
    links = {(link.kind, link.resource.name) for link in rviz.links}
    assert {("publish", "/planner_selector"), ("action-client", "/dock_robot"),
            ("subscribe", "/undock_robot/_action/status")} <= links
    selector = next(link for link in rviz.links if link.resource.name == "/planner_selector")
    assert selector.qos is not None and selector.qos.get("durability") == "transient_local"
    assert rviz.is_complete, rviz.completeness_reasons
    other = tmp_path / "other"
    other.mkdir()
    config = _graph(other, NAV2_PANEL.replace("Navigation 2\n", "Navigation 3\n", 1), 2)
    rviz = next(n for n in config.nodes if n.name == "/rviz")
    assert not rviz.is_complete
    assert rviz.completeness_reasons[0].startswith("panel nav2_rviz_plugins/Navigation 3")


DEPTH = """\
Visualization Manager:
  Displays:
    - Class: rviz/DepthCloud
      Enabled: true
      Depth Map Topic: /camera/depth/image_rect_raw
      Depth Map Transport Hint: compressedDepth
      Color Image Topic: /camera/color/image_raw
      Color Transport Hint: raw
    - Class: rviz_imu_plugin/Imu
      Enabled: true
      Topic: /imu/data
"""


def test_depth_cloud_and_imu_displays(tmp_path: Path) -> None:
    """ROS 1 rviz's depth cloud display takes its depth map through image_transport with
    its hint, the camera_info beside it and the color image; imu_tools' Imu display its
    topic."""
    config = _graph(tmp_path, DEPTH, 1)
    rviz = next(n for n in config.nodes if n.name == "/rviz")
    links = {(link.kind, link.resource.name, link.type) for link in rviz.links}
    assert {("subscribe", "/camera/depth/image_rect_raw/compressedDepth",
             "sensor_msgs/CompressedImage"),
            ("subscribe", "/camera/depth/camera_info", "sensor_msgs/CameraInfo"),
            ("subscribe", "/camera/color/image_raw", "sensor_msgs/Image"),
            ("subscribe", "/imu/data", "sensor_msgs/Imu")} <= links
    assert rviz.is_complete, rviz.completeness_reasons


def test_a_panel_following_an_action_shows_no_display_without_data(tmp_path: Path) -> None:
    """rviz alone with nav2's view: its Map display has no publisher (an info), the
    Navigation 2 panel's action feedback and status subscriptions are no display."""
    from haros_arch.model import Model
    from haros_arch.query.catalogue import load_catalogue, run_rule

    config = _graph(tmp_path, NAV2_PANEL, 2)
    rule = next(r for r in load_catalogue() if r.id == "rviz-display-without-data")
    found = run_rule(rule, Model(project="p", configurations=[config]))
    assert [f.entities[-1] for f in found] == ["topic:/map"]
