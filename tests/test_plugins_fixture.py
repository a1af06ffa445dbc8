"""Plugins end to end on fixtures/build/plugins: classes exported by package.xml and by
CMake, extracted from their libraries, attached to move_base and controller_manager."""

from __future__ import annotations

import os
import shutil

import pytest
from conftest import FIXTURES

from haros_arch import pipeline
from haros_arch.model.runtime import Configuration
from haros_arch.project import ConfigurationSpec, Project

ROOT = str(FIXTURES / "build" / "plugins")


def configuration(launch: str, models: bool = True, root: str = ROOT, **args: str
                  ) -> Configuration:
    project = Project("plugins", os.path.join(root, "project.yaml"), workspace=[root],
                      configurations=[ConfigurationSpec("c", [launch], dict(args))])
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1,
                                                           models=models))
    return model.configurations[0]


def links(config: Configuration, node: str) -> list[tuple[str, str, str]]:
    # not those of move_base's own interface model
    return sorted((link.kind, link.resource.name, link.origin) for link in config.links
                  if link.node.name == node and link.origin in ("source", "plugin"))


@pytest.mark.parametrize("layer", ["true", "false"])
def test_move_base_loads_planner_recovery_and_layer_from_the_workspace(layer: str):
    # move_base's own interface model is left out: the links below are its plugins'
    config = configuration("bringup/launch/move_base.launch", models=False, layer=layer)
    expected = [
        ("publish", "/move_base/Straight/plan", "source"),
        ("read", "/move_base/Straight/step", "source"),
        ("read", "/move_base/base_global_planner", "plugin"),
        ("read", "/move_base/recovery_behaviors", "plugin"),
        ("read", "/move_base/spin/speed", "source"),
    ]
    if layer == "true":  # the layer's topic parameter, set under its plugin name
        expected += [("read", "/move_base/global_costmap/laser/topic", "source"),
                     ("read", "/move_base/global_costmap/plugins", "plugin"),
                     ("subscribe", "/front/scan", "source")]
    assert links(config, "/move_base") == sorted(expected)
    missing = [d.message.split()[2] for d in config.diagnostics
               if d.code == "PLUGIN_NOT_FOUND"]
    # move_base's default local planner, and the pre-Hydro layers of each costmap that
    # sets no ``plugins`` (costmap_2d has no source here and models are off)
    layered = 1 if layer == "true" else 2
    assert sorted(missing) == sorted(["base_local_planner/TrajectoryPlannerROS",
                                      *["costmap_2d::ObstacleLayer",
                                        "costmap_2d::InflationLayer"] * layered])


def test_spawned_controller_is_a_node_with_its_parameter_file():
    # ros2_control_node (no source, no jazzy model here) is launched unnamed: the spawner
    # reaches it under the name its code gives (controller_manager) whatever it is called
    config = configuration("ros2_bringup/launch/control.launch.xml")
    follower = config.node("/robot/follower")
    assert follower.origin == "plugin" and follower.node.name == "ros2_ctrl/ros2_ctrl/Follower"
    assert links(config, "/robot/follower") == [
        ("read", "/robot/follower/gain", "source"),
        # ControllerInterfaceBase::init, run by the manager, declares them
        ("read", "/robot/follower/is_async", "plugin"),
        ("read", "/robot/follower/thread_priority", "plugin"),
        ("read", "/robot/follower/type", "plugin"),
        ("read", "/robot/follower/update_rate", "plugin"),
        ("subscribe", "/cmds", "source"),  # --controller-ros-args -r ~/commands:=/cmds
    ]
    never_read = [p.name for p in config.parameters if p.set_by_launch and not p.is_read]
    assert never_read == ["/robot/follower/unused"]


def test_nav2_planner_costmap_and_layers_come_from_the_jazzy_models():
    config = configuration("ros2_bringup/launch/nav.launch.xml")
    costmap = config.node("/r1/global_costmap/global_costmap")
    assert costmap is not None and costmap.node is not None
    assert costmap.node.model and "nav2_costmap_2d" in costmap.node.model
    by_costmap = {(link.kind, link.resource.name, link.type) for link in config.links
                  if link.node is costmap}
    assert ("subscribe", "/scan", "sensor_msgs/msg/LaserScan") in by_costmap
    reads = {name for kind, name, _ in by_costmap if kind == "read"}
    assert "/r1/global_costmap/global_costmap/obstacle_layer.scan.clearing" in reads
    assert "/r1/global_costmap/global_costmap/obstacle_layer.observation_sources" in reads
    never_read = [p.name for p in config.parameters if p.set_by_launch and not p.is_read
                  and "global_costmap" in p.name]
    assert never_read == []


def test_mavros_loads_every_exported_plugin_its_deny_list_lets_through():
    config = configuration("ros2_bringup/launch/uas.launch.xml")
    added = sorted((n.name, n.node.name) for n in config.nodes if n.origin == "plugin"
                   and n.node.name.startswith("uas_plugins/"))
    # plugin nodes named by their code (``Plugin(uas_, "sys")``), not by their lookup
    # names; "vibration" matches the deny list's "VIB*" (case folded)
    assert added == [("/mavros/imu", "uas_plugins/imu"), ("/mavros/sys", "uas_plugins/sys_status")]
    # and those of mavros' own model (its package has no source here); mavros_extras'
    # load where it is installed, which nothing here says (no package depends on it)
    modelled = {n.node.name: (n.name, [c.text for c in n.conditions]) for n in config.nodes
                if n.origin == "plugin" and not n.node.name.startswith("uas_plugins/")}
    assert modelled["mavros/local_position"] == ("/mavros/local_position", [])
    assert modelled["mavros/sys_status"] == ("/mavros/sys", [])
    assert modelled["mavros_extras/gps_status"] == (
        "/mavros/gpsstatus", ["mavros_extras is installed"])
    assert "mavros_extras/vibration" not in modelled  # denied too
    assert len(modelled) > 50
    assert not any(d.code == "PLUGIN_CLASS_UNKNOWN" for d in config.diagnostics)
    assert links(config, "/mavros/imu") == [
        ("publish", "/mavros/imu/data", "source"), ("read", "/mavros/imu/frame_id", "source")]
    assert ("publish", "/mavros/state", "source") in links(config, "/mavros/sys")
    imu_frame = next(p for p in config.parameters if p.name == "/mavros/imu/frame_id")
    assert imu_frame.value == "imu_link"
    # the /** entries go to each node of mavros_node's process (mavros, mavros_router,
    # mavros_node), a setting for several nodes: unread only when none of them reads it
    read_by_setting = {(p.setting, p.rosname.own) for p in config.parameters if p.is_read}
    never_read = [p.name for p in config.parameters if p.set_by_launch and not p.is_read
                  and not p.name.startswith("/mavros/?")
                  and (p.setting is None or (p.setting, p.rosname.own) not in read_by_setting)]
    assert never_read == []
    # the model's calls that no node of the process could be told for were those of
    # the UAS's and router's member declarations, built twice (a node '?''s); the
    # members are built by the constructors' initialisers only (helper followups9's
    # rebuilt model), so every call is a node's of the process
    assert {n.name for n in config.nodes if n.origin == "launch"} == {
        "/mavros/mavros", "/mavros/mavros_router", "/mavros/mavros_node"}
    # the router's own calls are its node's (the model rebuilt with the delegating
    # constructor's name left out), no longer the first node's
    served = {(link.node.name, link.resource.name) for link in config.links
              if link.kind == "server"}
    assert ("/mavros/mavros_router", "/mavros/mavros_router/add_endpoint") in served
    assert not [name for node, name in served if name.endswith("/add_endpoint")
                and node != "/mavros/mavros_router"]


@pytest.mark.parametrize("distro", ["jazzy", "humble"])
def test_nav2_servers_started_without_plugin_lists_load_their_defaults_from_the_models(
        tmp_path, distro) -> None:
    # an installed jazzy waypoint_follower and behavior_server, no parameter file: the
    # servers load wait_at_waypoint and spin, backup, drive_on_heading, wait (their
    # code's defaults), from the shipped models; the follower's own read of
    # ``<id>.plugin`` (an id its parameter names) is the host row's load, not a load
    # of unknown classes; humble exports DriveOnHeading as the C++ type
    # ``nav2_behaviors::DriveOnHeading<>``, the same class
    (tmp_path / "demo" / "launch").mkdir(parents=True)
    (tmp_path / "demo" / "package.xml").write_text(
        '<?xml version="1.0"?><package format="3"><name>demo</name><version>0.1.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        "<license>MIT</license><exec_depend>nav2_waypoint_follower</exec_depend>"
        "<exec_depend>nav2_behaviors</exec_depend></package>")
    (tmp_path / "demo" / "launch" / "nav.launch.xml").write_text(
        '<launch>\n  <node pkg="nav2_waypoint_follower" exec="waypoint_follower" '
        'name="waypoint_follower"/>\n  <node pkg="nav2_behaviors" exec="behavior_server" '
        'name="behavior_server"/>\n</launch>\n')
    project = Project("nav", str(tmp_path / "p.yaml"), workspace=[str(tmp_path)],
                      distro=distro, configurations=[
                          ConfigurationSpec("c", ["demo/launch/nav.launch.xml"], {})])
    config = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1)
                              ).configurations[0]
    follower, behaviors = config.node("/waypoint_follower"), config.node("/behavior_server")
    assert follower.completeness == behaviors.completeness == "model"
    names = {link.resource.name for link in config.links}
    assert "/waypoint_follower/wait_at_waypoint.waypoint_pause_duration" in names
    served = {link.resource.name for link in config.links
              if link.node is behaviors and link.kind == "action-server"}
    assert {"/spin", "/backup", "/drive_on_heading", "/wait"} <= served


def test_mavros_plugins_without_a_namespace_are_beneath_its_uas_node():
    """A plugin's node is made in the namespace of the UAS node's full name, which a
    process's namespace replaces: started with none, mavros' UAS node is /mavros and
    its plugins' nodes are beneath it, as with one (not /imu)."""
    config = configuration("ros2_bringup/launch/uas_root.launch.xml")
    placed = {n.node.name: n.name for n in config.nodes if n.origin == "plugin"}
    assert placed["uas_plugins/imu"] == "/mavros/imu"
    assert placed["mavros/local_position"] == "/mavros/local_position"
    assert ("publish", "/mavros/imu/data", "source") in links(config, "/mavros/imu")


def test_mavros_extras_plugins_load_unconditionally_where_a_package_depends_on_it(tmp_path):
    root = tmp_path / "plugins"
    shutil.copytree(ROOT, root)
    xml = root / "ros2_bringup" / "package.xml"
    xml.write_text(xml.read_text().replace(
        "<buildtool_depend>", "<exec_depend>mavros_extras</exec_depend>\n  <buildtool_depend>"))
    config = configuration("ros2_bringup/launch/uas.launch.xml", root=str(root))
    extras = {n.name: n.conditions for n in config.nodes
              if n.node is not None and n.node.name.startswith("mavros_extras/")}
    assert extras["/mavros/gpsstatus"] == ()


def test_the_inputs_mavros_offers_through_its_own_plugins_are_no_missing_publishers():
    """Every plugin mavros finds is loaded; the configuration feeds a few of their inputs
    (setpoint_raw/local, ...) and the rest stay unfed by design: a subscription of such a
    plugin of the installed package is no subscriber-without-publisher. A plugin class
    of the workspace's own is not one."""
    from haros_arch.query import run_catalogue

    project = Project("plugins", os.path.join(ROOT, "project.yaml"), workspace=[ROOT],
                      configurations=[ConfigurationSpec(
                          "c", ["ros2_bringup/launch/uas.launch.xml"], {})])
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    offered = {n.name for n in config.nodes if n.offered}
    assert "/mavros/setpoint_raw" in offered and "/mavros/imu" not in {
        n.name for n in config.nodes if n.offered and n.node.name.startswith("uas_plugins/")}
    assert any(link.kind == "subscribe" and link.node.name == "/mavros/setpoint_raw"
               for link in config.links)
    unfed = [f for f in run_catalogue(model, project)
             if f.rule == "subscriber-without-publisher"]
    assert not any(entity.startswith("node:") and entity[5:] in offered
                   for f in unfed for entity in f.entities), unfed


def test_mavros_plugins_take_the_name_a_launch_file_gives_its_process():
    """``name=`` is launch_ros' ``__node`` rule, which rcl applies to every node of the
    process that takes the global arguments: mavros' plugin nodes (made with default
    options) are all renamed, as a container's name renamed them in mavros issues 1919
    and 2216, and their private topics move with them (``~/data``)."""
    config = configuration("ros2_bringup/launch/uas_named.launch.xml")
    placed = {n.node.name: n.name for n in config.nodes if n.origin == "plugin"}
    assert placed["uas_plugins/imu"] == "/mavros/mavros"
    assert placed["mavros/local_position"] == "/mavros/mavros"
    imu = next(n for n in config.nodes if n.node is not None
               and n.node.name == "uas_plugins/imu")
    assert ("publish", "/mavros/mavros/data") in {
        (link.kind, link.resource.name) for link in config.links if link.node is imu}


def test_ros1_mavros_plugins_make_offered_calls_on_its_node():
    """ROS 1 mavros' plugins make their calls on the mavros node (``~setpoint_raw/local``),
    from its noetic model: whole, and what they offer is no finding of a missing
    partner; the deny list still takes effect."""
    from haros_arch.query import run_catalogue

    project = Project("plugins", os.path.join(ROOT, "project.yaml"), workspace=[ROOT],
                      configurations=[ConfigurationSpec(
                          "c", ["bringup/launch/mavros.launch"], {})])
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    mavros = config.node("/drone1/mavros")
    assert mavros is not None and mavros.completeness != "partial", mavros.completeness_reasons
    made = {(link.kind, link.resource.name): link for link in config.links
            if link.node is mavros}
    offered = made[("subscribe", "/drone1/mavros/setpoint_raw/local")]
    assert offered.call is not None and offered.call.offered
    assert not any(name.startswith("/drone1/mavros/safety_area/") for _, name in made)
    found = run_catalogue(model, project)
    assert not any(f.rule in ("subscriber-without-publisher", "publisher-without-subscriber",
                              "similar-disconnected-topics")
                   and "/drone1/mavros/setpoint_raw/" in f.message for f in found)
