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
