"""In ROS 1 two node instances of one name never run at one time: roslaunch refuses a
launch that starts two (LAUNCH_NODE_DUPLICATE), and a node started later under a name
shuts the earlier one down. hexapod_ros' all_local_debug.launch:12 includes rviz.launch,
which hexapod_full.launch already includes through hexapod_simple.launch:13: roslaunch
refuses the file, said once with its place, and multiple-publishers and
multiple-service-servers said the same mistake seven times more ("/initialpose is
published by /rviz (2 instances)", one per topic and service of rviz). Two ROS 1
instances of one name are one publisher; a node of another name beside them still
counts, and in ROS 2, where two nodes of one name both run, they are two. The refusal
names the include of each when both start at one place, the included file's line."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load as load_project
from haros_arch.query.catalogue import load_catalogue, run_rule

TALKER = """
    #!/usr/bin/env python
    import rospy
    from std_msgs.msg import String
    from std_srvs.srv import Empty
    rospy.init_node("talker")
    pub = rospy.Publisher("/chatter", String, queue_size=10)
    srv = rospy.Service("/reset", Empty, lambda req: None)
    rospy.spin()
    """

VIEW = """
    <launch>
      <node name="talker" pkg="t" type="talker.py"/>
    </launch>
    """

# the same file included twice: roslaunch refuses the second /talker
TWICE = """
    <launch>
      <include file="$(find t)/launch/view.launch"/>
      <include file="$(find t)/launch/view.launch"/>
    </launch>
    """

# beside it, a node of another name on the same topic and service
OTHER = """
    <launch>
      <include file="$(find t)/launch/view.launch"/>
      <include file="$(find t)/launch/view.launch"/>
      <node name="second" pkg="t" type="talker.py"/>
    </launch>
    """

TALKER2 = """
    import rclpy
    from std_msgs.msg import String
    from std_srvs.srv import Empty

    def main():
        rclpy.init()
        node = rclpy.create_node('talker')
        node.create_publisher(String, '/chatter', 10)
        node.create_service(Empty, '/reset', lambda req, res: res)
        rclpy.spin(node)
    """

LAUNCH2 = """
    from launch import LaunchDescription
    from launch_ros.actions import Node

    def generate_launch_description():
        return LaunchDescription([
            Node(package='t2', executable='talker', name='talker'),
            Node(package='t2', executable='talker', name='talker'),
        ])
    """

SETUP2 = """
    from setuptools import setup
    setup(name='t2', packages=['t2'],
          entry_points={'console_scripts': ['talker = t2.talker:main']})
    """


def _findings(root, rule_id: str) -> dict[str, str]:
    model = analyse(load_project(str(root / "project.yaml")),
                    {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    rule = next(r for r in load_catalogue() if r.id == rule_id)
    return {f.rule: f.message for f in run_rule(rule, model)}


def _ros1(write_tree, launch: str):
    root = write_tree({
        "src/t/package.xml": package_xml("t"),
        "src/t/CMakeLists.txt": "project(t)\n",
        "src/t/scripts/talker.py": TALKER,
        "src/t/launch/view.launch": VIEW,
        "src/t/launch/robot.launch": launch,
        "project.yaml": "project: p\nconfigurations:\n  c: [t/launch/robot.launch]\n"})
    (root / "src/t/scripts/talker.py").chmod(0o755)
    return root


def test_two_ros1_instances_of_one_name_are_one_publisher(write_tree) -> None:
    root = _ros1(write_tree, TWICE)
    assert _findings(root, "multiple-publishers") == {}
    assert _findings(root, "multiple-service-servers") == {}
    # the mistake itself is said once, by roslaunch's refusal
    model = analyse(load_project(str(root / "project.yaml")),
                    {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    refused = [d for d in model.configurations[0].diagnostics
               if d.code == "LAUNCH_NODE_DUPLICATE"]
    assert len(refused) == 1
    # both start at view.launch:2: the includes that reached each are what to change
    assert refused[0].message == (
        "launch starts two nodes named /talker (also at t/launch/view.launch:2, "
        "included at t/launch/robot.launch:2; this one included at "
        "t/launch/robot.launch:3)")


def test_another_ros1_name_beside_them_still_counts(write_tree) -> None:
    root = _ros1(write_tree, OTHER)
    assert _findings(root, "multiple-publishers") == {
        "multiple-publishers": "/chatter is published by /talker (2 instances), /second"}
    assert _findings(root, "multiple-service-servers") == {
        "multiple-service-servers": "/reset is served by /talker (2 instances), /second"}


def test_two_ros2_nodes_of_one_name_both_run(write_tree) -> None:
    root = write_tree({
        "src/t2/package.xml": package_xml("t2", "ament_python"),
        "src/t2/setup.py": SETUP2,
        "src/t2/t2/__init__.py": "",
        "src/t2/t2/talker.py": TALKER2,
        "src/t2/launch/a.launch.py": LAUNCH2,
        "project.yaml": "project: p\nconfigurations:\n  c: [t2/launch/a.launch.py]\n"})
    assert _findings(root, "multiple-publishers") == {
        "multiple-publishers": "/chatter is published by /talker (2 instances)"}
