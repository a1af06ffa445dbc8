"""Items of a Python launch file's ``parameters=`` and ``remappings=`` that launch_ros
cannot use as written. A set ``{"name", value}`` (a comma for the dictionary's colon) is
taken by launch_ros for a parameter file's path, which is no file: it warns and passes
nothing (yolo_ros 7d3292d^'s detect_3d_node); a set of one item is its item's path. Text
where a ``(from, to)`` tuple belongs, ``remappings=['from', 'to']``, makes launch_ros raise
TypeError: the file does not load (f1tenth_system 7c5bc1b^'s ackermann_mux). Both were
said as values not known statically (or, for the set, as a relative file path not
read)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch.ros2 import load
from haros_arch.workspace import scan

LAUNCH = """
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    threshold = LaunchConfiguration('threshold', default='0.3')
    return LaunchDescription([
        Node(package='demo', executable='detect', name='detect',
             parameters=[{'target_frame': 'base_link'},
                         {'maximum_detection_threshold', threshold}]),
        Node(package='demo', executable='mux', name='mux',
             remappings=['cmd_out', 'drive']),
        Node(package='demo', executable='relay', name='relay',
             remappings=[('in', 'drive')],
             parameters=[{'rate': 5.0}, {get_package_share_directory('demo')
                                         + '/config/relay.yaml'}]),
    ])
"""


def run(write_tree):
    root = write_tree({"src/demo/package.xml": package_xml("demo", "ament_cmake"),
                       "src/demo/config/relay.yaml": "relay:\n  ros__parameters:\n"
                                                     "    gain: 2.0\n",
                       "src/demo/launch/main.launch.py": LAUNCH})
    ws = scan([str(root / "src")], {})
    return load(str(root / "src/demo/launch/main.launch.py"), ws, {}, {})


def test_a_set_among_the_parameters_is_said_and_sets_nothing(write_tree):
    model = run(write_tree)
    said = [(d.code, d.severity, d.location.line, d.message) for d in model.diagnostics
            if d.code in ("LAUNCH_PARAMS_SET", "LAUNCH_UNKNOWN_VALUE")]
    assert said == [(
        "LAUNCH_PARAMS_SET", "warning", 12,
        "parameters holds the set {'maximum_detection_threshold', threshold}, not a "
        "dictionary: launch_ros takes it for a parameter file's path, which is no file, "
        "and the node gets none of it")]
    # a set of one item is that item's path, as launch_ros joins it: the file is read
    names = sorted(p.name for p in model.params)
    assert names == ["/detect/target_frame", "/relay/gain", "/relay/rate"]


def test_text_where_a_remap_tuple_belongs_is_an_error(write_tree):
    model = run(write_tree)
    said = [(d.code, d.severity, d.location.line, d.message) for d in model.diagnostics
            if d.code in ("LAUNCH_BAD_VALUE", "LAUNCH_PY_UNSUPPORTED")]
    assert said == [
        ("LAUNCH_BAD_VALUE", "error", 13,
         "remappings holds the text 'cmd_out', not a (from, to) tuple: launch_ros refuses "
         "it (TypeError) and the launch file does not load"),
        ("LAUNCH_BAD_VALUE", "error", 13,
         "remappings holds the text 'drive', not a (from, to) tuple: launch_ros refuses "
         "it (TypeError) and the launch file does not load")]
    (relay,) = [n for n in model.nodes if n.name == "/relay"]
    assert [(str(a), str(b)) for a, b in relay.remaps] == [("in", "drive")]
