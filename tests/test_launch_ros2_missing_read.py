"""A file a Python launch file reads (``open(path).read()``) that is not in the
workspace: vrx_gz's spawn reads ``vrx_gazebo/models/wamv/tmp/model.urdf``, which its own
``Model.generate`` writes when the launch runs. That was an error FILE_UNREADABLE at the
missing file's line 0; it is now a warning where the launch code reads it, and what it
read stays unknown, as for a parameter file that does not exist."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

LAUNCH = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node

def generate_launch_description():
    urdf = os.path.join(get_package_share_directory('sim'), 'models', 'tmp', 'model.urdf')
    with open(urdf, 'r') as infp:
        description = infp.read()
    return LaunchDescription([
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             name='rsp', parameters=[{'robot_description': description}])])
"""


def test_a_file_not_there_is_said_where_it_is_read(write_tree):
    root = write_tree({
        "src/sim/package.xml": package_xml("sim", "ament_cmake"),
        "src/sim/launch/sim.launch.py": LAUNCH,
    })
    model = load(str(root / "src/sim/launch/sim.launch.py"), scan([str(root / "src")], {}),
                 {}, {})
    assert not [d for d in model.diagnostics if d.code == "FILE_UNREADABLE"]
    said = [d for d in model.diagnostics if "model.urdf" in d.message]
    assert [(d.code, d.severity, d.location.file, d.location.line) for d in said] == [
        ("LAUNCH_PY_UNSUPPORTED", "warning", "sim/launch/sim.launch.py", 9)]
    assert "does not exist" in said[0].message
    assert [p.value for p in model.params if p.key == "robot_description"] == [None]
