"""Python launch file shapes met on real workspaces (survey of 2026-11-29)."""

from __future__ import annotations

from test_launch_ros2_python import codes, run


def test_add_entity_of_a_launch_description_declares_its_arguments(write_tree):
    """ur_moveit_config's ur_moveit.launch.py: ``ld.add_entity(declare_arguments())``
    adds a LaunchDescription of DeclareLaunchArgument; their defaults hold after it."""
    model, _ = run(write_tree, """
def declare_arguments():
    return LaunchDescription([
        DeclareLaunchArgument('launch_rviz', default_value='false'),
        DeclareLaunchArgument('robot', default_value='r1'),
    ])

def generate_launch_description():
    ld = LaunchDescription()
    ld.add_entity(declare_arguments())
    ld.add_entity(Node(package='p', executable='e', name=LaunchConfiguration('robot')))
    ld.add_action(Node(package='p', executable='rviz', name='rviz',
                       condition=IfCondition(LaunchConfiguration('launch_rviz'))))
    return ld
""")
    assert [n.name for n in model.nodes] == ["/r1"]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)
    assert "LAUNCH_ARG_UNSET" not in codes(model)


def test_module_level_calls_fill_the_lists_the_launch_function_reads(write_tree):
    """usb_cam's camera.launch.py: ``CAMERAS.append(CameraConfig(...))`` at module level
    and a comprehension over CAMERAS in generate_launch_description. The append runs
    when launch imports the file: the list is not empty, its item is not known, and
    the node it makes has an unknown name, not no node at all."""
    model, _ = run(write_tree, """
from camera_config import CameraConfig

CAMERAS = []
CAMERAS.append(CameraConfig(name='camera1'))
EXTRA = []
for index in range(2):
    EXTRA.append('extra_%d' % index)

def generate_launch_description():
    nodes = [Node(package='cam', executable='cam_node', name=camera.name,
                  namespace=camera.namespace) for camera in CAMERAS]
    nodes += [Node(package='p', executable='e', name=name) for name in EXTRA]
    return LaunchDescription(nodes)
""")
    names = [n.name for n in model.nodes]
    assert len(names) == 3 and "?" in names[0]
    assert names[1:] == ["/extra_0", "/extra_1"]
    messages = [d.message for d in model.diagnostics]
    assert any("camera_config.CameraConfig" in m for m in messages)
    assert any("camera.name (an attribute of a value not known statically)" in m
               for m in messages)
    assert not any("_Bound" in m or "module-level" in m for m in messages)


def test_a_list_joined_to_an_unknown_keeps_its_actions(write_tree):
    """realsense2_camera's examples: ``helper.declare(...) + [Node(...), ...]`` where
    the helper is not interpreted. The known actions stay; a LaunchDescription of a
    value not known says so instead of being empty."""
    model, _ = run(write_tree, """
import helper_module

def generate_launch_description():
    return LaunchDescription(
        helper_module.declare_arguments() + helper_module.more() + [
            Node(package='rviz2', executable='rviz2', name='rviz2'),
        ] + helper_module.tail() + [Node(package='p', executable='e', name='last')])
""")
    assert [n.name for n in model.nodes] == ["/rviz2", "/last"]
    model, _ = run(write_tree, """
import helper_module

def generate_launch_description():
    return LaunchDescription(helper_module.everything())
""")
    assert model.nodes == []
    messages = [d.message for d in model.diagnostics]
    assert any("launch description is not known statically" in m for m in messages)


HELPER = """
import os
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

PARAMETERS = [{'name': 'camera_name', 'default': 'cam'},
              {'name': 'log_level', 'default': 'info'}]

def declare(parameters):
    return [DeclareLaunchArgument(p['name'], default_value=p['default'])
            for p in parameters]

def setup(context, suffix=''):
    name = LaunchConfiguration('camera_name' + suffix).perform(context)
    return [Node(package='cam', executable='cam_node', name=name,
                 arguments=['--log-level', LaunchConfiguration('log_level' + suffix)])]
"""


def test_a_helper_module_put_on_sys_path_is_read(write_tree):
    """realsense2_camera's examples (``sys.path.append(<share>/launch)``; ``import
    rs_launch``; ``OpaqueFunction(function=rs_launch.launch_setup)``) and usb_cam
    (``from camera_config import ...``): a module of the workspace found on the
    sys.path the file builds is interpreted like the file; its nodes are placed in it."""
    model, _ = run(write_tree, """
import sys
import pathlib
sys.path.append(str(pathlib.Path(__file__).parent.absolute()))
sys.path.append(os.path.join(get_package_share_directory('pkg'), 'launch', 'helpers'))
import cam_helpers
from cam_helpers import declare as declare_them

def generate_launch_description():
    return LaunchDescription(declare_them(cam_helpers.PARAMETERS) + [
        OpaqueFunction(function=cam_helpers.setup)])
""", extra={"src/pkg/launch/helpers/cam_helpers.py": HELPER})
    assert [n.name for n in model.nodes] == ["/cam"]
    node = model.nodes[0]
    assert node.location.file.endswith("launch/helpers/cam_helpers.py")
    written = HELPER.lstrip("\n").splitlines()
    assert written[node.location.line - 1].strip().startswith("return [Node(")
    assert not any(d.severity == "warning" for d in model.diagnostics), model.diagnostics


def test_a_helper_module_not_on_sys_path_is_not_read(write_tree):
    """launch loads the file by its path and puts no folder on sys.path: ``import
    cam_helpers`` without ``sys.path.append`` finds nothing of the workspace."""
    model, _ = run(write_tree, """
import cam_helpers

def generate_launch_description():
    return LaunchDescription(cam_helpers.declare(cam_helpers.PARAMETERS) + [
        OpaqueFunction(function=cam_helpers.setup)])
""", extra={"src/pkg/launch/cam_helpers.py": HELPER})
    assert model.nodes == []
    assert "LAUNCH_UNSUPPORTED" in codes(model)


def test_helper_modules_bounded_cycles_and_folders_outside(write_tree, tmp_path):
    """A helper that imports itself is read once and gets itself as read so far, as
    Python gives it (a name it has not bound yet is not there); a folder outside the workspace
    put on sys.path is never read from; a folder not known statically is said."""
    outside = tmp_path / "elsewhere"
    outside.mkdir()
    (outside / "secret_helper.py").write_text("NODES = ['x']\n")
    model, _ = run(write_tree, f"""
import sys
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
sys.path.append({str(outside)!r})
sys.path.append(os.environ.get('NOT_SET_ANYWHERE'))
import looping
import secret_helper

def generate_launch_description():
    return LaunchDescription([Node(package='p', executable='e', name=n)
                              for n in looping.NAMES] + [
        Node(package='p', executable='e', name=secret_helper.NODES[0])])
""", extra={"src/pkg/launch/looping.py":
                "import looping\nfrom looping import LATER\nNAMES = ['a', 'b']\nLATER = 1\n"})
    assert [n.name for n in model.nodes][:2] == ["/a", "/b"]
    assert "x" not in model.nodes[2].name
    messages = [d.message for d in model.diagnostics]
    assert any("LATER is not defined in looping as read here" in m for m in messages)
    assert any("sys.path.append of a folder not known statically" in m for m in messages)


def test_copy_and_deepcopy_of_known_values(write_tree):
    """realsense2_camera's rs_dual_camera_launch.py: ``copy.deepcopy(params)`` then a
    suffix on each copy's name, for two cameras; the original stays as it was."""
    model, _ = run(write_tree, """
import copy
from copy import copy as shallow

PARAMS = [{'name': 'camera_name', 'default': 'cam'}]

def duplicate(params, suffix):
    local = copy.deepcopy(params)
    for p in local:
        p['name'] += suffix
    return local

def generate_launch_description():
    first, second = duplicate(PARAMS, '1'), duplicate(PARAMS, '2')
    same = shallow(PARAMS)
    same.append({'name': 'extra'})
    return LaunchDescription([Node(package='p', executable='e', name=p['name'])
                              for p in first + second + PARAMS + same])
""")
    assert [n.name for n in model.nodes] == [
        "/camera_name1", "/camera_name2", "/camera_name", "/camera_name", "/extra"]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)


def _conditional(model) -> dict[str, bool]:
    return {n.name: bool(n.conditions) for n in model.nodes}


def test_a_return_under_a_test_not_known_is_one_of_the_outcomes(write_tree):
    """realsense2_description's view_model.launch.py: ``if 'model' not in params:
    print(usage); return LaunchDescription()`` with params from sys.argv. The early
    return is one outcome; the nodes after it run under the other branch's test."""
    model, _ = run(write_tree, """
import sys

def generate_launch_description():
    params = dict([aa for aa in [aa.split(':=') for aa in sys.argv] if len(aa) == 2])
    if 'model' not in params:
        print('USAGE')
        return LaunchDescription([Node(package='p', executable='usage', name='usage')])
    return LaunchDescription([Node(package='rviz2', executable='rviz2', name='rviz2')])
""")
    assert _conditional(model) == {"/usage": True, "/rviz2": True}
    rviz = model.nodes[1]
    assert any("'model' not in params" in str(c) for c in rviz.conditions)


def test_both_branches_returning_and_known_tests_are_as_before(write_tree):
    model, _ = run(write_tree, """
def pick(flag):
    if flag:
        return [Node(package='p', executable='e', name='yes')]
    else:
        return [Node(package='p', executable='e', name='no')]
    return [Node(package='p', executable='e', name='never')]

def generate_launch_description():
    known = pick(True)
    unknown = pick(os.environ.get('NOT_SET_HERE_EITHER') == '1')
    return LaunchDescription(known + unknown)
""")
    assert [n.name for n in model.nodes] == ["/yes", "/yes", "/no"]
    assert [bool(n.conditions) for n in model.nodes] == [False, True, True]


def test_a_loop_over_a_value_not_known_may_make_its_nodes(write_tree):
    """A ``for`` statement or a comprehension over a value not known statically
    (``os.listdir``, a helper's result) runs its body once on an unknown item, under
    the loop: a conditional node of unknown name, not no node at all. (``sys.argv`` is
    known now: the ros2 launch command line, tests/test_launch_ros2_while_argv.py.)"""
    model, _ = run(write_tree, """
def generate_launch_description():
    nodes = []
    for robot in os.listdir('/robots'):
        nodes.append(Node(package='p', executable='driver', name=robot + '_driver'))
        nodes.append(Node(package='p', executable='fixed', name='fixed'))
    devices = [d for d in os.listdir('/dev') if d.startswith('video')]
    cameras = [Node(package='cam', executable='cam_node', name=d) for d in devices]
    listed = dict([(d, len(d)) for d in devices])
    return LaunchDescription(nodes + cameras + [
        Node(package='p', executable='e', name='lister', arguments=[', '.join(devices)],
             parameters=[listed])])
""")
    names = [n.name for n in model.nodes]
    assert len(names) == 4 and "?" in names[0] and names[1] == "/fixed" and "?" in names[2]
    # the loops' own nodes are conditional; a node made later from the list such a
    # loop made is named '?' (the list holds one item not known, not a condition)
    assert [bool(n.conditions) for n in model.nodes][:2] == [True, True]
    assert not model.nodes[3].conditions
    assert [n.executable for n in model.nodes] == ["driver", "fixed", "cam_node", "e"]
    assert not any("fails" in d.message for d in model.diagnostics)
    assert any("filter not known statically; the item is kept" in d.message
               for d in model.diagnostics)


def test_list_remove_and_pop(write_tree):
    """Universal_Robots_ROS2_Driver's ur_control.launch.py: the initial joint controller
    moves from the inactive list to the active one (``append`` / ``remove``)."""
    model, _ = run(write_tree, """
def generate_launch_description():
    active = ['broadcaster']
    inactive = ['joint_trajectory_controller', 'forward_controller', 'spare']
    chosen = LaunchConfiguration('initial', default='joint_trajectory_controller')
    chosen = 'joint_trajectory_controller'
    active.append(chosen)
    inactive.remove(chosen)
    last = inactive.pop()
    options = {'a': 1, 'b': 2}
    first = options.pop('a')
    other = options.pop('zzz', 'fallback')
    inactive.remove('not_there')
    return LaunchDescription([
        Node(package='cm', executable='spawner', name='active', arguments=active),
        Node(package='cm', executable='spawner', name='inactive', arguments=inactive),
        Node(package='p', executable='e', name=last + '_' + other + '_' + str(first)),
    ])
""")
    assert [(n.name, n.args) for n in model.nodes] == [
        ("/active", "broadcaster joint_trajectory_controller"),
        ("/inactive", "forward_controller"), ("/spare_fallback_1", "")]
    messages = [d.message for d in model.diagnostics]
    assert messages == ["list.remove('not_there') fails: not in the list"]


def test_execute_process_of_ros2_run_and_ros2_topic_pub_starts_nodes(write_tree):
    """pointcloud_to_laserscan's sample launch files publish the scan with
    ``ExecuteProcess(cmd=['ros2', 'topic', 'pub', ...])``: a publisher of the graph
    (``models.commands`` reads its topic), named as ros2cli names it; ``ros2 run PKG
    EXE`` is that node. Other processes (a simulator) still make no node."""
    model, _ = run(write_tree, """
from launch.actions import ExecuteProcess
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackagePrefix

def generate_launch_description():
    scanner = LaunchConfiguration('scanner', default='front')
    return LaunchDescription([
        ExecuteProcess(cmd=['ros2', 'topic', 'pub', '-r', '10', [scanner, '/scan'],
                            'sensor_msgs/msg/LaserScan', '{}'], name='scan_publisher'),
        ExecuteProcess(cmd=['ros2', 'topic', 'pub', '--node-name', 'named_pub', 'chatter',
                            'std_msgs/msg/String']),
        ExecuteProcess(cmd=['ros2', 'run', 'demo_nodes_cpp', 'talker', '--ros-args', '-r',
                            '__node:=speaker'],
                       condition=IfCondition(LaunchConfiguration('talk', default='true'))),
        ExecuteProcess(cmd=['gz', 'sim', '-r', 'world.sdf']),
        ExecuteProcess(cmd=[PathJoinSubstitution([FindPackagePrefix('tools'), 'lib',
                                                  'bridge.py']), scanner, '--port']),
    ])
""")
    assert [(n.name, n.package, n.executable) for n in model.nodes] == [
        ("/_ros2cli_?", "ros2topic", "ros2"), ("/named_pub", "ros2topic", "ros2"),
        ("/speaker", "demo_nodes_cpp", "talker")]
    assert model.nodes[0].args == (
        "topic pub -r 10 front/scan sensor_msgs/msg/LaserScan {}")
    assert "LAUNCH_UNSUPPORTED" not in codes(model)
    # the simulator is said: a ROS node it may start is not in the graph
    assert [(d.code, d.severity, d.location.line, d.message) for d in model.diagnostics
            if d.code == "LAUNCH_PROCESS"] == [
        ("LAUNCH_PROCESS", "info", 26, "process gz sim -r started here is no node the "
                                       "reader can name"),
        ("LAUNCH_PROCESS", "info", 27, "process bridge.py started here is no node the "
                                       "reader can name")]


def test_xml_executable_of_ros2_topic_pub_read_when_performed(write_tree):
    """Autoware's dummy_scenario_selector_*.launch.xml: ``<executable cmd="$(var cmd)"
    shell="true"/>`` with cmd ``ros2 topic pub $(var output_scenario) TYPE '{...}'``:
    the command line is known only when the file runs; then it is a publisher."""
    from test_launch_ros2 import run as run_xml

    model, _ = run_xml(write_tree, "main.launch.xml", """
<launch>
  <arg name="output_scenario" default="/planning/scenario"/>
  <arg name="cmd" default="ros2 topic pub $(var output_scenario)
    tier4_planning_msgs/msg/Scenario '{current_scenario: LaneDriving}'"/>
  <executable cmd="$(var cmd)" name="scenario_pub" output="screen" shell="true"/>
  <arg name="listen" default="false"/>
  <executable cmd="ros2 run demo_nodes_cpp listener" if="$(var listen)"/>
  <executable cmd="ros2 run demo_nodes_cpp talker --ros-args -r __node:=speaker"/>
  <executable cmd="gz sim -r world.sdf"/>
  <executable cmd="$(var not_declared_anywhere)"/>
</launch>
""")
    assert [(n.name, n.package, n.executable) for n in model.nodes] == [
        ("/_ros2cli_?", "ros2topic", "ros2"), ("/speaker", "demo_nodes_cpp", "talker")]
    assert model.nodes[0].args == ("topic pub /planning/scenario "
                                   "tier4_planning_msgs/msg/Scenario "
                                   "'{current_scenario: LaneDriving}'")
    assert sorted(d.message.split(" started")[0] for d in model.diagnostics
                  if d.code == "LAUNCH_PROCESS") == [
        "process (a command not known statically)", "process gz sim -r"]


def test_undecided_info_names_two_instances_of_one_name_once():
    """rosbot_bringup's combined.launch.py starts micro_ros_agent in either branch of an
    ``if`` on an environment variable: two instances of one name, each of unknown
    interface; the undecided info names it once, counted once per possible finding."""
    from test_query_catalogue import RULES, configuration

    from haros_arch.query.catalogue import run_rule

    found = run_rule(RULES["subscriber-without-publisher"], configuration({
        "nodes": [{"name": "/agent", "node": None}, {"name": "/agent", "node": None}],
        "links": [{"kind": "subscribe", "node": "/controller", "name": "/joint_states",
                   "type": "sensor_msgs/JointState"},
                  {"kind": "subscribe", "node": "/controller", "name": "/odom",
                   "type": "nav_msgs/Odometry"}]}))
    (info,) = found
    assert info.message.endswith(": /agent (2)"), info.message


def test_outcomes_that_share_actions_run_them_once(write_tree):
    """One LaunchDescription returned from two places, or two lists that share their
    first actions: each action is in the graph once, not once per outcome."""
    model, _ = run(write_tree, """
def generate_launch_description():
    ld = LaunchDescription([Node(package='p', executable='e', name='base')])
    base = [Node(package='p', executable='e', name='shared')]
    if os.environ.get('NOT_SET_FOR_THIS_TEST'):
        ld.add_action(Node(package='p', executable='e', name='extra'))
        return LaunchDescription([ld] + base)
    ld.add_action(Node(package='p', executable='e', name='other'))
    return LaunchDescription([ld] + base)
""")
    names = sorted(n.name for n in model.nodes)
    assert names == ["/base", "/extra", "/other", "/shared"]


def test_a_helper_returning_one_of_two_lists_of_names_gives_an_unknown(write_tree):
    model, _ = run(write_tree, """
def controllers():
    if os.environ.get('NOT_SET_FOR_THIS_TEST'):
        return ['a']
    return ['b']

def same():
    if os.environ.get('NOT_SET_FOR_THIS_TEST'):
        return ['c']
    return ['c']

def generate_launch_description():
    return LaunchDescription([
        Node(package='p', executable='spawner', name='s', arguments=controllers()),
        Node(package='p', executable='spawner', name='t', arguments=same())])
""")
    assert [n.args for n in model.nodes] == ["?", "c"]


def test_a_launch_configuration_default_that_is_no_text_is_pythons_str(write_tree):
    """rosbot_xl_bringup's combined.launch.py: ``LaunchConfiguration(name,
    default=True)``. launch turns a default item that is neither a str nor a
    substitution into ``str(item)``: "True", not "true", so a PythonExpression over it
    (bringup.launch.py's ``use_sim or combined_launch_deprecated``) is valid Python and
    its condition is known."""
    model, _ = run(write_tree, """
def generate_launch_description():
    flag = LaunchConfiguration('deprecated', default=True)
    return LaunchDescription([
        Node(package='p', executable='e', name='agent',
             condition=UnlessCondition(PythonExpression(['False or ', flag]))),
        Node(package='p', executable='e', name='kept',
             condition=IfCondition(PythonExpression([flag, ' and True']))),
        Node(package='p', executable='e',
             name=LaunchConfiguration('unit', default=['n', 7, True])),
        Node(package='p', executable='e', name=LaunchConfiguration('count', default=3)),
    ])
""")
    assert [n.name for n in model.nodes] == ["/kept", "/n7True", "/3"]
    assert "LAUNCH_UNSUPPORTED" not in codes(model)


def test_a_launch_configuration_default_that_is_an_action_is_its_object_text(write_tree):
    """limo_ros2's voice_control.launch.py: ``LaunchConfiguration("speaker_index",
    default=declare_speaker_index)``, the default a ``DeclareLaunchArgument`` (whose
    name, ``speakcer_index``, is misspelt, so the default is used). launch keeps
    ``str()`` of it, the object's text: no TypeError, the parameter gets that text
    (``<launch.actions...DeclareLaunchArgument object at 0x...>``, its address not known
    here). A configuration that is set never reads its default."""
    model, _ = run(write_tree, """
def generate_launch_description():
    declared = DeclareLaunchArgument(name='mic_index', default_value='11')
    misspelt = DeclareLaunchArgument(name='speakcer_index', default_value='11')
    mic = LaunchConfiguration('mic_index', default=declared)
    speaker = LaunchConfiguration('speaker_index', default=misspelt)
    return LaunchDescription([declared, misspelt, Node(
        package='p', executable='e', name='voice',
        parameters=[{'mic_index': mic, 'speaker_index': speaker}])])
""")
    values = {p.name: p.value for p in model.params}
    assert "TypeError" not in " ".join(d.message for d in model.diagnostics)
    assert "LAUNCH_BAD_VALUE" not in codes(model)
    assert str(values["/voice/mic_index"]) == "11"
    # its text holds the object's address, not known here: the value is not known
    assert values["/voice/speaker_index"] is None
    assert any("object text" in d.message for d in model.diagnostics)


def test_logging_the_module_name_and_isabs(write_tree):
    """OrbbecSDK_ROS2's orbbec_camera.launch.py and utils_yaml.py: ``logger =
    logging.getLogger(__name__)`` at module level (launch loads the file as the module
    ``python_launch_file``), ``logger.info(...)`` in helpers, and ``if not
    os.path.isabs(path): path = os.path.join(share, 'config', path)``. Logging writes
    messages only; the test of a known path is decided, so the absolute path is not
    joined to the share folder (a false LAUNCH_PATH_JOIN_ABSOLUTE)."""
    model, _ = run(write_tree, """
import logging
logging.basicConfig(level=logging.INFO)
logger = logging.getLogger(__name__)

def absolute(path):
    if not os.path.isabs(path):
        logger.info(f"not absolute: {path}")
        return os.path.join(get_package_share_directory('pkg'), 'config', path)
    logger.warning("absolute")
    return path

def generate_launch_description():
    common = absolute(os.path.join(get_package_share_directory('pkg'), 'config', 'a.yaml'))
    name = 'main' if __name__ == '__main__' else __name__
    return LaunchDescription([Node(package='p', executable='e', name=name,
                                   parameters=[{'file': common}])])
""")
    assert [n.name for n in model.nodes] == ["/python_launch_file"]
    assert codes(model) == [], model.diagnostics


def test_a_process_is_said_only_where_it_is_performed(write_tree):
    """px4_ros_com's sensor_combined_listener.launch.py makes an ``ExecuteProcess`` of
    the micro-ROS agent and leaves it out of the description (``#micro_ros_agent,``):
    nothing starts it, so no ``LAUNCH_PROCESS`` says it is started. One under a condition
    that does not hold is not started either; one under a condition not known is said."""
    model, _ = run(write_tree, """
from launch.actions import ExecuteProcess

def generate_launch_description():
    agent = ExecuteProcess(cmd=[['micro-ros-agent udp4 --port 8888 -v ']], shell=True)
    gz = ExecuteProcess(cmd=['gz', 'sim', '-r', 'world.sdf'],
                        condition=IfCondition(LaunchConfiguration('sim', default='false')))
    tool = ExecuteProcess(cmd=['tool.py', '--port'],
                          condition=IfCondition(EnvironmentVariable('USE_TOOL')))
    listener = Node(package='p', executable='listener', name='listener')
    return LaunchDescription([
        # agent,
        gz, tool, listener,
    ])
""")
    assert [n.name for n in model.nodes] == ["/listener"]
    assert [(d.code, d.location.line, d.message) for d in model.diagnostics
            if d.code == "LAUNCH_PROCESS"] == [
        ("LAUNCH_PROCESS", 18, "process tool.py --port started here is no node the reader "
                               "can name")]


def test_a_context_performs_a_substitution(write_tree):
    """rosbot_xl_gazebo's spawn.launch.py / simulation.launch.py and realsense2_camera's
    rs_launch.py read launch configurations in an OpaqueFunction with
    ``context.perform_substitution(LaunchConfiguration(name))``, the same as
    ``LaunchConfiguration(name).perform(context)``; nav2_common's
    ``launch.utilities.perform_substitutions(context, [...])`` joins a list's values."""
    model, _ = run(write_tree, """
import launch

def setup(context, *args, **kwargs):
    namespace = context.perform_substitution(LaunchConfiguration('namespace'))
    model = context.perform_substitution(TextSubstitution(text='s1'))
    name = launch.utilities.perform_substitutions(
        context, [LaunchConfiguration('prefix'), TextSubstitution(text='_lidar')])
    return [Node(package='p', executable='e', name=name + '_' + model, namespace=namespace)]

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value='robot1'),
        DeclareLaunchArgument('prefix', default_value='front'),
        OpaqueFunction(function=setup),
    ])
""")
    assert [n.name for n in model.nodes] == ["/robot1/front_lidar_s1"]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)
    assert "LAUNCH_UNSUPPORTED" not in codes(model)


def test_ros2_launch_as_a_process_runs_that_launch_file(write_tree):
    """open_manipulator's omx_ai.launch.py starts its follower and leader with
    ``ExecuteProcess(cmd=['ros2', 'launch', 'open_manipulator_bringup', 'omx_f_follower_ai
    .launch.py'])``, the second on the exit of a node: their controller managers, state
    publishers and spawners were not in the graph (a subscriber of /joint_states without
    publisher). The file ros2launch finds in the package is run as a launch of its own:
    only the arguments on the command line reach it (not this file's configurations,
    namespace or parameters), and the process's conditions are its nodes'."""
    child = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='own'),
        DeclareLaunchArgument('mode', default_value='sim'),
        Node(package='pkg', executable='driver', name='driver',
             namespace=LaunchConfiguration('robot'),
             parameters=[{'mode': LaunchConfiguration('mode')}]),
    ])
"""
    model, _ = run(write_tree, """
from launch.actions import ExecuteProcess, RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch_ros.actions import PushRosNamespace, SetParameter

def generate_launch_description():
    first = Node(package='pkg', executable='setup', name='setup')
    return LaunchDescription([
        DeclareLaunchArgument('mode', default_value='real'),
        PushRosNamespace('outer'),
        SetParameter(name='shared', value=1),
        first,
        ExecuteProcess(cmd=['ros2', 'launch', 'pkg', 'child.launch.py', 'robot:=r1']),
        RegisterEventHandler(OnProcessExit(target_action=first, on_exit=[
            ExecuteProcess(cmd=['ros2', 'launch', '--debug', 'pkg', 'child.launch.py'],
                           shell=True)])),
        ExecuteProcess(cmd=['ros2', 'launch', 'pkg', 'absent.launch.py']),
        ExecuteProcess(cmd=['ros2', 'launch', 'elsewhere', 'x.launch.py']),
        ExecuteProcess(cmd=['ros2', 'launch', '--print', 'pkg', 'child.launch.py']),
    ])
""", extra={"src/pkg/launch/sub/child.launch.py": child})
    nodes = [(n.name, [c.statement for c in n.conditions]) for n in model.nodes]
    assert nodes == [("/outer/setup", []), ("/r1/driver", []),
                     ("/own/driver", ["event"])]
    assert [sorted(p.name for p in model.params if p.name.startswith(n))
            for n in ("/r1/", "/own/")] == [["/r1/driver/mode"], ["/own/driver/mode"]]
    assert {p.name: p.value for p in model.params}["/r1/driver/mode"] == "sim"
    assert "pkg/launch/sub/child.launch.py" in model.files
    found = {(d.code, d.location.line) for d in model.diagnostics}
    assert ("LAUNCH_FILE_MISSING", 27) in found  # ros2 launch fails: no such file
    assert ("LAUNCH_UNKNOWN_VALUE", 28) in found  # a package not here: unknown
    assert "LAUNCH_PROCESS" not in codes(model)


def test_xml_executable_of_ros2_launch_runs_that_launch_file(write_tree):
    from test_launch_ros2 import run as run_xml

    model, _ = run_xml(write_tree, "main.launch.xml", """
<launch>
  <arg name="who" default="r2"/>
  <executable cmd="ros2 launch pkg child.launch.xml robot:=$(var who)" shell="true"/>
  <executable cmd="ros2 launch pkg missing.launch.xml"/>
</launch>
""", extra={"src/pkg/launch/child.launch.xml": """
<launch>
  <arg name="robot" default="own"/>
  <node pkg="pkg" exec="driver" name="driver" namespace="$(var robot)"/>
</launch>
"""})
    assert [n.name for n in model.nodes] == ["/r2/driver"]
    assert [(d.code, d.location.line) for d in model.diagnostics] == [
        ("LAUNCH_FILE_MISSING", 4)]


def test_a_command_line_in_one_word_with_shell_is_split_as_the_shell_does(write_tree):
    """``ExecuteProcess(cmd=['ros2 launch pkg child.launch.py robot:=r3'], shell=True)``:
    launch joins the words and the shell splits the line; without shell=True the one
    word is a program of that name (no node)."""
    child = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='own'),
        Node(package='pkg', executable='driver', name='driver',
             namespace=LaunchConfiguration('robot')),
    ])
"""
    model, _ = run(write_tree, """
from launch.actions import ExecuteProcess

def generate_launch_description():
    who = LaunchConfiguration('who', default='r4')
    return LaunchDescription([
        ExecuteProcess(cmd=['ros2 launch pkg child.launch.py robot:=r3'], shell=True),
        ExecuteProcess(cmd=['ros2 run demo_nodes_cpp talker --ros-args -r',
                            ['__node:=', who]], shell=True),
        ExecuteProcess(cmd=['ros2 run demo_nodes_cpp listener']),
    ])
""", extra={"src/pkg/launch/child.launch.py": child})
    assert [n.name for n in model.nodes] == ["/r3/driver", "/r4"]
    assert [d.message for d in model.diagnostics if d.code == "LAUNCH_PROCESS"] == [
        "process ros2 run demo_nodes_cpp listener started here is no node the reader "
        "can name"]


def test_an_opaque_function_adds_to_the_description_it_is_given(write_tree):
    """spot_ros2's spot_driver.launch.py: ``ld.add_action(OpaqueFunction(function=
    launch_setup, args=[ld]))`` and launch_setup calls ``ld.add_action(Node(...))`` and
    returns nothing. launch visits the description's own list, which grows while it is
    visited: those actions run after the rest of it (the node added before them does not
    take their SetParameter), with the arguments of the moment. A description that does
    not hold the function is not run: what is added there is said, not started."""
    model, _ = run(write_tree, """
def launch_setup(context, ld, extra=None):
    robot = LaunchConfiguration('robot').perform(context)
    ld.add_action(SetParameter(name='use_sim_time', value='true'))
    ld.add_action(Node(package='p', executable='driver', name=robot + '_driver'))
    if extra is not None:
        extra.add_action(Node(package='p', executable='extra', name='extra'))
    return [Node(package='p', executable='returned', name='returned')]

def generate_launch_description():
    ld = LaunchDescription([DeclareLaunchArgument('robot', default_value='spot')])
    more = LaunchDescription()
    ld.add_action(OpaqueFunction(function=launch_setup, args=[ld],
                                 kwargs={'extra': more}))
    ld.add_action(Node(package='p', executable='after', name='after'))
    ld.add_action(OpaqueFunction(function=launch_setup, args=[ld],
                                 condition=IfCondition(LaunchConfiguration('twice'))))
    return ld
""")
    assert [n.name for n in model.nodes] == [
        "/returned", "/after", "/returned", "/spot_driver", "/spot_driver"]
    assert sorted({p.name for p in model.params}) == ["/spot_driver/use_sim_time"]
    assert [bool(n.conditions) for n in model.nodes] == [False, False, True, False, True]
    messages = [d.message for d in model.diagnostics]
    assert any("launch description that does not hold it" in m for m in messages)


def test_the_name_of_a_declared_argument_keys_a_dict_of_every_argument(write_tree):
    """OrbbecSDK_ROS2's camera launch files: ``{arg.name: LaunchConfiguration(arg.name)
    .perform(context) for arg in args}`` over a list of DeclareLaunchArgument makes the
    node's parameters, one per argument. ``arg.name`` is the argument's name (it was a
    method waiting for a call, and a dict key that cannot be hashed stopped the run)."""
    model, _ = run(write_tree, """
def load(context, args):
    return {arg.name: LaunchConfiguration(arg.name).perform(context) for arg in args}

def generate_launch_description():
    args = [DeclareLaunchArgument('fps', default_value='30'),
            DeclareLaunchArgument('serial', default_value='')]
    return LaunchDescription(args + [OpaqueFunction(function=lambda context: [
        Node(package='p', executable='e', name='cam', parameters=[load(context, args)])])])
""")
    assert [n.name for n in model.nodes] == ["/cam"]
    params = {p.name: p.value for p in model.params}
    assert params == {"/cam/fps": "30", "/cam/serial": ""}, params
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)


def test_a_dict_key_that_cannot_be_hashed_is_not_known(write_tree):
    """A dict comprehension whose key is a value the interpreter cannot hash (here a
    method of an action, never called) makes an unknown key, not a crash."""
    model, _ = run(write_tree, """
def generate_launch_description():
    args = [DeclareLaunchArgument('fps', default_value='30')]
    table = {arg.description: 1 for arg in args}
    return LaunchDescription(args + [Node(package='p', executable='e', name='cam')])
""")
    assert [n.name for n in model.nodes] == ["/cam"]


def test_a_builtin_exception_goes_to_the_handler_that_catches_it(write_tree):
    """OrbbecSDK_ROS2's convert_value: ``try: return int(value) except ValueError: pass``
    then float(), then 'true' / 'false', else the string. The handlers were not run:
    each int('camera_01') was a LAUNCH_PY_UNSUPPORTED warning (358 on the workspace) and
    made the parameter unknown. A handler of a class not known here is not taken."""
    model, _ = run(write_tree, """
import json

def convert(value):
    try:
        return int(value)
    except ValueError:
        pass
    try:
        return float(value)
    except (TypeError, ValueError) as err:
        pass
    if value.lower() == 'true':
        return True
    return value

def other(value):
    try:
        return int(value)
    except json.JSONDecodeError:
        return 'caught'

def generate_launch_description():
    return LaunchDescription([Node(package='p', executable='e', name='cam', parameters=[{
        'name': convert('camera_01'), 'rate': convert('30'), 'scale': convert('0.5'),
        'on': convert('true'), 'x': other('y')}])])
""")
    params = {p.name: p.value for p in model.params}
    assert {k: params[k] for k in ("/cam/name", "/cam/rate", "/cam/scale", "/cam/on")} == {
        "/cam/name": "camera_01", "/cam/rate": 30, "/cam/scale": 0.5, "/cam/on": True}
    messages = [d.message for d in model.diagnostics if d.code == "LAUNCH_PY_UNSUPPORTED"]
    assert len(messages) == 1 and "int() fails" in messages[0], messages


def test_a_star_import_of_a_helper_module_binds_its_public_names(write_tree):
    """OrbbecSDK_ROS2's orbbec_camera.launch.py: ``sys.path.append(<its folder>)`` then
    ``from utils_yaml import *`` and calls of load_and_parse_yaml, update_params,
    find_param: each name was "not defined here". A module's ``__all__`` limits them."""
    model, _ = run(write_tree, """
import sys
sys.path.append(os.path.dirname(os.path.realpath(__file__)))
from name_helpers import *
from listed_helpers import *

def generate_launch_description():
    names = [camera_name('front'), PREFIX]
    return LaunchDescription([Node(package='p', executable='e', name=n) for n in names])
""", extra={"src/pkg/launch/name_helpers.py": "PREFIX = 'rig'\n_private = 'no'\n"
                                              "def camera_name(side):\n"
                                              "    return 'cam_' + side\n",
            "src/pkg/launch/listed_helpers.py": "__all__ = ['other']\nother = 1\n"
                                                "PREFIX = 'overwritten'\n"})
    assert [n.name for n in model.nodes] == ["/cam_front", "/rig"]
    assert not any("not defined" in d.message for d in model.diagnostics), model.diagnostics


def test_execute_process_of_ros2_service_call_is_a_client_named_by_its_type(write_tree):
    """space-ros demos' curiosity_gazebo.launch.py activates the hardware with
    ``ExecuteProcess(cmd=['ros2', 'service', 'call', 'controller_manager/
    set_hardware_component_state', 'controller_manager_msgs/srv/SetHardwareComponentState',
    '{...}'])``: ros2service's requester node, ``_ros2cli_requester_<pkg>_<Service>``,
    a client of that service (``models.commands``), not a process nothing is known of."""
    from haros_arch.launch.model import NodeDecl
    from haros_arch.models.commands import command_node

    model, _ = run(write_tree, """
from launch.actions import ExecuteProcess

def generate_launch_description():
    return LaunchDescription([
        ExecuteProcess(cmd=['ros2', 'service', 'call',
                            'controller_manager/set_hardware_component_state',
                            'controller_manager_msgs/srv/SetHardwareComponentState',
                            '{name: "IgnitionSystem"}']),
        ExecuteProcess(cmd=['ros2', 'service', 'call', '-r', '2', '/reset',
                            'std_srvs/Empty']),
        ExecuteProcess(cmd=['ros2', 'service', 'call', '/reset',
                            LaunchConfiguration('kind', default='std_srvs/srv/Trigger')]),
        ExecuteProcess(cmd=['ros2', 'service', 'list']),
    ])
""")
    assert [(n.name, n.package, n.executable) for n in model.nodes] == [
        ("/_ros2cli_requester_controller_manager_msgs_SetHardwareComponentState",
         "ros2service", "ros2"),
        ("/_ros2cli_requester_std_srvs_Empty", "ros2service", "ros2"),
        ("/_ros2cli_requester_?", "ros2service", "ros2")]
    # the verbs that make no client stay processes, said
    assert [d.message.split(" started")[0] for d in model.diagnostics
            if d.code == "LAUNCH_PROCESS"] == ["process ros2 service list"]
    calls = [(c.kind, c.name, c.type) for n in model.nodes
             for c in command_node(n).calls]
    assert calls == [
        ("client", "controller_manager/set_hardware_component_state",
         "controller_manager_msgs/srv/SetHardwareComponentState"),
        ("client", "/reset", "std_srvs/srv/Empty"),
        ("client", "/reset", "std_srvs/srv/Trigger")]
    # argparse wants the service and its type: without the type, no client is made up
    assert command_node(NodeDecl("/r", "ros2service", "ros2", args="service call /reset")) \
        is None
