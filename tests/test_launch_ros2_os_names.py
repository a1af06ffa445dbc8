"""``os`` names a launch file imports or reads (tiago_simulation's tiago_gazebo.launch.py:
``from os import environ, pathsep``, model paths joined with ``pathsep``, ``if 'X' in
environ: ... environ['X']``; vrx's ``world_name, ext = os.path.splitext(world)``): the
Linux constants, the configuration's environment and ``splitext`` of a known path.
They were names not known statically."""

from __future__ import annotations

from test_launch_ros2_python import run


def test_os_constants_environ_and_splitext(write_tree) -> None:
    model, _ = run(write_tree, """
from os import environ, pathsep

def generate_launch_description():
    paths = '/a' + pathsep + '/b'
    if 'EXTRA' in environ:
        paths += pathsep + environ['EXTRA']
    world, ext = os.path.splitext('/worlds/sydney.sdf')
    return LaunchDescription([
        Node(package='p', executable='e', name='sim',
             parameters=[{'paths': paths, 'world': world + os.sep + 'x', 'ext': ext}]),
    ])
""", env={"EXTRA": "/c"})
    values = {p.name: p.value for p in model.params}
    assert values == {"/sim/paths": "/a:/b:/c", "/sim/world": "/worlds/sydney/x",
                      "/sim/ext": ".sdf"}
    assert not {"LAUNCH_PY_UNSUPPORTED", "LAUNCH_UNSUPPORTED"} & {
        d.code for d in model.diagnostics}
