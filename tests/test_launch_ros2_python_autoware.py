"""Python launch file shapes of Autoware's launch files (2026-12-02): launch_ros'
``global_params`` read back in an OpaqueFunction, ``yaml.load`` with the full or safe
loader, ``pathlib.Path(...).read_text()``."""

from __future__ import annotations

from test_launch_ros2_python import codes, run

# a vehicle's dimensions set as global parameters from a YAML file (Autoware's
# vehicle_info.launch.py), then read back to size a crop box (ground_segmentation's)
VEHICLE = """
import yaml
from launch_ros.actions import SetParameter

def load_vehicle(context):
    path = os.path.join(get_package_share_directory('pkg'), 'config', 'vehicle.yaml')
    with open(path, 'r') as f:
        given = yaml.safe_load(f)['/**']['ros__parameters']
    return [SetParameter(name=k, value=v) for (k, v) in given.items()]

class Pipeline:
    def __init__(self, context):
        self.context = context

    def size(self):
        gp = self.context.launch_configurations.get('ros_params', {})
        if not gp:
            gp = dict(self.context.launch_configurations.get('global_params', {}))
        return gp['front_overhang'] + gp['wheel_base'], -gp['rear_overhang']

def crop(context):
    front, rear = Pipeline(context).size()
    return [Node(package='p', executable='crop', name='crop_box',
                 parameters=[{'max_x': front, 'min_x': rear}])]
"""

VEHICLE_YAML = ("/**:\n  ros__parameters:\n    wheel_base: 2.79\n    front_overhang: 1.0\n"
                "    rear_overhang: 1.1\n")


def test_global_parameters_read_back_in_an_opaque_function(write_tree):
    """Before, ``global_params`` was performed as a text configuration nobody declared:
    every ``gp[...]`` was 'a subscript of a value not known statically' and the crop
    box's limits unknown."""
    model, _ = run(write_tree, VEHICLE + """
def generate_launch_description():
    return LaunchDescription([
        SetParameter(name='use_sim_time', value=LaunchConfiguration('sim', default='true')),
        OpaqueFunction(function=load_vehicle),
        OpaqueFunction(function=crop),
    ])
""", extra={"src/pkg/config/vehicle.yaml": VEHICLE_YAML})
    params = {p.name: p.value for p in model.params}
    assert params["/crop_box/max_x"] == 3.79
    assert params["/crop_box/min_x"] == -1.1
    assert params["/crop_box/wheel_base"] == 2.79  # the global parameters reach it too
    assert params["/crop_box/use_sim_time"] is True  # 'true' read as YAML, as launch_ros
    assert "LAUNCH_UNSUPPORTED" not in codes(model)


def test_global_parameters_with_an_unknown_value_stay_unknown(write_tree):
    """A global parameter whose value is not known here is not known when read back;
    the others are."""
    model, _ = run(write_tree, VEHICLE + """
def generate_launch_description():
    return LaunchDescription([
        SetParameter(name='wheel_base', value=LaunchConfiguration('not_declared')),
        SetParameter(name='front_overhang', value=1.0),
        SetParameter(name='rear_overhang', value=1.1),
        OpaqueFunction(function=crop),
    ])
""")
    params = {p.name: p.value for p in model.params}
    assert params["/crop_box/min_x"] == -1.1
    assert "/crop_box/max_x" not in params or not isinstance(
        params["/crop_box/max_x"], (int, float))


def test_global_parameters_after_an_action_not_seen_are_not_empty(write_tree):
    """An include the reader cannot follow may set more global parameters: a name the
    known ones lack is then not known (never a KeyError that drops the node); a name
    they have keeps its value."""
    model, _ = run(write_tree, """
def crop(context):
    gp = dict(context.launch_configurations['global_params'])
    return [Node(package='p', executable='crop', name='crop_box',
                 parameters=[{'base': gp['wheel_base'] * 2, 'front': gp['front_overhang']}])]

def generate_launch_description():
    return LaunchDescription([
        SetParameter(name='wheel_base', value=2.0),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(LaunchConfiguration('f'))),
        OpaqueFunction(function=crop),
    ])
""")
    assert [n.name for n in model.nodes] == ["/crop_box"]
    params = {p.name: p.value for p in model.params}
    assert params["/crop_box/base"] == 4.0
    assert params["/crop_box/front"] is None  # not known
    assert not any("fails" in d.message for d in model.diagnostics)


def test_an_unset_configuration_gives_its_default_as_it_is(write_tree):
    """``context.launch_configurations.get(name, {})`` of a configuration nothing
    sets is the dict given, falsy, as in Python."""
    model, _ = run(write_tree, """
def setup(context):
    got = context.launch_configurations.get('nothing_sets_this', {})
    name = 'empty' if not got else 'full'
    return [Node(package='p', executable='e', name=name)]

def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=setup)])
""")
    assert [n.name for n in model.nodes] == ["/empty"]


def test_yaml_load_with_the_full_loader(write_tree):
    """tier4_perception_launch's traffic light launch files: ``yaml.load(
    camera_namespaces, Loader=yaml.FullLoader)`` of a launch argument, then a node per
    camera. It was 'not interpreted': one node under an unknown Python test."""
    model, _ = run(write_tree, """
import yaml

def setup(context):
    namespaces = LaunchConfiguration('cameras').perform(context)
    namespaces = yaml.load(namespaces, Loader=yaml.FullLoader)
    if not isinstance(namespaces, list):
        raise ValueError('not a list')
    return [GroupAction([PushRosNamespace(ns),
                         Node(package='p', executable='relay', name='relay')])
            for ns in namespaces]

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('cameras', default_value="['camera6', 'camera7']"),
        OpaqueFunction(function=setup)])
""")
    assert sorted(n.name for n in model.nodes) == ["/camera6/relay", "/camera7/relay"]
    assert all(not n.conditions for n in model.nodes)


def test_yaml_load_with_another_loader_is_not_run(write_tree):
    """``BaseLoader`` keeps every scalar a string: not read as the safe loader. (The
    unsafe ``Loader`` / ``UnsafeLoader`` read plain YAML as the safe one does, which
    refuses the Python tags they add: tests/test_launch_ros2_python.py.)"""
    model, _ = run(write_tree, """
import yaml

def generate_launch_description():
    value = yaml.load('a: 1', Loader=yaml.BaseLoader)
    return LaunchDescription([Node(package='p', executable='e', name='n',
                                   parameters=[{'a': value['a']}])])
""")
    assert any(d.code == "LAUNCH_PY_UNSUPPORTED" and "loader" in d.message
               for d in model.diagnostics)


def test_read_text_of_a_path(write_tree):
    """autoware_component_state_monitor's launch file: ``yaml.safe_load(Path(
    LaunchConfiguration('file').perform(context)).read_text())``."""
    model, _ = run(write_tree, """
import yaml
from pathlib import Path

def setup(context):
    rows = yaml.safe_load(Path(LaunchConfiguration('file').perform(context)).read_text())
    return [Node(package='p', executable='monitor', name='monitor_' + row['module'])
            for row in rows]

def generate_launch_description():
    share = get_package_share_directory('pkg')
    return LaunchDescription([
        DeclareLaunchArgument('file', default_value=os.path.join(share, 'config', 'rows.yaml')),
        OpaqueFunction(function=setup)])
""", extra={"src/pkg/config/rows.yaml": "- module: planning\n- module: control\n"})
    assert sorted(n.name for n in model.nodes) == ["/monitor_control", "/monitor_planning"]


def test_assert_on_a_launch_argument(write_tree):
    """traffic_light_node_container.launch.py: ``assert detection_type in [...]``
    before the nodes. An assertion that holds (or is not known) lets the launch go on,
    with no word; one known false is said: the launch stops there."""
    body = """
def setup(context):
    kind = LaunchConfiguration('kind').perform(context)
    assert kind in ['whole', 'fine'], 'kind must be whole or fine'
    return [Node(package='p', executable='e', name='detector_' + kind)]

def generate_launch_description():
    return LaunchDescription([DeclareLaunchArgument('kind', default_value='%s'),
                              OpaqueFunction(function=setup)])
"""
    model, _ = run(write_tree, body % "fine")
    assert [n.name for n in model.nodes] == ["/detector_fine"]
    assert not any(d.code.startswith("LAUNCH_PY") and "ssert" in d.message
                   for d in model.diagnostics)
    model, _ = run(write_tree, body % "other")
    assert any("assert kind in" in d.message and "fails" in d.message
               for d in model.diagnostics)


def test_itertools_chain_of_lists_of_actions(write_tree):
    """traffic_light_node_container.launch.py: a list of actions per camera, joined
    with ``list(chain(*lists))``: it was 'not interpreted' and the launch description
    returned not known, so no container at all."""
    model, _ = run(write_tree, """
from itertools import chain
import itertools

def per_camera(name):
    return [Node(package='p', executable='e', name=name + '_a'),
            Node(package='p', executable='e', name=name + '_b')]

def generate_launch_description():
    lists = [per_camera(n) for n in ['c6', 'c7']]
    return LaunchDescription(list(chain(*lists)) + list(itertools.chain([], ())))
""")
    assert [n.name for n in model.nodes] == ["/c6_a", "/c6_b", "/c7_a", "/c7_b"]


def test_defaultdict_of_lists(write_tree):
    """autoware_component_state_monitor's launch file groups its topic monitors by type
    and module with ``defaultdict(lambda: defaultdict(list))`` for the component's
    parameters; 'not interpreted' before, and the parameters unknown."""
    model, _ = run(write_tree, """
from collections import defaultdict
import collections

def generate_launch_description():
    rows = [{'type': 'topic', 'module': 'map', 'name': 'a'},
            {'type': 'topic', 'module': 'map', 'name': 'b'},
            {'type': 'tf', 'module': 'loc', 'name': 'c'}]
    grouped = defaultdict(lambda: defaultdict(list))
    for row in rows:
        grouped[row['type']][row['module']].append(row['name'])
    grouped = {t: dict(m) for t, m in grouped.items()}
    counts = collections.defaultdict(int)
    for row in rows:
        counts[row['module']] += 1
    return LaunchDescription([Node(package='p', executable='monitor', name='monitor',
                                   parameters=[grouped, {'maps': counts['map']}])])
""")
    params = {p.name: p.value for p in model.params}
    assert params["/monitor/topic.map"] == ["a", "b"]
    assert params["/monitor/tf.loc"] == ["c"]
    assert params["/monitor/maps"] == 2
    assert not [d for d in model.diagnostics if d.code.startswith("LAUNCH_PY")]
