"""Python launch file shapes met on real workspaces (survey Z40, 2026-12-01)."""

from __future__ import annotations

from test_launch_ros2_python import codes, run


def test_an_opaque_function_sets_a_launch_configuration(write_tree):
    """Universal_Robots_ROS2_Driver's ur_control.launch.py:241: ``context.
    launch_configurations["update_rate"] = str(update_rate)``, the rate read from a
    file, for the ``$(var update_rate)`` of the controllers' parameter file given with
    ``allow_substs=True``. The assignment was dropped without a word: LAUNCH_ARG_UNSET
    for update_rate and the controller's rate unknown."""
    model, _ = run(write_tree, """
import yaml

def setup(context):
    share = get_package_share_directory('pkg')
    with open(os.path.join(share, 'config', 'rate.yaml')) as f:
        rate = yaml.safe_load(f)['controller_manager']['ros__parameters']['update_rate']
    context.launch_configurations['update_rate'] = str(rate)
    again = context.launch_configurations['update_rate']
    return [Node(package='p', executable='manager', name='controller_manager',
                 namespace='at_' + again,
                 parameters=[ParameterFile(os.path.join(share, 'config', 'c.yaml'),
                                           allow_substs=True)])]

def generate_launch_description():
    return LaunchDescription([
        OpaqueFunction(function=setup),
        Node(package='p', executable='after', name='after',
             parameters=[{'rate': LaunchConfiguration('update_rate')}]),
    ])
""", extra={
        "src/pkg/config/rate.yaml":
            "controller_manager:\n  ros__parameters:\n    update_rate: 500\n",
        "src/pkg/config/c.yaml":
            "/**:\n  ros__parameters:\n    rate: $(var update_rate)\n"})
    assert {p.name: p.value for p in model.params} == {
        "/at_500/controller_manager/rate": 500, "/after/rate": 500}
    assert "LAUNCH_ARG_UNSET" not in codes(model)


def test_a_launch_configuration_set_under_a_name_not_known_is_said(write_tree):
    model, _ = run(write_tree, """
def setup(context):
    context.launch_configurations[input()] = '1'
    return []

def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=setup)])
""")
    assert any(d.code == "LAUNCH_PY_UNSUPPORTED" and "launch configuration" in d.message
               for d in model.diagnostics)


def test_a_parameter_value_given_by_keyword(write_tree):
    """ur_control.launch.py:219: ``ParameterValue(value=robot_description_content,
    value_type=str)``. Only a value by position was read: the robot description was
    ``None``, not the xacro command, and the controller manager's hardware unknown
    (HARDWARE_UNKNOWN) though the description was in the workspace."""
    model, _ = run(write_tree, """
from launch.substitutions import Command
from launch_ros.parameter_descriptions import ParameterValue

def generate_launch_description():
    xacro_file = os.path.join(get_package_share_directory('pkg'), 'urdf', 'r.urdf.xacro')
    return LaunchDescription([
        Node(package='p', executable='e', name='by_keyword', parameters=[{
            'robot_description': ParameterValue(value=Command(['xacro ', xacro_file]),
                                                value_type=str),
            'rate': ParameterValue(value='5')}]),
        Node(package='p', executable='e', name='by_position', parameters=[{
            'robot_description': ParameterValue(Command(['xacro ', xacro_file]),
                                                value_type=str),
            'rate': ParameterValue('5')}]),
    ])
""")
    commands = {p.name: p.command for p in model.params if p.name.endswith("description")}
    assert commands["/by_keyword/robot_description"] == commands[
        "/by_position/robot_description"]
    assert commands["/by_keyword/robot_description"].startswith("xacro ")
    values = {p.name: p.value for p in model.params}
    assert values["/by_keyword/rate"] == values["/by_position/rate"] is not None
