"""launch_ros' ``Node`` takes ``executable=`` as a required keyword (``node_executable=``
in Dashing and Eloquent); ``LifecycleNode`` and ``ComposableNodeContainer`` hand their
keywords on to it. A call without it raises TypeError when generate_launch_description
runs, and the launch file does not load: sjtu_drone e33e86e built
``Node(package="sjtu_drone_control", namespace=..., output="screen")`` and set
``node.executable`` afterwards. Said where the call is (LAUNCH_PY_UNSUPPORTED, the
Python error of the interpreted code, as for a keyword a function does not take), not
read as a node of an executable not known statically. A call that splats a dict not
known here (``**options``) may give it: nothing said."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch.ros2 import load
from haros_arch.workspace import scan

LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer, Node


def teleop(namespace):
    node = Node(
        package='demo',
        namespace=namespace,
        output='screen')
    return node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo', executable='listener', name='listener'),
        teleop('drone'),
        ComposableNodeContainer(name='box', namespace='', package='rclcpp_components'),
    ])
"""

SPLAT = """
from launch import LaunchDescription
from launch_ros.actions import Node
from demo_helpers import options


def generate_launch_description():
    return LaunchDescription([Node(package='demo', **options())])
"""

OLD_KEYWORD = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package='demo', node_executable='talker')])
"""


def _load(write_tree, text: str, env: dict[str, str] | None = None):
    root = write_tree({"src/demo/package.xml": package_xml("demo", "ament_cmake"),
                       "src/demo/launch/main.launch.py": text})
    ws = scan([str(root / "src")], env or {})
    return load(str(root / "src/demo/launch/main.launch.py"), ws, {}, env or {})


def _type_errors(model) -> list[tuple[int, str]]:
    return sorted((d.location.line, d.message) for d in model.diagnostics
                  if d.code == "LAUNCH_PY_UNSUPPORTED" and "TypeError" in d.message)


def test_a_node_without_an_executable_is_the_type_error(write_tree):
    model = _load(write_tree, LAUNCH)
    said = _type_errors(model)
    assert [line for line, _ in said] == [6, 17]  # Node( in teleop, the container
    assert "Node(...) fails: TypeError" in said[0][1]
    assert "'executable'" in said[0][1]
    assert "ComposableNodeContainer(...) fails: TypeError" in said[1][1]
    # the node with its executable is there; the failed calls started nothing
    assert [n.executable for n in model.nodes] == ["listener"]
    assert not [d for d in model.diagnostics if d.code == "NODE_TYPE_UNKNOWN"]


def test_a_splat_not_known_may_give_it(write_tree):
    assert _type_errors(_load(write_tree, SPLAT)) == []


def test_dashings_keyword_is_an_executable(write_tree):
    model = _load(write_tree, OLD_KEYWORD, {"ROS_DISTRO": "eloquent"})
    assert _type_errors(model) == []
    assert [n.executable for n in model.nodes] == ["talker"]
