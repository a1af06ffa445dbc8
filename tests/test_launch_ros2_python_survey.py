"""Python launch file shapes met on real workspaces (survey of 2026-11-29)."""

from __future__ import annotations

from test_launch_ros2_python import codes, run


def test_add_entity_of_a_launch_description_declares_its_arguments(write_tree):
    """ur_moveit_config's ur_moveit.launch.py: ``ld.add_entity(declare_arguments())``
    adds a LaunchDescription of DeclareLaunchArgument; their defaults hold after it."""
    model, _ = run(write_tree, """
def declare_arguments():
    return LaunchDescription([
        DeclareLaunchArgument('launch_rviz', default_value='false'),
        DeclareLaunchArgument('robot', default_value='r1'),
    ])

def generate_launch_description():
    ld = LaunchDescription()
    ld.add_entity(declare_arguments())
    ld.add_entity(Node(package='p', executable='e', name=LaunchConfiguration('robot')))
    ld.add_action(Node(package='p', executable='rviz', name='rviz',
                       condition=IfCondition(LaunchConfiguration('launch_rviz'))))
    return ld
""")
    assert [n.name for n in model.nodes] == ["/r1"]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)
    assert "LAUNCH_ARG_UNSET" not in codes(model)
