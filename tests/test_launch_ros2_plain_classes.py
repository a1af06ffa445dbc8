"""Classes of a ROS 2 Python launch file (or of a helper module it imports) that are no
launch action are run: vrx's vrx_gz package builds its bridges as ``@dataclass Bridge``
objects whose ``argument()`` / ``remapping()`` give ros_gz_bridge's arguments, with an
``Enum`` for the direction, and spawns each ``Model`` (``__init__``, methods,
classmethods) after ``if type(models) != list``. Before, every such class was "not
interpreted" and the bridges and the robot's nodes were lost."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

LAUNCH = """
from dataclasses import dataclass
from enum import Enum
from launch import LaunchDescription
from launch_ros.actions import Node

class Direction(Enum):
    BIDIRECTIONAL = 0
    GZ_TO_ROS = 1

SYMBOLS = {Direction.BIDIRECTIONAL: '@', Direction.GZ_TO_ROS: '['}

@dataclass
class Bridge:
    gz_topic: str
    ros_topic: str
    direction: Direction = Direction.GZ_TO_ROS

    def argument(self):
        return f'{self.gz_topic}@msgs{SYMBOLS[self.direction]}gz'

    def remapping(self):
        return (self.gz_topic, self.ros_topic)

class Model:
    KIND = 'usv'

    def __init__(self, name):
        self.name = name
        self.bridges = []

    @property
    def namespace(self):
        return '/' + self.name

    @classmethod
    def from_name(cls, name):
        return cls(name)

    @staticmethod
    def executable():
        return 'parameter_bridge'

    def add(self, gz, ros, direction=Direction.GZ_TO_ROS):
        self.bridges.append(Bridge(gz, ros, direction=direction))
        return self

def generate_launch_description():
    models = Model.from_name('wamv').add('/gz/pose', 'pose').add(
        '/gz/cmd', 'cmd', Direction.BIDIRECTIONAL)
    if type(models) != list:
        models = [models]
    return LaunchDescription([
        Node(package='ros_gz_bridge', executable=m.executable(), name=m.KIND,
             namespace=m.namespace, arguments=[b.argument() for b in m.bridges],
             remappings=[b.remapping() for b in m.bridges],
             parameters=[{'direction': Direction.BIDIRECTIONAL.value,
                          'member': Direction.GZ_TO_ROS.name}])
        for m in models])
"""


def _load(write_tree, text: str):
    root = write_tree({
        "src/sim/package.xml": package_xml("sim", "ament_cmake"),
        "src/sim/launch/sim.launch.py": text,
    })
    return load(str(root / "src/sim/launch/sim.launch.py"), scan([str(root / "src")], {}),
                {}, {})


def test_dataclasses_enums_and_classes_of_the_launch_code_run(write_tree):
    model = _load(write_tree, LAUNCH)
    assert [(n.name, n.executable) for n in model.nodes] == [
        ("/wamv/usv", "parameter_bridge")]
    node = model.nodes[0]
    assert node.args == "/gz/pose@msgs[gz /gz/cmd@msgs@gz"
    assert [tuple(map(str, r)) for r in node.remaps][-2:] == [("/gz/pose", "pose"),
                                                              ("/gz/cmd", "cmd")]
    assert {p.key: p.value for p in model.params} == {"direction": 0, "member": "GZ_TO_ROS"}
    assert not [d for d in model.diagnostics if d.code.startswith("LAUNCH_")], \
        [d.message for d in model.diagnostics]


def test_what_a_class_does_not_define_stays_unknown_and_said(write_tree):
    model = _load(write_tree, """
from enum import Enum
from launch import LaunchDescription
from launch_ros.actions import Node

class Box:
    def __init__(self):
        self.size = 1

class Kind(Enum):
    A = 'a'

def generate_launch_description():
    b = Box()
    return LaunchDescription([Node(package='p', executable='e', name=b.label),
                              Node(package='p', executable='e', name=Kind(b.label).value),
                              Node(package='p', executable='e', name=str(b))])
""")
    said = [d.message for d in model.diagnostics if d.code == "LAUNCH_PY_UNSUPPORTED"]
    assert any("Box.label is not set" in m for m in said), said
    assert any("call to the enum Kind is not interpreted" in m for m in said), said
    assert all("?" in n.name for n in model.nodes), [n.name for n in model.nodes]


def test_dataclass_fields_of_field_defaults(write_tree):
    # moveit_configs_utils' MoveItConfigs: ``field(default_factory=dict)``, each
    # instance its own dict; a lambda factory; ``field(default=...)``
    model = _load(write_tree, """
from dataclasses import dataclass, field
from launch import LaunchDescription
from launch_ros.actions import Node

@dataclass(slots=True)
class Configs:
    name: str = field(default='move_group')
    params: dict = field(default_factory=dict)
    caps: dict = field(default_factory=lambda: {'capabilities': ''})

def generate_launch_description():
    a, b = Configs(), Configs(name='servo')
    a.params['planning'] = 'ompl'
    return LaunchDescription([
        Node(package='moveit_ros_move_group', executable='move_group', name=c.name,
             parameters=[c.params, c.caps]) for c in (a, b)])
""")
    values = {p.name: p.value for p in model.params}
    assert values == {"/move_group/planning": "ompl", "/move_group/capabilities": "",
                      "/servo/capabilities": ""}
    assert not [d for d in model.diagnostics if d.code.startswith("LAUNCH_")], \
        [d.message for d in model.diagnostics]
