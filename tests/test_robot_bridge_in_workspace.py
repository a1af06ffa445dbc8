"""A ros_gz bridge whose source is in the workspace (ros_gz itself): parameter_bridge's
code makes its ROS topics from argv and its config file at run time, in factories
generated at build time, so its source gives none. Its instances get the topics of their
arguments and config file, as an instance of its interface model does (ros_gz jazzy's
ros_gz_sim_demos: a remap of a bridged topic was reported unused, remap-unused)."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

BRIDGE_CPP = """
    #include <memory>
    #include "rclcpp/rclcpp.hpp"

    int main(int argc, char * argv[])
    {
      rclcpp::init(argc, argv);
      auto node = std::make_shared<rclcpp::Node>("ros_gz_bridge");
      node->declare_parameter<std::string>("config_file", "");
      rclcpp::spin(node);
      return 0;
    }
    """

LAUNCH = """
    from launch import LaunchDescription
    from launch_ros.actions import Node

    def generate_launch_description():
        return LaunchDescription([
            Node(package='ros_gz_bridge', executable='parameter_bridge',
                 arguments=['/model/v/pose@tf2_msgs/msg/TFMessage[gz.msgs.Pose_V',
                            '/cmd@geometry_msgs/msg/Twist]gz.msgs.Twist'],
                 remappings=[('/model/v/pose', '/tf')]),
            Node(package='ros_gz_bridge', executable='parameter_bridge', name='other',
                 parameters=[{'config_file': '/nowhere/bridge.yaml'}]),
        ])
    """


def test_a_workspace_parameter_bridge_gets_the_topics_of_its_arguments(write_tree):
    root = write_tree({
        "src/ros_gz_bridge/package.xml": package_xml("ros_gz_bridge", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend></package>"),
        "src/ros_gz_bridge/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.5)
            project(ros_gz_bridge)
            find_package(rclcpp REQUIRED)
            add_executable(parameter_bridge src/parameter_bridge.cpp)
            ament_target_dependencies(parameter_bridge rclcpp)
            install(TARGETS parameter_bridge DESTINATION lib/${PROJECT_NAME})
            """,
        "src/ros_gz_bridge/src/parameter_bridge.cpp": BRIDGE_CPP,
        "src/demo/package.xml": package_xml("demo", "ament_cmake").replace(
            "</package>", "<exec_depend>ros_gz_bridge</exec_depend></package>"),
        "src/demo/CMakeLists.txt": "project(demo)\n",
        "src/demo/launch/bridge.launch.py": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [demo/launch/bridge.launch.py]\n",
    })
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    config = model.configurations[0]
    made = sorted((link.node.name, link.kind, link.resource.name) for link in config.links
                  if link.kind in ("publish", "subscribe"))
    assert made == [("/ros_gz_bridge", "publish", "/tf"),
                    ("/ros_gz_bridge", "subscribe", "/cmd")]
    bridge = config.node("/ros_gz_bridge")
    assert bridge.node is not None and bridge.node.model is None  # the workspace's source
    assert bridge.completeness == "complete"
    # a config file that cannot be read leaves its instance partial, not the other
    other = config.node("/other")
    assert other.completeness == "partial"
    rules = {f.rule for f in run_catalogue(model, project)}
    assert "remap-unused" not in rules
