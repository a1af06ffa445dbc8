"""A launch class subscripted instead of called, ``PathJoinSubstitution[share,
'x.launch.py']`` (kyubic_ros' client.launch.py), is a TypeError when launch loads the
file: launch's and launch_ros' classes define no ``__class_getitem__``. It was said as a
construct not interpreted, "a subscript of a value not known statically"; it is said as
the file's Python error (LAUNCH_PY_UNSUPPORTED, as ``+`` of a substitution and text)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

PY = """
import launch
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    share = PathJoinSubstitution([FindPackageShare('demo'), 'launch'])
    table = {'a': 'b'}
    return LaunchDescription([
        IncludeLaunchDescription(PathJoinSubstitution[share, 'other.launch.py']),
        Node(package='demo', executable='talker', name='a',
             parameters=[launch.substitutions.PathJoinSubstitution[share, 'a.yaml']]),
        Node(package='demo', executable='talker', name='b',
             remappings=[('scan', table['a'])]),
    ])
"""


def test_a_launch_class_subscripted_is_a_type_error(write_tree) -> None:
    root = write_tree({"src/demo/package.xml": package_xml("demo", "ament_python"),
                       "src/demo/launch/view.launch.py": PY})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/demo/launch/view.launch.py"), ws, {}, {})
    said = sorted((d.location.line, d.message) for d in model.diagnostics
                  if d.code == "LAUNCH_PY_UNSUPPORTED")
    assert said == [
        (13, "PathJoinSubstitution[share, 'other.launch.py'] fails: TypeError: type "
             "'PathJoinSubstitution' is not subscriptable; the class is called with a "
             "list of the parts, PathJoinSubstitution([...])"),
        (15, "launch.substitutions.PathJoinSubstitution[share, 'a.yaml'] fails: TypeError: "
             "type 'PathJoinSubstitution' is not subscriptable; the class is called with a "
             "list of the parts, PathJoinSubstitution([...])")]
    assert not [d for d in model.diagnostics if "a subscript of a value not known"
                in d.message]
    (b,) = [n for n in model.nodes if n.name == "/b"]
    assert b.remaps == [("scan", "b")]
