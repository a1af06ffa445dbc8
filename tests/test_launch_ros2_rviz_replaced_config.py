"""rviz2 started with ``-d`` a configuration the launch file gives with text replaced
(nav2_common's ``ReplaceString``): rviz reads the replaced text. nav2 humble's
rviz_launch.py starts the namespaced rviz with ``ReplaceString(source_file=rviz_config,
replacements={'<robot_namespace>': ('/', namespace)})``, its nav2_namespaced_view.rviz
naming ``<robot_namespace>/scan`` and the like: the file was read as written, and
multi_tb3_simulation's rviz instances subscribed to ``/robot1/<robot_namespace>/scan``
(wheeltec_ros2 58a869f, 54 undecided rviz-display infos)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

RVIZ = """\
Visualization Manager:
  Displays:
    - Class: rviz_default_plugins/LaserScan
      Enabled: true
      Topic:
        Value: <robot_namespace>/scan
  Tools:
    - Class: rviz_default_plugins/SetInitialPose
      Topic:
        Value: <robot_namespace>/initialpose
"""

LAUNCH = """import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from nav2_common.launch import ReplaceString


def generate_launch_description():
    namespace = LaunchConfiguration('namespace')
    config = os.path.join(get_package_share_directory('viz'), 'rviz', 'ns.rviz')
    replaced = ReplaceString(source_file=config,
                             replacements={'<robot_namespace>': ('/', namespace)})
    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value='robot1'),
        Node(package='rviz2', executable='rviz2', namespace=namespace,
             arguments=['-d', replaced]),
    ])
"""

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(viz)
find_package(ament_cmake REQUIRED)
install(DIRECTORY launch rviz DESTINATION share/${PROJECT_NAME})
ament_package()
"""


def test_rviz_reads_its_configuration_with_the_text_replaced(write_tree):
    root = write_tree({
        "src/viz/package.xml": package_xml("viz", "ament_cmake"),
        "src/viz/CMakeLists.txt": CMAKE,
        "src/viz/rviz/ns.rviz": RVIZ,
        "src/viz/launch/view.launch.py": LAUNCH,
        "project.yaml": "project: p\ndistro: humble\nworkspace: src\nconfigurations:\n"
                        "  c: [viz/launch/view.launch.py]\n"})
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    (rviz,) = [n for n in config.nodes if n.name == "/robot1/rviz"]
    names = sorted((link.kind, link.resource.name) for link in rviz.links
                   if link.kind in ("subscribe", "publish") and "tf" not in link.resource.name)
    assert names == [("publish", "/robot1/initialpose"), ("subscribe", "/robot1/scan")]
