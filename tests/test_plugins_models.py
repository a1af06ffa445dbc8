"""Plugin classes of packages without source come from their interface models."""

from __future__ import annotations

import json
from pathlib import Path

from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Location
from haros_arch.model.source import Package
from haros_arch.models.attach import Attacher
from haros_arch.models.generate import build_package, read_list, tasks
from haros_arch.models.library import Library
from haros_arch.workspace import Workspace


def _model(path: Path, package: str, nodes: list[dict], distro: str = "jazzy") -> str:
    path.write_text(json.dumps({"schema": "haros-arch-model/1", "package": package,
                                "distro": distro, "nodes": nodes}))
    return str(path)


def _read(name: str, line: int) -> dict:
    return {"kind": "read", "name": name, "type": "double",
            "location": {"package": "p", "file": "p/src/a.cpp", "line": line, "column": 1}}


def _configure(tmp_path: Path, workspace: Workspace):
    files = [
        _model(tmp_path / "planner.json", "nav2_planner", [
            {"package": "nav2_planner", "executable": "planner_server",
             "calls": [{"kind": "publish", "name": "plan", "type": "nav_msgs/msg/Path"}]}]),
        _model(tmp_path / "navfn.json", "nav2_navfn_planner", [
            {"package": "nav2_navfn_planner", "executable": "nav2_navfn_planner::NavfnPlanner",
             "kind": "plugin", "plugin_class": "nav2_navfn_planner::NavfnPlanner",
             "calls": [_read("?.tolerance", 3)]}]),
        _model(tmp_path / "smac.json", "smac", [
            {"package": "smac", "executable": "smac/Smac", "kind": "plugin",
             "plugin_class": "smac::Smac", "calls": [_read("?.smoothing", 4)]}]),
    ]
    decl = NodeDecl("/planner_server", "nav2_planner", "planner_server", ros_version=2)
    where = Location("b", "b/launch/x.launch", 5, 0)
    launch = LaunchModel(nodes=[decl], params=[
        ParamDecl("/planner_server/planner_plugins", ["GridBased", "S"], location=where),
        ParamDecl("/planner_server/GridBased.plugin", "nav2_navfn_planner::NavfnPlanner"),
        ParamDecl("/planner_server/S.plugin", "smac/Smac", location=where)])
    packages: list[Package] = []
    attacher = Attacher(Library(files, shipped=None), "jazzy", packages)
    config = Configuration("c")
    nodes = attacher.nodes_for(launch, workspace, {}, {}, config.diagnostics)
    build(config, launch, workspace, nodes, attacher.plugin_models(launch, {}))
    return config, packages


def _links(config) -> list[tuple[str, str]]:
    return sorted((link.kind, link.resource.name) for link in config.links
                  if link.origin != "plugin")


def test_a_modelled_host_gets_the_modelled_classes_of_packages_without_source(tmp_path):
    config, packages = _configure(tmp_path, Workspace(root=str(tmp_path)))
    assert _links(config) == [("publish", "/plan"),
                              ("read", "/planner_server/GridBased.tolerance"),
                              ("read", "/planner_server/S.smoothing")]
    assert not [d for d in config.diagnostics if d.code.startswith("PLUGIN")
                and "costmap" not in d.message]  # no model of nav2_costmap_2d here
    instance = config.node("/planner_server")
    assert instance.completeness == "model"
    # the modelled plugin nodes are listed under their packages, as modelled hosts are
    assert sorted(n.name for p in packages for n in p.nodes) == [
        "nav2_navfn_planner/nav2_navfn_planner::NavfnPlanner", "nav2_planner/planner_server",
        "smac/smac/Smac"]


def test_a_class_whose_package_has_source_is_not_taken_from_a_model(tmp_path):
    workspace = Workspace(root=str(tmp_path))
    workspace.packages["smac"] = Package("smac", str(tmp_path / "smac"))
    config, _ = _configure(tmp_path, workspace)
    assert ("read", "/planner_server/S.smoothing") not in _links(config)
    (found,) = [d for d in config.diagnostics if d.code.startswith("PLUGIN")
                and "costmap" not in d.message]
    assert (found.code, found.location.line) == ("PLUGIN_NOT_FOUND", 5)
    assert config.node("/planner_server").completeness == "partial"


def test_a_modelled_ros1_host_gets_a_plugin_from_a_generated_model(tmp_path):
    """`models build` makes a move_base planner plugin node from its package's export,
    and a modelled move_base (no source) gets that generated plugin's calls."""
    fixture = Path(__file__).resolve().parent.parent / "fixtures/models/plugin_generate"
    (task,) = tasks(read_list(str(fixture / "list.yaml")), str(fixture / "sources"),
                    str(tmp_path / "no-overrides"), cache_dir=None)
    outcome = build_package(task)
    assert outcome.problem is None and outcome.text is not None
    (plugin,) = json.loads(outcome.text)["nodes"]
    assert (plugin["kind"], plugin["plugin_class"], plugin["plugin_base"]) == (
        "plugin", "tiny_planner::TinyPlanner", "nav_core::BaseGlobalPlanner")
    (tmp_path / "tiny_planner.json").write_text(outcome.text)
    host = _model(tmp_path / "move_base.json", "move_base", [
        {"package": "move_base", "executable": "move_base",
         "calls": [{"kind": "subscribe", "name": "~goal",
                    "type": "geometry_msgs/PoseStamped"}]}], "noetic")
    decl = NodeDecl("/move_base", "move_base", "move_base", ros_version=1)
    launch = LaunchModel(nodes=[decl], params=[
        ParamDecl("/move_base/base_global_planner", "tiny_planner/TinyPlanner")])
    attacher = Attacher(Library([host, str(tmp_path / "tiny_planner.json")], shipped=None),
                        "noetic", [])
    config = Configuration("c")
    workspace = Workspace(root=str(tmp_path))
    nodes = attacher.nodes_for(launch, workspace, {}, {}, config.diagnostics)
    build(config, launch, workspace, nodes, attacher.plugin_models(launch, {}))
    links = {(link.kind, link.resource.name) for link in config.links}
    assert {("publish", "/move_base/TinyPlanner/plan"),
            ("read", "/move_base/TinyPlanner/step_size")} <= links


def test_a_partial_plugin_makes_its_modelled_host_instance_partial(tmp_path):
    """A plugin whose calls are made on the host and whose interface is partial leaves
    the host instance partial, even when the host is a complete model."""
    files = [
        _model(tmp_path / "move_base.json", "move_base", [
            {"package": "move_base", "executable": "move_base", "calls": []}], "noetic"),
        _model(tmp_path / "layer.json", "layer", [
            {"package": "layer", "executable": "layer/Layer", "kind": "plugin",
             "plugin_class": "layer::Layer", "completeness": "partial",
             "completeness_reasons": ["layer/src/l.cpp:9: C++ error"],
             "calls": [_read("~?/gain", 3)]}], "noetic"),
    ]
    decl = NodeDecl("/move_base", "move_base", "move_base", ros_version=1)
    launch = LaunchModel(nodes=[decl], params=[
        ParamDecl("/move_base/base_global_planner", "layer/Layer")])
    attacher = Attacher(Library(files, shipped=None), "noetic", [])
    config = Configuration("c")
    workspace = Workspace(root=str(tmp_path))
    nodes = attacher.nodes_for(launch, workspace, {}, {}, config.diagnostics)
    build(config, launch, workspace, nodes, attacher.plugin_models(launch, {}))
    instance = config.node("/move_base")
    assert instance.completeness == "partial"
    assert any("layer/Layer" in r and "l.cpp:9" in r for r in instance.completeness_reasons)
    assert nodes["move_base/move_base"].completeness != "partial"  # the shared model is not


def test_modelled_move_group_gets_capabilities_named_by_another_prefix(tmp_path):
    # MoveIt's capabilities are move_group/<Name>, exported by moveit_ros_move_group
    model = _model(tmp_path / "move_group.json", "moveit_ros_move_group", [
        {"package": "moveit_ros_move_group", "executable": "move_group",
         "calls": [{"kind": "read", "name": "capabilities", "type": "str"}]},
        {"package": "moveit_ros_move_group", "executable": "move_group/MoveGroupPlanService",
         "kind": "plugin", "plugin_class": "move_group::MoveGroupPlanService",
         "calls": [{"kind": "server", "name": "plan_kinematic_path",
                    "type": "moveit_msgs/srv/GetMotionPlan"}]}])
    decl = NodeDecl("/move_group", "moveit_ros_move_group", "move_group", ros_version=2)
    launch = LaunchModel(nodes=[decl], params=[
        ParamDecl("/move_group/disable_capabilities", " ".join(
            f"move_group/{name}" for name in (
                "LoadGeometryFromFileService", "SaveGeometryToFileService", "GetUrdfService",
                "MoveGroupCartesianPathService", "MoveGroupKinematicsService",
                "MoveGroupExecuteTrajectoryAction", "MoveGroupMoveAction",
                "MoveGroupQueryPlannersService", "MoveGroupStateValidationService",
                "MoveGroupGetPlanningSceneService", "ApplyPlanningSceneService",
                "ClearOctomapService")))])
    attacher = Attacher(Library([model], shipped=None), "jazzy", [])
    config = Configuration("c")
    workspace = Workspace(root=str(tmp_path))
    nodes = attacher.nodes_for(launch, workspace, {}, {}, config.diagnostics)
    build(config, launch, workspace, nodes, attacher.plugin_models(launch, {}))
    assert ("server", "/plan_kinematic_path") in _links(config)
    assert not [d for d in config.diagnostics if d.code.startswith("PLUGIN")]
    assert config.node("/move_group").completeness == "model"


def test_ros1_move_group_hosts_its_capabilities_from_two_packages(tmp_path):
    """MoveIt 1's move_group loads its default capabilities, those its ``~capabilities``
    string adds, less ``~disable_capabilities``; its default pick and place capability
    (``move_group/MoveGroupPickPlaceAction``) is moveit_ros_manipulation's, found
    through the ``move_group`` prefix too."""
    def capability(package: str, name: str, kind: str, topic: str, type_: str) -> dict:
        return {"package": package, "executable": f"move_group/{name}", "kind": "plugin",
                "plugin_class": f"move_group::{name}",
                "calls": [{"kind": kind, "name": topic, "type": type_}]}
    group = "moveit_ros_move_group"
    move_group = _model(tmp_path / "move_group.json", group, [
        {"package": group, "executable": "move_group",
         "calls": [{"kind": "read", "name": "~capabilities", "type": "str"}]},
        capability(group, "MoveGroupMoveAction", "action-server", "move_group",
                   "moveit_msgs/MoveGroup"),
        capability(group, "MoveGroupPlanService", "server", "plan_kinematic_path",
                   "moveit_msgs/GetMotionPlan"),
        capability(group, "Extra", "server", "extra", "std_srvs/Empty")], distro="noetic")
    manipulation = _model(tmp_path / "manipulation.json", "moveit_ros_manipulation", [
        capability("moveit_ros_manipulation", "MoveGroupPickPlaceAction", "action-server",
                   "pickup", "moveit_msgs/Pickup")], distro="noetic")
    decl = NodeDecl("/move_group", group, "move_group", ros_version=1)
    launch = LaunchModel(nodes=[decl], params=[
        ParamDecl("/move_group/capabilities", "move_group/Extra"),
        ParamDecl("/move_group/disable_capabilities", "move_group/MoveGroupPlanService")])
    attacher = Attacher(Library([move_group, manipulation], shipped=None), "noetic", [])
    config = Configuration("c")
    workspace = Workspace(root=str(tmp_path))
    nodes = attacher.nodes_for(launch, workspace, {}, {}, config.diagnostics)
    build(config, launch, workspace, nodes, attacher.plugin_models(launch, {}))
    links = _links(config)
    assert ("action-server", "/move_group") in links
    assert ("action-server", "/pickup") in links
    assert ("server", "/extra") in links
    assert ("server", "/plan_kinematic_path") not in links
    # the defaults no model holds here (kinematics, cartesian path, ...) are not found
    missing = {d.message.split()[2] for d in config.diagnostics
               if d.code == "PLUGIN_NOT_FOUND"}
    assert "move_group/MoveGroupPickPlaceAction" not in missing
    assert "move_group/MoveGroupKinematicsService" in missing


def test_gripper_action_controllers_come_from_the_packages_that_export_them(tmp_path):
    """``position_controllers/GripperActionController`` (and the effort one) is
    gripper_controllers', ``parallel_gripper_action_controller/GripperActionController``
    parallel_gripper_controller's: their prefixes name no package, so the shipped models
    are found through the packages that export them (Kinova's gen3_lite loads the first
    and was left unknown)."""
    attacher = Attacher(Library(), "jazzy", [])
    find = attacher.plugin_models(LaunchModel(), {})
    for cls, package in (
            ("position_controllers/GripperActionController", "gripper_controllers"),
            ("effort_controllers/GripperActionController", "gripper_controllers"),
            ("parallel_gripper_action_controller/GripperActionController",
             "parallel_gripper_controller")):
        node = find(cls)
        assert node is not None, cls
        assert (node.package, node.executable) == (package, cls)
        assert ("action-server", "~gripper_cmd") in {(c.kind, c.name) for c in node.calls}
