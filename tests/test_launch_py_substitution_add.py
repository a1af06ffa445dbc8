"""``+`` between a launch substitution and text fails when launch loads the file:
launch's ``Substitution`` defines only ``describe`` and ``perform`` (no ``__add__`` nor
``__radd__``), and a str's ``+`` takes a str, so ``LaunchConfiguration('ns') + '/scan'``
and ``'/scan' + LaunchConfiguration('ns')`` raise TypeError. The file was read as if it
joined them as text; a list of the parts (or ``PathJoinSubstitution``) is what does.
Said as the TypeError it is (LAUNCH_PY_UNSUPPORTED, as the file's other Python errors),
where it is."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

PY = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    ns = LaunchConfiguration('ns', default='robot')
    share = get_package_share_directory('demo')
    return LaunchDescription([
        Node(package='demo', executable='talker', name='a',
             remappings=[('scan', ns + '/scan')]),
        Node(package='demo', executable='talker', name='b',
             remappings=[('scan', '/' + LaunchConfiguration('ns'))]),
        Node(package='demo', executable='talker', name='c',
             parameters=[PathJoinSubstitution([FindPackageShare('demo'), 'c.yaml']) + 'x']),
        Node(package='demo', executable='talker', name='d',
             remappings=[('scan', [ns, '/scan']), ('odom', share + '/odom')],
             parameters=[os.path.join(share, 'd.yaml')]),
    ])
"""


def test_a_substitution_added_to_text_is_a_type_error(write_tree) -> None:
    root = write_tree({"src/demo/package.xml": package_xml("demo", "ament_python"),
                       "src/demo/launch/view.launch.py": PY})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/demo/launch/view.launch.py"), ws, {}, {})
    said = sorted((d.location.line, d.message) for d in model.diagnostics
                  if d.code == "LAUNCH_PY_UNSUPPORTED")
    assert said == [
        (14, "ns + '/scan' fails: TypeError: unsupported operand type(s) for +: a launch "
             "substitution and str; a list of the parts joins them"),
        (16, "'/' + LaunchConfiguration('ns') fails: TypeError: unsupported operand "
             "type(s) for +: str and a launch substitution; a list of the parts joins them"),
        (18, "PathJoinSubstitution([FindPackageShare('demo'), 'c.yaml']) + 'x' fails: "
             "TypeError: unsupported operand type(s) for +: a launch substitution and str; "
             "a list of the parts joins them")]
    # the list of parts and a path of text are read as before
    (d,) = [n for n in model.nodes if n.name == "/d"]
    assert d.remaps == [("scan", "robot/scan"), ("odom", f"{root}/src/demo/odom")]
