"""Bring up the rover: the lidar filter in a container and the safety stop."""

import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import ComposableNodeContainer, Node
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    share = get_package_share_directory("demo_rover")
    params = os.path.join(share, "config", "rover.yaml")
    namespace = LaunchConfiguration("namespace")
    use_safety = LaunchConfiguration("use_safety")

    container = ComposableNodeContainer(
        name="rover_container",
        namespace=namespace,
        package="rclcpp_components",
        executable="component_container",
        composable_node_descriptions=[
            ComposableNode(
                package="demo_rover",
                plugin="demo_rover::LidarFilter",
                name="lidar_filter",
                namespace=namespace,
                parameters=[params],
                remappings=[("scan", "lidar/scan")],
            ),
        ],
    )
    safety = Node(
        package="demo_rover",
        executable="safety_stop.py",
        name="safety_stop",
        namespace=namespace,
        parameters=[params, {"stop_distance": 0.5}],
        condition=IfCondition(use_safety),
    )
    return LaunchDescription([
        DeclareLaunchArgument("namespace", default_value="rover"),
        DeclareLaunchArgument("use_safety", default_value="true"),
        container,
        safety,
    ])
