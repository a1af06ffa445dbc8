"""A ROS 2 launch ``Node`` without ``name=`` runs its node under the name the code gives
it: the instance, its private names and the launch parameters follow that name."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

SETUP = """
    from setuptools import setup
    setup(name='{pkg}', packages=['{pkg}'],
          entry_points={{'console_scripts': ['{exe} = {pkg}.{exe}:main']}})
    """

TALKER = """
    import rclpy
    from std_msgs.msg import String

    def main():
        rclpy.init()
        node = rclpy.create_node('talker'{namespace})
        node.declare_parameter('rate', 1.0)
        node.create_publisher(String, 'chatter', 10)
        node.create_publisher(String, '~/status', 10)
        rclpy.spin(node)
    """


def workspace(write_tree, launch: str, namespace: str = ""):
    return write_tree({
        "src/talk/package.xml": package_xml("talk", build_type="ament_python"),
        "src/talk/setup.py": SETUP.format(pkg="talk", exe="talker"),
        "src/talk/resource/talk": "",
        "src/talk/talk/__init__.py": "",
        "src/talk/talk/talker.py": TALKER.format(namespace=namespace),
        "src/talk/launch/talk.launch.py": launch,
        "project.yaml": "project: p\nconfigurations:\n  c: [talk/launch/talk.launch.py]\n",
    })


def build(root):
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    return model.configuration("c")


LAUNCH = """
    from launch import LaunchDescription
    from launch_ros.actions import Node

    def generate_launch_description():
        return LaunchDescription([
            Node(package='talk', executable='talker', {extra}
                 parameters=[{{'rate': 5.0}}]),
        ])
    """


def test_unnamed_node_takes_its_code_name_in_the_launch_namespace(write_tree):
    config = build(workspace(write_tree, LAUNCH.format(extra="namespace='robot',")))
    assert [n.name for n in config.nodes] == ["/robot/talker"]
    assert sorted((link.kind, link.name) for link in config.links) == [
        ("publish", "/robot/chatter"), ("publish", "/robot/talker/status"),
        ("read", "/robot/talker/rate")]
    rate = config.parameter("/robot/talker/rate")
    assert rate is not None and rate.set_by_launch and rate.value == 5.0
    assert config.parameter("/robot/?/rate") is None


def test_code_namespace_holds_unless_the_launch_gives_one(write_tree):
    """jetbot_ros d8e5ee1's nav_model: ``super().__init__('nav_model',
    namespace='jetbot')``, launched with no namespace, subscribes ``camera/image_raw``,
    which is ``/jetbot/camera/image_raw``: the node's relative names resolve in the
    namespace its code gives, as its own name does (they resolved in ``/``)."""
    config = build(workspace(write_tree, LAUNCH.format(extra=""), ", namespace='arm'"))
    assert [(n.name, n.namespace) for n in config.nodes] == [("/arm/talker", "/arm/")]
    assert sorted((link.kind, link.name) for link in config.links) == [
        ("publish", "/arm/chatter"), ("publish", "/arm/talker/status"),
        ("read", "/arm/talker/rate")]
    assert config.parameter("/arm/talker/rate").set_by_launch
    config = build(workspace(write_tree, LAUNCH.format(extra="namespace='robot',"),
                             ", namespace='arm'"))
    assert [n.name for n in config.nodes] == ["/robot/talker"]


def test_launch_name_keeps_the_code_namespace_unless_one_is_given(write_tree):
    """``Node(name='speaker')`` with no namespace of a node whose code says
    ``namespace='arm'``: launch_ros passes ``__node:=speaker`` and no ``__ns``, so rcl
    names it ``/arm/speaker`` and its relative names resolve in ``/arm`` (it was
    ``/speaker``, its topics in ``/``). A namespace the launch gives, even ``/``, is
    passed as ``__ns`` and replaces the code's."""
    config = build(workspace(write_tree, LAUNCH.format(extra="name='speaker',"),
                             ", namespace='arm'"))
    assert [(n.name, n.namespace) for n in config.nodes] == [("/arm/speaker", "/arm/")]
    assert sorted((link.kind, link.name) for link in config.links) == [
        ("publish", "/arm/chatter"), ("publish", "/arm/speaker/status"),
        ("read", "/arm/speaker/rate")]
    assert config.parameter("/arm/speaker/rate").set_by_launch
    config = build(workspace(write_tree, LAUNCH.format(extra="name='speaker', namespace='/',"),
                             ", namespace='arm'"))
    assert [(n.name, n.namespace) for n in config.nodes] == [("/speaker", "/")]
    assert sorted(link.name for link in config.links) == [
        "/chatter", "/speaker/rate", "/speaker/status"]
    config = build(workspace(write_tree, LAUNCH.format(extra="namespace='/',"),
                             ", namespace='arm'"))
    assert [n.name for n in config.nodes] == ["/talker"]


def test_launch_name_wins_over_the_code_name(write_tree):
    config = build(workspace(write_tree, LAUNCH.format(extra="name='speaker',")))
    assert [n.name for n in config.nodes] == ["/speaker"]
    assert config.parameter("/speaker/rate").set_by_launch


def test_two_unnamed_nodes_keep_their_own_launch_parameters(write_tree):
    # acme_driver is not in the workspace and has no interface model: named after its
    # executable, a guess said in a diagnostic, with its parameter; the talker's parameter
    # goes to /talker only; an executable not known statically leaves the name unknown
    launch = """
        from launch import LaunchDescription
        from launch_ros.actions import Node

        def generate_launch_description():
            return LaunchDescription([
                Node(package='acme_driver', executable='acme_driver',
                     parameters=[{'robot_description': '<robot/>'}]),
                Node(package='talk', executable='talker', parameters=[{'rate': 5.0}]),
                Node(package='other', executable=EnvironmentVariable('EXE_UNSET'),
                     parameters=[{'x': 1}]),
            ])
        """
    config = build(workspace(write_tree, launch.replace(
        "from launch_ros.actions import Node",
        "from launch_ros.actions import Node\n        "
        "from launch.substitutions import EnvironmentVariable")))
    assert [n.name for n in config.nodes] == ["/acme_driver", "/talker", "/?"]
    assert config.parameter("/talker/rate").value == 5.0
    assert config.parameter("/talker/robot_description") is None
    assert config.parameter("/acme_driver/robot_description").set_by_launch
    assert config.parameter("/acme_driver/rate") is None
    assert config.parameter("/?/x").set_by_launch
    guessed = [d for d in config.diagnostics if d.code == "NODE_NAME_GUESSED"]
    assert [(d.location.line, "guess" in d.message) for d in guessed] == [(7, True)]


FILE_LAUNCH = """
    import os
    from launch import LaunchDescription
    from launch_ros.actions import Node

    def generate_launch_description():
        here = os.path.dirname(os.path.abspath(__file__))
        return LaunchDescription([
            Node(package='talk', executable='talker',
                 parameters=[os.path.join(here, 'talk.yaml'), {'late': 3}]),
        ])
    """

PARAM_FILE = """
    /**:
      ros__parameters:
        shared: 1
    talker:
      ros__parameters:
        rate: 7.0
        late: 2
    /**/talker:
      ros__parameters:
        wild: true
    listener:
      ros__parameters:
        rate: 9.0
    """


def test_a_parameter_files_section_for_the_node_applies_once_its_code_names_it(write_tree):
    root = workspace(write_tree, FILE_LAUNCH)
    (root / "src/talk/launch/talk.yaml").write_text(PARAM_FILE.replace("\n    ", "\n"))
    config = build(root)
    given = {p.name: p.value for p in config.parameters if p.set_by_launch}
    # /** for any name; talker: and /**/talker match /talker; listener: does not; the
    # launch file's later {'late': 3} replaces the file's late
    assert given == {"/talker/shared": 1, "/talker/rate": 7.0, "/talker/wild": True,
                     "/talker/late": 3}


UNNAMED_FILE_LAUNCH = """
    import os
    from launch import LaunchDescription
    from launch_ros.actions import Node

    def generate_launch_description():
        here = os.path.dirname(__file__)
        return LaunchDescription([
            Node(package='talk', executable='{executable}',
                 parameters=[os.path.join(here, 'talk.yaml')]),
        ])
    """


def test_a_parameter_file_of_an_unnamed_node_its_code_names_is_no_warning(write_tree):
    """TurtleBot 4 (``robot.launch.py:62``), joy_teleop, twist_mux: a Node without
    ``name=`` given a file with a section for its node warned "applied to /?, whose name
    is not known here" although the code names it and the section is applied. The
    warning stays for a node whose name is only guessed from its executable."""
    root = workspace(write_tree, UNNAMED_FILE_LAUNCH.format(executable="talker"))
    (root / "src/talk/launch/talk.yaml").write_text(
        "talker:\n  ros__parameters:\n    rate: 7.0\n")
    config = build(root)
    rate = config.parameter("/talker/rate")
    assert rate is not None and rate.set_by_launch and rate.value == 7.0
    assert [d for d in config.diagnostics if d.code == "LAUNCH_PARAM_FILE"] == []
    root = workspace(write_tree, UNNAMED_FILE_LAUNCH.format(executable="listener"))
    (root / "src/talk/launch/talk.yaml").write_text(
        "talker:\n  ros__parameters:\n    rate: 7.0\n")
    config = build(root)
    warned = [d for d in config.diagnostics if d.code == "LAUNCH_PARAM_FILE"]
    assert [(d.severity, d.location.line) for d in warned] == [("warning", 8)]
    assert "/?, whose name is not known here" in warned[0].message


def test_a_launch_name_not_known_statically_is_not_the_code_name(write_tree):
    """usb_cam's camera.launch.py: ``Node(..., name=camera.name)`` with ``camera`` an
    object the reader cannot compute. The launch does name the node (the code's name is
    not used): the name stays unknown rather than becoming the code's 'talker'."""
    config = build(workspace(write_tree, LAUNCH.format(
        extra="name=os.environ.get('NOT_SET_HERE_AT_ALL'),").replace(
        "from launch import", "import os\n    from launch import")))
    assert [n.name for n in config.nodes] == ["/?"]
    config = build(workspace(write_tree, LAUNCH.format(extra="")))
    assert [n.name for n in config.nodes] == ["/talker"]
