"""ros_gz's launch actions: ``<ros_gz_bridge>``, ``<gz_server>``, ``<gz_spawn_model>`` in
XML launch files and ``RosGzBridge``, ``GzServer``, ``GzSpawnModel`` in Python ones each
include their package's launch file, which starts one node (the bridge's
``bridge_node`` named ``bridge_name`` with ``config_file``, ``gzserver``, ``create``).
They were an unknown tag and a call not interpreted: the nodes and the bridged topics
were missing from the graph."""

from __future__ import annotations

from typing import Any

from conftest import package_xml

from haros_arch.api import analyse_path
from haros_arch.pipeline import Options

BRIDGE_YAML = """
- ros_topic_name: "scan"
  gz_topic_name: "/lidar"
  ros_type_name: "sensor_msgs/msg/LaserScan"
  gz_type_name: "gz.msgs.LaserScan"
  direction: GZ_TO_ROS
- ros_topic_name: "cmd_vel"
  gz_topic_name: "/model/robot/cmd_vel"
  ros_type_name: "geometry_msgs/msg/Twist"
  gz_type_name: "gz.msgs.Twist"
  direction: ROS_TO_GZ
"""

XML = """
<launch>
  <gz_server world_sdf_file="empty.sdf"/>
  <ros_gz_bridge bridge_name="robot_bridge" namespace="robot" use_composition="False"
                 config_file="$(find-pkg-share demo)/config/bridge.yaml"/>
  <gz_spawn_model world="empty" topic="robot_description" entity_name="robot" z="0.1"/>
</launch>
"""

PYTHON = """
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare
from ros_gz_bridge.actions import RosGzBridge
from ros_gz_sim.actions import GzServer


def generate_launch_description():
    return LaunchDescription([
        GzServer(world_sdf_file='empty.sdf'),
        RosGzBridge(
            bridge_name='robot_bridge',
            config_file=PathJoinSubstitution([FindPackageShare('demo'), 'config',
                                              'bridge.yaml']),
            namespace='robot'),
    ])
"""


def _configurations(write_tree: Any) -> dict[str, Any]:
    root = write_tree({
        "demo/package.xml": package_xml("demo", "ament_cmake").replace(
            "</package>", "<exec_depend>ros_gz_bridge</exec_depend>"
            "<exec_depend>ros_gz_sim</exec_depend></package>"),
        "demo/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.8)\nproject(demo)\n"
            "find_package(ament_cmake REQUIRED)\n"
            "install(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})\n"
            "ament_package()\n"),
        "demo/config/bridge.yaml": BRIDGE_YAML,
        "demo/launch/sim.launch.xml": XML,
        "demo/launch/sim.launch.py": PYTHON})
    analysis = analyse_path(str(root), Options(cache_dir=None, jobs=1))
    assert analysis.model is not None
    return {config.launch[0].rsplit(".", 1)[-1]: config
            for config in analysis.model.configurations}


def test_ros_gz_actions_start_their_nodes_in_xml_and_python(write_tree) -> None:
    configs = _configurations(write_tree)
    assert set(configs) == {"xml", "py"}
    for kind, config in configs.items():
        nodes = {instance.name: instance.node.name if instance.node else None
                 for instance in config.nodes}
        assert nodes["/robot/robot_bridge"] == "ros_gz_bridge/bridge_node", kind
        assert nodes["/gzserver"] == "ros_gz_sim/gzserver", kind
        bridged = {(link.kind, link.resource.name, link.type) for link in config.links
                   if link.node.name == "/robot/robot_bridge"
                   and link.kind in ("publish", "subscribe")}
        assert bridged == {("publish", "/robot/scan", "sensor_msgs/msg/LaserScan"),
                           ("subscribe", "/robot/cmd_vel", "geometry_msgs/msg/Twist")}, kind
        assert not any(d.code in ("LAUNCH_UNKNOWN_TAG", "LAUNCH_PY_UNSUPPORTED")
                       for d in config.diagnostics), kind
    spawner = {(link.kind, link.resource.name) for link in configs["xml"].links
               if link.node.name == "/ros_gz_sim"}
    assert ("subscribe", "/robot_description") in spawner


def test_a_bridge_whose_config_file_is_not_read_leaves_absences_undecided(write_tree) -> None:
    """A modelled bridge (bridge_node, parameter_bridge: their models say complete, their
    topics come from the config file at run time) whose file cannot be read may bridge
    any topic: the instance is partial, not a bridge of nothing."""
    from haros_arch.pipeline import analyse
    from haros_arch.project import load
    from haros_arch.query import run_catalogue

    root = write_tree({
        "demo/package.xml": package_xml("demo", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend><depend>sensor_msgs</depend>"
            "<exec_depend>ros_gz_bridge</exec_depend></package>"),
        "demo/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.8)\nproject(demo)\n"
            "find_package(ament_cmake REQUIRED)\nadd_executable(listener src/listener.cpp)\n"
            "install(TARGETS listener DESTINATION lib/${PROJECT_NAME})\n"
            "install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})\n"
            "ament_package()\n"),
        "demo/src/listener.cpp": (
            "#include <memory>\n#include <rclcpp/rclcpp.hpp>\n"
            "#include <sensor_msgs/msg/laser_scan.hpp>\n"
            "int main(int argc, char** argv) {\n  rclcpp::init(argc, argv);\n"
            "  auto node = std::make_shared<rclcpp::Node>(\"listener\");\n"
            "  auto sub = node->create_subscription<sensor_msgs::msg::LaserScan>(\n"
            "      \"scan\", 10, [](sensor_msgs::msg::LaserScan::SharedPtr) {});\n"
            "  rclcpp::spin(node);\n}\n"),
        "demo/launch/sim.launch.xml": (
            "<launch>\n  <ros_gz_bridge bridge_name='bridge' config_file='missing.yaml'/>\n"
            "  <node pkg='demo' exec='listener' name='listener'/>\n</launch>\n"),
        "project.yaml": "project: p\nconfigurations:\n  c: [demo/launch/sim.launch.xml]\n"})
    project = load(str(root / "project.yaml"))
    model = analyse(project, {}, Options(cache_dir=None))
    (config,) = model.configurations
    bridge = next(n for n in config.nodes if n.name == "/bridge")
    assert bridge.completeness == "partial"
    rules = {finding.rule for finding in run_catalogue(model, project)}
    assert "subscriber-without-publisher" not in rules
    assert "subscriber-without-publisher-undecided" in rules
