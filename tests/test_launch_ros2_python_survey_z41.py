"""Python launch file shapes met on real workspaces (survey Z41, 2026-12-02)."""

from __future__ import annotations

from test_launch_ros2_python import codes, run


def test_dict_with_keyword_items(write_tree):
    """``dict(key=value)`` and ``dict(mapping, key=value)``, as a launch helper builds the
    arguments of an include or a node's parameters (the survey's aerostack2 bringup
    wrapper: ``dict(common, plugin_name='ground_truth')``). Keyword items made the value
    not known: LAUNCH_PY_UNSUPPORTED and the node's parameters lost."""
    model, _ = run(write_tree, """
def generate_launch_description():
    ns = LaunchConfiguration('namespace')
    common = {'use_sim_time': True}
    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value='drone0'),
        Node(package='p', executable='est', name='est', namespace=ns,
             parameters=[dict(common, plugin_name='ground_truth'),
                         dict(rate=2.0, frame=ns),
                         dict([('a', 1)], b=2)]),
    ])
""")
    assert {p.name: p.value for p in model.params} == {
        "/drone0/est/use_sim_time": True, "/drone0/est/plugin_name": "ground_truth",
        "/drone0/est/rate": 2.0, "/drone0/est/frame": "drone0",
        "/drone0/est/a": 1, "/drone0/est/b": 2}
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)


def test_an_opaque_function_returning_a_descriptions_entities(write_tree):
    """``LaunchDescription.entities``, launch's property (survey Z43: lbr_fri_ros2_stack's
    move_group.launch.py builds a description in an OpaqueFunction and returns
    ``ld.entities``): the description's actions, not a value not known
    (LAUNCH_PY_UNSUPPORTED, and move_group and RViz never started)."""
    model, _ = run(write_tree, """
def hidden_setup(context):
    ld = LaunchDescription()
    ld.add_action(Node(package='p', executable='move_group', name='move_group'))
    ld.add_action(Node(package='p', executable='rviz2', name='rviz'))
    return ld.entities


def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=hidden_setup)])
""")
    assert [n.name for n in model.nodes] == ["/move_group", "/rviz"]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)


def test_a_pathlib_path_as_a_parameter_file(write_tree):
    """launch_ros takes a ``pathlib.Path`` among a node's parameters as a parameter file
    (survey Z43: carla_ackermann_control.launch.py gives
    ``Path(get_package_share_directory('carla_ackermann_control'), "settings.yaml")``):
    it was "a node parameter entry not known statically" and the file not read."""
    model, _ = run(write_tree, """
from pathlib import Path


def generate_launch_description():
    return LaunchDescription([
        Node(package='p', executable='ctl', name='ctl',
             parameters=[Path(os.path.dirname(__file__), 'settings.yaml'), {'rate': 5}]),
    ])
""", extra={"src/pkg/launch/settings.yaml": "ctl:\n  ros__parameters:\n    gain: 2.0\n"})
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)
    assert [n.name for n in model.nodes] == ["/ctl"]
    assert {p.name: p.value for p in model.params} == {"/ctl/gain": 2.0, "/ctl/rate": 5}
