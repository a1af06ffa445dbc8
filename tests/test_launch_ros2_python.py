"""Python launch files interpreted statically: the subset, and hostile files."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

HEADER = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import (DeclareLaunchArgument, GroupAction, IncludeLaunchDescription,
                            OpaqueFunction, TimerAction)
from launch.conditions import IfCondition, LaunchConfigurationEquals, UnlessCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PythonExpression, TextSubstitution
from launch_ros.actions import Node, PushRosNamespace, SetParameter
from launch_ros.descriptions import ParameterFile
"""


def run(write_tree, body: str, args: dict[str, str] | None = None,
        extra: dict[str, str] | None = None, env: dict[str, str] | None = None):
    files = {"src/pkg/package.xml": package_xml("pkg", "ament_python"),
             "src/pkg/launch/main.launch.py": HEADER + body}
    files.update(extra or {})
    root = write_tree(files)
    ws = scan([str(root / "src")], env or {})
    return load(str(root / "src/pkg/launch/main.launch.py"), ws, args or {}, env or {}), root


def codes(model) -> list[str]:
    return sorted({d.code for d in model.diagnostics})


def test_helpers_loops_comprehensions_and_strings(write_tree):
    model, _ = run(write_tree, """
ROBOTS = [('alpha', 1), ('beta', 2)]

def driver(name, index, prefix='unit'):
    return Node(package='drive', executable='base_node', name=f'{prefix}_{index}',
                namespace=name, parameters=[{'id': index, 'frame': name + '/base',
                                             'limits': {'v': 0.5 * index, 'w': [1, 2]}}],
                remappings=[('cmd', '/{}/cmd'.format(name))])

def generate_launch_description():
    nodes = [driver(name, i) for name, i in ROBOTS if i > 0]
    extra = []
    for name, i in ROBOTS:
        if i == 2:
            extra.append(Node(package='p', executable='e', name='only_' + name))
    cfg = os.path.join(get_package_share_directory('pkg'), 'config', 'x.yaml')
    return LaunchDescription(nodes + extra + [
        Node(package='p', executable='e', name='with_file', parameters=[{'cfg': cfg}])])
""")
    assert [n.name for n in model.nodes] == [
        "/alpha/unit_1", "/beta/unit_2", "/only_beta", "/with_file"]
    assert model.nodes[0].remaps == [("cmd", "/alpha/cmd")]
    params = {p.name: p.value for p in model.params}
    assert params["/beta/unit_2/limits.v"] == 1.0
    assert params["/alpha/unit_1/limits.w"] == [1, 2]
    assert params["/alpha/unit_1/frame"] == "alpha/base"
    assert params["/with_file/cfg"].endswith("src/pkg/config/x.yaml")
    assert model.diagnostics == []


def test_conditions_known_unknown_and_config_equals(write_tree):
    model, _ = run(write_tree, """
def generate_launch_description():
    mode = LaunchConfiguration('mode')
    return LaunchDescription([
        DeclareLaunchArgument('mode', default_value='sim'),
        DeclareLaunchArgument('robot'),
        Node(package='p', executable='e', name='sim',
             condition=LaunchConfigurationEquals('mode', 'sim')),
        Node(package='p', executable='e', name='real', condition=UnlessCondition(
            PythonExpression(["'", mode, "' == 'sim'"]))),
        Node(package='p', executable='e', name='maybe',
             condition=IfCondition(LaunchConfiguration('robot'))),
    ])
""")
    assert [n.name for n in model.nodes] == ["/sim", "/maybe"]
    [cond] = model.nodes[1].conditions
    assert (cond.text, cond.statement, cond.kind) == (
        "LaunchConfiguration('robot')", "if", "launch")
    assert model.args == {"mode": "sim", "robot": None}


def test_include_group_namespace_and_launch_arguments(write_tree):
    model, _ = run(write_tree, """
def generate_launch_description():
    here = os.path.dirname(__file__) if False else None
    part = os.path.join(get_package_share_directory('pkg'), 'launch', 'part.launch.py')
    return LaunchDescription([
        SetParameter(name='use_sim_time', value=True),
        GroupAction([
            PushRosNamespace('fleet'),
            IncludeLaunchDescription(PythonLaunchDescriptionSource(part),
                                     launch_arguments={'robot': 'r7'}.items()),
        ]),
        Node(package='p', executable='e', name='after'),
    ])
""", extra={"src/pkg/launch/part.launch.py": HEADER + """
def generate_launch_description():
    robot = LaunchConfiguration('robot')
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='r0'),
        Node(package='p', executable='e', name=[robot, '_driver'], namespace=robot),
    ])
"""})
    assert [n.name for n in model.nodes] == ["/fleet/r7/r7_driver", "/after"]
    assert [p.name for p in model.params] == ["/fleet/r7/r7_driver/use_sim_time",
                                              "/after/use_sim_time"]
    assert model.files == ["pkg/launch/main.launch.py", "pkg/launch/part.launch.py"]


def test_opaque_function_runs_in_the_scope_it_is_reached_in(write_tree):
    model, _ = run(write_tree, """
def setup(context, *args, **kwargs):
    count = int(LaunchConfiguration('count').perform(context))
    mode = context.launch_configurations['mode']
    nodes = [Node(package='p', executable='w', name=f'worker_{i}') for i in range(count)]
    if mode == 'debug':
        nodes.append(Node(package='p', executable='d', name='debugger'))
    return nodes

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('count', default_value='2'),
        DeclareLaunchArgument('mode'),
        OpaqueFunction(function=setup),
        TimerAction(period=3.0, actions=[Node(package='p', executable='late', name='late')]),
    ])
""", args={"count": "3"})
    names = [n.name for n in model.nodes]
    assert names == ["/worker_0", "/worker_1", "/worker_2", "/debugger", "/late"]
    debugger, late = model.nodes[3], model.nodes[4]
    assert debugger.conditions and debugger.conditions[0].text == "mode == 'debug'"
    assert [c.statement for c in late.conditions] == ["timer"]


def test_hostile_system_call_and_imports_run_nothing(write_tree, tmp_path):
    marker = tmp_path / "pwned"
    model, root = run(write_tree, f"""
import subprocess
import evil_helper
os.system('touch {marker}')
subprocess.run(['touch', '{marker}'])
__import__('os').system('touch {marker}')

def generate_launch_description():
    os.system('touch {marker}')
    eval("__import__('os').system('touch {marker}')")
    open('{marker}', 'w')
    evil_helper.go()
    return LaunchDescription([Node(package='p', executable='e', name='n')])
""", extra={"src/pkg/launch/evil_helper.py": f"open('{marker}', 'w').write('x')\n"})
    assert not marker.exists()
    assert [n.name for n in model.nodes] == ["/n"]
    messages = " ".join(d.message for d in model.diagnostics)
    assert "os.system" in messages and "evil_helper.go" in messages
    # the text eval is given is read as the file's code, never run: its builtin
    # __import__ is said where the eval is
    lines = (root / "src/pkg/launch/main.launch.py").read_text().splitlines()
    line = next(i + 1 for i, text in enumerate(lines) if text.strip().startswith("eval("))
    evaluated = [d.message for d in model.diagnostics if d.location.line == line]
    assert evaluated == ["builtin __import__ is not interpreted (never run)"], evaluated
    assert codes(model) == ["LAUNCH_PY_UNSUPPORTED"]


def test_hostile_loops_recursion_and_huge_values_are_bounded(write_tree):
    model, _ = run(write_tree, """
def forever():
    while True:
        pass

def deep(n):
    return deep(n + 1)

def generate_launch_description():
    forever()
    return LaunchDescription([Node(package='p', executable='e', name='ok')])
""")
    assert [n.name for n in model.nodes] == ["/ok"]
    assert "while loops" in " ".join(d.message for d in model.diagnostics)
    for body in ("deep(0)", "'x' * 10**12", "[0] * (10 ** 9)", "2 ** 10 ** 10",
                 "[[i for i in range(9999)] for j in range(9999)]",
                 "[1 for _ in 'a' * 1000 for _ in 'b' * 1000]"):
        hostile, _ = run(write_tree, f"""
def deep(n):
    return deep(n + 1)

def generate_launch_description():
    value = {body}
    return LaunchDescription([Node(package='p', executable='e', name='n')])
""")
        assert "LAUNCH_PY_BUDGET" in codes(hostile), body
        assert hostile.nodes == []


def test_recursion_on_values_not_known_stops_at_the_recursive_call(write_tree):
    # zed_wrapper's helper walks a YAML file it loads (not known here) recursively: each
    # call recurses on an unknown item again; the recursive call's value is unknown,
    # and what the launch function makes after it is still read (not a budget stop)
    model, _ = run(write_tree, """
def find(node):
    if isinstance(node, dict):
        for value in node.values():
            found = find(value)
            if found is not None:
                return found
    return None

def setup(context, *args, **kwargs):
    data = os.path.isfile('/no/such.yaml')
    flag = find(data)
    return [Node(package='p', executable='e', name='camera', parameters=[{'f': flag}])]

def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=setup)])
""")
    assert [n.name for n in model.nodes] == ["/camera"]
    assert "LAUNCH_PY_BUDGET" not in codes(model)
    assert any("recursive call" in d.message for d in model.diagnostics)


def test_recursion_with_some_values_not_known_stops_too(write_tree):
    """OrbbecSDK_ROS2's utils_yaml.parse_yaml(data, prefix, params) walks a YAML file not
    read here, passing the dict it fills on: not every argument is unknown, so each
    call recursed again until the depth bound stopped the whole file (orbbec_multicamera:
    no node at all). Nested a few times on a value not known, its value is unknown; a
    recursion on known values runs to its end."""
    model, _ = run(write_tree, """
def parse(data, prefix='', params=None):
    if params is None:
        params = {}
    if isinstance(data, dict):
        for key, value in data.items():
            params = parse(value, prefix=f'{key}.', params=params)
    else:
        params[prefix[:-1]] = data
    return params

def depth(n):
    return 0 if n == 0 else 1 + depth(n - 1)

def setup(context, *args, **kwargs):
    data = os.path.isfile('/no/such.yaml')
    parsed = parse(data)
    return [Node(package='p', executable='e', name='camera_%d' % depth(20),
                 parameters=[parsed])]

def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=setup)])
""")
    assert [n.name for n in model.nodes] == ["/camera_20"]
    assert "LAUNCH_PY_BUDGET" not in codes(model)

def test_hostile_sources_are_refused_before_interpretation(write_tree):
    nested, _ = run(write_tree, "x = " + "(" * 5000 + "1" + ")" * 5000 + "\n")
    assert codes(nested) in (["LAUNCH_PY_SYNTAX"], ["LAUNCH_PY_BUDGET"])
    huge, _ = run(write_tree, "x = '" + "a" * 600_000 + "'\n")
    assert codes(huge) == ["LAUNCH_PY_BUDGET"]
    broken, _ = run(write_tree, "def generate_launch_description(:\n")
    assert codes(broken) == ["LAUNCH_PY_SYNTAX"]
    assert broken.diagnostics[0].location.line > 0


def test_event_handlers_and_rewritten_parameter_files(write_tree):
    model, _ = run(write_tree, """
from launch.actions import RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch_ros.descriptions import ParameterFile
from nav2_common.launch import ReplaceString, RewrittenYaml

def generate_launch_description():
    ns = LaunchConfiguration('ns')
    base = os.path.join(get_package_share_directory('pkg'), 'config', 'robot.yaml')
    replaced = ReplaceString(source_file=base, replacements={'<robot>': ('/', ns)},
                             condition=IfCondition(LaunchConfiguration('use_ns')))
    params = ParameterFile(RewrittenYaml(source_file=replaced, root_key=ns,
                                         param_rewrites={'rate': '50'}, convert_types=True))
    spawner = Node(package='cm', executable='spawner', name='spawner')
    return LaunchDescription([
        DeclareLaunchArgument('ns', default_value='r1'),
        DeclareLaunchArgument('use_ns', default_value='true'),
        spawner,
        RegisterEventHandler(OnProcessExit(target_action=spawner, on_exit=[
            Node(package='cm', executable='spawner', name='second')])),
        GroupAction([PushRosNamespace(ns),
                     Node(package='p', executable='e', name='ctrl', parameters=[params])]),
    ])
""", extra={"src/pkg/config/robot.yaml": """
        ctrl:
          ros__parameters:
            rate: 10
            frame: <robot>/base
        """})
    second = model.nodes[1]
    assert [(c.statement, c.kind) for c in second.conditions] == [("event", "launch")]
    params = {p.name: p.value for p in model.params if p.node == "/r1/ctrl"}
    assert params == {"/r1/ctrl/rate": 50, "/r1/ctrl/frame": "/r1/base"}
    assert "pkg/config/robot.yaml" in model.files


def test_opaque_function_reads_yaml_and_evaluates_conditions(write_tree, tmp_path):
    outside = tmp_path.parent / "outside_config.yaml"
    outside.write_text("names: [leak]\n")
    model, _ = run(write_tree, f"""
import yaml

def setup(context):
    path = os.path.join(get_package_share_directory('pkg'), 'config', 'sensors.yaml')
    with open(path, 'r') as handle:
        config = yaml.safe_load(handle)
    with open('{outside}') as other:
        leaked = yaml.safe_load(other)
    with open(path, 'w') as bad:
        pass
    composed = IfCondition(LaunchConfiguration('composed')).evaluate(context)
    nodes = [Node(package='drv', executable='lidar', name=name,
                  parameters=[{{'rate': config['rate']}}]) for name in config['names']]
    if composed:
        nodes.append(Node(package='p', executable='container', name='box'))
    return nodes

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('composed', default_value='true'),
        OpaqueFunction(function=setup),
        Node(package='p', executable='e', name='cfg', parameters=[
            ParameterFile(os.path.join(get_package_share_directory('pkg'), 'config',
                                       'subst.yaml'), allow_substs=True)]),
    ])
""", extra={"src/pkg/config/sensors.yaml": "names: [front, rear]\nrate: 15\n",
            "src/pkg/config/subst.yaml": "cfg:\n  ros__parameters:\n    mode: $(var composed)\n"})
    assert [n.name for n in model.nodes] == ["/front", "/rear", "/box", "/cfg"]
    assert {p.name: p.value for p in model.params} == {
        "/cfg/mode": True, "/front/rate": 15, "/rear/rate": 15}
    messages = " ".join(d.message for d in model.diagnostics)
    assert "outside the workspace" in messages and "open() other than for reading" in messages


def test_open_takes_a_pathlib_path(write_tree):
    """roverrobotics_ros2 a90640a's accessories.launch.py opens ``Path(share,
    'config/accessories.yaml')`` and starts each accessory whose ``active`` is true:
    ``open`` takes any path-like, so the file is read as for a text path and the
    accessories it turns off are not started (they were undecided: the file unread)."""
    model, _ = run(write_tree, """
from pathlib import Path
import yaml

def generate_launch_description():
    ld = LaunchDescription()
    config_path = Path(get_package_share_directory('pkg'), 'config/accessories.yaml')
    with open(config_path, 'r') as f:
        config = yaml.load(f, Loader=yaml.FullLoader)
    for name in ('lidar', 'imu'):
        if config.get(name, {}).get('ros__parameters', {}).get('active', False):
            ld.add_action(Node(package='drv', executable=name, name=name,
                               parameters=[config_path]))
    return ld
""", extra={"src/pkg/config/accessories.yaml":
            "lidar:\n  ros__parameters:\n    active: true\n"
            "imu:\n  ros__parameters:\n    active: false\n"})
    assert [(n.name, n.conditions) for n in model.nodes] == [("/lidar", ())]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)


def test_yaml_load_with_the_unsafe_loader_reads_plain_yaml(write_tree):
    """autonomous_f1tenth's car.launch.py reads its algorithm with ``yaml.load(open(p),
    Loader=yaml.Loader)``: PyYAML's Loader reads standard YAML as the safe loader does
    (it adds the Python tags), so the value is known and the node it names is started;
    a document with a Python tag stays not known (nothing is built or run here), and
    ``BaseLoader``, whose scalars are all strings, is not interpreted."""
    model, _ = run(write_tree, """
import yaml

def generate_launch_description():
    share = get_package_share_directory('pkg')
    config = yaml.load(open(os.path.join(share, 'config/car.yaml')), Loader=yaml.Loader)
    alg = config['car']['ros__parameters']['algorithm']
    other = yaml.load(open(os.path.join(share, 'config/tagged.yaml')),
                      Loader=yaml.UnsafeLoader)
    base = yaml.load(open(os.path.join(share, 'config/car.yaml')), Loader=yaml.BaseLoader)
    return LaunchDescription([
        Node(package='controllers', executable=f'{alg}_policy', name=alg),
        Node(package='p', executable='e', name='tagged', parameters=[{'x': other}]),
        Node(package='p', executable='e', name='base', parameters=[{'y': base}]),
    ])
""", extra={"src/pkg/config/car.yaml": "car:\n  ros__parameters:\n    algorithm: ftg\n",
            "src/pkg/config/tagged.yaml": "x: !!python/object/apply:os.getcwd []\n"})
    node = model.nodes[0]
    assert (node.name, node.package, node.executable) == ("/ftg", "controllers", "ftg_policy")
    messages = [d.message for d in model.diagnostics if d.code == "LAUNCH_PY_UNSUPPORTED"]
    assert any("YAML cannot be read" in m for m in messages)
    assert any("yaml.BaseLoader" in m and "not run" in m for m in messages)
    assert not any("yaml.Loader)" in m for m in messages)


def test_match_statement_of_value_patterns(write_tree):
    """autonomous_f1tenth's sim.launch.py chooses with ``match alg: case 'rl' | 'ftg':``:
    a match whose cases test values is the if / elif / else chain Python runs (a guard
    joined with ``and``, ``case _`` or a captured name the else); a subject known picks
    one case, one not known leaves each case under its test; a case of another pattern
    (a class) is still not interpreted, said."""
    model, _ = run(write_tree, """
def pick(alg):
    match alg.lower():
        case 'rl' | 'ftg':
            return 'learned'
        case 'mpc' if alg != 'MPC':
            return 'model'
        case None:
            return 'none'
        case other:
            return 'other_' + other

def generate_launch_description():
    kind = LaunchConfiguration('kind')
    nodes = [Node(package='p', executable='e', name=pick(a)) for a in ('FTG', 'mpc', 'pp')]
    match os.environ.get('ROBOT_KIND'):
        case 'car':
            nodes.append(Node(package='p', executable='e', name='car'))
        case _:
            nodes.append(Node(package='p', executable='e', name='any'))
    match len(nodes):
        case int():
            nodes.append(Node(package='p', executable='e', name='typed'))
    return LaunchDescription(nodes)
""")
    names = [n.name for n in model.nodes]
    assert names[:3] == ["/learned", "/model", "/other_pp"]
    assert sorted(names[3:5]) == ["/any", "/car"]
    assert all(n.conditions for n in model.nodes[3:5])
    messages = [d.message for d in model.diagnostics if d.code == "LAUNCH_PY_UNSUPPORTED"]
    assert messages == ["Match statements are not interpreted"]


def test_path_substitution_grows_with_slash(write_tree):
    model, root = run(write_tree, """
from launch.substitutions import PathSubstitution
from launch_ros.substitutions import FindPackageShare

def generate_launch_description():
    base = PathSubstitution(FindPackageShare('pkg'))
    urdf = base / 'urdf' / LaunchConfiguration('model', default='bot.urdf')
    return LaunchDescription([
        Node(package='p', executable='e', name='n',
             parameters=[{'urdf': urdf, 'config': PathSubstitution('/etc') / 'x.yaml'}]),
    ])
""")
    assert {p.key: p.value for p in model.params} == {
        "urdf": str(root / "src/pkg/urdf/bot.urdf"), "config": "/etc/x.yaml"}
    assert codes(model) == []


def test_file_is_the_launch_file_path(write_tree):
    # nav2's dual_ekf_navsat.launch.py: parameters beside the launch file, by __file__
    model, _root = run(write_tree, """
from launch_ros.actions import Node

def generate_launch_description():
    launch_dir = os.path.dirname(os.path.realpath(__file__))
    params = os.path.join(launch_dir, 'ekf.yaml')
    return LaunchDescription([
        Node(package='robot_localization', executable='ekf_node', name='ekf_local',
             parameters=[params]),
    ])
""", extra={"src/pkg/launch/ekf.yaml": "ekf_local:\n  ros__parameters:\n    freq: 30.0\n"})
    assert [(p.key, p.value) for p in model.params] == [("freq", 30.0)]
    assert codes(model) == []


def test_os_path_split_of_the_launch_file_path(write_tree):
    # livox_ros_driver2's launch files: the config folder from os.path.split(...)[0]
    model, root = run(write_tree, """
from launch_ros.actions import Node

here = os.path.split(os.path.realpath(__file__))[0] + '/'
config = os.path.join(here + '../config', 'lidar.json')
head, tail = os.path.split('a/b/c.txt')

def generate_launch_description():
    return LaunchDescription([
        Node(package='p', executable='e', name='n',
             parameters=[{'config': config, 'head': head, 'tail': tail}]),
    ])
""")
    assert {p.key: p.value for p in model.params} == {
        "config": str(root / "src/pkg/launch") + "/../config/lidar.json",  # join keeps '..'
        "head": "a/b", "tail": "c.txt"}
    assert codes(model) == []


def test_a_subscript_of_an_unknown_value_says_which(write_tree):
    # a value not known statically, indexed: the diagnostic names the expression
    model, _ = run(write_tree, """
stem = os.path.expanduser('~/robot.yaml')[0]

def generate_launch_description():
    return LaunchDescription([
        Node(package='p', executable='e', name='n', parameters=[{'stem': stem}]),
    ])
""")
    # HOME not set: said where it is read (an info), and not again at the subscript
    assert [d.code for d in model.diagnostics] == ["LAUNCH_UNKNOWN_VALUE"]
    model, _ = run(write_tree, """
def generate_launch_description():
    stem = os.path.dirname(LaunchConfiguration('path'))[0]
    return LaunchDescription([
        Node(package='p', executable='e', name='n', parameters=[{'stem': stem}]),
    ])
""")
    messages = sorted(d.message for d in model.diagnostics if d.code == "LAUNCH_UNSUPPORTED")
    assert messages and all(
        "os.path.dirname(LaunchConfiguration('path'))[0]" in m for m in messages)


def test_an_argument_with_a_space_stays_one_argument(write_tree):
    # ros2_control_demos' spawners: "--controller-ros-args", "-r ~/cmd_vel:=/cmd_vel"
    model, _ = run(write_tree, """
def generate_launch_description():
    return LaunchDescription([Node(
        package='controller_manager', executable='spawner', name='spawner',
        arguments=['base', '--controller-ros-args', '-r ~/cmd_vel:=/cmd_vel', ''])])
""")
    import shlex
    assert shlex.split(model.nodes[0].args) == [
        "base", "--controller-ros-args", "-r ~/cmd_vel:=/cmd_vel", ""]


def test_pathlib_paths_of_known_parts(write_tree):
    # autoware_default_adapi: a node's namespace and name from a pathlib path
    model, _ = run(write_tree, """
import pathlib

def api_node(name):
    full = pathlib.Path('adapi/node') / name
    return Node(package='p', executable='e', namespace=str(full.parent), name=full.name,
                parameters=[{'file': (full / 'x.yaml').with_suffix('.json').as_posix(),
                             'joined': os.path.join(full, 'y')}])

def generate_launch_description():
    return LaunchDescription([api_node('interface')])
""")
    assert [n.name for n in model.nodes] == ["/adapi/node/interface"]
    assert {p.key: p.value for p in model.params} == {
        "file": "adapi/node/interface/x.json", "joined": "adapi/node/interface/y"}
    assert codes(model) == []


def test_dashing_keywords_of_node_and_composable_node(write_tree):
    # joystick_drivers' joy-composed-launch.py: ComposableNode(node_plugin=, node_name=)
    model, _ = run(write_tree, """
from launch_ros.actions import ComposableNodeContainer
from launch_ros.descriptions import ComposableNode

def generate_launch_description():
    return LaunchDescription([ComposableNodeContainer(
        node_name='joy_container', node_namespace='', package='rclcpp_components',
        node_executable='component_container', composable_node_descriptions=[
            ComposableNode(package='joy', node_plugin='joy::Joy', node_name='joy_node',
                           node_namespace='pad', parameters=[{'device_id': 0}])])])
""")
    assert [(n.name, n.package, n.executable, n.container) for n in model.nodes] == [
        ("/joy_container", "rclcpp_components", "component_container", None),
        ("/pad/joy_node", "joy", "joy::Joy", "/joy_container")]
    assert [p.name for p in model.params] == ["/pad/joy_node/device_id"]
    # said, where each is given them: Galactic and later refuse them (TypeError)
    assert [(d.code, d.location.line) for d in model.diagnostics] == [
        ("LAUNCH_DASHING_KEYWORD", 19), ("LAUNCH_DASHING_KEYWORD", 16)]


def test_str_and_repr_of_literal_containers(write_tree):
    # linorobot2 sensors.launch.py: the condition tests a name against str() of a list
    model, _ = run(write_tree, """
laser = os.getenv('LASER', '')
topics = {'': ['', ''], 'realsense': ['/camera/depth', '/camera/info'], 'zed': ['/zed', '/zi']}
SENSORS = ['zed', 'zed2']

def generate_launch_description():
    return LaunchDescription([
        Node(package='d2l', executable='d2l_node', name='d2l',
             condition=IfCondition(PythonExpression(
                 ['"" != "', laser, '" and "', laser, '" in "',
                  str(list(topics.keys())[1:]), '"'])),
             remappings=[('depth', topics[laser][0])]),
        Node(package='p', executable='e', name='zed', condition=IfCondition(PythonExpression(
            ['"zed2" in ', str(SENSORS)])),
             parameters=[{'texts': repr((1, 'a', None, {'k': [True, 2.5]})),
                          'plain': str(3) + repr('x'), 'f': f'{SENSORS}|{SENSORS!r:>18}'}]),
        Node(package='p', executable='e', name='unknown',
             parameters=[{'sub': str([LaunchConfiguration('x')])}]),
    ])
""")
    assert [n.name for n in model.nodes] == ["/zed", "/unknown"]
    params = {p.name: p.value for p in model.params}
    assert params["/zed/texts"] == "(1, 'a', None, {'k': [True, 2.5]})"
    assert params["/zed/plain"] == "3'x'"
    assert params["/zed/f"] == "['zed', 'zed2']|   ['zed', 'zed2']"
    assert params["/unknown/sub"] is None  # a substitution's text is not ours to print
    assert [(d.code, d.message) for d in model.diagnostics] == [
        ("LAUNCH_UNSUPPORTED", "str() of values not known statically")]


def test_a_new_launch_context_performs_what_needs_no_configuration(write_tree):
    """turtlebot4's bringup makes ``lc = LaunchContext()`` and includes its diagnostics
    only if ``EnvironmentVariable('TURTLEBOT4_DIAGNOSTICS', default_value='1')
    .perform(lc) == '1'``: the call and the test were unsupported, the included nodes
    conditional on the test. A new context has the configuration's environment and no
    launch configurations (a LaunchConfiguration is its default)."""
    body = """
from launch import LaunchContext
from launch.substitutions import EnvironmentVariable

def generate_launch_description():
    lc = LaunchContext()
    ld = LaunchDescription([DeclareLaunchArgument('robot', default_value='r2')])
    if EnvironmentVariable('DIAGNOSTICS', default_value='1').perform(lc) == '1':
        ld.add_action(Node(package='p', executable='e', name='diagnostics'))
    if EnvironmentVariable('MODEL').perform(lc) == 'lite':
        ld.add_action(Node(package='p', executable='e', name='lite'))
    name = LaunchConfiguration('robot', default='r1').perform(lc)
    ld.add_action(Node(package='p', executable='e', name=name))
    return ld
"""
    model, _ = run(write_tree, body, env={"MODEL": "full"})
    assert [(n.name, n.conditions) for n in model.nodes] == [
        ("/diagnostics", ()), ("/r1", ())]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)
    assert "LAUNCH_UNSUPPORTED" not in codes(model)
    model, _ = run(write_tree, body, env={"DIAGNOSTICS": "0", "MODEL": "lite"})
    assert [n.name for n in model.nodes] == ["/lite", "/r1"]
    model, _ = run(write_tree, body)  # MODEL unset, no default: unknown, the node may run
    assert [(n.name, bool(n.conditions)) for n in model.nodes] == [
        ("/diagnostics", False), ("/lite", True), ("/r1", False)]


def test_lifecycle_events_change_no_node_and_are_said_once(write_tree):
    """joystick_drivers' wiimote launch files: EmitEvent(ChangeState(...)) and
    RegisterEventHandler(OnStateTransition(...)) drive a managed node's state, which
    changes nothing in the graph: one info note per file, not a warning per call; the
    actions a transition handler runs are read, under that event."""
    model, _ = run(write_tree, """
import launch
import launch_ros
import lifecycle_msgs.msg

def generate_launch_description():
    driver = launch_ros.actions.LifecycleNode(package='p', executable='drv', name='drv',
                                              namespace='')
    configure = launch.actions.EmitEvent(event=launch_ros.events.lifecycle.ChangeState(
        lifecycle_node_matcher=launch_ros.events.lifecycle.matches_node_name('/drv'),
        transition_id=lifecycle_msgs.msg.Transition.TRANSITION_CONFIGURE))
    activate = launch.actions.EmitEvent(event=launch_ros.events.lifecycle.ChangeState(
        lifecycle_node_matcher=launch_ros.events.lifecycle.matches_node_name('/drv'),
        transition_id=lifecycle_msgs.msg.Transition.TRANSITION_ACTIVATE))
    on_configured = launch.actions.RegisterEventHandler(
        launch_ros.event_handlers.OnStateTransition(
            target_lifecycle_node=driver, start_state='configuring', goal_state='inactive',
            entities=[launch.actions.LogInfo(msg='configured'), activate,
                      Node(package='p', executable='mon', name='monitor')]))
    return LaunchDescription([driver, configure, on_configured])
""")
    assert [n.name for n in model.nodes] == ["/drv", "/monitor"]
    assert model.nodes[0].conditions == ()
    assert [c.statement for c in model.nodes[1].conditions] == ["event"]
    assert [(d.code, d.severity) for d in model.diagnostics] == [("LAUNCH_PY_LIFECYCLE", "info")]


def test_str_join_of_a_list_with_parts_not_known_is_a_value_not_known(write_tree):
    """clearpath_simulator's gz_sim.launch.py joins ``os.path.join(p, 'share')`` for each
    entry of ``AMENT_PREFIX_PATH`` (not set here): the loop runs once on an entry not
    known, and ``':'.join`` of those paths is a value with a part not known, not
    "str.join() fails: ... Lazy found" (Python's join does not fail there)."""
    model, _ = run(write_tree, """
def generate_launch_description():
    paths = [os.path.join(p, 'share') for p in os.getenv('AMENT_PREFIX_PATH').split(':')]
    joined = ':'.join(paths)
    return LaunchDescription([
        Node(package='pkg', executable='sim', name='sim',
             parameters=[{'path': '/base:' + joined,
                          'arg': ':'.join([LaunchConfiguration('w'), 'x'])}]),
    ])
""")
    assert not [d.message for d in model.diagnostics if "fails" in d.message]
    params = {p.name: p.value for p in model.params}
    assert set(params) == {"/sim/path", "/sim/arg"}


def test_python_if_on_a_launch_object_is_always_true(write_tree):
    """A plain ``if`` on a launch object (a condition, a substitution, an action) is
    Python's truth of an ordinary object: true, whatever the launch arguments (launch
    evaluates a condition only as an action's ``condition=``). Only the ``if`` branch
    runs, with an info that says so; ``not`` of one is false. A string with
    substitutions, an unknown and a container keep their truth: not known (both
    branches), or the container's length."""
    model, root = run(write_tree, """
def generate_launch_description():
    chosen = []
    if LaunchConfigurationEquals('aligned', 'True'):
        chosen.append(Node(package='p', executable='e', name='aligned_node'))
    else:
        chosen.append(Node(package='p', executable='e', name='unaligned_node'))
    if not IfCondition(LaunchConfiguration('rviz')):
        chosen.append(Node(package='p', executable='e', name='never_node'))
    if LaunchConfiguration('x') and []:
        chosen.append(Node(package='p', executable='e', name='empty_list_node'))
    if os.environ.get('UNSET_VAR_FOR_TEST'):
        chosen.append(Node(package='p', executable='e', name='env_node'))
    return LaunchDescription([DeclareLaunchArgument('aligned', default_value='False'),
                              *chosen])
""", args={"aligned": "False"})
    assert [n.name for n in model.nodes] == ["/aligned_node", "/env_node"]
    assert model.nodes[0].conditions == ()
    assert model.nodes[1].conditions != ()  # an unset variable: both branches, guarded
    lines = (root / "src/pkg/launch/main.launch.py").read_text().splitlines()
    test_line = 1 + next(n for n, text in enumerate(lines) if "if LaunchConfigurationEq" in text)
    found = [(d.code, d.severity, d.location.line) for d in model.diagnostics
             if d.code in ("LAUNCH_PY_ALWAYS_TRUE", "LAUNCH_UNSUPPORTED", "LAUNCH_PY_UNSUPPORTED")
             and d.location.line < test_line + 5]
    assert found == [("LAUNCH_PY_ALWAYS_TRUE", "warning", test_line)]
    assert "LaunchConfigurationEquals('aligned', 'True')" in next(
        d.message for d in model.diagnostics if d.code == "LAUNCH_PY_ALWAYS_TRUE")


def test_and_or_of_launch_conditions_takes_one_whole(write_tree):
    """``condition=IfCondition(a) and IfCondition(b)`` (panther_ros dcdc6731): Python
    takes the first condition as true without evaluating it, so ``and`` gives the second
    whole and ``or`` the first; the other is never tested. The node runs under the one
    taken, with a warning at the operand whose truth was taken
    (``LAUNCH_PY_BOOLEAN_OBJECT``). An action tested so (a variable that may hold None)
    is not said."""
    model, root = run(write_tree, """
def generate_launch_description():
    a = LaunchConfiguration('a')
    b = LaunchConfiguration('b')
    spare = None
    return LaunchDescription([
        DeclareLaunchArgument('a', default_value='false'),
        DeclareLaunchArgument('b', default_value='true'),
        Node(package='p', executable='e', name='both_node',
             condition=IfCondition(a) and IfCondition(b)),
        Node(package='p', executable='e', name='either_node',
             condition=IfCondition(b) or IfCondition(a)),
        *([spare and Node(package='p', executable='e', name='spare_node')] if spare else []),
    ])
""")
    # a is false: both_node would not run if launch tested both; Python kept b's alone
    assert sorted(n.name for n in model.nodes) == ["/both_node", "/either_node"]
    lines = (root / "src/pkg/launch/main.launch.py").read_text().splitlines()
    said = sorted((d.location.line, d.severity, d.message) for d in model.diagnostics
                  if d.code == "LAUNCH_PY_BOOLEAN_OBJECT")
    assert [line for line, _, _ in said] == [
        1 + n for n, text in enumerate(lines) if "condition=IfCondition" in text]
    assert {severity for _, severity, _ in said} == {"warning"}
    assert "'and' takes the launch object 'IfCondition(a)'" in said[0][2]
    assert "'or' takes the launch object 'IfCondition(b)'" in said[1][2]
    assert not [d for d in model.diagnostics if d.code == "LAUNCH_PY_ALWAYS_TRUE"]


def test_a_call_of_a_value_python_does_not_call_is_a_type_error(write_tree):
    # clearpath_robot 577bfcf: a comma missing between two remappings calls the first
    # tuple with the second: a TypeError, said as such (not "a value not known");
    # a try that catches TypeError takes it
    model, _ = run(write_tree, """
def generate_launch_description():
    try:
        caught = 'x'(1)
    except TypeError:
        caught = 'handled'
    return LaunchDescription([Node(
        package='p', executable='e', name=caught,
        remappings=[('image_color', 'color/image') ('image_mono', 'mono/image')])])
""")
    said = [d.message for d in model.diagnostics if d.code == "LAUNCH_PY_UNSUPPORTED"]
    assert any("('image_color', 'color/image') fails: TypeError: 'tuple' object is not "
               "callable" in m for m in said), said
    assert not any("not known statically" in m and "image_color" in m for m in said)
    assert [n.name for n in model.nodes] == ["/handled"]


def test_eval_of_a_known_text_is_its_value_never_run(write_tree):
    # yolo_ros 2553d0a: ``use_tracking = eval(context.perform_substitution(use_tracking))``
    # in an OpaqueFunction, then ``IfCondition(PythonExpression([str(use_tracking)]))``
    model, _ = run(write_tree, """
def setup(context, use_tracking, use_3d):
    use_tracking = eval(context.perform_substitution(use_tracking))
    use_3d = eval(context.perform_substitution(use_3d))
    size = eval("2 * 3")
    return [
        Node(package='p', executable='tracker', name='tracker',
             parameters=[{'size': size}],
             condition=IfCondition(PythonExpression([str(use_tracking)]))),
        Node(package='p', executable='detect', name='detect',
             condition=IfCondition(PythonExpression([str(use_3d)]))),
        Node(package='p', executable='odd', name='odd',
             parameters=[{'v': eval(os.environ.get('NOT_SET', '__import__("os")'))}]),
    ]

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('use_tracking', default_value='True'),
        DeclareLaunchArgument('use_3d', default_value='False'),
        OpaqueFunction(function=setup, args=[LaunchConfiguration('use_tracking'),
                                             LaunchConfiguration('use_3d')]),
    ])
""")
    assert sorted(n.name for n in model.nodes) == ["/odd", "/tracker"]
    params = {p.name: p.value for p in model.params}
    assert params["/tracker/size"] == 6
    # a text that is no expression of the subset (a call of __import__) stays unknown
    assert "/odd/v" not in params or params["/odd/v"] is None
    assert "LAUNCH_PY_UNSUPPORTED" in codes(model)


def test_fields_set_on_an_object_not_interpreted_are_not_said_again(write_tree):
    """crane_x7's launch files: ``loader = RobotDescriptionLoader()`` of a package not in
    the workspace (said there), then ``loader.port_name = '/dev/ttyUSB0'`` and four more
    fields, each said "assignment to this target is not interpreted"; its ``.load()``
    stays unknown where it is used."""
    model, _ = run(write_tree, """
from robot_description_loader import RobotDescriptionLoader

def generate_launch_description():
    loader = RobotDescriptionLoader()
    loader.port_name = '/dev/ttyUSB0'
    loader.baudrate = '3000000'
    return LaunchDescription([
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[{'robot_description': loader.load()}]),
    ])
""")
    said = [d.message for d in model.diagnostics if d.code == "LAUNCH_PY_UNSUPPORTED"]
    assert len(said) == 1 and "RobotDescriptionLoader" in said[0]
    [param] = [p for p in model.params if p.name.endswith("/robot_description")]
    assert param.value is None  # not known
    # a field of a value known to be no object is still said
    model, _ = run(write_tree, """
def generate_launch_description():
    name = 'text'
    name.field = 1
    return LaunchDescription([])
""")
    assert [d.message for d in model.diagnostics if d.code == "LAUNCH_PY_UNSUPPORTED"] == [
        "assignment to this target is not interpreted"]


def test_a_pathlib_path_joined_with_text_known_at_launch_time(write_tree):
    # robosub-ros2's fuse.launch.py: the parameter file is named by an environment
    # variable, ``Path(share) / 'config' / f'{robot_name}.yaml'``; pathlib joins the str
    # as launch runs, so the file is the share folder's config/<robot>.yaml: named with a
    # '?' where the variable is not set, not an operation we cannot read
    body = """
from pathlib import Path

def generate_launch_description():
    robot = os.getenv('ROBOT_NAME')
    share = Path(get_package_share_directory('pkg'))
    return LaunchDescription([Node(package='p', executable='e', name='n',
        parameters=[str(share / 'config' / f'{robot}.yaml')])])
"""
    extra = {"src/pkg/config/crush.yaml": "n:\n  ros__parameters:\n    rate: 3\n"}
    model, root = run(write_tree, body, extra=extra)
    assert codes(model) == ["LAUNCH_PARAM_FILE", "LAUNCH_UNKNOWN_VALUE"]
    unknown = next(d for d in model.diagnostics if d.code == "LAUNCH_PARAM_FILE")
    assert str(root / "src/pkg/config/?.yaml") in unknown.message
    model, _ = run(write_tree, body, extra=extra, env={"ROBOT_NAME": "crush"})
    assert [(p.name, p.value) for p in model.params] == [("/n/rate", 3)]
    assert codes(model) == []


def test_os_path_normpath_of_a_known_path(write_tree):
    # kalman_robot's cloud_raster.launch.py: os.path.normpath(os.path.abspath(...)); a
    # pure function of its text, as os.path computes it
    model, _ = run(write_tree, """
def generate_launch_description():
    share = get_package_share_directory('pkg')
    config = os.path.normpath(os.path.join(share, 'launch', '..', 'config', '.', 'a.yaml'))
    return LaunchDescription([Node(package='p', executable='e', name='n',
        parameters=[config, {'relative': os.path.normpath('a//b/../c/')}])])
""", extra={"src/pkg/config/a.yaml": "n:\n  ros__parameters:\n    rate: 3\n"})
    assert sorted((p.name, p.value) for p in model.params) == [
        ("/n/rate", 3), ("/n/relative", "a/c")]
    assert codes(model) == []


def test_sum_adds_with_the_interpreters_plus(write_tree):
    # kalman_robot's aruco / clouds / nav2 launch files: a list of actions made as
    # ``sum((make(id) for id in ids), [])``; numbers too, and Python's TypeError for a
    # text start
    body = """
def one(ns):
    return [Node(package='p', executable='e', name='tracker', namespace=ns)]

def setup(context):
    ids = [x for x in LaunchConfiguration('ids').perform(context).split(' ') if x != '']
    actions = []
    actions += sum((one(i) for i in ids), [])
    total = sum([1, 2, 3]) + sum((0.5, 0.5), start=10)
    actions.append(Node(package='p', executable='e', name='n', parameters=[{'total': total}]))
    return actions

def generate_launch_description():
    return LaunchDescription([DeclareLaunchArgument('ids', default_value='front back'),
                              OpaqueFunction(function=setup)])
"""
    model, _ = run(write_tree, body)
    assert [n.name for n in model.nodes] == ["/front/tracker", "/back/tracker", "/n"]
    assert [(p.name, p.value) for p in model.params] == [("/n/total", 17.0)]
    assert codes(model) == []
    model, _ = run(write_tree, body, args={"ids": "left"})
    assert [n.name for n in model.nodes] == ["/left/tracker", "/n"]
    model, _ = run(write_tree, """
def generate_launch_description():
    name = sum(['a', 'b'], '')
    return LaunchDescription([Node(package='p', executable='e', name=name)])
""")
    assert any("can't sum strings" in d.message for d in model.diagnostics)


def test_the_log_folder_of_launch_logging(write_tree):
    # cabot-navigation's launch files keep each run's logs together:
    # ``SetEnvironmentVariable('ROS_LOG_DIR', launch_config.log_dir)``, a folder launch
    # chooses when it runs: a value not known here, not a construct not read
    model, _ = run(write_tree, """
from launch.actions import SetEnvironmentVariable
from launch.logging import launch_config
import launch.logging

def generate_launch_description():
    return LaunchDescription([
        SetEnvironmentVariable('ROS_LOG_DIR', launch_config.log_dir),
        Node(package='p', executable='e', name='n',
             parameters=[{'logs': launch.logging.launch_config.log_dir}]),
    ])
""")
    assert [n.name for n in model.nodes] == ["/n"]
    assert [d.code for d in model.diagnostics
            if d.code in ("LAUNCH_UNSUPPORTED", "LAUNCH_PY_UNSUPPORTED")] == []


def test_perform_and_evaluate_take_the_context_by_keyword(write_tree):
    # reseq_ros2's arm.launch.py: ``LaunchConfiguration('use_sim_time').perform(
    # context=context)`` inside an OpaqueFunction, Substitution.perform's parameter
    # named: the argument's value, as given by position
    model, _ = run(write_tree, """
def setup(context):
    mode = LaunchConfiguration('mode').perform(context=context)
    nodes = [Node(package='p', executable='e', name='a', parameters=[{'mode': mode}])]
    if IfCondition(LaunchConfiguration('arm')).evaluate(context=context):
        nodes.append(Node(package='p', executable='e', name='arm'))
    return nodes

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('mode', default_value='fast'),
        DeclareLaunchArgument('arm', default_value='false'),
        OpaqueFunction(function=setup),
    ])
""")
    assert [n.name for n in model.nodes] == ["/a"]
    assert [(p.name, p.value) for p in model.params] == [("/a/mode", "fast")]
    assert [d.code for d in model.diagnostics
            if d.code in ("LAUNCH_UNSUPPORTED", "LAUNCH_PY_UNSUPPORTED")] == []
