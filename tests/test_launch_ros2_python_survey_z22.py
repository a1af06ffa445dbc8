"""Python launch file shapes met on real workspaces (survey Z22, 2026-12-01)."""

from __future__ import annotations

from test_launch_ros2_python import codes, run


def test_isinstance_of_a_known_value_stops_a_flattening_helper(write_tree):
    """panther_ros' welcomeMsg.py: ``flatten(lst)`` recurses while ``isinstance(lst,
    list)``. With isinstance never known, both branches ran, the loop went over a
    string's characters and each one-character string recursed on itself until the call
    depth bound stopped the whole file: no node of the bringup was seen."""
    model, _ = run(write_tree, """
from launch.actions import LogInfo

def flatten(lst):
    if isinstance(lst, list):
        flat = []
        for element in lst:
            flat.extend(flatten(element))
        return flat
    else:
        return [lst]

def generate_launch_description():
    stats = {'Serial': LaunchConfiguration('serial'), 'Site': 'https://example.com'}
    nested = [item for name, value in stats.items() for item in (f'{name}: ', value, '\\n')]
    parts = flatten(nested)
    known = [p for p in parts if isinstance(p, (str, int))]
    return LaunchDescription([LogInfo(msg=parts),
                              Node(package='p', executable='e', name='n', namespace=known[0])])
""")
    assert "LAUNCH_PY_BUDGET" not in codes(model)
    # the first str of the flattened list, 'Serial: ', names the namespace
    [node] = model.nodes
    assert node.name.startswith("/Serial") and node.name.endswith("/n")


def test_isinstance_of_a_value_not_plain_stays_unknown(write_tree):
    """A package path found at launch time stands for a ``str``; a class other than a
    builtin type is not decided: the node exists only under the test."""
    model, _ = run(write_tree, """
from launch.substitutions import TextSubstitution

def generate_launch_description():
    share = get_package_share_directory('not_installed_anywhere')
    nodes = []
    if isinstance(share, str):
        nodes.append(Node(package='p', executable='e', name='a'))
    if isinstance('x', TextSubstitution):
        nodes.append(Node(package='p', executable='e', name='b'))
    if isinstance(3, str):
        nodes.append(Node(package='p', executable='e', name='c'))
    return LaunchDescription(nodes)
""")
    names = {n.name: n for n in model.nodes}
    assert sorted(names) == ["/a", "/b"]
    assert names["/a"].conditions and names["/b"].conditions


MULTI_ROBOT = """
from nav2_common.launch import ParseMultiRobotPose

def generate_launch_description():
    robots = ParseMultiRobotPose('robots').value()
    if len(robots) == 0:
        robots = {LaunchConfiguration('namespace', default='solo'): {
            'x': '0.0', 'y': '-2.0', 'z': '0.2', 'roll': '0.0', 'pitch': '0.0', 'yaw': '0.0'}}
    else:
        for name, pose in robots.items():
            robots[name] = {k: str(v) for k, v in pose.items()}
    nodes = []
    for idx, name in enumerate(robots):
        x, y, z, roll, pitch, yaw = [value for value in robots[name].values()]
        nodes.append(Node(package='tf2_ros', executable='static_transform_publisher',
                          name='world_tf', namespace=name,
                          arguments=[x, y, z, roll, pitch, yaw, 'world', 'odom']))
    return LaunchDescription(nodes)
"""


def test_multi_robot_poses_absent_from_the_command_line_are_none(write_tree):
    """panther_ros' simulate_multiple_robots.launch.py (Humble's nav2_common):
    ``ParseMultiRobotPose('robots').value()`` reads ``robots:=`` from ``sys.argv``; a
    configuration without it has no robots, so the file's default robot is started."""
    model, _ = run(write_tree, MULTI_ROBOT)
    assert [(n.name, n.args) for n in model.nodes] == [
        ("/solo/world_tf", "0.0 -2.0 0.2 0.0 0.0 0.0 world odom")]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)
    assert "LAUNCH_UNSUPPORTED" not in codes(model)


def test_multi_robot_poses_from_the_command_line(write_tree):
    """``robots:='r1={x: 1.5}; bad; r2={yaw: 3, y: 2}'``: one robot per entry with one
    ``=``, the fields it omits 0.0, after those it gives (the order the file unpacks)."""
    model, _ = run(write_tree, MULTI_ROBOT,
                   args={"robots": "r1={x: 1.5}; bad; r2={yaw: 3, y: 2}"})
    assert [(n.name, n.args) for n in model.nodes] == [
        ("/r1/world_tf", "1.5 0.0 0.0 0.0 0.0 0.0 world odom"),
        ("/r2/world_tf", "3 2 0.0 0.0 0.0 0.0 world odom")]


ROBOTNIK = """
from robotnik_common.launch import AddArgumentParser, ExtendedArgument, add_launch_args

def generate_launch_description():
    ld = LaunchDescription()
    add_to_launcher = AddArgumentParser(ld)
    add_to_launcher.add_arg(ExtendedArgument(
        name='namespace', description='Namespace', default_value='robot', use_env=True,
        environment='NAMESPACE'))
    add_to_launcher.add_arg(ExtendedArgument(
        name='robot', description='Robot model', default_value='rbvogui'))
    add_to_launcher.add_arg(ExtendedArgument(
        name='x', description='x position', default_value='0.0', use_env=False))
    params = add_to_launcher.process_arg()
    more = add_launch_args(ld, [('world', 'World', 'warehouse')])
    ld.add_action(Node(package='ros_gz_sim', executable='create', name='spawn',
                       namespace=params['namespace'],
                       arguments=['-name', [params['namespace'], '/', params['robot']],
                                  '-x', params['x'], '-world', more['world']]))
    return ld
"""


def test_robotnik_common_argument_helpers(write_tree):
    """Robotnik's robot_simulation spawn files: robotnik_common (installed, not in the
    workspace) declares each ExtendedArgument when process_arg() runs, its default read
    from the environment variable (NAME upper-cased unless named) unless use_env=False,
    and returns their configurations; every use of them was a value not known."""
    model, _ = run(write_tree, ROBOTNIK)
    assert [(n.name, n.args) for n in model.nodes] == [
        ("/robot/spawn", "-name robot/rbvogui -x 0.0 -world warehouse")]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)
    assert "LAUNCH_UNSUPPORTED" not in codes(model)
    model, _ = run(write_tree, ROBOTNIK, env={"NAMESPACE": "r2", "ROBOT": "rbkairos",
                                              "X": "5", "WORLD": "office"},
                   args={"x": "1.5"})
    assert [(n.name, n.args) for n in model.nodes] == [
        ("/r2/spawn", "-name r2/rbkairos -x 1.5 -world office")]
