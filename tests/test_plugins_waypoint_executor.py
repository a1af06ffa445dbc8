"""nav2's waypoint follower loads its task executors with
``ClassLoader<nav2_core::WaypointTaskExecutor>("nav2_waypoint_follower", ...)`` from Humble
to Jazzy, so their descriptions are exported under the tag ``nav2_waypoint_follower``
(its own plugins.xml: WaitAtWaypoint, PhotoAtWaypoint, InputAtWaypoint), ``nav2_core``
after. A description under the first tag was not read: no plugin node for its classes,
and a waypoint_follower choosing one got PLUGIN_NOT_FOUND with the source in the
workspace (interbotix_ros_rovers 0e4fa09 with navigation2 1.1.6)."""

from __future__ import annotations

from typing import Any

import pytest

PACKAGE = (
    "<package format='3'><name>my_wp</name><version>1.0.0</version>"
    "<description>d</description><maintainer email='a@b.c'>m</maintainer>"
    "<license>BSD</license><buildtool_depend>ament_cmake</buildtool_depend>"
    "<depend>rclcpp</depend><depend>pluginlib</depend><depend>nav2_core</depend>"
    "<export><build_type>ament_cmake</build_type>"
    "<TAG plugin='${prefix}/plugins.xml'/></export></package>")
CMAKE = ("cmake_minimum_required(VERSION 3.8)\nproject(my_wp)\n"
         "add_library(beep SHARED src/beep.cpp)\n")
DESCRIPTION = (
    "<class_libraries>\n<library path='beep'>\n"
    "  <class type='my_wp::Beep' base_class_type='nav2_core::WaypointTaskExecutor'/>\n"
    "</library>\n</class_libraries>\n")
SOURCE = (
    "#include <string>\n#include \"rclcpp/rclcpp.hpp\"\n"
    "#include \"pluginlib/class_list_macros.hpp\"\n"
    "#include \"nav2_core/waypoint_task_executor.hpp\"\n"
    "#include \"std_msgs/msg/string.hpp\"\n"
    "namespace my_wp {\nclass Beep : public nav2_core::WaypointTaskExecutor {\npublic:\n"
    "  void initialize(const rclcpp_lifecycle::LifecycleNode::WeakPtr & parent,\n"
    "                  const std::string & plugin_name) override {\n"
    "    auto node = parent.lock();\n"
    "    pub_ = node->create_publisher<std_msgs::msg::String>(\"beeps\", 1);\n  }\n"
    "  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;\n};\n}\n"
    "PLUGINLIB_EXPORT_CLASS(my_wp::Beep, nav2_core::WaypointTaskExecutor)\n")
LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node

def generate_launch_description():
    return LaunchDescription([
        Node(package='nav2_waypoint_follower', executable='waypoint_follower',
             name='waypoint_follower',
             parameters=[{'waypoint_task_executor_plugin': 'beeper',
                          'beeper.plugin': 'my_wp::Beep'}]),
    ])
"""


def _analyse(write_tree: Any, tag: str) -> Any:
    from haros_arch.pipeline import Options, analyse
    from haros_arch.project import load

    root = write_tree({
        "src/my_wp/package.xml": PACKAGE.replace("TAG", tag),
        "src/my_wp/CMakeLists.txt": CMAKE,
        "src/my_wp/plugins.xml": DESCRIPTION,
        "src/my_wp/src/beep.cpp": SOURCE,
        "src/my_wp/launch/wp.launch.py": LAUNCH,
        "project.yaml": "project: p\nworkspace: src\ndistro: humble\nconfigurations:\n"
                        "  c: [my_wp/launch/wp.launch.py]\n",
    })
    return analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None))


@pytest.mark.parametrize("tag", ["nav2_waypoint_follower", "nav2_core"])
def test_a_task_executor_of_either_export_tag_is_the_follower_s_plugin(
        write_tree: Any, tag: str) -> None:
    model = _analyse(write_tree, tag)
    assert [n.name for n in model.nodes if n.plugin_class == "my_wp::Beep"]
    assert "PLUGIN_NOT_FOUND" not in [d.code for c in model.configurations
                                      for d in c.diagnostics]
    (config,) = model.configurations
    assert ("publish", "/beeps") in [(link.kind, link.resource.name)
                                     for link in config.links
                                     if link.node.name == "/waypoint_follower"]
