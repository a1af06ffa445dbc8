"""A ROS 1 controller whose manager no instance of the configuration is (the manager
lives in Gazebo, or in a hardware node) is a node instance of its own, standing for its
part of a process not seen. squirrel_robotino's simulation configurations set each
controller's ``required_drive_mode`` (robotino_controller_configuration_gazebo/
controller/base_controller_8dof.yaml:18), which Care-O-bot's
hwi_switch_gazebo_ros_control, the Gazebo plugin that runs the manager, reads: Gazebo is
of unknown interface for that plugin, but the parameter was the controller instance's
alone, of known interface, so "set but never read" (11 warnings). Now the nodes of
partial or unknown interface (one may be the process the controller runs in) and the
includes not read leave it undecided; with none of them there is no manager at all,
and the finding stays."""

from __future__ import annotations

from typing import Any

from haros_arch.model.load import from_data
from haros_arch.model.runtime import NodeInstance
from haros_arch.model.serialise import to_data
from haros_arch.query import run_catalogue
from tests.test_ros1_controller_root_handle import _model

LAUNCH = """<launch>
  {sim}
  <group ns="arm">
    <param name="pose/type" value="quad/PoseController"/>
    <param name="pose/required_drive_mode" value="3"/>
    <node name="spawner" pkg="controller_manager" type="spawner" args="pose"/>
  </group>
</launch>
"""

SIM = '<node name="sim" pkg="vendor_sim" type="sim_node"/>'

DRIVE_MODE = "/arm/pose/required_drive_mode"


def _findings(write_tree: Any, sim: str) -> tuple[Any, list[Any]]:
    model = _model(write_tree, LAUNCH.format(sim=sim))
    return model.configurations[0], run_catalogue(model)


def test_a_node_that_may_host_the_controller_leaves_its_parameters_undecided(
        write_tree: Any) -> None:
    config, findings = _findings(write_tree, SIM)
    assert not [f.message for f in findings if f.rule == "parameter-set-not-read"]
    pose = config.node("/arm/pose")
    assert pose is not None and pose.is_complete and pose.host_unseen
    assert config.node("/sim").completeness == "unknown"
    (undecided,) = [f for f in findings if f.rule == "parameter-set-not-read-undecided"]
    assert DRIVE_MODE in undecided.message and "/sim (1)" in undecided.message


def test_with_no_manager_anywhere_the_parameter_is_unread(write_tree: Any) -> None:
    # the guard: no node that may run the manager, no include not read
    config, findings = _findings(write_tree, "")
    assert config.node("/arm/pose").host_unseen
    unread = [f.message.split(" is set")[0] for f in findings
              if f.rule == "parameter-set-not-read"]
    assert unread == [DRIVE_MODE]


def test_a_node_of_the_controllers_name_does_not_take_its_parameters(
        write_tree: Any) -> None:
    # squirrel_robotino's shell_controller.launch:10,14 spawns door_controller into
    # Gazebo's manager and starts a door_controller.py node of that name beside it
    launch = LAUNCH.format(sim=SIM).replace(
        '<node name="spawner"',
        '<node name="pose" pkg="quad" type="base_node"/>\n    <node name="spawner"')
    model = _model(write_tree, launch)
    findings = run_catalogue(model)
    assert not [f.message for f in findings if f.rule == "parameter-set-not-read"]


def test_the_mark_is_kept_in_saved_models(write_tree: Any) -> None:
    model = _model(write_tree, LAUNCH.format(sim=SIM))
    again = from_data(to_data(model)).configurations[0]
    assert again.node("/arm/pose").host_unseen and not again.node("/sim").host_unseen
    assert "host_unseen" not in to_data(NodeInstance("/c"))
