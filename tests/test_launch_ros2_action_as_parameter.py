"""A launch action among a Node's parameters (EduArt's edu_robot eduard-360-pi.launch.py
gives ``OpaqueFunction(function=get_motor_parameter_file, args=[...])`` to pick a motor's
parameter file): launch_ros takes each entry that is no mapping for a file's path and
refuses what is neither text nor a substitution (``ensure_argument_type``: TypeError)
when the Node is made, so the launch file does not load. It was a warning that the entry
was not known statically; now it is LAUNCH_BAD_VALUE where the entry is written."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch.ros2 import load
from haros_arch.workspace import scan

LAUNCH = """
from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

def pick(context, model):
    return 'leison.yaml' if context.perform_substitution(model) == 'leison' else 'f.yaml'

def generate_launch_description():
    return LaunchDescription([
        Node(package='p', executable='bot', name='bot',
             parameters=['base.yaml',
                         OpaqueFunction(function=pick, args=[LaunchConfiguration('m')])]),
        Node(package='p', executable='other', name='other', parameters=['base.yaml']),
    ])
"""


def test_a_launch_action_as_a_parameter_entry_is_a_bad_value(write_tree) -> None:
    root = write_tree({"src/p/package.xml": package_xml("p", "ament_cmake"),
                       "src/p/launch/bot.launch.py": LAUNCH})
    workspace = scan([str(root / "src")], {})
    model = load(str(root / "src/p/launch/bot.launch.py"), workspace, {}, {})
    said = [(d.code, d.location.line) for d in model.diagnostics
            if d.code in ("LAUNCH_BAD_VALUE", "LAUNCH_PY_UNSUPPORTED")]
    written = (root / "src/p/launch/bot.launch.py").read_text().splitlines()
    line = next(number for number, text in enumerate(written, 1)
                if "OpaqueFunction(function=pick" in text)
    assert said == [("LAUNCH_BAD_VALUE", line)]
    bad = next(d for d in model.diagnostics if d.code == "LAUNCH_BAD_VALUE")
    assert "OpaqueFunction(function=pick" in bad.message and "TypeError" in bad.message
