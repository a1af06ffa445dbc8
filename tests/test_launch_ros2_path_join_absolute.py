"""A path join whose later part starts with '/' starts the path again there, as
os.path.join, launch's PathJoinSubstitution and pathlib do: ros2_control_demos 6ed3b66af
included [FindPackageShare('gazebo_ros'), 'launch', '/gazebo.launch.py'], which launch
makes /gazebo.launch.py. Said as a warning (LAUNCH_PATH_JOIN_ABSOLUTE) where the join is
made; a first part '/' and a join with nothing dropped say nothing."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

PY = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare
def generate_launch_description():
    share = get_package_share_directory('pkg')
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource([PathJoinSubstitution(
            [FindPackageShare('pkg'), 'launch', '/other.launch.py'])])),
        Node(package='pkg', executable='talker',
             parameters=[os.path.join(share, '/config/params.yaml'),
                         os.path.join('/', 'opt', 'params.yaml'),
                         PathJoinSubstitution(['/', 'opt', 'more.yaml'])]),
    ])
"""


def test_a_later_absolute_part_of_a_path_join_is_said(write_tree):
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg", "ament_python"),
        "src/pkg/launch/main.launch.py": PY,
        "src/pkg/launch/other.launch.py": "from launch import LaunchDescription\n"
        "def generate_launch_description():\n    return LaunchDescription([])\n",
    })
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/pkg/launch/main.launch.py"), ws, {}, {})
    said = sorted(d.message for d in model.diagnostics
                  if d.code == "LAUNCH_PATH_JOIN_ABSOLUTE")
    assert len(said) == 2
    assert "part /other.launch.py" in said[1] and "the path is /other.launch.py" in said[1]
    assert "part /config/params.yaml" in said[0]
    assert all(d.severity == "warning" for d in model.diagnostics
               if d.code == "LAUNCH_PATH_JOIN_ABSOLUTE")
