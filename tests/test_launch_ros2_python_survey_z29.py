"""Python launch file shapes met on real workspaces (survey Z29, 2026-12-01)."""

from __future__ import annotations

from test_launch_ros2_python import codes, run


def test_a_str_method_of_a_command_output_is_said_as_the_command_not_run(write_tree):
    """andino_gz_classic's spawn_robot.launch.py: ``process_file(xacro).toprettyxml()``
    then ``.replace('package://...', 'file://...')``. The document is a xacro command's
    output, never run: an info where the command is performed, as for the command given
    as it is, not a LAUNCH_UNSUPPORTED warning for the ``replace``."""
    model, _ = run(write_tree, """
from xacro import process_file

def description():
    doc = process_file('/x/robot.urdf.xacro', mappings={'sim': 'true'})
    text = doc.toprettyxml(indent='  ')
    return text.replace('package://pkg/', 'file:///x/').strip()

def generate_launch_description():
    return LaunchDescription([Node(package='p', executable='e', name='n',
                                   parameters=[{'robot_description': description()}])])
""")
    assert "LAUNCH_UNSUPPORTED" not in codes(model)
    [said] = [d for d in model.diagnostics if d.code == "LAUNCH_UNKNOWN_VALUE"]
    assert "xacro /x/robot.urdf.xacro sim:=true" in said.message
    [param] = [p for p in model.params if p.name == "/n/robot_description"]
    assert param.value is None  # not known statically



def test_a_str_method_of_a_text_without_a_command_is_still_said(write_tree):
    """A text known only when the launch runs that holds no command (a launch argument
    read by ``perform`` in an OpaqueFunction is known; a ``PathJoinSubstitution`` is a
    launch object): its str method stays not interpreted, said where it is called."""
    model, _ = run(write_tree, """
def generate_launch_description():
    path = PathJoinSubstitution([FindPackageShare('not_here'), 'urdf'])
    return LaunchDescription([Node(package='p', executable='e', name='n',
                                   parameters=[{'frame': path.replace('a', 'b')}])])
""")
    assert "LAUNCH_PY_UNSUPPORTED" in codes(model) or "LAUNCH_UNSUPPORTED" in codes(model)
