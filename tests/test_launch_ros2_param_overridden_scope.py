"""A ``SetParameter`` in scope whose value is a launch argument's, which a node's own
parameter file sets again with a value written in it, never reaches that node:
launch_ros hands a node the ``SetParameter`` values before its own ``parameters`` (node.py:
"Expand global parameters first, so they can be overridden with specific parameters of
this Node"; load_composable_nodes.py puts them first in a component's request too) and
the last value wins (LAUNCH_PARAM_OVERRIDDEN, said at the SetParameter). Not for a
written-out value (a default the node's file may mean to change), a node's own
dictionary (an override written beside the node), a file rewritten with the same
argument (nav2's bringup), nor a file without the key."""

from __future__ import annotations

from test_launch_ros2_python import run

BODY = """
from launch_ros.actions import ComposableNodeContainer
from launch_ros.descriptions import ComposableNode
from nav2_common.launch import RewrittenYaml


def generate_launch_description():
    use_sim_time = LaunchConfiguration('use_sim_time')
    ekf = os.path.join(get_package_share_directory('pkg'), 'config', 'ekf.yaml')
    rewritten = RewrittenYaml(source_file=ekf, param_rewrites={'use_sim_time': use_sim_time},
                              convert_types=True)
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='true'),
        GroupAction([
            SetParameter(name='use_sim_time', value=use_sim_time),
            Node(package='robot_localization', executable='ekf_node', name='ekf_filter_node',
                 parameters=[ekf]),
            Node(package='robot_localization', executable='ekf_node', name='ekf_own',
                 parameters=[ekf, {'use_sim_time': False}]),
            Node(package='robot_localization', executable='ekf_node', name='ekf_rewritten',
                 parameters=[rewritten]),
            Node(package='robot_localization', executable='ekf_node', name='ekf_plain',
                 parameters=[ekf]),
            ComposableNodeContainer(
                name='c', namespace='', package='rclcpp_components',
                executable='component_container',
                composable_node_descriptions=[
                    ComposableNode(package='p', plugin='p::Filter', name='ekf_filter_node',
                                   namespace='comp', parameters=[ekf])]),
        ]),
        GroupAction([
            SetParameter(name='use_sim_time', value=True),
            Node(package='robot_localization', executable='ekf_node', name='ekf_literal',
                 parameters=[ekf]),
        ]),
    ])
"""

EKF = """\
ekf_filter_node:
  ros__parameters:
    use_sim_time: false
ekf_own:
  ros__parameters:
    use_sim_time: false
ekf_rewritten:
  ros__parameters:
    use_sim_time: false
ekf_literal:
  ros__parameters:
    use_sim_time: false
ekf_plain:
  ros__parameters:
    frequency: 30.0
/**/comp/ekf_filter_node:
  ros__parameters:
    use_sim_time: false
"""


def test_a_set_parameter_a_node_file_sets_again_is_said(write_tree):
    model, root = run(write_tree, BODY, args={"use_sim_time": "true"},
                      extra={"src/pkg/config/ekf.yaml": EKF})
    lines = (root / "src/pkg/launch/main.launch.py").read_text().splitlines()
    setting = next(n + 1 for n, text in enumerate(lines)
                   if "SetParameter(name='use_sim_time', value=use_sim_time)" in text)
    said = sorted((d.location.line, d.severity, d.message) for d in model.diagnostics
                  if d.code == "LAUNCH_PARAM_OVERRIDDEN")
    assert [(line, severity) for line, severity, _ in said] == [
        (setting, "warning"), (setting, "warning")]
    messages = " ".join(message for _, _, message in said)
    assert "given to /ekf_filter_node by SetParameter here" in messages
    assert "given to /comp/ekf_filter_node by SetParameter here" in messages
    assert "ekf.yaml:3" in messages and "ekf.yaml:18" in messages
    for absent in ("ekf_own", "ekf_rewritten", "ekf_plain", "ekf_literal"):
        assert absent not in messages
    # the value the node is given is its file's, as rcl keeps it; the others' as before
    params = {p.name: p.value for p in model.params}
    assert params["/ekf_filter_node/use_sim_time"] is False
    assert params["/ekf_own/use_sim_time"] is False
    assert params["/ekf_plain/use_sim_time"] is True
