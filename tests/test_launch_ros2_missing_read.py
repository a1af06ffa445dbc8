"""A file a Python launch file reads (``open(path).read()``) that is not in the
workspace: vrx_gz's spawn reads ``vrx_gazebo/models/wamv/tmp/model.urdf``, which its own
``Model.generate`` writes when the launch runs. That was an error FILE_UNREADABLE at the
missing file's line 0; it is now a warning where the launch code reads it, and what it
read stays unknown, as for a parameter file that does not exist.

Its own code, LAUNCH_PY_FILE_UNKNOWN, hides no launch configuration: husky's
accessories.launch.py (3da29d7e^) passes ``baud`` to microstrain_inertial_driver's
microstrain_launch.py, which declares ``baudrate`` and loads its default parameters with
``yaml.safe_load(open(...))`` from a submodule not checked out; the unused argument was
undecided (the unread file "may read it"), though a file's content reads no
configuration."""

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
        ("LAUNCH_PY_FILE_UNKNOWN", "warning", "sim/launch/sim.launch.py", 9)]
    assert "does not exist" in said[0].message
    assert [p.value for p in model.params if p.key == "robot_description"] == [None]


DRIVER = """
import os, yaml
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

DEFAULTS = os.path.join(os.path.dirname(__file__), '..', 'common', 'params.yml')

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('baudrate', default_value='115200'),
        Node(package='imu', executable='driver', name='imu', parameters=[
            yaml.safe_load(open(DEFAULTS, 'r')),
            {'baudrate': LaunchConfiguration('baudrate')}])])
"""

INCLUDER = """
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare

def generate_launch_description():
    return LaunchDescription([IncludeLaunchDescription(
        PythonLaunchDescriptionSource(PathJoinSubstitution(
            [FindPackageShare('imu'), 'launch', 'driver.launch.py'])),
        launch_arguments={'%s': '57600'}.items())])
"""


def _uses(write_tree, passed: str, driver: str = DRIVER) -> list[tuple[str, str, str]]:
    root = write_tree({
        "src/imu/package.xml": package_xml("imu", "ament_cmake"),
        "src/imu/launch/driver.launch.py": driver,
        "src/robot/package.xml": package_xml("robot", "ament_cmake"),
        "src/robot/launch/robot.launch.py": INCLUDER % passed,
    })
    model = load(str(root / "src/robot/launch/robot.launch.py"),
                 scan([str(root / "src")], {}), {}, {})
    assert [d.code for d in model.diagnostics if "params.yml" in d.message] == [
        "LAUNCH_PY_FILE_UNKNOWN"]
    items, found = list(model.tree), []
    while items:
        item = items.pop()
        items.extend(item.children)
        found += [(a.name, a.use, a.unseen) for a in item.args if a.name == passed]
    return found


def test_a_file_not_read_hides_no_argument(write_tree):
    # the file's content reads no configuration: baud is unused, not undecided
    assert _uses(write_tree, "baud") == [("baud", "unused", "")]
    assert _uses(write_tree, "baudrate") == [("baudrate", "declared", "")]
    # a construct not interpreted still may read any: undecided
    hidden = DRIVER.replace("yaml.safe_load(open(DEFAULTS, 'r'))",
                            "yaml.safe_load(open(DEFAULTS, 'r')) or unknown_helper()")
    ((name, use, unseen),) = _uses(write_tree, "baud", hidden)
    assert (name, use) == ("baud", "unknown") and "LAUNCH_PY_UNSUPPORTED" in unseen
