"""A parameter a ROS 2 launch file sets through a parameter file (``parameters=[file]``,
a RewrittenYaml, a composable node's flat file) is said at its key's line in that file,
as a spawner's ``--param-file`` already was; it was said at the launch file's line, so a
finding about it (a parameter set and never read) pointed at the launch call, not at the
key to fix. The lines follow what the launch stage does to the document: RewrittenYaml's
``root_key`` and ``key_rewrites``, a ``/**`` section, a key given twice (rcl merges)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

LAUNCH = """
import os
from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer, Node
from launch_ros.descriptions import ComposableNode
from nav2_common.launch import RewrittenYaml

def generate_launch_description():
    here = os.path.join(os.path.dirname(__file__), '..', 'config')
    rewritten = RewrittenYaml(source_file=os.path.join(here, 'robot.yaml'),
                              root_key='r1', param_rewrites={'rate': '50'},
                              key_rewrites={'old_frame': 'frame'}, convert_types=True)
    return LaunchDescription([
        Node(package='p', executable='e', name='ctrl',
             parameters=[os.path.join(here, 'ctrl.yaml'), {'inline': 1}]),
        Node(package='p', executable='e', name='ctrl', namespace='r1',
             parameters=[rewritten]),
        ComposableNodeContainer(
            name='container', namespace='', package='rclcpp_components',
            executable='component_container',
            composable_node_descriptions=[
                ComposableNode(package='p', plugin='p::Driver', name='driver',
                               parameters=[os.path.join(here, 'flat.yaml')])]),
    ])
"""

FILES = {
    "src/p/package.xml": package_xml("p", "ament_cmake"),
    "src/p/launch/a.launch.py": LAUNCH,
    "src/p/config/ctrl.yaml": (
        "# the controller\n"
        "/**:\n"
        "  ros__parameters:\n"
        "    shared: true\n"
        "ctrl:\n"
        "  ros__parameters:\n"
        "    rate: 10\n"
        "    pid:\n"
        "      p: 1.0\n"
        "ctrl:\n"
        "  ros__parameters:\n"
        "    later: x\n"),
    "src/p/config/robot.yaml": (
        "ctrl:\n"
        "  ros__parameters:\n"
        "    rate: 10\n"
        "    old_frame: base\n"),
    "src/p/config/flat.yaml": "device: tcp\nserial:\n  baud: 9600\n",
}


def test_file_parameters_are_said_at_their_keys(write_tree):
    root = write_tree(FILES)
    model = load(str(root / "src/p/launch/a.launch.py"), scan([str(root / "src")], {}),
                 {}, {})
    where = {p.name: (p.location.file, p.location.line) for p in model.params}
    ctrl, robot, flat = ("p/config/ctrl.yaml", "p/config/robot.yaml",
                         "p/config/flat.yaml")
    assert where["/ctrl/shared"] == (ctrl, 4)
    assert where["/ctrl/rate"] == (ctrl, 7)
    assert where["/ctrl/pid.p"] == (ctrl, 9)
    assert where["/ctrl/later"] == (ctrl, 12)  # the second section of one name
    assert where["/ctrl/inline"] == ("p/launch/a.launch.py", 13)  # a dict: the Node line
    assert where["/r1/ctrl/rate"] == (robot, 3)  # rewritten value, its key's line
    assert where["/r1/ctrl/frame"] == (robot, 4)  # a renamed key
    assert where["/driver/device"] == (flat, 1)
    assert where["/driver/serial.baud"] == (flat, 3)
