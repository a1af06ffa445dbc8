"""A list or tuple among a ROS 2 ``LaunchDescription``'s entities is no launch entity:
launch keeps the entities as given and walks each one, so the launch stops with an
AttributeError. A comma after an action makes such a tuple (cyberdog_nav2's
node.laser_mapping.launch.py: ``camera_params_declare = DeclareLaunchArgument(...),``);
it was read as the action itself, and nothing was said. Its items are still read, so
the rest of the file keeps its nodes; a flat list built by ``+`` or ``*`` is fine."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

HEAD = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

def generate_launch_description():
    rate = LaunchConfiguration('rate')
"""

TUPLE = HEAD + """    declare = DeclareLaunchArgument('rate', default_value='5.0'),
    talker = Node(package='p', executable='e', name='talker', parameters=[{'rate': rate}])
    return LaunchDescription([
        declare,
        talker,
    ])
"""

ADDED = HEAD + """    ld = LaunchDescription()
    ld.add_action(DeclareLaunchArgument('rate', default_value='5.0'))
    ld.add_action([Node(package='p', executable='e', name='talker')])
    return ld
"""

FLAT = HEAD + """    declared = [DeclareLaunchArgument('rate', default_value='5.0')]
    nodes = [Node(package='p', executable='e', name='talker')]
    return LaunchDescription(declared + nodes + [*nodes[:0]])
"""


def _run(write_tree, text: str):
    root = write_tree({"src/pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "src/pkg/launch/main.launch.py": text})
    ws = scan([str(root / "src")], {})
    return load(str(root / "src/pkg/launch/main.launch.py"), ws, {}, {})


def _bad(model) -> list[tuple[int, str]]:
    return [(d.location.line, d.message) for d in model.diagnostics
            if d.code == "LAUNCH_BAD_VALUE"]


def test_a_tuple_in_a_launch_description_stops_the_launch(write_tree):
    model = _run(write_tree, TUPLE)
    bad = _bad(model)
    assert [line for line, _ in bad] == [11], bad  # the tuple's place in the list
    assert "tuple" in bad[0][1] and "AttributeError" in bad[0][1], bad
    # the rest of the file is still read: the node and its parameter from the argument
    assert [n.name for n in model.nodes] == ["/talker"]


def test_a_list_added_as_one_entity_stops_the_launch(write_tree):
    model = _run(write_tree, ADDED)
    bad = _bad(model)
    assert [line for line, _ in bad] == [10], bad
    assert "list" in bad[0][1], bad
    assert [n.name for n in model.nodes] == ["/talker"]


def test_a_flat_list_of_actions_is_no_mistake(write_tree):
    model = _run(write_tree, FLAT)
    assert _bad(model) == []
    assert [n.name for n in model.nodes] == ["/talker"]
