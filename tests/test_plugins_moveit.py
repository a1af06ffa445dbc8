"""MoveIt 1's move_group loads its planners, request adapters, kinematics solvers,
controller manager and octomap updaters by the parameters that name them."""

from __future__ import annotations

import json
from pathlib import Path

from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Location
from haros_arch.models.attach import Attacher
from haros_arch.models.library import Library
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
            "ompl_interface::OMPLPlannerManager", [_read("?/planner_configs", 2)])],
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
    assert _readers(config, "/move_group/planner_configs") == ["/move_group"]
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
    assert _readers(config, "/move_group/planning_pipelines/ompl/planner_configs") == [
        "/move_group"]
    assert _readers(config, "/move_group/planning_pipelines/ompl/"
                            "start_state_max_bounds_error") == ["/move_group"]
    assert _readers(config, "/move_group/planner_configs") == []


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
