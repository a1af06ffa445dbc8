"""navigation2's controller, planner and smoother plugins have interface models (jazzy
and humble, built from their pinned commits): a controller server loading regulated
pure pursuit, navigation2 installed, reads its parameters under the plugin's name, so
a setting the plugin does not read is said (opennav_coverage's demo sets Humble's
``use_interpolation``, gone from Jazzy's controller), where before the plugin was not
found and every setting under it undecided."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

PARAMS = """
controller_server:
  ros__parameters:
    controller_plugins: ["FollowPath"]
    FollowPath:
      plugin: "nav2_regulated_pure_pursuit_controller::RegulatedPurePursuitController"
      desired_linear_vel: 0.5
      use_interpolation: false
planner_server:
  ros__parameters:
    planner_plugins: ["GridBased"]
    GridBased:
      plugin: "nav2_navfn_planner::NavfnPlanner"
      tolerance: 0.5
"""

LAUNCH = """
<launch>
  <node pkg="nav2_controller" exec="controller_server" name="controller_server">
    <param from="$(find-pkg-share demo)/config/nav.yaml"/>
  </node>
  <node pkg="nav2_planner" exec="planner_server" name="planner_server">
    <param from="$(find-pkg-share demo)/config/nav.yaml"/>
  </node>
</launch>
"""


def _analysed(write_tree, params: str, launch: str, distro: str, depends: str):
    """A workspace of one package launching navigation2's servers (installed: their
    interface models) with ``params``: the project, its model and its one
    configuration."""
    root = write_tree({
        "src/demo/package.xml": package_xml("demo", "ament_cmake").replace(
            "</package>", depends + "</package>"),
        "src/demo/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.8)\nproject(demo)\n"
            "find_package(ament_cmake REQUIRED)\n"
            "install(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})\n"
            "ament_package()\n"),
        "src/demo/config/nav.yaml": params,
        "src/demo/launch/nav.launch.xml": launch,
        "project.yaml": (f"project: p\ndistro: {distro}\nworkspace: [src]\n"
                         "configurations:\n  c: [demo/launch/nav.launch.xml]\n")})
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    (config,) = model.configurations
    return project, model, config


# the controller server alone
CONTROLLER = LAUNCH.split("  <node pkg=\"nav2_planner\"")[0] + "</launch>\n"


def test_a_modelled_controller_plugin_reads_its_settings(write_tree) -> None:
    project, model, config = _analysed(
        write_tree, PARAMS, LAUNCH, "jazzy", "<exec_depend>nav2_controller</exec_depend>"
        "<exec_depend>nav2_planner</exec_depend>")
    assert not any(d.code == "PLUGIN_NOT_FOUND" for d in config.diagnostics)
    reads = {link.resource.name for link in config.links if link.kind == "read"}
    assert {"/controller_server/FollowPath.desired_linear_vel",
            "/planner_server/GridBased.tolerance"} <= reads
    unread = [f.message for f in run_catalogue(model, project)
              if f.rule == "parameter-set-not-read"]
    assert any("FollowPath.use_interpolation" in message for message in unread)
    assert not any("desired_linear_vel" in message or "tolerance" in message
                   for message in unread)


DWB = """
controller_server:
  ros__parameters:
    controller_plugins: ["FollowPath"]
    FollowPath:
      plugin: "dwb_core::DWBLocalPlanner"
      critics: ["RotateToGoal"]
      trajectory_generator_name: "dwb_plugins::StandardTrajectoryGenerator"
      sim_time: 1.7
      vx_samples: 20
      max_vel_x: 0.26
      sim_tme: 1.5
"""


def test_dwb_s_trajectory_generator_is_modelled(write_tree) -> None:
    """DWB's trajectory generators (dwb_plugins, exported under dwb_core's tag with a
    base only dwb_core's code loads) have models too: a DWB controller with navigation2
    installed reads its generator's settings under the controller's name, and one it
    does not read (``sim_tme``) is said, where before the generator was not found and
    every setting under the controller undecided."""
    project, model, config = _analysed(
        write_tree, DWB, CONTROLLER, "humble", "<exec_depend>nav2_controller</exec_depend>")
    assert not any(d.code == "PLUGIN_NOT_FOUND" for d in config.diagnostics), [
        d.message for d in config.diagnostics if d.code == "PLUGIN_NOT_FOUND"]
    reads = {link.resource.name for link in config.links if link.kind == "read"}
    assert {"/controller_server/FollowPath.sim_time",
            "/controller_server/FollowPath.vx_samples",
            "/controller_server/FollowPath.max_vel_x"} <= reads, sorted(reads)
    unread = [f.message for f in run_catalogue(model, project)
              if f.rule == "parameter-set-not-read"]
    assert any("FollowPath.sim_tme" in message for message in unread), unread


MPPI = """
controller_server:
  ros__parameters:
    controller_plugins: ["FollowPath"]
    FollowPath:
      plugin: "nav2_mppi_controller::MPPIController"
      time_steps: 56
      critics: ["GoalCritic", "PathAlignCritic"]
      GoalCritic:
        enabled: true
        cost_weight: 5.0
        threshold_to_consider: 1.4
      PathAlignCritic:
        cost_weight: 14.0
        offset_from_furthest: 20
        use_path_orientations: false
      PreferForwardCritic:
        cost_weight: 5.0
"""


def test_mppi_s_critics_are_loaded_under_the_controller(write_tree) -> None:
    """MPPI's critics (classes the controller's critic manager loads from
    ``<plugin>.critics``, ``mppi::critics::<name>``, each named ``<plugin>.<name>``) have
    models and are attached: their settings are read, a critic the list does not name
    reads none (``PreferForwardCritic``), where before the controller loaded them unseen
    and every critic setting was undecided."""
    project, model, config = _analysed(
        write_tree, MPPI, CONTROLLER, "jazzy", "<exec_depend>nav2_controller</exec_depend>")
    reads = {link.resource.name for link in config.links if link.kind == "read"}
    assert {"/controller_server/FollowPath.GoalCritic.cost_weight",
            "/controller_server/FollowPath.GoalCritic.threshold_to_consider",
            "/controller_server/FollowPath.PathAlignCritic.offset_from_furthest",
            "/controller_server/FollowPath.time_steps"} <= reads, sorted(
        r for r in reads if "FollowPath" in r)
    unread = [f.message for f in run_catalogue(model, project)
              if f.rule == "parameter-set-not-read"]
    assert any("FollowPath.PreferForwardCritic.cost_weight" in m for m in unread), unread
    assert not any("GoalCritic" in m or "PathAlignCritic" in m for m in unread), unread
