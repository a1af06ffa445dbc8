"""MoveIt 1's move_group loads its planners, request adapters, kinematics solvers,
controller manager and octomap updaters by the parameters that name them."""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

from conftest import package_xml

from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Location
from haros_arch.models.attach import Attacher
from haros_arch.models.library import Library
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue
from haros_arch.query.catalogue import UNDECIDED
from haros_arch.workspace import Workspace

GROUP = "moveit_ros_move_group"
WHERE = Location("cfg", "cfg/launch/move_group.launch", 7, 0)


def _plugin(package: str, name: str, cls: str, calls: list[dict]) -> dict:
    return {"package": package, "executable": name, "kind": "plugin", "plugin_class": cls,
            "calls": calls}


def _read(name: str, line: int) -> dict:
    return {"kind": "read", "name": name, "type": "double",
            "location": {"package": "p", "file": "p/src/p.cpp", "line": line, "column": 1}}


def _models(tmp_path: Path) -> list[str]:
    files = {
        GROUP: [{"package": GROUP, "executable": "move_group",
                 "calls": [_read("~capabilities", 1)]}],
        "moveit_planners_ompl": [_plugin(
            "moveit_planners_ompl", "ompl_interface/OMPLPlanner",
            "ompl_interface::OMPLPlannerManager",
            [_read("~planner_configs/?", 2), _read("~?/default_planner_config", 6)])],
        "moveit_ros_planning": [_plugin(
            "moveit_ros_planning", "default_planner_request_adapters/FixStartStateBounds",
            "default_planner_request_adapters::FixStartStateBounds",
            [_read("?/start_state_max_bounds_error", 3)])],
        "moveit_kinematics": [_plugin(
            "moveit_kinematics", "kdl_kinematics_plugin/KDLKinematicsPlugin",
            "kdl_kinematics_plugin::KDLKinematicsPlugin", [_read("~?/epsilon", 4)])],
        "moveit_simple_controller_manager": [_plugin(
            "moveit_simple_controller_manager",
            "moveit_simple_controller_manager/MoveItSimpleControllerManager",
            "moveit_simple_controller_manager::MoveItSimpleControllerManager",
            [_read("~controller_list", 5)])],
    }
    paths = []
    for package, nodes in files.items():
        path = tmp_path / f"{package}.json"
        path.write_text(json.dumps({"schema": "haros-arch-model/1", "package": package,
                                    "distro": "noetic", "nodes": nodes}))
        paths.append(str(path))
    return paths


def _configure(tmp_path: Path, params: list[ParamDecl]) -> Configuration:
    decl = NodeDecl("/move_group", GROUP, "move_group", ros_version=1)
    launch = LaunchModel(nodes=[decl], params=[
        ParamDecl("/move_group/disable_capabilities", " ".join(  # none modelled here
            f"move_group/{name}" for name in (
                "MoveGroupCartesianPathService", "MoveGroupKinematicsService",
                "MoveGroupExecuteTrajectoryAction", "MoveGroupMoveAction",
                "MoveGroupPickPlaceAction", "MoveGroupPlanService",
                "MoveGroupQueryPlannersService", "MoveGroupStateValidationService",
                "MoveGroupGetPlanningSceneService", "ApplyPlanningSceneService",
                "ClearOctomapService"))), *params])
    attacher = Attacher(Library(_models(tmp_path), shipped=None), "noetic", [])
    config = Configuration("c")
    workspace = Workspace(root=str(tmp_path))
    nodes = attacher.nodes_for(launch, workspace, {}, {}, config.diagnostics)
    build(config, launch, workspace, nodes, attacher.plugin_models(launch, {}))
    return config


def _readers(config: Configuration, name: str) -> list[str]:
    return sorted(link.node.name for link in config.links
                  if link.kind == "read" and link.resource.name == name)


_OWN_PIPELINE = [
    ParamDecl("/move_group/planning_plugin", "ompl_interface/OMPLPlanner", location=WHERE),
    ParamDecl("/move_group/request_adapters",
              " default_planner_request_adapters/FixStartStateBounds\n", location=WHERE),
    ParamDecl("/move_group/start_state_max_bounds_error", 0.1, location=WHERE),
    ParamDecl("/robot_description_kinematics/manipulator/kinematics_solver",
              "kdl_kinematics_plugin/KDLKinematicsPlugin", location=WHERE),
    ParamDecl("/move_group/moveit_controller_manager",
              "moveit_simple_controller_manager/MoveItSimpleControllerManager",
              location=WHERE),
]


def test_move_group_pipeline_of_its_own_namespace_kinematics_and_controller_manager(
        tmp_path):
    """Without ``~planning_pipelines`` the pipeline is on ``~`` (move_group.cpp:263-269):
    the planner and each adapter of the string read there; the group's solver, found
    at ``/robot_description_kinematics`` by ``searchParam``, reads under the group; every
    class is modelled, so move_group is not partial and a parameter nobody reads is
    decidedly so."""
    config = _configure(tmp_path, [
        *_OWN_PIPELINE, ParamDecl("/move_group/start_state_max_bound_error", 0.1)])
    assert not [d for d in config.diagnostics if d.code.startswith("PLUGIN")]
    instance = config.node("/move_group")
    assert instance.completeness == "model", instance.completeness_reasons
    assert _readers(config, "/move_group/start_state_max_bounds_error") == ["/move_group"]
    assert _readers(config, "/move_group/planner_configs/?") == ["/move_group"]
    # the planner's unknown parts are groups, not a plugin name
    assert _readers(config, "/move_group/?/default_planner_config") == ["/move_group"]
    assert _readers(config, "/move_group/manipulator/epsilon") == ["/move_group"]
    assert _readers(config, "/move_group/controller_list") == ["/move_group"]
    assert _readers(config, "/robot_description_kinematics/manipulator/"
                            "kinematics_solver") == ["/move_group"]
    assert _readers(config, "/move_group/start_state_max_bound_error") == []


def test_move_group_pipelines_by_name(tmp_path):
    """``~planning_pipelines/<name>/planning_plugin`` makes a pipeline in that namespace
    (moveit_cpp.cpp:141) and the one of ``~`` is not made."""
    config = _configure(tmp_path, [
        ParamDecl("/move_group/planning_pipelines/ompl/planning_plugin",
                  "ompl_interface/OMPLPlanner", location=WHERE),
        ParamDecl("/move_group/planning_pipelines/ompl/request_adapters",
                  "default_planner_request_adapters/FixStartStateBounds", location=WHERE),
        ParamDecl("/move_group/planning_plugin", "nobody/Planner", location=WHERE)])
    assert not [d for d in config.diagnostics if d.code.startswith("PLUGIN")]
    assert _readers(config, "/move_group/planning_pipelines/ompl/planner_configs/?") == [
        "/move_group"]
    assert _readers(config, "/move_group/planning_pipelines/ompl/"
                            "start_state_max_bounds_error") == ["/move_group"]
    assert _readers(config, "/move_group/planning_pipelines/ompl/?/"
                            "default_planner_config") == ["/move_group"]
    assert _readers(config, "/move_group/planner_configs/?") == []


def test_move_group_octomap_updaters_are_the_sensors_entries_with_a_class(tmp_path):
    """``~sensors`` entries without ``sensor_plugin``, or with an empty one or one
    starting with ``~``, load nothing (occupancy_map_monitor.cpp:113-130: the Setup
    Assistant writes ``sensors: [{}]``); another class is loaded, here not found."""
    config = _configure(tmp_path, [*_OWN_PIPELINE, ParamDecl(
        "/move_group/sensors", [{}, {"sensor_plugin": ""}, {"sensor_plugin": "~x/Y"}, 3],
        location=WHERE)])
    assert not [d for d in config.diagnostics if d.code.startswith("PLUGIN")]
    assert config.node("/move_group").completeness == "model"
    other = tmp_path / "other"
    other.mkdir()
    config = _configure(other, [*_OWN_PIPELINE, ParamDecl(
        "/move_group/sensors", [{}, {"sensor_plugin": "vendor/Updater"}], location=WHERE)])
    assert [d.message.split()[2] for d in config.diagnostics
            if d.code == "PLUGIN_NOT_FOUND"] == ["vendor/Updater"]


def test_move_group_planner_nobody_models_leaves_it_partial(tmp_path):
    """An unmodelled planner class (CHOMP here) is not found: move_group stays partial
    with that reason, so its unread parameters stay undecided."""
    config = _configure(tmp_path, [
        ParamDecl("/move_group/planning_plugin", "chomp_interface/CHOMPPlanner",
                  location=WHERE), *_OWN_PIPELINE[1:]])
    assert [d.code for d in config.diagnostics if d.code.startswith("PLUGIN")] == [
        "PLUGIN_NOT_FOUND"]
    instance = config.node("/move_group")
    assert instance.completeness == "partial"
    assert any("chomp_interface/CHOMPPlanner" in r for r in instance.completeness_reasons)


def test_move_group_without_a_planner_parameter_takes_an_installed_one(tmp_path):
    """Neither ``~planning_plugin`` nor pipelines: MoveIt takes the first planner class
    installed (planning_pipeline.cpp:101-112), unknown here: partial, not empty."""
    config = _configure(tmp_path, _OWN_PIPELINE[1:])
    assert config.node("/move_group").completeness == "partial"
    assert [d.code for d in config.diagnostics if d.code.startswith("PLUGIN")] == [
        "PLUGIN_CLASS_UNKNOWN"]


# -- with the shipped models of MoveIt noetic ---------------------------------------------

MOVE_GROUP_LAUNCH = """
<launch>
  <param name="robot_description_kinematics/manipulator/kinematics_solver"
         value="kdl_kinematics_plugin/KDLKinematicsPlugin"/>
  <group ns="move_group">
    <param name="planning_plugin" value="PLANNER"/>
    <param name="request_adapters" value="default_planner_request_adapters/AddTimeParameterization
        default_planner_request_adapters/FixStartStateBounds"/>
    <param name="start_state_max_bounds_error" value="0.1"/>
    <param name="moveit_controller_manager"
           value="moveit_simple_controller_manager/MoveItSimpleControllerManager"/>
    <param name="trajectory_execution/allowed_goal_duration_margin" value="0.5"/>
    <param name="allowed_execution_duration_scaling" value="1.2"/>
    <param name="octomap_resolution" value="0.025"/>
    <rosparam param="sensors">[{}]</rosparam>
    <rosparam param="controller_list">[]</rosparam>
    <param name="max_safe_path_cost" value="1"/>
  </group>
  <node name="move_group" pkg="moveit_ros_move_group" type="move_group"/>
</launch>
"""


def _check(write_tree: Any, planner: str) -> tuple[Any, dict[str, list[tuple[str, ...]]]]:
    root = write_tree({
        "src/arm_moveit_config/package.xml": package_xml("arm_moveit_config"),
        "src/arm_moveit_config/launch/move_group.launch":
            MOVE_GROUP_LAUNCH.replace("PLANNER", planner),
        "project.yaml": "project: p\ndistro: noetic\nworkspace: src\nconfigurations:\n"
                        "  c: [arm_moveit_config/launch/move_group.launch]\n",
    })
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    found: dict[str, list[tuple[str, ...]]] = {}
    for finding in run_catalogue(model, project):
        found.setdefault(finding.rule, []).append(finding.entities)
    instance = next(n for n in model.configurations[0].nodes if n.name == "/move_group")
    return instance, found


SCALING = ("parameter:/move_group/allowed_execution_duration_scaling",)


def test_shipped_models_find_a_trajectory_execution_parameter_set_at_the_top(write_tree):
    """ROBUST universal_robot 778c1ac's mistake: the trajectory execution manager reads
    ``~trajectory_execution/allowed_execution_duration_scaling``; with OMPL, the default
    adapters, KDL and the simple controller manager all modelled, the one set at the top
    of move_group's namespace is decidedly never read."""
    instance, found = _check(write_tree, "ompl_interface/OMPLPlanner")
    assert instance.completeness == "model", instance.completeness_reasons
    assert SCALING in found.get("parameter-set-not-read", [])
    unread = {e for e in found.get("parameter-set-not-read", []) if e[0].startswith(
        "parameter:/move_group/")}
    # the pipeline's, the adapters', the manager's and the octomap monitor's are read;
    # max_safe_path_cost too is read under sense_for_plan/ (plan_with_sensing.cpp:53-62)
    assert unread == {SCALING, ("parameter:/move_group/max_safe_path_cost",)}
    # KDL's reads have lookupParam's default: none is read but never set
    assert not found.get("parameter-read-not-set")


def test_shipped_models_leave_move_group_undecided_with_an_unmodelled_planner(write_tree):
    instance, found = _check(write_tree, "chomp_interface/CHOMPPlanner")
    assert instance.completeness == "partial"
    assert SCALING not in found.get("parameter-set-not-read", [])
    assert ("node:/move_group",) in found.get("parameter-set-not-read" + UNDECIDED, [])
