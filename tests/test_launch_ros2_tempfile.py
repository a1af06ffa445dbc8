"""navigation2's simulation launch files (tb3_simulation_launch.py and ten others) have
xacro write the world into ``tempfile.mktemp(prefix='nav2_', suffix='.sdf')``, hand that
path to Gazebo, and remove it on shutdown, ``OpaqueFunction(function=lambda _:
os.remove(world_sdf))``: two calls not interpreted and a shutdown handler whose actions
were not known (a part of each configuration unread). The path is the folder, the
prefix, a part chosen when the launch file runs and the suffix; the removal is not run
here and returns None, as it does."""

from __future__ import annotations

from test_launch_ros2_python import codes, run

BODY = """
import tempfile
from launch.actions import ExecuteProcess, RegisterEventHandler
from launch.event_handlers import OnShutdown

def generate_launch_description():
    world_sdf = tempfile.mktemp(prefix='nav2_', suffix='.sdf')
    make_world = ExecuteProcess(cmd=['xacro', '-o', world_sdf, 'world.sdf.xacro'])
    gazebo = ExecuteProcess(cmd=['gz', 'sim', '-r', '-s', world_sdf])
    cleanup = RegisterEventHandler(event_handler=OnShutdown(
        on_shutdown=[OpaqueFunction(function=lambda _: os.remove(world_sdf))]))
    return LaunchDescription([make_world, gazebo, cleanup,
                              Node(package='p', executable='a', name='a')])
"""


def test_a_temporary_world_file_is_no_unread_part(write_tree):
    model, _ = run(write_tree, BODY)
    assert [n.name for n in model.nodes] == ["/a"]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model), [
        d.message for d in model.diagnostics]
