"""A dictionary among a ROS 2 ``Node``'s ``parameters`` whose key a parameter file later
in the same list sets again for that node is dead: launch_ros hands rcl the list in
order and rcl keeps the last value (LAUNCH_PARAM_OVERRIDDEN, a warning).
roverrobotics_ros2 a97557f1: ``parameters=[{'use_sim_time': use_sim_time}, ekf_yaml]``
with ``use_sim_time: false`` in the file's section for the node, so
``use_sim_time:=true`` never reached the EKFs. A component's list is read in the same
order (its case, once a guard that never ran: the file did not import
``ComposableNodeContainer``, so launch stopped before it)."""

from __future__ import annotations

from test_launch_ros2_python import run

BODY = """
from launch_ros.actions import ComposableNodeContainer
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    use_sim_time = LaunchConfiguration('use_sim_time')
    ekf = os.path.join(get_package_share_directory('pkg'), 'config', 'ekf.yaml')
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        Node(package='robot_localization', executable='ekf_node', name='ekf_filter_node',
             parameters=[{'use_sim_time': use_sim_time}, ekf]),
        Node(package='robot_localization', executable='ekf_node', name='ekf_after',
             parameters=[ekf, {'use_sim_time': use_sim_time}]),
        Node(package='robot_localization', executable='ekf_node', name='ekf_rates',
             parameters=[{'frequency': 30.0, 'two_d_mode': True, 'publish_tf': False}, ekf]),
        Node(package='robot_localization', executable='ekf_node', name='other',
             parameters=[{'use_sim_time': use_sim_time}, ekf]),
        ComposableNodeContainer(
            name='c', namespace='', package='rclcpp_components',
            executable='component_container',
            composable_node_descriptions=[
                ComposableNode(package='p', plugin='p::Filter', name='ekf_filter_node',
                               namespace='comp',
                               parameters=[{'use_sim_time': use_sim_time}, ekf])]),
    ])
"""

EKF = """\
ekf_filter_node:
  ros__parameters:
    use_sim_time: false
    frequency: 30.0
ekf_after:
  ros__parameters:
    use_sim_time: false
ekf_rates:
  ros__parameters:
    frequency: 30.0
    two_d_mode: false
/**/comp/ekf_filter_node:
  ros__parameters:
    use_sim_time: false
"""


def test_a_dictionary_a_later_file_sets_again_is_said(write_tree):
    model, root = run(write_tree, BODY, args={"use_sim_time": "true"},
                      extra={"src/pkg/config/ekf.yaml": EKF})
    lines = (root / "src/pkg/launch/main.launch.py").read_text().splitlines()
    first = next(n + 1 for n, text in enumerate(lines) if "name='ekf_filter_node'" in text
                 and "Node(package='robot_localization'" in text)
    rates = next(n + 1 for n, text in enumerate(lines) if "name='ekf_rates'" in text)
    component = next(n + 1 for n, text in enumerate(lines) if "ComposableNode(" in text)
    said = sorted((d.location.line, d.severity, d.message) for d in model.diagnostics
                  if d.code == "LAUNCH_PARAM_OVERRIDDEN")
    assert [(line, severity) for line, severity, _ in said] == [
        (first, "warning"), (rates, "warning"), (component, "warning")]
    assert "use_sim_time" in said[0][2] and "ekf.yaml:3" in said[0][2]
    assert "launch argument" in said[0][2]
    # of ekf_rates' three keys only two_d_mode differs from the file's (frequency is the
    # file's own value, publish_tf a key the file has not)
    assert "two_d_mode" in said[1][2] and "ekf.yaml:11" in said[1][2]
    # a component's list is one list of overrides in order (launch_ros'
    # to_parameters_list, rclcpp_components' NodeOptions::parameter_overrides): the
    # file's section for /comp/ekf_filter_node comes after the dictionary
    assert "/comp/ekf_filter_node" in said[2][2] and "ekf.yaml:14" in said[2][2]
    # the file's value is the node's, as rcl keeps it
    params = {p.name: p.value for p in model.params}
    assert params["/ekf_filter_node/use_sim_time"] is False
    assert params["/ekf_after/use_sim_time"] is True
