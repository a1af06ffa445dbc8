"""A Python ``if`` whose test is not known statically (an environment variable not
set, a launch configuration not known in an OpaqueFunction): both branches are
interpreted, each under its test, and what follows the ``if`` sees either branch's
values: a name both branches set alike keeps its value, one they set differently is
not known where they differ (``?``: ``real_driver`` or ``sim_driver`` is ``?_driver``),
as a function returning one of two values is; actions made in a branch carry that
branch's test as their condition."""

from __future__ import annotations

from test_launch_ros2_python import run

BRANCHES = """
def generate_launch_description():
    prefix = 'fixed'
    if os.environ.get('NOT_SET_FOR_THIS_TEST') == 'real':
        name = 'real_driver'
        rate = 50
        same = 'kept'
        only_here = 'one_branch'
        extra = Node(package='p', executable='e', name='real_only')
    else:
        name = 'sim_driver'
        rate = 10
        same = 'kept'
        extra = Node(package='p', executable='e', name='sim_only')
    return LaunchDescription([
        Node(package='p', executable='e', name=name, parameters=[{'rate': rate}]),
        Node(package='p', executable='e', name=same + '_' + prefix),
        Node(package='p', executable='e', name=only_here),
        extra,
    ])
"""


def test_values_two_branches_set_differently_are_not_known_after_the_if(write_tree):
    model, _ = run(write_tree, BRANCHES)
    names = [n.name for n in model.nodes]
    # not "sim_driver" unconditionally: the else branch does not win
    assert names == ["/?_driver", "/kept_fixed", "/one_branch", "/real_only", "/sim_only"]
    params = {(p.node, p.key): p.value for p in model.params}
    assert params == {("/?_driver", "rate"): None}
    unconditional = {n.name for n in model.nodes if not n.conditions}
    assert unconditional == {"/?_driver", "/kept_fixed", "/one_branch"}
    real_only, sim_only = model.nodes[3:]
    assert "NOT_SET_FOR_THIS_TEST" in real_only.conditions[0].text
    assert sim_only.conditions[0].text.startswith("not (") or \
        "not (" in sim_only.conditions[0].text


OPAQUE = """
def choose(context):
    if context.launch_configurations['robot'] == 'big':
        config = 'big.yaml'
        nodes = [Node(package='p', executable='e', name='big_extra')]
    else:
        config = 'small.yaml'
        nodes = []
    return nodes + [Node(package='p', executable='e', name='driver',
                         parameters=[{'config': config}])]

def generate_launch_description():
    return LaunchDescription([DeclareLaunchArgument('robot'), OpaqueFunction(function=choose)])
"""


def test_an_opaque_function_testing_a_configuration_not_known(write_tree):
    model, _ = run(write_tree, OPAQUE)
    nodes = {n.name: n for n in model.nodes}
    assert sorted(nodes) == ["/big_extra", "/driver"]
    assert nodes["/big_extra"].conditions and not nodes["/driver"].conditions
    params = {(p.node, p.key): p.value for p in model.params}
    assert params == {("/driver", "config"): None}  # big.yaml or small.yaml: ?.yaml
    # with the argument given, the test is known: one branch, no condition
    model, _ = run(write_tree, OPAQUE, args={"robot": "small"})
    assert [n.name for n in model.nodes] == ["/driver"]
    assert {(p.node, p.key): p.value for p in model.params} == {
        ("/driver", "config"): "small.yaml"}


def test_a_name_in_os_environ_reads_the_configurations_environment(write_tree):
    body = """
def generate_launch_description():
    if 'ROBOT_KIND' in os.environ:
        name = 'from_env'
    else:
        name = 'default'
    return LaunchDescription([Node(package='p', executable='e', name=name)])
"""
    model, _ = run(write_tree, body, env={"ROBOT_KIND": "x"})
    assert [(n.name, n.conditions) for n in model.nodes] == [("/from_env", ())]
    model, _ = run(write_tree, body)
    assert [n.name for n in model.nodes] == ["/?"]
    assert any("ROBOT_KIND is not set" in d.message for d in model.diagnostics)


def test_composable_nodes_made_in_branches_are_both_loaded_each_under_its_test(write_tree):
    """zed_camera.launch.py: ``if is_stereo_model: component = ComposableNode(plugin=A)
    else: component = ComposableNode(plugin=B)``, then ``LoadComposableNodes(...,
    composable_node_descriptions=[component])``, the camera model being an argument
    not given."""
    model, _ = run(write_tree, """
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes
from launch_ros.descriptions import ComposableNode

def setup(context):
    model = LaunchConfiguration('camera_model').perform(context)
    if model in ('zed', 'zedx'):
        component = ComposableNode(package='zed', plugin='zed::Stereo', name='cam')
    else:
        component = ComposableNode(package='zed', plugin='zed::Mono', name='cam')
    return [ComposableNodeContainer(name='box', namespace='', package='rclcpp_components',
                                    executable='component_container'),
            LoadComposableNodes(target_container='/box',
                                composable_node_descriptions=[component])]

def generate_launch_description():
    return LaunchDescription([DeclareLaunchArgument('camera_model'),
                              OpaqueFunction(function=setup)])
""")
    loaded = [(n.name, n.executable, bool(n.conditions)) for n in model.nodes if n.composable]
    assert loaded == [("/cam", "zed::Stereo", True), ("/cam", "zed::Mono", True)]


def test_dicts_and_lists_set_in_both_branches_keep_what_they_agree_on(write_tree):
    model, _ = run(write_tree, """
def generate_launch_description():
    if os.environ.get('NOT_SET_FOR_THIS_TEST'):
        params = {'use_sim_time': True, 'rate': 10}
        args = ['--ros-args', '--log-level', 'debug']
    else:
        params = {'use_sim_time': False, 'rate': 10}
        args = ['--ros-args', '--log-level', 'info']
    return LaunchDescription([
        Node(package='p', executable='e', name='n', parameters=[params], arguments=args)])
""")
    assert {p.key: p.value for p in model.params} == {"use_sim_time": None, "rate": 10}
    [node] = model.nodes
    assert node.args == ""  # all of it --ros-args: none is a plain argument
