"""ROS 2: declare_parameter(name, default) gives the parameter a value, so reading it
afterwards is no 'read but never set'; reading one never declared is."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import load_catalogue, run_rule

TALKER = """
    import rclpy

    def main():
        rclpy.init()
        node = rclpy.create_node('talker')
        node.declare_parameter('gain', 2.0)
        gain = node.get_parameter('gain').value
        node.declare_parameter('port', rclpy.Parameter.Type.STRING)
        port = node.get_parameter('port').value
        rate = node.get_parameter('undeclared_rate').value
    """

LAUNCH = """
    from launch import LaunchDescription
    from launch_ros.actions import Node

    def generate_launch_description():
        return LaunchDescription([Node(package='talk', executable='talker')])
    """


def _analysed(write_tree, script: str, code: str, launch: str):
    """The model of an ament_python package ``talk`` whose executable ``script`` runs
    ``talk/<script>.py`` (``code``), launched by ``launch``."""
    root = write_tree({
        "src/talk/package.xml": package_xml("talk", build_type="ament_python"),
        "src/talk/setup.py": "from setuptools import setup\n"
                             "setup(name='talk', packages=['talk'], entry_points="
                             f"{{'console_scripts': ['{script} = talk.{script}:main']}})\n",
        "src/talk/resource/talk": "",
        "src/talk/talk/__init__.py": "",
        f"src/talk/talk/{script}.py": code,
        f"src/talk/launch/{script}.launch.py": launch,
        "project.yaml": f"project: p\nconfigurations:\n  c: [talk/launch/{script}.launch.py]\n",
    })
    return analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                   Options(cache_dir=None))


def test_declared_with_a_default_is_set(write_tree):
    model = _analysed(write_tree, "talker", TALKER, LAUNCH)
    rule = next(r for r in load_catalogue() if r.id == "parameter-read-not-set")
    found = sorted(e for f in run_rule(rule, model) for e in f.entities
                   if e.startswith("parameter:"))
    # gain has a default in its declaration; port is declared by type only (no value);
    # undeclared_rate is never declared nor set
    assert found == ["parameter:/talker/port", "parameter:/talker/undeclared_rate"]


def test_a_declaration_by_type_has_that_type_and_no_default(tmp_path):
    from haros_arch.extract.python import extract_python
    from haros_arch.workspace import scan

    source = tmp_path / "n.py"
    source.write_text(
        "import rclpy\nfrom rcl_interfaces.msg import ParameterType\n"
        "node = rclpy.create_node('n')\n"
        "node.declare_parameter('port', rclpy.Parameter.Type.STRING)\n"
        "node.declare_parameter('ids', ParameterType.PARAMETER_INTEGER_ARRAY)\n"
        "node.declare_parameter('gain', 2.0)\n")
    found = extract_python([str(source)], scan([str(tmp_path)]))
    declared = {c.name: (c.type, c.has_default) for c in found.calls if c.kind == "declare"}
    assert declared["port"] == ("str", False)
    assert declared["ids"][1] is False and declared["ids"][0] != "str"
    assert declared["gain"] == ("double", True)


DECLARED_TOGETHER = """
    import rclpy
    from rclpy.node import Node

    class Follower(Node):
        def __init__(self):
            super().__init__('follower')
            self.declare_parameters(namespace='', parameters=[
                ('scan_topic', 'scan'), ('gain', 0.5), ('port', rclpy.Parameter.Type.STRING),
                ('ids',)])
            self.declare_parameters('limits', [('max_speed', 1.0)])
            topic = self.get_parameter('scan_topic').value
            gain = self.get_parameter('gain').value
            port = self.get_parameter('port').value
            ids = self.get_parameter('ids').value
            top = self.get_parameter('limits.max_speed').value

    def main():
        rclpy.init()
        Follower()
    """


def test_parameters_declared_together_keep_their_defaults(write_tree):
    """``declare_parameters(namespace, [(name, value), ...])``, the rclpy idiom for many
    parameters at once, gives each its default as ``declare_parameter`` does: the
    defaults were dropped, so every read of them was a false 'read but never set'."""
    model = _analysed(write_tree, "follower", DECLARED_TOGETHER,
                      LAUNCH.replace("talker", "follower"))
    rule = next(r for r in load_catalogue() if r.id == "parameter-read-not-set")
    found = sorted(e for f in run_rule(rule, model) for e in f.entities
                   if e.startswith("parameter:"))
    # ``('ids',)``, the name alone, rclpy declares dynamically typed: its get returns None
    assert found == ["parameter:/follower/port"]
    declared = {c.name: (c.type, c.has_default, c.default)
                for p in model.packages for n in p.nodes for c in n.calls
                if c.kind == "declare"}
    assert declared["scan_topic"] == ("str", True, "scan")
    assert declared["gain"] == ("double", True, 0.5)
    assert declared["port"] == ("str", False, None)
    assert declared["limits.max_speed"] == ("double", True, 1.0)


JSP = """
    import rclpy
    from rclpy.node import Node

    class JointStatePublisher(Node):
        def __init__(self):
            super().__init__('jsp', automatically_declare_parameters_from_overrides=True)
            self.dependent = self.get_parameters_by_prefix('dependent_joints')
            self.zeros = self.get_parameters_by_prefix('zeros')

    def main():
        rclpy.init()
        JointStatePublisher()
    """

JSP_LAUNCH = """
    from launch import LaunchDescription
    from launch_ros.actions import Node

    def generate_launch_description():
        return LaunchDescription([Node(package='talk', executable='jsp', name='jsp',
            parameters=[{'dependent_joints': {'j1': {'parent': 'j0'}}, 'other': 1}])])
    """


def test_parameters_by_prefix_is_an_optional_read_of_every_parameter_under_it(write_tree):
    # joint_state_publisher: get_parameters_by_prefix gives {} when nothing is set there
    model = _analysed(write_tree, "jsp", JSP, JSP_LAUNCH)
    found = [(f.rule, list(f.entities), f.message) for rule in load_catalogue()
             if rule.id.startswith("parameter-") for f in run_rule(rule, model)]
    # nothing is "read but never set"; 'other' is set and not read; what is set under the
    # prefix is read as part of it (it was undecided, a read of 'dependent_joints.?')
    assert [(rule, entities) for rule, entities, _ in found] == [
        ("parameter-set-not-read", ["parameter:/jsp/other"])]
    params = {p.name: p for p in model.configuration("c").parameters}
    assert params["/jsp/dependent_joints.j1.parent"].read_as_part_of is \
        params["/jsp/dependent_joints."]


QOS_NODE = """
    import rclpy

    def main():
        rclpy.init()
        node = rclpy.create_node('talker')
        node.create_publisher(String, '/chatter', 10)
    """

QOS_LAUNCH = """
    from launch import LaunchDescription
    from launch_ros.actions import Node

    def generate_launch_description():
        return LaunchDescription([Node(package='talk', executable='talker', parameters=[{
            'qos_overrides./chatter.publisher.reliability': 'best_effort',
            'qos_overrides./a/b.subscription.depth': 5,
            'qos_overrides./chatter.subscriber.reliability': 'reliable',
            'gain': 1.0}])])
    """


def test_qos_overrides_of_a_topic_full_name_are_not_reported(write_tree):
    """rclcpp's QoS override parameters are ``qos_overrides.<the topic's full name>.
    publisher|subscription.<policy>`` (ros_gz's air_pressure.launch.py sets
    ``qos_overrides./air_pressure.publisher.reliability`` for parameter_bridge): the
    rule leaves them out, as its description says, also when the topic's "/" makes the
    last part of the name ``air_pressure.publisher.reliability``; one that names no
    entity rclcpp reads (``subscriber``, ros_gz's diff_drive.launch.py) stays."""
    model = _analysed(write_tree, "talker", QOS_NODE, QOS_LAUNCH)
    rule = next(r for r in load_catalogue() if r.id == "parameter-set-not-read")
    found = sorted(e for f in run_rule(rule, model) for e in f.entities
                   if e.startswith("parameter:"))
    assert found == ["parameter:/talker/gain",
                     "parameter:/talker/qos_overrides./chatter.subscriber.reliability"]


DECLARED_FROM_LOCAL = DECLARED_TOGETHER.replace(
    """            self.declare_parameters(namespace='', parameters=[
                ('scan_topic', 'scan'), ('gain', 0.5), ('port', rclpy.Parameter.Type.STRING),
                ('ids',)])""",
    """            parameters = [
                ('scan_topic', 'scan'), ('gain', 0.5), ('port', rclpy.Parameter.Type.STRING),
                ('ids',)]
            self.declare_parameters(namespace='', parameters=parameters)""")


def test_parameters_declared_together_from_a_local_list(write_tree):
    """raspimouse_ros2_examples' joystick_control builds its ``(name, default)`` list in a
    local and then calls ``declare_parameters('', parameters)``: the local's one list is
    read as if written in the call (its names, defaults and type-only entries), not as
    one parameter named '?'."""
    assert DECLARED_FROM_LOCAL != DECLARED_TOGETHER
    model = _analysed(write_tree, "follower", DECLARED_FROM_LOCAL,
                      LAUNCH.replace("talker", "follower"))
    declared = {c.name: (c.type, c.has_default, c.default)
                for p in model.packages for n in p.nodes for c in n.calls
                if c.kind == "declare"}
    assert declared == {"scan_topic": ("str", True, "scan"), "gain": ("double", True, 0.5),
                        "port": ("str", False, None), "ids": (None, True, None),
                        "limits.max_speed": ("double", True, 1.0)}
    rule = next(r for r in load_catalogue() if r.id == "parameter-read-not-set")
    found = sorted(e for f in run_rule(rule, model) for e in f.entities
                   if e.startswith("parameter:"))
    # ``('ids',)``, the name alone, rclpy declares dynamically typed: its get returns None
    assert found == ["parameter:/follower/port"]
