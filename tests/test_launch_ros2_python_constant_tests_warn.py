"""A Python ``if`` of a launch file that tests a launch object itself is constant: the
launch argument it reads changes nothing of what starts, which is a mistake of the file,
said as a warning (LAUNCH_PY_ALWAYS_TRUE / LAUNCH_PY_ALWAYS_FALSE), as an ``and`` / ``or``
of one is (LAUNCH_PY_BOOLEAN_OBJECT), not as an info ``check`` lists only with ``-v``.
sjtu_drone 93515e0: ``controller == "joystick"`` of ``LaunchConfiguration('controller')``
never started the joystick teleop, whatever ``controller:=`` said; 2023Rover's
``if(launch_ouster):`` starts the lidar's driver even with ``launch_ouster:=false``."""

from __future__ import annotations

from test_launch_ros2_python import run

BODY = """
def teleop(controller, namespace):
    if controller == 'joystick':
        return Node(package='pkg', executable='teleop_joystick', namespace=namespace)
    return Node(package='pkg', executable='teleop', namespace=namespace)


def generate_launch_description():
    controller = LaunchConfiguration('controller')
    launch_ouster = LaunchConfiguration('launch_ouster')
    ld = LaunchDescription([
        DeclareLaunchArgument('controller', default_value='keyboard'),
        DeclareLaunchArgument('launch_ouster', default_value='true'),
        teleop(controller, 'drone'),
    ])
    if(launch_ouster):
        ld.add_action(Node(package='pkg', executable='ouster_driver', name='ouster'))
    return ld
"""


def test_a_constant_test_of_a_launch_object_is_a_warning(write_tree):
    model, root = run(write_tree, BODY, args={"controller": "joystick",
                                               "launch_ouster": "false"})
    lines = (root / "src/pkg/launch/main.launch.py").read_text().splitlines()
    line_of = {text.strip(): n + 1 for n, text in enumerate(lines)}
    said = sorted((d.location.line, d.code, d.severity) for d in model.diagnostics
                  if d.code.startswith("LAUNCH_PY_ALWAYS"))
    assert said == [
        (line_of["if controller == 'joystick':"], "LAUNCH_PY_ALWAYS_FALSE", "warning"),
        (line_of["if(launch_ouster):"], "LAUNCH_PY_ALWAYS_TRUE", "warning")]
    # what Python runs, whatever the arguments: the keyboard teleop and the driver
    assert sorted(n.executable for n in model.nodes) == ["ouster_driver", "teleop"]
