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
