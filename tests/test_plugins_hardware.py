"""ros2_control hardware plugins: a controller manager (ros2_control_node) loads the class
of each ``<ros2_control><hardware><plugin>`` of the robot description it reads; what that
code does with ROS happens in the manager's process (xarm_ros2's UFRobotSystemHardware
makes the node ``ufactory_driver``, whose driver publishes ``<hw_ns>/joint_states``)."""

from __future__ import annotations

from pathlib import Path

import pytest

from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Location, Node, PrimitiveCall
from haros_arch.models.attach import Attacher
from haros_arch.models.library import Library
from haros_arch.plugins.classes import narrow
from haros_arch.robot.attach import param_get_command
from haros_arch.workspace import Workspace

DESCRIPTION = """<?xml version="1.0"?>
<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="sim" default="false"/>
  <link name="base"/>
  <ros2_control name="Arm" type="system">
    <hardware><plugin>arm_hw/ArmSystem</plugin></hardware>
    <joint name="j1"/>
  </ros2_control>
  <xacro:if value="$(arg sim)">
    <ros2_control name="Gripper" type="system">
      <hardware><plugin>arm_hw/QuietGripper</plugin></hardware>
    </ros2_control>
  </xacro:if>
  <ros2_control name="Mock" type="system">
    <hardware><plugin>mock_components/GenericSystem</plugin></hardware>
  </ros2_control>
</robot>
"""


def call(kind, name, type_=None, line=1):
    return PrimitiveCall(kind, name, type_, 10,
                         location=Location("arm_hw", "arm_hw/src/arm.cpp", line, 3))


def hardware_nodes() -> list[Node]:
    # the class whose code makes a node of its own (``Node::make_shared("arm_driver")``)
    # and one whose calls are made on no node it names
    arm = Node("arm_hw", "arm_hw/ArmSystem", "plugin", rosname="arm_driver",
               calls=[call("publish", "arm/joint_states", "sensor_msgs/msg/JointState"),
                      call("read", "hw_ns", "str", 2)],
               plugin_class="arm_hw::ArmSystem",
               plugin_base="hardware_interface::SystemInterface")
    quiet = Node("arm_hw", "arm_hw/QuietGripper", "plugin",
                 calls=[call("publish", "gripper_status", "std_msgs/msg/String", 3)],
                 plugin_class="arm_hw::QuietGripper",
                 plugin_base="hardware_interface::SystemInterface")
    return [arm, quiet]


def configure(tmp_path: Path, decls: list[NodeDecl], params: list[ParamDecl],
              with_models: bool = True, distro: str = "jazzy") -> Configuration:
    (tmp_path / "arm_hw").mkdir(exist_ok=True)
    (tmp_path / "arm_hw" / "package.xml").write_text(
        "<package format='3'><name>arm_hw</name><version>0.1.0</version></package>")
    launch = LaunchModel(nodes=decls, params=params)
    workspace = Workspace(root=str(tmp_path))
    workspace.packages = {}
    config = Configuration("c")
    attacher = Attacher(Library([]), distro, [])
    nodes = {n.name: n for n in hardware_nodes()}
    nodes = attacher.nodes_for(launch, workspace, nodes, {}, config.diagnostics)
    build(config, launch, workspace, nodes,
          attacher.plugin_models(launch, {}) if with_models else None)
    return config


def manager(name: str = "/controller_manager", **more) -> NodeDecl:
    return NodeDecl(name, "controller_manager", "ros2_control_node", ros_version=2,
                    location=Location("bringup", "bringup/launch/arm.launch.py", 7, 4),
                    **more)


def links_of(config: Configuration, node: str) -> list[tuple[str, str]]:
    return sorted((link.kind, link.resource.name) for link in config.links
                  if link.node.name == node and link.origin != "model")


def test_the_hardware_of_the_description_a_manager_reads_makes_its_calls(tmp_path):
    urdf = tmp_path / "arm.urdf.xacro"
    urdf.write_text(DESCRIPTION)
    where = Location("bringup", "bringup/launch/arm.launch.py", 9, 4)
    config = configure(tmp_path, [manager()], [ParamDecl(
        "/controller_manager/robot_description", "?", location=where,
        command=f"xacro {urdf} sim:=true")])
    by_name = {n.name: n for n in config.nodes}
    # before: the manager alone, of its model's interface, and nothing of its hardware
    assert sorted(by_name) == ["/arm_driver", "/controller_manager"]
    assert by_name["/arm_driver"].node is not None
    assert by_name["/arm_driver"].node.executable == "arm_hw/ArmSystem"
    assert links_of(config, "/arm_driver") == [("publish", "/arm/joint_states"),
                                                ("read", "/arm_driver/hw_ns")]
    # a class whose code names no node of its own: its calls are the manager's
    assert ("publish", "/gripper_status") in links_of(config, "/controller_manager")
    # the mock hardware comes from ros2_control's hardware_interface model: no ROS call,
    # and the manager's interface stays whole
    assert by_name["/controller_manager"].node.completeness != "partial"
    assert not [d for d in config.diagnostics if d.code in (
        "PLUGIN_NOT_FOUND", "PLUGIN_CLASS_UNKNOWN", "HARDWARE_UNKNOWN")]
    assert [r.name for r in config.robot_descriptions] == [
        "/controller_manager/robot_description"]


def test_a_system_under_a_xacro_condition_is_loaded_under_it(tmp_path):
    urdf = tmp_path / "arm.urdf.xacro"
    urdf.write_text(DESCRIPTION)
    config = configure(tmp_path, [manager()], [ParamDecl(
        "/controller_manager/robot_description", "?", command=f"xacro {urdf}")])
    # sim defaults to false: no gripper system, so none of its calls
    assert ("publish", "/gripper_status") not in links_of(config, "/controller_manager")
    assert links_of(config, "/arm_driver") == [("publish", "/arm/joint_states"),
                                                ("read", "/arm_driver/hw_ns")]


def test_the_description_robot_state_publisher_publishes_is_the_managers(tmp_path):
    """Jazzy: the manager reads the description from its subscription, which the launch
    file remaps to what robot_state_publisher publishes from its parameter."""
    urdf = tmp_path / "arm.urdf.xacro"
    urdf.write_text(DESCRIPTION)
    decls = [NodeDecl("/robot_state_publisher", "robot_state_publisher",
                      "robot_state_publisher", ros_version=2),
             manager(remaps=[("~/robot_description", "/robot_description")])]
    config = configure(tmp_path, decls, [ParamDecl(
        "/robot_state_publisher/robot_description", "?", command=f"xacro {urdf}",
        node="/robot_state_publisher", key="robot_description")])
    assert "/arm_driver" in {n.name for n in config.nodes}
    assert not [d for d in config.diagnostics if d.code == "HARDWARE_UNKNOWN"]


def test_humbles_manager_reads_the_description_of_its_private_topic(tmp_path):
    """Humble: the manager subscribes to ``~/robot_description`` (its model writes
    ``~robot_description``), which lbr_fri_ros2_stack remaps to ``robot_description``,
    what robot_state_publisher publishes: the last part of that name is the key too
    (it was ``HARDWARE_UNKNOWN`` and the manager partial), and the manager's own
    ``robot_description`` parameter, which the remap does not rename, is no other's."""
    urdf = tmp_path / "arm.urdf.xacro"
    urdf.write_text(DESCRIPTION)
    decls = [NodeDecl("/lbr/robot_state_publisher", "robot_state_publisher",
                      "robot_state_publisher", namespace="/lbr", ros_version=2),
             manager("/lbr/controller_manager", namespace="/lbr",
                     remaps=[("~/robot_description", "robot_description")])]
    config = configure(tmp_path, decls, [ParamDecl(
        "/lbr/robot_state_publisher/robot_description", "?", command=f"xacro {urdf}",
        node="/lbr/robot_state_publisher", key="robot_description")], distro="humble")
    assert "/lbr/arm_driver" in {n.name for n in config.nodes}
    assert not [d for d in config.diagnostics if d.code == "HARDWARE_UNKNOWN"]
    assert ("read", "/lbr/robot_description") not in links_of(config, "/lbr/controller_manager")


def test_a_description_copied_with_ros2_param_get_is_the_one_it_reads(tmp_path):
    """articubot_one (and the tutorials after it): the manager's ``robot_description`` is
    ``Command(['ros2 param get --hide-type /robot_state_publisher robot_description'])``,
    robot_state_publisher's parameter the xacro command gives; the hardware was not
    known (HARDWARE_UNKNOWN) and the manager partial."""
    urdf = tmp_path / "arm.urdf.xacro"
    urdf.write_text(DESCRIPTION)
    decls = [NodeDecl("/robot_state_publisher", "robot_state_publisher",
                      "robot_state_publisher", ros_version=2), manager()]
    config = configure(tmp_path, decls, [
        ParamDecl("/robot_state_publisher/robot_description", "?",
                  command=f"xacro {urdf} sim:=true", node="/robot_state_publisher",
                  key="robot_description"),
        ParamDecl("/controller_manager/robot_description", "?",
                  command="ros2 param get --hide-type robot_state_publisher "
                          "robot_description", node="/controller_manager",
                  key="robot_description")])
    assert links_of(config, "/arm_driver") == [("publish", "/arm/joint_states"),
                                                ("read", "/arm_driver/hw_ns")]
    assert ("publish", "/gripper_status") in links_of(config, "/controller_manager")
    assert not [d for d in config.diagnostics if d.code == "HARDWARE_UNKNOWN"]


@pytest.mark.parametrize(("command", "expected"), [
    ("ros2 param get --hide-type /robot_state_publisher robot_description",
     ("/robot_state_publisher", "robot_description")),
    ("/opt/ros/humble/bin/ros2 param get --spin-time 5 rsp robot_description",
     ("/rsp", "robot_description")),
    ("ros2 param get ?/rsp robot_description", None),
    ("ros2 param list /rsp", None),
    ("xacro robot.urdf.xacro", None),
])
def test_ros2_param_get_command_lines(command: str, expected: object):
    assert param_get_command(command) == expected


def test_a_manager_whose_description_is_not_known_is_partial(tmp_path):
    config = configure(tmp_path, [manager()], [ParamDecl(
        "/controller_manager/robot_description", "?")])
    found = [d for d in config.diagnostics if d.code == "HARDWARE_UNKNOWN"]
    assert [(d.location.file, d.location.line) for d in found] == [
        ("bringup/launch/arm.launch.py", 7)]
    host = next(n for n in config.nodes if n.name == "/controller_manager")
    assert host.node is not None and host.node.completeness == "partial"


def test_hardware_not_built_here_and_not_modelled_makes_the_manager_partial(tmp_path):
    urdf = tmp_path / "arm.urdf.xacro"
    urdf.write_text(DESCRIPTION.replace("mock_components/GenericSystem",
                                        "vendor_hw/VendorSystem"))
    config = configure(tmp_path, [manager()], [ParamDecl(
        "/controller_manager/robot_description", "?", command=f"xacro {urdf}")])
    assert [d.code for d in config.diagnostics if d.code.startswith("PLUGIN")] == [
        "PLUGIN_NOT_FOUND"]
    host = next(n for n in config.nodes if n.name == "/controller_manager")
    assert host.node is not None and host.node.completeness == "partial"


def test_an_export_macro_in_an_included_header_makes_the_source_the_classs(tmp_path):
    """xarm_controller writes PLUGINLIB_EXPORT_CLASS in uf_robot_system_hardware.h, which
    uf_robot_system_hardware.cpp includes; the library's other file exports its own."""
    package = tmp_path / "arm_hw"
    (package / "include" / "arm_hw").mkdir(parents=True)
    (package / "src").mkdir()
    (package / "package.xml").write_text("<package format='3'><name>arm_hw</name></package>")
    (package / "include" / "arm_hw" / "arm.h").write_text(
        "namespace arm_hw { class ArmSystem {}; }\n"
        "PLUGINLIB_EXPORT_CLASS(arm_hw::ArmSystem, hardware_interface::SystemInterface)\n")
    (package / "src" / "arm.cpp").write_text('#include "arm_hw/arm.h"\n')
    (package / "src" / "fake.cpp").write_text(
        "PLUGINLIB_EXPORT_CLASS(arm_hw::FakeSystem, hardware_interface::SystemInterface)\n")
    workspace = Workspace(root=str(tmp_path))
    sources = ["arm_hw/src/arm.cpp", "arm_hw/src/fake.cpp"]
    # before: none (the library exports another class and not this one)
    assert narrow(sources, "arm_hw::ArmSystem", workspace) == ["arm_hw/src/arm.cpp"]
    assert narrow(sources, "arm_hw::FakeSystem", workspace) == ["arm_hw/src/fake.cpp"]


MOCK = """<?xml version="1.0"?>
<robot name="rrbot"><link name="base"/>
  <ros2_control name="Rrbot" type="system">
    <hardware><plugin>mock_components/GenericSystem</plugin></hardware>
    <joint name="joint1"/>
  </ros2_control>
</robot>
"""


def test_a_remap_given_to_a_manager_whose_plugins_are_all_known_is_judged(tmp_path):
    """ros2_control_demos' example_15 (ec1ae61^) gives ros2_control_node in /rrbot the
    remap /forward_position_controller/commands:=/position_commands; its controller
    subscribes /rrbot/forward_position_controller/commands, so the remap changes nothing.
    The manager's model loads plugins, but the host row loaded each of them (hardware of
    its description, controllers its spawners name: nodes that take its remaps), so
    nothing unseen may use the name: remap-unused reports it. Before, a model of code
    that loads plugins always left it undecided."""
    urdf = tmp_path / "rrbot.urdf"
    urdf.write_text(MOCK)
    controllers = tmp_path / "controllers.yaml"
    controllers.write_text("/rrbot/forward_position_controller:\n  ros__parameters:\n"
                           "    type: forward_command_controller/ForwardCommandController\n"
                           "    joints: [joint1]\n    interface_name: position\n")

    def remap_of(source: str, kind: str = "forward_command_controller/"
                 "ForwardCommandController") -> tuple[list[str], list[str]]:
        controllers.write_text(controllers.read_text().replace(
            "forward_command_controller/ForwardCommandController", kind))
        decls = [manager("/rrbot/controller_manager", namespace="/rrbot/",
                         remaps=[(source, "/position_commands")]),
                 NodeDecl("/rrbot/spawner", "controller_manager", "spawner", "/rrbot/",
                          args=f"forward_position_controller --param-file {controllers}",
                          ros_version=2)]
        config = configure(tmp_path, decls, [ParamDecl(
            "/rrbot/controller_manager/robot_description", "?", command=f"xacro {urdf}")])
        (remap,) = config.remaps
        near.extend(remap.near)
        return [n.name for n in remap.users], [n.name for n in remap.unseen]

    near: list[str] = []
    assert remap_of("/forward_position_controller/commands") == ([], [])
    # the message names the controller's own topic, which the remap may have meant
    assert near == ["/rrbot/forward_position_controller/commands"]
    assert remap_of("forward_position_controller/commands") == (
        ["/rrbot/forward_position_controller"], [])
    # a controller whose class is found nowhere (a node of unknown interface in the
    # manager's process) may use the name unseen
    assert remap_of("/forward_position_controller/commands", kind="nowhere/Controller")[1] \
        == ["/rrbot/forward_position_controller"]
