"""launch's PathJoinSubstitution joins its parts with os.path.join: a separator goes
between two parts unless the path so far is empty or already ends with one
(clearpath_common 2f04d13's manipulators/control.launch.py remaps ``joint_states`` to
``PathJoinSubstitution(['/', namespace, 'platform', 'joint_states'])``; with no namespace
that is ``/platform/joint_states``, which the reading made ``///platform/joint_states``).
Each case is compared with os.path.join of the same parts."""

from __future__ import annotations

import os

import pytest
from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

CASES = [
    ("/", "", "platform", "joint_states"),
    ("/", "robot", "platform", "joint_states"),
    ("a", "", "b"),
    ("", "b"),
    ("a/", "b"),
    ("a", "b", ""),
    ("robot/", "/abs", "c"),
]

PY = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value=''),
        Node(package='pkg', executable='talker', name='talker',
             remappings=[%s]),
    ])
"""


@pytest.mark.parametrize("parts", CASES, ids=["+".join(c) or "empty" for c in CASES])
def test_a_path_join_is_os_path_join(write_tree, parts: tuple[str, ...]) -> None:
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg", "ament_python"),
        "src/pkg/launch/main.launch.py": PY % f"('out', PathJoinSubstitution({list(parts)!r}))",
    })
    model = load(str(root / "src/pkg/launch/main.launch.py"), scan([str(root / "src")], {}),
                 {}, {})
    [node] = model.nodes
    assert [(src, str(dst)) for src, dst in node.remaps] == [("out", os.path.join(*parts))]


def test_an_empty_launch_argument_between_separators(write_tree) -> None:
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg", "ament_python"),
        "src/pkg/launch/main.launch.py": PY % (
            "('joint_states', PathJoinSubstitution(['/', LaunchConfiguration('namespace'), "
            "'platform', 'joint_states']))"),
    })
    model = load(str(root / "src/pkg/launch/main.launch.py"), scan([str(root / "src")], {}),
                 {}, {})
    [node] = model.nodes
    assert [(src, str(dst)) for src, dst in node.remaps] == [
        ("joint_states", "/platform/joint_states")]
