"""``os.environ[key] = value`` in a Python launch file sets the launch process's
environment: a later ``os.environ.get`` / ``os.getenv`` of the same file reads it.
rslidar_sdk's humble_start.py (78d2abb7) sets RMW_IMPLEMENTATION, then prints
``os.environ.get('RMW_IMPLEMENTATION')``: the write was dropped without a word and the
read said the variable was not set in the configuration."""

from __future__ import annotations

from test_launch_ros2_python import run

BODY = """
import os

def generate_launch_description():
    os.environ['ROBOT_NAME'] = 'rover'
    name = os.environ.get('ROBOT_NAME')
    side = os.getenv('ROBOT_NAME') + '_side'
    if os.environ.get('UNSET_FOR_TEST'):
        os.environ['LATER'] = 'x'
    later = os.environ.get('LATER', 'default')
    return LaunchDescription([Node(package='p', executable='e', name=name),
                              Node(package='p', executable='e', name=side),
                              Node(package='p', executable='e', name=later)])
"""


def test_a_variable_the_file_sets_is_read_back(write_tree):
    environment = {"OTHER": "1"}
    model, _ = run(write_tree, BODY, env=environment)
    assert [n.name for n in model.nodes][:2] == ["/rover", "/rover_side"]
    # the write under a test not known: LATER may be 'x' or not set, its read not known
    assert "?" in model.nodes[2].name, model.nodes[2].name
    said = [(d.code, d.message) for d in model.diagnostics
            if d.code in ("LAUNCH_UNKNOWN_VALUE", "LAUNCH_PY_UNSUPPORTED")]
    # the read of ROBOT_NAME is known; UNSET_FOR_TEST is not, nor LATER after it
    assert [code for code, _ in said] == ["LAUNCH_UNKNOWN_VALUE"] * 2, said
    assert "UNSET_FOR_TEST" in said[0][1] and "LATER" in said[1][1]
    assert environment == {"OTHER": "1"}  # the configuration's own is left as it is


PARENT = """
os.environ['ROBOT_NAME'] = 'rover'
if os.environ.get('UNSET_FOR_TEST'):
    os.environ['MAYBE'] = 'x'

def generate_launch_description():
    share = get_package_share_directory('pkg')
    return LaunchDescription([
        Node(package='p', executable='e', name=EnvironmentVariable('ROBOT_NAME')),
        SetEnvironmentVariable('SCOPED', 'scoped'),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            os.path.join(share, 'launch', 'child.launch.py'))),
        IncludeLaunchDescription(XMLLaunchDescriptionSource(
            os.path.join(share, 'launch', 'child.launch.xml'))),
    ])
""".replace("from launch.substitutions import", "")

CHILD_PY = """
import os
from launch import LaunchDescription
from launch.substitutions import EnvironmentVariable
from launch_ros.actions import Node

def generate_launch_description():
    loaded = os.environ.get('ROBOT_NAME', 'none') + '_' + os.environ.get('SCOPED', 'none')
    return LaunchDescription([
        Node(package='p', executable='e', name=loaded),
        Node(package='p', executable='e', name=EnvironmentVariable('ROBOT_NAME')),
        Node(package='p', executable='e', name=EnvironmentVariable('MAYBE', default_value='d')),
    ])
"""

CHILD_XML = """<launch>
  <node pkg="p" exec="e" name="xml_$(env ROBOT_NAME)"/>
</launch>
"""


def test_a_variable_written_as_a_file_loads_is_seen_by_the_files_it_includes(write_tree):
    """``ros2 launch`` loads a Python launch file (its module, then
    ``generate_launch_description``) before it runs any action of it, and loads an
    included file when the include runs: what the includer wrote in ``os.environ`` is
    the process's by then, for ``EnvironmentVariable`` / ``$(env X)`` of either file and
    ``os.environ`` reads of the included one, as a ``SetEnvironmentVariable`` in scope
    is. A write under a test not known leaves the variable not known there too."""
    body = PARENT.replace("\nos.environ", "\nimport os\nfrom launch.actions import "
                          "SetEnvironmentVariable\nfrom launch.substitutions import "
                          "EnvironmentVariable\nfrom launch.launch_description_sources "
                          "import XMLLaunchDescriptionSource\nos.environ", 1)
    model, _ = run(write_tree, body, extra={
        "src/pkg/launch/child.launch.py": CHILD_PY,
        "src/pkg/launch/child.launch.xml": CHILD_XML}, env={"OTHER": "1"})
    # the includer's own substitution, the included file's os.environ reads (the
    # scoped variable too) and substitution, MAYBE (written under a test), the XML's
    assert [n.name for n in model.nodes] == [
        "/rover", "/rover_scoped", "/rover", "/?", "/xml_rover"]

UNKNOWN_VALUE = """
import os

def generate_launch_description():
    os.environ['SDF_PATH'] = 'known'
    before = os.environ.get('SDF_PATH')
    os.environ['SDF_PATH'] = os.environ['SDF_PATH'] + ':' + os.environ['UNSET_FOR_TEST']
    after = os.environ.get('SDF_PATH', 'default')
    os.environ['SDF_PATH'] = 'again'
    again = os.getenv('SDF_PATH')
    return LaunchDescription([Node(package='p', executable='e', name=before),
                              Node(package='p', executable='e', name=after),
                              Node(package='p', executable='e', name=again)])
"""


def test_a_value_not_known_makes_the_variable_not_known(write_tree):
    """ardupilot_ros's cartographer.launch.py (5c7086e7) appends a variable the
    configuration does not set to SDF_PATH: the variable is set, to a value not known
    (its reads after are not known, not the earlier value nor the default); nothing is
    unsupported there, and a later known value is read again."""
    model, _ = run(write_tree, UNKNOWN_VALUE, env={})
    names = [n.name for n in model.nodes]
    assert names[0] == "/known" and names[2] == "/again", names
    assert "?" in names[1], names
    codes = [(d.code, d.message) for d in model.diagnostics
             if d.code in ("LAUNCH_UNKNOWN_VALUE", "LAUNCH_PY_UNSUPPORTED")]
    assert [code for code, _ in codes] == ["LAUNCH_UNKNOWN_VALUE"] * 2, codes
    assert "UNSET_FOR_TEST" in codes[0][1] and "SDF_PATH" in codes[1][1], codes
