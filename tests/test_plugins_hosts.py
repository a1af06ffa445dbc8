"""Hosts get the calls of the plugins their parameters name (plugins.hosts / attach)."""

from __future__ import annotations

from pathlib import Path

import pytest

from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Location, Node, PrimitiveCall
from haros_arch.model.launch_tree import LaunchItem
from haros_arch.model.values import UNKNOWN_MARK
from haros_arch.plugins.attach import ros1_spawn_args, spawn_args
from haros_arch.workspace import Workspace


def call(kind, name, type_=None, line=1, **more):
    return PrimitiveCall(kind, name, type_, 10, location=Location("p", "p/src/x.cpp", line, 3),
                         **more)


def plugin(package, lookup, cls, *calls):
    return Node(package, lookup, "plugin", calls=list(calls), plugin_class=cls)


def graph(decls, params=(), nodes=(), root="/nowhere"):
    launch = LaunchModel(nodes=list(decls), params=list(params))
    return build(Configuration("c"), launch, Workspace(root=root), {n.name: n for n in nodes})


def ros2(decl: NodeDecl) -> NodeDecl:
    decl.ros_version = 2
    return decl


def where(line):
    return Location("bringup", "bringup/launch/nav.launch", line, 0)


def base_declares(node: str) -> list[tuple[str, str]]:
    """What ros2_control's ControllerInterfaceBase::init declares on a controller's node."""
    return [("read", f"{node}/{name}") for name in ("is_async", "thread_priority",
                                                    "update_rate")]


def links_of(config, node):
    return sorted((link.kind, link.resource.name) for link in config.links
                  if link.node.name == node)


def no_layers(host: str, *costmaps: str) -> list[ParamDecl]:
    """An empty ``plugins`` list: the costmap loads no layer (without the parameter it
    would make the pre-Hydro ones)."""
    return [ParamDecl(f"{host}/{costmap}/plugins", []) for costmap in costmaps]


def recoveries() -> list[Node]:
    """move_base's default recovery behaviours (loaded without ``recovery_behaviors``)."""
    return [plugin("clear_costmap_recovery", "clear_costmap_recovery/ClearCostmapRecovery",
                   "clear_costmap_recovery::ClearCostmapRecovery"),
            plugin("rotate_recovery", "rotate_recovery/RotateRecovery",
                   "rotate_recovery::RotateRecovery")]


def test_move_base_gets_planner_recovery_and_costmap_layer_calls_under_their_names():
    move_base = Node("move_base", "move_base", calls=[call("publish", "~goal")])
    navfn = plugin("navfn", "navfn/NavfnROS", "navfn::NavfnROS",
                   call("publish", "~?/plan", "nav_msgs/Path", handle_namespace="~?"),
                   call("publish", "?", "nav_msgs/Path"),  # unknown: stays unknown
                   call("read", "~?/tolerance", "double", handle_namespace="~?"))
    recovery = plugin("rec", "rec/Spin", "rec::Spin", call("read", "~?/speed", "double"))
    trajectory = plugin("base_local_planner", "base_local_planner/TrajectoryPlannerROS",
                        "base_local_planner::TrajectoryPlannerROS",
                        call("publish", "~?/local_plan", "nav_msgs/Path"))
    static = plugin("costmap_2d", "costmap_2d::StaticLayer", "costmap_2d::StaticLayer",
                    call("subscribe", "?", "nav_msgs/OccupancyGrid",
                         name_param="~?/map_topic", name_default="map"))
    params = [
        ParamDecl("/move_base/base_global_planner", "navfn/NavfnROS", "str",
                  location=where(3)),
        ParamDecl("/move_base/recovery_behaviors", [{"name": "spin", "type": "rec/Spin"}],
                  location=where(4)),
        ParamDecl("/move_base/global_costmap/plugins",
                  [{"name": "static", "type": "costmap_2d::StaticLayer"}], location=where(5)),
        ParamDecl("/move_base/global_costmap/static/map_topic", "/map", "str"),
        *no_layers("/move_base", "local_costmap"),
    ]
    config = graph([NodeDecl("/move_base", "move_base", "move_base")], params,
                   [move_base, navfn, recovery, static, trajectory])
    assert links_of(config, "/move_base") == [
        ("publish", "/move_base/NavfnROS/plan"),
        # not set: move_base's default local planner, initialised with its short name
        ("publish", "/move_base/TrajectoryPlannerROS/local_plan"),
        ("publish", "/move_base/goal"),
        ("publish", "?"),
        ("read", "/move_base/NavfnROS/tolerance"),
        # the parameters that choose the plugins: move_base reads them to load them
        ("read", "/move_base/base_global_planner"),
        ("read", "/move_base/global_costmap/plugins"),
        ("read", "/move_base/recovery_behaviors"),
        ("read", "/move_base/spin/speed"),
        ("subscribe", "/map"),
    ]
    assert [d.code for d in config.diagnostics] == []
    assert config.node("/move_base").is_complete


def test_a_plugin_not_in_the_workspace_is_a_diagnostic_and_only_that_instance_is_partial():
    move_base = Node("move_base", "move_base", calls=[call("publish", "~goal")])
    defaults = [plugin("navfn", "navfn/NavfnROS", "navfn::NavfnROS"),
                plugin("base_local_planner", "base_local_planner/TrajectoryPlannerROS",
                       "base_local_planner::TrajectoryPlannerROS"), *recoveries()]
    params = [ParamDecl("/a/move_base/base_local_planner", "dwa/DWAPlannerROS", "str",
                        location=where(7)),
              *no_layers("/a/move_base", "global_costmap", "local_costmap"),
              *no_layers("/b/move_base", "global_costmap", "local_costmap")]
    config = graph([NodeDecl("/a/move_base", "move_base", "move_base", "/a/"),
                    NodeDecl("/b/move_base", "move_base", "move_base", "/b/")],
                   params, [move_base, *defaults])
    (found,) = [d for d in config.diagnostics if d.code.startswith("PLUGIN")]
    assert (found.code, found.location.line) == ("PLUGIN_NOT_FOUND", 7)
    partial, other = config.node("/a/move_base"), config.node("/b/move_base")
    assert partial.completeness == "partial"
    assert "dwa/DWAPlannerROS" in partial.completeness_reasons[0]
    assert "bringup/launch/nav.launch:7" in partial.completeness_reasons[0]
    # the node model is shared: the other instance and the model itself stay complete
    assert other.completeness == "complete" and move_base.completeness == "complete"
    assert other.node is move_base and partial.node is not move_base



def test_a_host_whose_plugin_parameter_a_file_not_read_may_set_is_partial():
    # yujin_ocs' move_base_with_vel_smoother.launch loads turtlebot_navigation's
    # move_base_params.yaml, a package not in the workspace: /move_base/? may set
    # base_local_planner (turtlebot's sets dwa_local_planner/DWAPlannerROS), so the
    # default TrajectoryPlannerROS is only one possibility and move_base is not whole
    move_base = Node("move_base", "move_base", calls=[call("publish", "~goal")])
    defaults = [plugin("navfn", "navfn/NavfnROS", "navfn::NavfnROS"),
                plugin("base_local_planner", "base_local_planner/TrajectoryPlannerROS",
                       "base_local_planner::TrajectoryPlannerROS"), *recoveries()]
    unread = [ParamDecl(f"/a/move_base/{UNKNOWN_MARK}", None, location=where(4)),
              ParamDecl(f"/b/move_base/global_costmap/{UNKNOWN_MARK}", None,
                        location=where(5))]
    params = [*unread, *no_layers("/a/move_base", "global_costmap", "local_costmap"),
              *no_layers("/b/move_base", "global_costmap", "local_costmap")]
    config = graph([NodeDecl("/a/move_base", "move_base", "move_base", "/a/"),
                    NodeDecl("/b/move_base", "move_base", "move_base", "/b/")],
                   params, [move_base, *defaults])
    partial, other = config.node("/a/move_base"), config.node("/b/move_base")
    assert partial.completeness == "partial"
    assert any("/a/move_base/base_local_planner" in r and "nav.launch:4" in r
               for r in partial.completeness_reasons), partial.completeness_reasons
    # a file that can only set a costmap's parameters chooses none of move_base's
    assert other.completeness == "complete"

def test_a_modelled_host_whose_plugin_is_not_known_is_partial():
    # noetic move_base from its interface model (completeness "model") on Fetch loads
    # base_local_planner/TrajectoryPlannerROS, which no analysed package exports: its
    # ~TrajectoryPlannerROS/local_plan publisher is unseen, so move_base is not whole
    move_base = Node("move_base", "move_base", calls=[call("publish", "~goal")],
                     completeness="model", model="noetic/move_base 1.17.3")
    params = [ParamDecl("/move_base/base_local_planner",
                        "base_local_planner/TrajectoryPlannerROS", "str", location=where(7))]
    config = graph([NodeDecl("/move_base", "move_base", "move_base")], params, [move_base])
    instance = config.node("/move_base")
    assert instance.completeness == "partial" and not instance.is_complete
    assert any("TrajectoryPlannerROS" in r for r in instance.completeness_reasons)
    assert move_base.completeness == "model"  # the shared model is not touched


def test_nav2_server_plugins_take_their_names_from_the_list_and_defaults():
    navfn = plugin("nav2_navfn_planner", "nav2_navfn_planner::NavfnPlanner",
                   "nav2_navfn_planner::NavfnPlanner",
                   call("declare", "?.tolerance", "double"))
    smac = plugin("smac", "smac/Smac", "smac::Smac", call("declare", "?.tolerance", "double"),
                  call("publish", "unsmoothed_plan", "nav_msgs/Path"))
    decls = [ros2(NodeDecl("/planner_server", "nav2_planner", "planner_server")),
             ros2(NodeDecl("/r2/planner_server", "nav2_planner", "planner_server", "/r2/"))]
    params = [ParamDecl("/r2/planner_server/planner_plugins", ["A"]),
              ParamDecl("/r2/planner_server/A.plugin", "smac::Smac", location=where(9))]
    config = graph(decls, params, [navfn, smac])
    # no list: nav2's default plugin name and class
    assert links_of(config, "/planner_server") == [
        ("read", "/planner_server/GridBased.tolerance")]
    assert links_of(config, "/r2/planner_server") == [
        ("publish", "/r2/unsmoothed_plan"), ("read", "/r2/planner_server/A.plugin"),
        ("read", "/r2/planner_server/A.tolerance"),
        ("read", "/r2/planner_server/planner_plugins")]


def test_a_composed_nav2_server_is_a_host_as_its_executable_is():
    # nav2_bringup's default: the servers are components loaded into one container
    navfn = plugin("nav2_navfn_planner", "nav2_navfn_planner::NavfnPlanner",
                   "nav2_navfn_planner::NavfnPlanner",
                   call("declare", "?.tolerance", "double"))
    server = Node("nav2_planner", "nav2_planner::PlannerServer", "component",
                  plugin_loads=["nav2_planner/src/planner_server.cpp:98"])
    decl = ros2(NodeDecl("/planner_server", "nav2_planner", "nav2_planner::PlannerServer",
                         composable=True, container="/nav2_container"))
    config = graph([decl], no_layers("/planner_server", "global_costmap"), [navfn, server])
    assert ("read", "/planner_server/GridBased.tolerance") in links_of(
        config, "/planner_server")
    assert "/global_costmap/global_costmap" in [n.name for n in config.nodes]
    assert next(n for n in config.nodes if n.name == "/planner_server").is_complete


def test_a_node_that_loads_plugins_and_is_no_host_is_partial():
    loader = Node("planner", "planner_node", calls=[call("declare", "rate", "double")],
                  plugin_loads=["planner/src/manager.cpp:41"])
    config = graph([ros2(NodeDecl("/planner", "planner", "planner_node"))], nodes=[loader])
    instance = config.nodes[0]
    assert instance.completeness == "partial"
    assert instance.completeness_reasons == [
        "planner/src/manager.cpp:41: loads plugin classes by name whose calls "
        "are not known here"]
    assert loader.completeness == "complete"  # the node model others share is untouched


def test_a_plugin_that_loads_plugins_makes_its_host_partial():
    # nav2's MPPI controller loads its critics through pluginlib; their reads are unseen
    mppi = Node("mppi", "mppi::MPPIController", "plugin", plugin_class="mppi::MPPIController",
                calls=[call("declare", "?.time_steps", "int")],
                plugin_loads=["mppi/src/critic_manager.cpp:62"])
    decl = ros2(NodeDecl("/controller_server", "nav2_controller", "controller_server"))
    params = [ParamDecl("/controller_server/controller_plugins", ["FollowPath"]),
              ParamDecl("/controller_server/FollowPath.plugin", "mppi::MPPIController"),
              *no_layers("/controller_server", "local_costmap")]
    host = Node("nav2_controller", "controller_server",
                plugin_loads=["nav2_controller/src/controller_server.cpp:87"])
    config = graph([decl], params, [mppi, host])
    server = next(n for n in config.nodes if n.name == "/controller_server")
    assert ("read", "/controller_server/FollowPath.time_steps") in links_of(
        config, "/controller_server")
    assert not server.is_complete
    assert server.completeness_reasons[0] == (
        "plugin mppi/mppi::MPPIController: mppi/src/critic_manager.cpp:62: loads plugin "
        "classes by name whose calls are not known here")


def test_a_conditional_choice_makes_the_plugin_calls_conditional():
    from haros_arch.model import Condition
    smac = plugin("smac", "smac/Smac", "smac::Smac", call("publish", "plan", "nav_msgs/Path"))
    when = (Condition("$(arg smac)", "launch"),)
    config = graph([ros2(NodeDecl("/planner_server", "nav2_planner", "planner_server"))],
                   [ParamDecl("/planner_server/planner_plugins", ["S"]),
                    ParamDecl("/planner_server/S.plugin", "smac/Smac", conditions=when)],
                   [smac])
    (link,) = [link for link in config.links if link.kind == "publish"]
    assert link.conditions == when


def test_spawned_ros2_controllers_are_nodes_in_the_managers_namespace(tmp_path: Path):
    params = tmp_path / "controllers.yaml"
    params.write_text(
        # rcl: a key without a leading "/" names a node in the root namespace
        "/robot/follower:\n  ros__parameters:\n    type: my/Follower\n    gain: 2.0\n"
        "    update_rate: 50\n"
        "/robot/controller_manager:\n  ros__parameters:\n    broadcaster:\n"
        "      type: my/Bcast\n")
    follower = plugin("my", "my/Follower", "my::Follower",
                      call("subscribe", "~/commands", "std_msgs/msg/String"),
                      call("declare", "gain", "double"))
    bcast = plugin("my", "my/Bcast", "my::Bcast",
                   call("publish", "joint_states", "sensor_msgs/msg/JointState"))
    decls = [ros2(NodeDecl("/robot/controller_manager", "controller_manager",
                           "ros2_control_node", "/robot/")),
             ros2(NodeDecl("/robot/spawner", "controller_manager", "spawner", "/robot/",
                           args=f"follower broadcaster missing --param-file {params} "
                                "--controller-ros-args -r ~/commands:=/cmds"))]
    config = graph(decls, nodes=[follower, bcast], root=str(tmp_path))
    added = {n.name: n for n in config.nodes if n.origin == "plugin"}
    assert sorted(added) == ["/robot/broadcaster", "/robot/follower"]
    assert added["/robot/follower"].node is follower
    assert links_of(config, "/robot/follower") == sorted([
        ("read", "/robot/follower/gain"), ("read", "/robot/follower/type"),
        ("subscribe", "/cmds"), *base_declares("/robot/follower")])
    # the broadcaster's class is the manager's parameter in the file: the manager reads it
    assert links_of(config, "/robot/controller_manager") == [
        ("read", "/robot/controller_manager/broadcaster.type")]
    assert links_of(config, "/robot/broadcaster") == sorted([
        ("publish", "/robot/joint_states"), *base_declares("/robot/broadcaster")])
    gain = config.parameter("/robot/follower/gain")
    assert gain.set_by_launch and gain.value == 2.0 and gain.is_read
    # each said where its key is written (a finding about one points at its line)
    assert gain.launch_location.file.endswith("controllers.yaml")
    assert gain.launch_location.line == 4
    assert config.parameter("/robot/controller_manager/broadcaster.type"
                            ).launch_location.line == 9
    # the controller's own code does not read it: the manager's init of it does
    assert config.parameter("/robot/follower/update_rate").is_read
    codes = [d.code for d in config.diagnostics if d.code.startswith("PLUGIN")]
    assert codes == ["PLUGIN_CLASS_UNKNOWN"]  # "missing" has no type anywhere


def test_spawned_controllers_take_the_remaps_of_the_managers_process(tmp_path: Path):
    # open_manipulator remaps /arm_controller/joint_trajectory on ros2_control_node: rcl
    # applies a process's -r remaps to every node in it, a controller's own
    # --controller-ros-args over them
    params = tmp_path / "controllers.yaml"
    params.write_text("/controller_manager:\n  ros__parameters:\n    arm:\n"
                      "      type: my/Arm\n    hand:\n      type: my/Arm\n")
    arm = plugin("my", "my/Arm", "my::Arm",
                 call("subscribe", "~/joint_trajectory", "std_msgs/msg/String"))
    decls = [ros2(NodeDecl("/controller_manager", "controller_manager", "ros2_control_node",
                           remaps=[("/arm/joint_trajectory", "/leader/joint_trajectory"),
                                   ("/hand/joint_trajectory", "/leader/hand")])),
             ros2(NodeDecl("/spawner", "controller_manager", "spawner",
                           args=f"arm --param-file {params}")),
             ros2(NodeDecl("/spawner_hand", "controller_manager", "spawner",
                           args=f"hand --param-file {params} "
                                "--controller-ros-args -r ~/joint_trajectory:=/own"))]
    config = graph(decls, nodes=[arm], root=str(tmp_path))
    assert ("subscribe", "/leader/joint_trajectory") in links_of(config, "/arm")
    assert ("subscribe", "/own") in links_of(config, "/hand")


def test_spawner_arguments_are_read_as_its_argparse_does():
    spawn = spawn_args(NodeDecl("/s", "controller_manager", "spawner", args=(
        "a b -c /x/cm --param-file /p.yaml --inactive -t pkg/T "
        "--controller-ros-args -r ~/in:=/out")))
    assert (spawn.controllers, spawn.manager, spawn.param_files, spawn.controller_type,
            spawn.ros_args) == (["a", "b"], "/x/cm", ["/p.yaml"], "pkg/T",
                                ["-r", "~/in:=/out"])


def test_framework_calls_a_plugin_shares_with_its_host_are_made_once():
    # nav2 plugins include the host's LifecycleNode header: its calls are the host's
    shared = call("read", "use_sim_time", "bool", line=40)
    server = Node("nav2_smoother", "smoother_server", calls=[shared])
    first = plugin("s", "s/A", "s::A", shared, call("declare", "?.tolerance", "double"))
    second = plugin("s", "s/B", "s::B", shared)
    config = graph([ros2(NodeDecl("/smoother_server", "nav2_smoother", "smoother_server"))],
                   [ParamDecl("/smoother_server/smoother_plugins", ["a", "b"]),
                    ParamDecl("/smoother_server/a.plugin", "s/A"),
                    ParamDecl("/smoother_server/b.plugin", "s/B")], [server, first, second])
    reads = [link.resource.name for link in config.links if link.kind == "read"]
    assert reads.count("/smoother_server/use_sim_time") == 1
    assert "/smoother_server/a.tolerance" in reads


def test_a_manager_named_only_by_its_code_serves_the_spawners_of_its_namespace(tmp_path):
    # launch_ros names the node as ros2_control_node's code does ("controller_manager",
    # which its interface model gives when its source is not here); the spawner's -c
    # default (controller_manager, in its namespace) reaches it
    params = tmp_path / "c.yaml"
    params.write_text("/robot/controller_manager:\n  ros__parameters:\n"
                      "    bcast:\n      type: my/Bcast\n")
    bcast = plugin("my", "my/Bcast", "my::Bcast", call("publish", "joint_states", "x/J"))
    decls = [ros2(NodeDecl("/robot/?", "controller_manager", "ros2_control_node", "/robot/")),
             ros2(NodeDecl("/robot/spawner", "controller_manager", "spawner", "/robot/",
                           args=f"bcast --param-file {params}")),
             ros2(NodeDecl("/other/spawner", "controller_manager", "spawner", "/other/",
                           args=f"bcast --param-file {params}"))]
    manager = Node("controller_manager", "ros2_control_node", rosname="controller_manager",
                   completeness="model")
    config = graph(decls, nodes=[bcast, manager], root=str(tmp_path))
    assert config.node("/robot/controller_manager") is not None
    # /other's spawner loads into /other/controller_manager, not started here: its
    # controller is a node of its own there (``unmanaged_controllers``), not /robot's
    assert [n.name for n in config.nodes if n.origin == "plugin"] == [
        "/robot/bcast", "/other/bcast"]
    assert links_of(config, "/robot/bcast") == sorted([
        ("publish", "/robot/joint_states"), *base_declares("/robot/bcast")])
    assert all(p.is_read for p in config.parameters
               if p.set_by_launch and not p.is_unresolved)
    # a manager whose code is here but does not say its name: the spawner still reaches
    # it, and the <name>.type it sets is not put under a name no instance has (it would
    # be "set but never read")
    manager = Node("controller_manager", "ros2_control_node")
    config = graph(decls, nodes=[bcast, manager], root=str(tmp_path))
    assert UNKNOWN_MARK in config.nodes[0].name or config.nodes[0].name.endswith(
        "/ros2_control_node")
    assert [n.name for n in config.nodes if n.origin == "plugin"] == [
        "/robot/bcast", "/other/bcast"]
    assert not [p.name for p in config.parameters if p.set_by_launch and not p.is_unresolved]


def test_a_hostile_or_broken_spawner_file_is_a_diagnostic(tmp_path):
    bomb = tmp_path / "bomb.yaml"
    lines = ["a0: &a0 [x, x, x, x, x, x, x, x, x, x]"]
    lines += [f"a{i}: &a{i} [{', '.join(['*a' + str(i - 1)] * 10)}]" for i in range(1, 9)]
    bomb.write_text("\n".join(lines) + "\n")
    broken = tmp_path / "broken.yaml"
    broken.write_text("a: [\n")
    deep = tmp_path / "deep.yaml"  # the YAML scanner is quadratic in open brackets
    deep.write_text("[" * 200_000)
    decls = [ros2(NodeDecl("/controller_manager", "controller_manager", "ros2_control_node")),
             ros2(NodeDecl("/s1", "controller_manager", "spawner", args=f"c --param-file {bomb}")),
             ros2(NodeDecl("/s2", "controller_manager", "spawner",
                           args=f"c --param-file {broken} --param-file {tmp_path}/none.yaml"
                                f" --param-file {deep}"))]
    config = graph(decls, root=str(tmp_path))
    codes = [d.code for d in config.diagnostics if d.code.startswith("PLUGIN")]
    assert codes.count("PLUGIN_PARAM_FILE") == 4


_COSTMAP_FILE = {"global_costmap": {"global_costmap": {"ros__parameters": {
    "plugins": ["obstacle_layer", "inflation_layer"],
    "obstacle_layer": {"plugin": "nav2_costmap_2d::ObstacleLayer",
                       "observation_sources": "scan cloud",
                       "scan": {"topic": "/scan", "data_type": "LaserScan"},
                       "cloud": {"topic": "points", "data_type": "PointCloud2"}}}}},
    "planner_server": {"ros__parameters": {"expected_planner_frequency": 1.0}}}


def _costmap_graph(version: str = ""):
    from haros_arch.model.source import Package
    costmap = Node("nav2_costmap_2d", "nav2_costmap_2d",
                   calls=[call("publish", "costmap", "nav_msgs/msg/OccupancyGrid")])
    obstacle = plugin("nav2_costmap_2d", "nav2_costmap_2d::ObstacleLayer",
                      "nav2_costmap_2d::ObstacleLayer",
                      call("read", "?.observation_sources", "str", 2),
                      call("read", "?.?.marking", "bool", 3))
    inflation = plugin("nav2_costmap_2d", "nav2_costmap_2d::InflationLayer",
                       "nav2_costmap_2d::InflationLayer",
                       call("read", "?.inflation_radius", "double", 4))
    decl = ros2(NodeDecl("/planner_server", "nav2_planner", "planner_server",
                         remaps=[("/tf", "tf")]))
    decl.param_files.append((_COSTMAP_FILE, where(2), {}))
    workspace = Workspace(root="/nowhere")
    if version:
        workspace.packages["nav2_costmap_2d"] = Package("nav2_costmap_2d", "/nowhere/c",
                                                         version=version)
    launch = LaunchModel(nodes=[decl])
    return build(Configuration("c"), launch, workspace,
                 {n.name: n for n in (costmap, obstacle, inflation)})


def test_nav2_planner_server_makes_its_costmap_node_with_layers_and_sources():
    config = _costmap_graph()
    costmap = config.node("/global_costmap/global_costmap")
    assert costmap.origin == "plugin" and costmap.namespace == "/global_costmap/"
    assert costmap.remaps == [("/tf", "tf")]  # the process's arguments
    assert links_of(config, "/global_costmap/global_costmap") == [
        ("publish", "/global_costmap/costmap"),
        ("read", "/global_costmap/global_costmap/inflation_layer.inflation_radius"),
        ("read", "/global_costmap/global_costmap/obstacle_layer.cloud.data_type"),
        ("read", "/global_costmap/global_costmap/obstacle_layer.cloud.marking"),
        ("read", "/global_costmap/global_costmap/obstacle_layer.cloud.topic"),
        ("read", "/global_costmap/global_costmap/obstacle_layer.observation_sources"),
        ("read", "/global_costmap/global_costmap/obstacle_layer.plugin"),
        ("read", "/global_costmap/global_costmap/obstacle_layer.scan.data_type"),
        ("read", "/global_costmap/global_costmap/obstacle_layer.scan.marking"),
        ("read", "/global_costmap/global_costmap/obstacle_layer.scan.topic"),
        ("read", "/global_costmap/global_costmap/plugins"),
        ("subscribe", "/global_costmap/points"),
        ("subscribe", "/scan"),
    ]
    types = {link.resource.name: link.type for link in config.links if link.kind == "subscribe"}
    assert types == {"/scan": "sensor_msgs/msg/LaserScan",
                     "/global_costmap/points": "sensor_msgs/msg/PointCloud2"}
    scan = next(link for link in config.links if link.resource.name == "/scan")
    assert scan.location.line == 2  # the parameter file that names the topic
    # the planner's own entry of the file is not the costmap's
    assert not [p for p in config.parameters
                if p.name.startswith("/global_costmap/") and "expected" in p.name]
    assert [d.code for d in config.diagnostics if d.code.startswith("PLUGIN")
            and "costmap" in d.message] == []


def test_nav2_from_1_4_resolves_a_relative_source_topic_in_the_parent_namespace():
    config = _costmap_graph("1.5.0")
    assert ("subscribe", "/points") in links_of(config, "/global_costmap/global_costmap")


def test_ros1_costmap_obstacle_layer_subscribes_its_observation_sources():
    move_base = Node("move_base", "move_base")
    obstacle = plugin("costmap_2d", "costmap_2d::ObstacleLayer", "costmap_2d::ObstacleLayer",
                      call("read", "~?/?/topic", "str", 2, handle_namespace="~?/?"),
                      # message_filters::Subscriber(g_nh, topic, 50): topic unknown here
                      call("subscribe", "?", "sensor_msgs/LaserScan", 154))
    defaults = [plugin("navfn", "navfn/NavfnROS", "navfn::NavfnROS"),
                plugin("base_local_planner", "base_local_planner/TrajectoryPlannerROS",
                       "base_local_planner::TrajectoryPlannerROS")]
    params = [
        ParamDecl("/move_base/global_costmap/plugins",
                  [{"name": "obstacles", "type": "costmap_2d::ObstacleLayer"}]),
        ParamDecl("/move_base/global_costmap/obstacles/observation_sources", "laser",
                  location=where(5)),
        ParamDecl("/move_base/global_costmap/obstacles/laser/data_type", "LaserScan"),
        ParamDecl("/move_base/global_costmap/obstacles/laser/topic", "scan",
                  location=where(6)),
        *no_layers("/move_base", "local_costmap"),
    ]
    config = graph([NodeDecl("/r/move_base", "move_base", "move_base", "/r/")],
                   [ParamDecl("/r" + p.name, p.value, location=p.location) for p in params],
                   [move_base, obstacle, *defaults])
    links = links_of(config, "/r/move_base")
    assert ("subscribe", "/r/scan") in links
    assert ("read", "/r/move_base/global_costmap/obstacles/laser/topic") in links
    assert ("read", "/r/move_base/global_costmap/obstacles/laser/data_type") in links
    (scan,) = [link for link in config.links if link.kind == "subscribe"]
    assert (scan.type, scan.location.line) == ("sensor_msgs/LaserScan", 6)


def test_ros1_mavros_loads_exported_plugins_its_black_and_white_lists_let_through():
    def mavros_plugin(name, *calls):
        node = plugin("mavros", name, f"mavros::std_plugins::{name}", *calls)
        node.plugin_base = "mavros::plugin::PluginBase"
        return node

    mavros = Node("mavros", "mavros_node", calls=[call("read", "~fcu_url", "str")])
    plugins = [mavros_plugin("imu", call("publish", "~imu/data", "sensor_msgs/Imu")),
               mavros_plugin("vibration", call("publish", "~vibration/raw", "V")),
               mavros_plugin("safety_area", call("read", "~safety_area/p1/x", "double")),
               plugin("other", "other/imu2", "o::Imu", call("publish", "~wrong", "X"))]
    params = [ParamDecl("/mavros/plugin_blacklist", ["VIB*", "safety_*"], location=where(3)),
              ParamDecl("/mavros/plugin_whitelist", ["safety_area"])]
    config = graph([NodeDecl("/mavros", "mavros", "mavros_node")], params,
                   [mavros, *plugins])
    assert links_of(config, "/mavros") == [
        ("publish", "/mavros/imu/data"),
        ("read", "/mavros/fcu_url"),
        ("read", "/mavros/plugin_blacklist"),
        ("read", "/mavros/plugin_whitelist"),
        ("read", "/mavros/safety_area/p1/x"),  # black-listed, then white-listed
    ]
    # an allow list alone: everything else is denied
    config = graph([NodeDecl("/mavros", "mavros", "mavros_node")],
                   [ParamDecl("/mavros/plugin_whitelist", ["imu"])], [mavros, *plugins])
    assert [k for k in links_of(config, "/mavros") if k[0] == "publish"] == [
        ("publish", "/mavros/imu/data")]


def test_ros1_mavros_before_0_18_loads_plugins_of_its_older_base():
    # mavros 0.x (2014-2016): plugin_loader("mavros", "mavplugin::MavRosPlugin")
    gps = plugin("mavros", "gps", "mavplugin::GPSPlugin",
                 call("publish", "~gps/fix", "sensor_msgs/NavSatFix"))
    gps.plugin_base = "mavplugin::MavRosPlugin"
    mavros = Node("mavros", "mavros_node", calls=[call("read", "~fcu_url", "str")])
    config = graph([NodeDecl("/mavros", "mavros", "mavros_node")],
                   [ParamDecl("/mavros/plugin_blacklist", ["image_pub"])], [mavros, gps])
    assert ("publish", "/mavros/gps/fix") in links_of(config, "/mavros")
    assert config.node("/mavros").completeness == "complete"


def _ros1_controllers_plugins():
    return [plugin("diff_drive_controller", "diff_drive_controller/DiffDriveController",
                   "diff_drive_controller::DiffDriveController",
                   call("subscribe", "?/cmd_vel", "geometry_msgs/Twist", handle_namespace="?"),
                   call("read", "?/publish_rate", "double", handle_namespace="?"))]


def _ros1_controllers_params():
    return [ParamDecl("/r/base/type", "diff_drive_controller/DiffDriveController",
                      location=where(4)),
            ParamDecl("/r/joints/type", "joint_state_controller/JointStateController",
                      location=where(5))]


def _ros1_controllers(decls, extra_nodes=()):
    return graph(decls, _ros1_controllers_params(),
                 [*_ros1_controllers_plugins(), *extra_nodes])


def test_ros1_spawned_controllers_without_a_manager_in_the_configuration_are_own_instances():
    spawner = NodeDecl("/r/spawner", "controller_manager", "spawner", "/r/",
                       args="base joints untyped --timeout 10")
    config = _ros1_controllers([spawner])
    base = config.node("/r/base")
    assert base.origin == "plugin" and base.node.name.endswith("DiffDriveController")
    assert links_of(config, "/r/base") == [
        ("read", "/r/base/publish_rate"), ("read", "/r/base/type"),
        ("subscribe", "/r/base/cmd_vel")]
    (missing,) = [d for d in config.diagnostics if d.code == "PLUGIN_NOT_FOUND"]
    assert missing.location.line == 5 and "JointStateController" in missing.message
    # a controller whose class is not found is an instance all the same, of unknown
    # interface: its parameters may be read (summit_xl's robotnik_base_control)
    joints = config.node("/r/joints")
    assert joints.origin == "plugin" and joints.node is None
    assert joints.completeness == "unknown"
    assert links_of(config, "/r/joints") == [("read", "/r/joints/type")]
    # no type at all: the manager refuses to load it, no instance
    assert config.node("/r/untyped") is None


def test_ros1_spawned_controllers_go_to_the_instance_serving_their_manager():
    hardware = Node("robot_base", "base_node",
                    calls=[call("server", "controller_manager/load_controller", "L")])
    spawner = NodeDecl("/spawner", "controller_manager", "spawner", "/",
                       args="--namespace=r base")
    config = _ros1_controllers([NodeDecl("/r/base_node", "robot_base", "base_node", "/r/"),
                                spawner], [hardware])
    assert config.node("/r/base") is None
    assert ("subscribe", "/r/base/cmd_vel") in links_of(config, "/r/base_node")
    assert ("read", "/r/base/type") in links_of(config, "/r/base_node")
    assert ros1_spawn_args(NodeDecl("/c", "controller_manager", "controller_manager",
                                    args="spawn a b")) == (["a", "b"], "")


def test_ros1_a_controller_whose_type_nothing_sets_is_a_read_of_its_host_not_unknown():
    # UR's ur3_ros_control.launch spawned velocity_based_position_trajectory_controller,
    # which its YAML file named vel_based_pos_traj_controller: the manager reads the
    # type, finds none and loads nothing (controller_manager.cpp, loadController), so its
    # host is not partial for it and the read is there for parameter-read-not-set
    hardware = Node("robot_base", "base_node",
                    calls=[call("server", "controller_manager/load_controller", "L")])
    spawner = NodeDecl("/spawner", "controller_manager", "spawner", "/",
                       args="--namespace=r base untyped", location=where(9))
    decls = [NodeDecl("/r/base_node", "robot_base", "base_node", "/r/"), spawner]
    config = _ros1_controllers(decls, [hardware])
    assert ("read", "/r/untyped/type") in links_of(config, "/r/base_node")
    (read,) = [link for link in config.links if link.resource.name == "/r/untyped/type"]
    assert read.location.line == 9  # the spawner's line
    assert config.node("/r/base_node").completeness == "complete"
    # still said where the spawner names it, as before (its class is not set)
    (unset,) = [d for d in config.diagnostics if d.code.startswith("PLUGIN")]
    assert unset.code == "PLUGIN_CLASS_UNKNOWN" and unset.location.line == 9
    assert not config.parameter("/r/untyped/type").is_set
    # an include not read may set it (ROS 1 files set any name): not known, as before
    unread = LaunchItem("include", "$(find other)/launch/more.launch", where(3))
    launch = LaunchModel(nodes=[NodeDecl("/r/base_node", "robot_base", "base_node", "/r/"),
                                NodeDecl("/spawner", "controller_manager", "spawner", "/",
                                         args="--namespace=r base untyped")],
                         params=_ros1_controllers_params(),
                         tree=[LaunchItem("file", "bringup.launch", children=[unread])])
    config = build(Configuration("c"), launch, Workspace(root="/nowhere"),
                   {n.name: n for n in [hardware, *_ros1_controllers_plugins()]})
    assert [d.code for d in config.diagnostics] == ["PLUGIN_CLASS_UNKNOWN"]
    assert config.node("/r/base_node").completeness == "partial"


def test_ros2_plugin_nodes_leave_their_hosts_framework_calls_to_the_host():
    framework = call("publish", "/diagnostics", "diagnostic_msgs/msg/DiagnosticArray", 268)
    mavros = Node("mavros", "mavros_node", calls=[framework])
    imu = plugin("mavros", "imu", "mavros::plugin::PluginFactoryTemplate<Imu>", framework,
                 call("publish", "~/data", "sensor_msgs/msg/Imu", 40))
    imu.plugin_base, imu.rosname = "mavros::plugin::PluginFactory", "imu"
    config = graph([ros2(NodeDecl("/mavros/mavros", "mavros", "mavros_node", "/mavros/"))],
                   nodes=[mavros, imu])
    assert links_of(config, "/mavros/imu") == [("publish", "/mavros/imu/data")]
    assert links_of(config, "/mavros/mavros") == [("publish", "/diagnostics")]


def test_mavros_with_no_exported_plugin_in_view_is_partial():
    mavros = Node("mavros", "mavros_node", calls=[call("read", "~fcu_url", "str")])
    config = graph([NodeDecl("/mavros", "mavros", "mavros_node")], nodes=[mavros])
    assert [d.code for d in config.diagnostics] == ["PLUGIN_CLASS_UNKNOWN"]
    assert config.node("/mavros").completeness == "partial"


def test_a_voxel_layer_runs_its_obstacle_layer_code_too():
    move_base = Node("move_base", "move_base")
    obstacle = plugin("costmap_2d", "costmap_2d::ObstacleLayer", "costmap_2d::ObstacleLayer",
                      call("read", "~?/observation_sources", "str", 78, handle_namespace="~?"))
    voxel = plugin("costmap_2d", "costmap_2d::VoxelLayer", "costmap_2d::VoxelLayer",
                   call("read", "~?/z_voxels", "int", 60, handle_namespace="~?"))
    defaults = [plugin("navfn", "navfn/NavfnROS", "navfn::NavfnROS"),
                plugin("base_local_planner", "base_local_planner/TrajectoryPlannerROS",
                       "base_local_planner::TrajectoryPlannerROS")]
    params = [ParamDecl("/move_base/local_costmap/plugins",
                        [{"name": "voxels", "type": "costmap_2d::VoxelLayer"}])]
    config = graph([NodeDecl("/move_base", "move_base", "move_base")], params,
                   [move_base, obstacle, voxel, *defaults])
    links = links_of(config, "/move_base")
    assert ("read", "/move_base/local_costmap/voxels/z_voxels") in links
    assert ("read", "/move_base/local_costmap/voxels/observation_sources") in links


def test_move_group_loads_default_capabilities_plus_its_string_less_the_disabled():
    plan = plugin("moveit_ros_move_group", "move_group/MoveGroupPlanService",
                  "move_group::MoveGroupPlanService",
                  call("server", "plan_kinematic_path", "moveit_msgs/srv/GetMotionPlan"))
    octomap = plugin("moveit_ros_move_group", "move_group/ClearOctomapService",
                     "move_group::ClearOctomapService",
                     call("server", "clear_octomap", "std_srvs/srv/Empty"))
    mine = plugin("my_caps", "my_caps/Stop", "my_caps::Stop",
                  call("server", "stop", "std_srvs/srv/Trigger"))
    decls = [ros2(NodeDecl("/move_group", "moveit_ros_move_group", "move_group")),
             ros2(NodeDecl("/r2/move_group", "moveit_ros_move_group", "move_group", "/r2/"))]
    params = [ParamDecl("/r2/move_group/capabilities", " my_caps/Stop\n", location=where(3)),
              ParamDecl("/r2/move_group/disable_capabilities",
                        "move_group/ClearOctomapService", location=where(4))]
    config = graph(decls, params, [plan, octomap, mine])
    served = sorted(link.resource.name for link in config.links if link.kind == "server")
    # no parameter: the defaults; a string adds its classes, the disable string drops
    assert served == ["/clear_octomap", "/plan_kinematic_path", "/r2/plan_kinematic_path",
                      "/r2/stop"]


def test_move_group_capabilities_not_known_statically_leave_it_partial():
    from haros_arch.model.values import Unknown
    plan = plugin("moveit_ros_move_group", "move_group/MoveGroupPlanService",
                  "move_group::MoveGroupPlanService",
                  call("server", "plan_kinematic_path", "moveit_msgs/srv/GetMotionPlan"))
    host = Node("moveit_ros_move_group", "move_group", completeness="model",
                model="jazzy/moveit_ros_move_group 2.12.4")
    decl = ros2(NodeDecl("/move_group", "moveit_ros_move_group", "move_group"))
    config = graph([decl], [ParamDecl("/move_group/capabilities", Unknown()),
                            ParamDecl("/move_group/disable_capabilities", Unknown())],
                   [host, plan])
    (link,) = [link for link in config.links if link.kind == "server"]
    assert [c.text for c in link.conditions] == [
        "move_group/MoveGroupPlanService not in /move_group/disable_capabilities"]
    instance = config.node("/move_group")
    assert instance.completeness == "partial" and not instance.is_complete


def test_a_hosts_unnamed_copy_of_its_plugins_base_class_code_goes():
    # nav2's costmap links costmap_filter.cpp, the filters' base class: the host's own
    # copy of CostmapFilter::onInitialize reads ``?.enabled``; each filter's copy names it
    base = call("declare", "?.enabled", "bool", line=74)
    server = Node("nav2_smoother", "smoother_server", calls=[base])
    first = plugin("s", "s/A", "s::A", base, call("declare", "?.tolerance", "double"))
    params = [ParamDecl("/smoother_server/smoother_plugins", ["a"]),
              ParamDecl("/smoother_server/a.plugin", "s/A")]
    decl = ros2(NodeDecl("/smoother_server", "nav2_smoother", "smoother_server"))
    config = graph([decl], params, [server, first])
    reads = sorted(link.resource.name for link in config.links if link.kind == "read")
    assert "/smoother_server/a.enabled" in reads
    assert not any(UNKNOWN_MARK in name for name in reads)
    # a plugin class not known: what runs that code is not known either, the copy stays
    config = graph([decl], [*params, ParamDecl("/smoother_server/smoother_plugins",
                                               ["a", "b"]),
                            ParamDecl("/smoother_server/b.plugin", "s/Missing")],
                   [server, first])
    reads = [link.resource.name for link in config.links if link.kind == "read"]
    assert "/smoother_server/?.enabled" in reads


def test_a_costmap_a_server_makes_keeps_its_own_unnamed_calls():
    # the planner server makes its global costmap, whose own services are named after the
    # costmap (``clear_except_?`` when not known): no plugin names them, they stay
    costmap_name = call("server", "clear_except_?", "nav2_msgs/srv/ClearCostmapExceptRegion",
                        line=44)
    planner = Node("nav2_planner", "planner_server")
    costmap = Node("nav2_costmap_2d", "nav2_costmap_2d", calls=[costmap_name])
    layer = plugin("nav2_costmap_2d", "nav2_costmap_2d::StaticLayer",
                   "nav2_costmap_2d::StaticLayer", call("read", "?.enabled", "bool", line=9))
    decl = ros2(NodeDecl("/planner_server", "nav2_planner", "planner_server"))
    config = graph([decl], [ParamDecl("/global_costmap/global_costmap/plugins", ["static"]),
                            ParamDecl("/global_costmap/global_costmap/static.plugin",
                                      "nav2_costmap_2d::StaticLayer")],
                   [planner, costmap, layer])
    names = links_of(config, "/global_costmap/global_costmap")
    assert ("read", "/global_costmap/global_costmap/static.enabled") in names
    assert ("server", "/global_costmap/clear_except_?") in names


def test_a_ros2_spawner_is_named_and_calls_the_manager_as_its_arguments_say():
    """controller_manager's ROS 2 spawner names itself ``spawner_<first controller>``
    and calls the manager's services that ``-c`` / ``--namespace`` name. Its interface
    model (names built from sys.argv) had the node ``/?`` calling a service ``/?``: every
    ros2_control launch file (turtlebot3_manipulation's base.launch.py, franka's) showed
    spawners without names and service calls that no server could be matched to."""
    model = Node("controller_manager", "spawner", "executable", "python",
                 calls=[call("client", UNKNOWN_MARK)], rosname=f"spawner_{UNKNOWN_MARK}")
    model.completeness = "model"
    decls = [ros2(NodeDecl("/robot/controller_manager", "controller_manager",
                           "ros2_control_node", "/robot/")),
             ros2(NodeDecl(f"/robot/{UNKNOWN_MARK}", "controller_manager", "spawner",
                           "/robot/", args="joint_state_broadcaster arm -c controller_manager")),
             ros2(NodeDecl(f"/{UNKNOWN_MARK}", "controller_manager", "spawner", "/",
                           args="gripper --load-only --namespace robot -t pkg/G "
                                "--ros-args --log-level warn")),
             ros2(NodeDecl(f"/{UNKNOWN_MARK}", "controller_manager", "spawner", "/",
                           args=f"{UNKNOWN_MARK} -c /cm"))]
    config = graph(decls, nodes=[model])
    names = sorted(n.name for n in config.nodes if n.node is not None
                   and n.node.executable == "spawner")
    # (controllers not known: the model's node, named as the model names it, the
    # controller's part unknown)
    assert names == ["/robot/spawner_joint_state_broadcaster", f"/spawner_{UNKNOWN_MARK}",
                     "/spawner_gripper"], names
    manager = "/robot/controller_manager"
    assert links_of(config, "/robot/spawner_joint_state_broadcaster") == [
        ("client", f"{manager}/{verb}") for verb in (
            "configure_controller", "list_controllers", "load_controller",
            "switch_controller")]
    assert links_of(config, "/spawner_gripper") == [
        ("client", f"{manager}/{verb}") for verb in (
            "list_controllers", "load_controller", "set_parameters")]
    # controllers not known: the model's node, as before
    assert links_of(config, f"/spawner_{UNKNOWN_MARK}") == [("client", UNKNOWN_MARK)]
    assert "NODE_NAME_GUESSED" not in [d.code for d in config.diagnostics]


def test_a_controller_whose_class_is_not_here_is_a_node_of_unknown_interface(tmp_path):
    """turtlebot3_manipulation's base.launch.py spawns joint_state_broadcaster and four
    more controllers of ros2_controllers, whose sources are not in the workspace (their
    types in hardware_controller_manager.yaml). Each is a node of its own all the same,
    named after the controller, its interface unknown; before, no node was made and the
    manager was marked partial instead, though its own interface is known."""
    params = tmp_path / "controllers.yaml"
    params.write_text("controller_manager:\n  ros__parameters:\n    jsb:\n"
                      "      type: joint_state_broadcaster/JointStateBroadcaster\n")
    manager = Node("controller_manager", "ros2_control_node", calls=[
        call("publish", "~/activity", "std_msgs/msg/String")])
    decls = [ros2(NodeDecl("/controller_manager", "controller_manager",
                           "ros2_control_node", "/")),
             ros2(NodeDecl(f"/{UNKNOWN_MARK}", "controller_manager", "spawner", "/",
                           args=f"jsb --param-file {params}"))]
    # a description with no <ros2_control>: no hardware to load (one not known would
    # leave the manager partial, HARDWARE_UNKNOWN)
    urdf = tmp_path / "robot.urdf"
    urdf.write_text("<robot name='r'><link name='base'/></robot>")
    config = graph(decls, [ParamDecl("/controller_manager/robot_description", "?",
                                     command=f"cat {urdf}")],
                   nodes=[manager], root=str(tmp_path))
    added = {n.name: n for n in config.nodes if n.origin == "plugin"}
    assert list(added) == ["/jsb"] and added["/jsb"].node is None
    assert links_of(config, "/jsb") == base_declares("/jsb")
    host = next(n for n in config.nodes if n.name == "/controller_manager")
    assert host.node is not None and host.node.completeness == "complete"
    assert [d.code for d in config.diagnostics if d.code.startswith("PLUGIN")] == [
        "PLUGIN_NOT_FOUND"]


def test_a_workspace_node_that_makes_the_manager_hosts_the_spawners_controllers(tmp_path):
    # KUKA's kuka_drivers_core/control_node makes controller_manager::ControllerManager
    # itself (its model serves ~load_controller, the C++ row of the manager's
    # constructor); the spawners' controllers are loaded into it as into
    # ros2_control_node (before: a node of no host, the controllers nowhere)
    params = tmp_path / "c.yaml"
    params.write_text("/controller_manager:\n  ros__parameters:\n"
                      "    bcast:\n      type: my/Bcast\n")
    bcast = plugin("my", "my/Bcast", "my::Bcast", call("publish", "joint_states", "x/J"))
    served = call("server", "~load_controller", "controller_manager_msgs/srv/LoadController")
    control = Node("robot", "control_node", rosname="controller_manager", calls=[served])
    decls = [ros2(NodeDecl("/controller_manager", "robot", "control_node", "/")),
             ros2(NodeDecl("/spawner", "controller_manager", "spawner", "/",
                           args=f"bcast --param-file {params}"))]
    config = graph(decls, nodes=[bcast, control], root=str(tmp_path))
    assert [n.name for n in config.nodes if n.origin == "plugin"] == ["/bcast"]
    assert links_of(config, "/bcast") == sorted([
        ("publish", "/joint_states"), *base_declares("/bcast")])
    assert config.parameter("/controller_manager/bcast.type").is_read
    # a node that serves a service of that name of another type is no manager
    served.type = "my_msgs/srv/Load"
    config = graph(decls, nodes=[bcast, control], root=str(tmp_path))
    assert not [n.name for n in config.nodes if n.origin == "plugin"]


def test_ros1_a_controller_topic_named_by_its_parameter_is_linked():
    # sawyer_sim_controllers' head controller: getParam("topic_command", name) then
    # NodeHandle("~").subscribe(name, ...); the controller's copy of that subscription
    # keeps its ``?`` for the parameter's value, and was taken for the host's own
    # unnamed copy and dropped once the controller's code parsed clean
    head = plugin("sawyer_sim_controllers", "sawyer_sim_controllers/SawyerHeadController",
                  "sawyer_sim_controllers::SawyerHeadController",
                  call("read", "?/topic_command", "str", 80, handle_namespace="?"),
                  call("subscribe", "~?", "std_msgs/Float64", 86, handle_namespace="~",
                       name_param="?/topic_command"))
    assert head.completeness == "complete"
    spawner = NodeDecl("/r/spawner", "controller_manager", "spawner", "/r/", args="head")
    params = [ParamDecl("/r/head/type", "sawyer_sim_controllers/SawyerHeadController",
                        location=where(4)),
              ParamDecl("/r/head/topic_command", "/r/head/command_head_pan",
                        location=where(5))]
    config = graph([spawner], params, [head])
    assert links_of(config, "/r/head") == [
        ("read", "/r/head/topic_command"), ("read", "/r/head/type"),
        ("subscribe", "/r/head/command_head_pan")]


def test_a_controllers_section_of_the_managers_parameter_file_is_the_controllers(
        tmp_path: Path):
    # franka_ros2 (and ros2_control's demos) give ros2_control_node one file whose
    # section for each controller is its parameters: rcl's global --params-file reaches
    # every node of the process, the controllers too. JointImpedanceWithIKExample-
    # Controller reads arm_id, k_gains, d_gains from it without declaring them: read but
    # never set (survey Z23). A spawner's own file still wins
    manager = ros2(NodeDecl("/controller_manager", "controller_manager", "ros2_control_node"))
    manager.param_files = [({
        "controller_manager": {"ros__parameters": {"arm": {"type": "my/Arm"},
                                                   "hand": {"type": "my/Arm"}}},
        "arm": {"ros__parameters": {"gain": 3.0, "arm_id": "panda"}},
        "hand": {"ros__parameters": {"gain": 4.0}},
        "other": {"ros__parameters": {"gain": 1.0}}}, where(3),
        {("/arm", "gain"): where(6)})]
    own = tmp_path / "hand.yaml"
    own.write_text("hand:\n  ros__parameters:\n    gain: 5.0\n")
    arm = plugin("my", "my/Arm", "my::Arm", call("read", "gain", "double"),
                 call("read", "arm_id", "str"))
    decls = [manager, ros2(NodeDecl("/spawner", "controller_manager", "spawner", args="arm")),
             ros2(NodeDecl("/spawner_hand", "controller_manager", "spawner",
                           args=f"hand --param-file {own}"))]
    config = graph(decls, [ParamDecl("/controller_manager/arm.type", "my/Arm"),
                           ParamDecl("/controller_manager/hand.type", "my/Arm")],
                   nodes=[arm], root=str(tmp_path))
    assert sorted(n.name for n in config.nodes if n.origin == "plugin") == ["/arm", "/hand"]
    values = {name: config.parameter(name) for name in (
        "/arm/gain", "/arm/arm_id", "/hand/gain")}
    assert all(p is not None and p.set_by_launch and p.is_read for p in values.values())
    assert [values[name].value for name in values] == [3.0, "panda", 5.0]
    assert config.parameter("/other/gain") is None  # no node of the process is named so
    # each at its entry's line where the file's places are known (rosbot_ros' imu
    # broadcaster's settings were all at the launch file's line), else the file's
    assert [values[name].launch_location.line for name in ("/arm/gain", "/arm/arm_id")] \
        == [6, 3]


def _dwb_config(critics: list[str], *more: ParamDecl):
    """nav2's controller server with a DWB controller ``FollowPath`` whose critics are
    ``critics``: the critics' classes complete as dwb's ``resolveCriticClassName`` does
    (``Critic`` added, the first of ``default_critic_namespaces`` with such a class)."""
    dwb = Node("dwb_core", "dwb_core::DWBLocalPlanner", "plugin",
               plugin_class="dwb_core::DWBLocalPlanner",
               calls=[call("declare", "?.critics", "str[]"),
                      # its loop's read per critic, and the critics' base's inline
                      # initialize, in a header its unit includes
                      call("declare", "?.?.class", "str", line=170),
                      call("declare", "?.?.scale", "double", line=105),
                      call("read", "?.trajectory_generator_name", "str", line=91,
                           has_default=True,
                           default="dwb_plugins::StandardTrajectoryGenerator",
                           loads="pluginlib:TrajectoryGenerator")],
               plugin_loads=["navigation2/nav2_dwb_controller/dwb_core/src/"
                             "dwb_local_planner.cpp:176"])
    generator = plugin("dwb_plugins", "dwb_plugins::StandardTrajectoryGenerator",
                       "dwb_plugins::StandardTrajectoryGenerator",
                       call("declare", "?.max_vel_x", "double"))
    obstacle = plugin("dwb_critics", "dwb_critics::BaseObstacleCritic",
                      "dwb_critics::BaseObstacleCritic", call("declare", "?.?.scale", "double"),
                      call("declare", "?.?.sum_scores", "bool"))
    oscillation = plugin("dwb_critics", "dwb_critics::OscillationCritic",
                         "dwb_critics::OscillationCritic",
                         call("declare", "?.?.scale", "double"),
                         call("declare", "?.oscillation_reset_dist", "double"))
    speed = plugin("my_critics", "my_critics::SpeedCritic", "my_critics::SpeedCritic",
                   call("declare", "?.?.gain", "double"))
    decl = ros2(NodeDecl("/controller_server", "nav2_controller", "controller_server"))
    params = [ParamDecl("/controller_server/controller_plugins", ["FollowPath"]),
              ParamDecl("/controller_server/FollowPath.plugin", "dwb_core::DWBLocalPlanner"),
              ParamDecl("/controller_server/FollowPath.critics", critics),
              ParamDecl("/controller_server/goal_checker_plugins", []),
              ParamDecl("/controller_server/progress_checker_plugins", []),
              ParamDecl("/controller_server/path_handler_plugins", []),
              *more, *no_layers("/controller_server", "local_costmap")]
    host = Node("nav2_controller", "controller_server",
                plugin_loads=["nav2_controller/src/controller_server.cpp:87"])
    config = graph([decl], params, [dwb, obstacle, oscillation, speed, generator, host])
    return config, next(n for n in config.nodes if n.name == "/controller_server")


def test_a_dwb_controller_loads_its_critics_with_their_names_under_its_own():
    config, server = _dwb_config(
        ["BaseObstacle", "OscillationCritic", "Speed"],
        ParamDecl("/controller_server/FollowPath.Speed.class", "my_critics::SpeedCritic"))
    assert server.is_complete, server.completeness_reasons
    links = links_of(config, "/controller_server")
    for name in ("FollowPath.critics", "FollowPath.BaseObstacle.scale",
                 "FollowPath.BaseObstacle.sum_scores", "FollowPath.OscillationCritic.scale",
                 "FollowPath.oscillation_reset_dist", "FollowPath.Speed.gain",
                 "FollowPath.Speed.class",
                 # the class the plugin loads by its parameter's value, given its name
                 "FollowPath.trajectory_generator_name", "FollowPath.max_vel_x",
                 # the planner's code made once per critic
                 "FollowPath.BaseObstacle.class", "FollowPath.Speed.scale"):
        assert ("read", f"/controller_server/{name}") in links, (name, links)
    assert not [link for link in links if UNKNOWN_MARK in link[1]], links


def test_dwb_critics_are_found_in_the_namespaces_it_is_given_or_not_at_all():
    config, server = _dwb_config(
        ["Speed"], ParamDecl("/controller_server/FollowPath.default_critic_namespaces",
                             ["other_critics", "my_critics"]))
    assert server.is_complete, server.completeness_reasons
    assert ("read", "/controller_server/FollowPath.Speed.gain") in links_of(
        config, "/controller_server")
    config, server = _dwb_config(["Speed"])  # not under dwb_critics
    assert not server.is_complete
    assert [d.code for d in config.diagnostics if "SpeedCritic" in d.message] == [
        "PLUGIN_NOT_FOUND"]


@pytest.mark.parametrize("allowed", [None, True, False])
def test_move_base_without_recovery_behaviors_loads_its_defaults(allowed):
    # move_base.cpp's loadDefaultRecoveryBehaviors: conservative_reset and aggressive_reset
    # (ClearCostmapRecovery) and rotate_recovery (RotateRecovery, whose initialize reads
    # ~TrajectoryPlannerROS/... too), the rotation only with clearing_rotation_allowed
    move_base = Node("move_base", "move_base", calls=[
        call("read", "~clearing_rotation_allowed", "bool", line=116, has_default=True,
             default=True)])
    clear = plugin("clear_costmap_recovery", "clear_costmap_recovery/ClearCostmapRecovery",
                   "clear_costmap_recovery::ClearCostmapRecovery",
                   call("read", "~?/reset_distance", "double"))
    rotate = plugin("rotate_recovery", "rotate_recovery/RotateRecovery",
                    "rotate_recovery::RotateRecovery",
                    call("read", "~?/frequency", "double"),
                    call("read", "~TrajectoryPlannerROS/yaw_goal_tolerance", "double"))
    planners = [plugin("navfn", "navfn/NavfnROS", "navfn::NavfnROS"),
                plugin("base_local_planner", "base_local_planner/TrajectoryPlannerROS",
                       "base_local_planner::TrajectoryPlannerROS")]
    params = [*no_layers("/move_base", "global_costmap", "local_costmap")]
    if allowed is not None:
        params.append(ParamDecl("/move_base/clearing_rotation_allowed", allowed, "bool"))
    config = graph([NodeDecl("/move_base", "move_base", "move_base")], params,
                   [move_base, clear, rotate, *planners])
    reads = [(name, conditions) for kind, name, conditions in (
        (link.kind, link.resource.name, link.conditions) for link in config.links)
        if kind == "read" and name != "/move_base/clearing_rotation_allowed"
        and "costmap" not in name]
    rotation = [("/move_base/TrajectoryPlannerROS/yaw_goal_tolerance", ()),
                ("/move_base/rotate_recovery/frequency", ())]
    assert sorted(reads) == sorted([
        ("/move_base/aggressive_reset/reset_distance", ()),
        ("/move_base/conservative_reset/reset_distance", ()),
        *(rotation if allowed is not False else [])])
    dropped = [d for d in config.diagnostics if d.code == "CONDITION_FALSE"]
    assert len(dropped) == (2 if allowed is False else 0)
    assert all("clearing_rotation_allowed_" in d.message and "move_base.cpp:1121" in d.message
               for d in dropped)
    assert config.node("/move_base").is_complete


def test_nav2_behavior_and_smoother_servers_load_their_defaults_when_not_listed():
    behaviors = [plugin("nav2_behaviors", f"nav2_behaviors/{cls}", f"nav2_behaviors::{cls}",
                        call("declare", f"?.{cls.lower()}_speed", "double"))
                 for cls in ("Spin", "BackUp", "DriveOnHeading", "Wait")]
    for each in behaviors:
        each.ros_version = 2
    smoother = plugin("nav2_smoother", "nav2_smoother/SimpleSmoother",
                      "nav2_smoother::SimpleSmoother", call("declare", "?.tolerance", "double"))
    wait = plugin("nav2_waypoint_follower", "nav2_waypoint_follower/WaitAtWaypoint",
                  "nav2_waypoint_follower::WaitAtWaypoint",
                  call("declare", "?.waypoint_pause_duration", "int"))
    config = graph([ros2(NodeDecl("/behavior_server", "nav2_behaviors", "behavior_server")),
                    ros2(NodeDecl("/smoother_server", "nav2_smoother", "smoother_server")),
                    ros2(NodeDecl("/waypoint_follower", "nav2_waypoint_follower",
                                  "waypoint_follower"))],
                   [], [Node("nav2_behaviors", "behavior_server"),
                        Node("nav2_smoother", "smoother_server"),
                        Node("nav2_waypoint_follower", "waypoint_follower"), *behaviors,
                        smoother, wait])
    declared = sorted(link.resource.name for link in config.links if link.kind == "read"
                      and not link.resource.name.endswith(".plugin"))
    assert declared == ["/behavior_server/backup.backup_speed",
                        "/behavior_server/drive_on_heading.driveonheading_speed",
                        "/behavior_server/spin.spin_speed",
                        "/behavior_server/wait.wait_speed",
                        "/smoother_server/simple_smoother.tolerance",
                        "/waypoint_follower/wait_at_waypoint.waypoint_pause_duration"]
    assert config.node("/behavior_server").is_complete
