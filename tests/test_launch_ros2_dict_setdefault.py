"""``dict.setdefault`` in a ROS 2 Python launch file (mini_pupper_ros' bringup.launch.py
reads its robot's YAML file and fills the sensors it leaves out with
``sensors_config.setdefault('lidar', False)``, then starts the lidar under
``IfCondition(str(sensors_config['lidar']))``): Python's own dict method, the item when
the dict has it, else the default, set; not LAUNCH_PY_UNSUPPORTED. A key not among the
known ones of a dict that has a key not known statically may be that one: its value is
unknown, never the default guessed."""

from __future__ import annotations

from test_launch_ros2_python import codes, run

BODY = """
import yaml

def get_config():
    path = os.path.join(get_package_share_directory('pkg'), 'config', 'robot.yaml')
    with open(path, 'r') as f:
        configuration = yaml.safe_load(f)
    sensors = configuration.get('sensors', {})
    sensors.setdefault('lidar', False)
    sensors.setdefault('camera', False)
    return sensors

def generate_launch_description():
    sensors = get_config()
    opened = {LaunchConfiguration('which'): True}
    return LaunchDescription([
        DeclareLaunchArgument('which', default_value='a'),
        Node(package='p', executable='lidar', name='lidar',
             condition=IfCondition(str(sensors['lidar']))),
        Node(package='p', executable='camera', name='camera',
             condition=IfCondition(str(sensors['camera']))),
        Node(package='p', executable='e', name='probe',
             parameters=[{'value': str(opened.setdefault('b', False))}]),
    ])
"""


def test_setdefault_keeps_an_item_and_sets_a_missing_one(write_tree):
    model, _ = run(write_tree, BODY, extra={
        "src/pkg/config/robot.yaml": "sensors:\n  lidar: true\n"})
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model), [
        d.message for d in model.diagnostics]
    assert [n.name for n in model.nodes] == ["/lidar", "/probe"]
    probe = {p.name: p.value for p in model.params}
    assert probe.get("/probe/value") != "False"
