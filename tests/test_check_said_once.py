"""``haros-arch check`` says each problem once, even where two mechanisms can see it."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.cli import main

SETUP = """
    from setuptools import setup
    setup(name="cams", packages=["cams"],
          entry_points={"console_scripts": ["cam = cams.cam:main"]})
    """
ROS2_NODE = """
    import rclpy
    from sensor_msgs.msg import Image
    def main():
        rclpy.init()
        node = rclpy.create_node("cam")
        node.create_publisher(Image, "image", 10)
    """
ROS1_NODE = """
    #!/usr/bin/env python
    import rospy
    from sensor_msgs.msg import Image
    rospy.init_node("cam")
    pub = rospy.Publisher("image", Image, queue_size=10)
    """


def check(root) -> dict:
    out = root / "check.json"
    main(["check", str(root / "project.yaml"), "--format", "json", "-o", str(out),
          "--fail-on", "never"])
    return json.loads(out.read_text())


def about(report: dict, *words: str) -> list[tuple[str, str, int]]:
    """Every diagnostic and finding whose code or rule names one of ``words``."""
    found = [(d["code"], d["location"]["file"], d["location"]["line"])
             for d in report["diagnostics"] if any(w in d["code"] for w in words)]
    found += [(f["rule"], f["location"]["file"], f["location"]["line"])
              for f in report["findings"] if any(w in f["rule"] for w in words)]
    return found


def ros1_workspace(write_tree, launch: dict[str, str], config: str):
    files = {"src/cams/package.xml": package_xml("cams"),
             "src/cams/CMakeLists.txt": "project(cams)\n",
             "src/cams/scripts/cam": ROS1_NODE,
             "project.yaml": f"project: p\nconfigurations:\n  c: {config}\n"}
    files.update({f"src/cams/launch/{name}": text for name, text in launch.items()})
    root = write_tree(files)
    (root / "src/cams/scripts/cam").chmod(0o755)
    return root


def test_a_ros1_duplicate_in_one_launch_file_is_roslaunchs_error_only(write_tree):
    root = ros1_workspace(write_tree, {"two.launch": """
        <launch>
          <node name="cam" pkg="cams" type="cam"/>
          <node name="cam" pkg="cams" type="cam"/>
        </launch>
        """}, "[cams/launch/two.launch]")
    assert about(check(root), "DUPLICATE", "duplicate") == [
        ("LAUNCH_NODE_DUPLICATE", "cams/launch/two.launch", 3)]


def test_a_ros1_duplicate_across_launch_files_is_the_querys(write_tree):
    root = ros1_workspace(write_tree, {
        "a.launch": '<launch>\n  <node name="cam" pkg="cams" type="cam"/>\n</launch>\n',
        "b.launch": '<launch>\n  <node name="cam" pkg="cams" type="cam"/>\n</launch>\n',
    }, "[cams/launch/a.launch, cams/launch/b.launch]")
    assert about(check(root), "DUPLICATE", "duplicate") == [
        ("duplicate-node-names", "cams/launch/a.launch", 2)]


# turtlebot3_bringup/launch/turtlebot3_lidar.launch (noetic): the LDS model comes from
# the environment; each model's driver is started in a group of its own under the name
# turtlebot3_lds, so whatever LDS_MODEL is, at most one of them starts (survey B)
TB3_LIDAR = """
<launch>
  <arg name="set_frame_id" default="base_scan"/>
  <arg name="lds_model" default="$(env LDS_MODEL)" doc="LDS MODEL [LDS-01, LDS-02]"/>

  <group if = "$(eval lds_model == 'LDS-01')">
    <node pkg="cams" type="cam" name="turtlebot3_lds" output="screen">
      <param name="port" value="/dev/ttyUSB0"/>
      <param name="frame_id" value="$(arg set_frame_id)"/>
    </node>
  </group>
  <group if = "$(eval lds_model == 'LDS-02')">
    <node pkg="cams" type="cam" name="turtlebot3_lds" output="screen" args="LD08">
      <param name="frame_id" value="$(arg set_frame_id)"/>
    </node>
  </group>
</launch>
"""


def test_ros1_nodes_of_one_name_under_exclusive_conditions_are_no_duplicate(
        write_tree, monkeypatch):
    monkeypatch.delenv("LDS_MODEL", raising=False)  # not known statically
    root = ros1_workspace(write_tree, {"lidar.launch": TB3_LIDAR, "switch.launch": """
        <launch>
          <arg name="sim"/>
          <node name="cam" pkg="cams" type="cam" if="$(arg sim)"/>
          <node name="cam" pkg="cams" type="cam" unless="$(arg sim)"/>
          <node name="other" pkg="cams" type="cam" if="$(eval arg('sim') == 'a')"/>
          <node name="other" pkg="cams" type="cam" if="$(eval arg('sim') != 'a')"/>
        </launch>
        """}, "[cams/launch/lidar.launch, cams/launch/switch.launch]")
    assert about(check(root), "DUPLICATE", "duplicate") == []


def test_ros1_nodes_of_one_name_under_conditions_not_known_are_undecided(write_tree):
    # under the same conditions both start together: roslaunch refuses them
    root = ros1_workspace(write_tree, {"two.launch": """
        <launch>
          <arg name="sim"/>
          <group if="$(arg sim)">
            <node name="cam" pkg="cams" type="cam"/>
            <node name="cam" pkg="cams" type="cam"/>
          </group>
        </launch>
        """}, "[cams/launch/two.launch]")
    assert about(check(root), "DUPLICATE", "duplicate") == [
        ("LAUNCH_NODE_DUPLICATE", "cams/launch/two.launch", 5)]
    # both start when sim and real are both true: not an error, one undecided info
    root = ros1_workspace(write_tree, {"two.launch": """
        <launch>
          <arg name="sim"/>
          <arg name="real"/>
          <node name="cam" pkg="cams" type="cam" if="$(arg sim)"/>
          <node name="cam" pkg="cams" type="cam" if="$(arg real)"/>
        </launch>
        """}, "[cams/launch/two.launch]")
    report = check(root)
    assert about(report, "DUPLICATE", "duplicate") == [
        ("duplicate-node-names-undecided", "cams/launch/two.launch", 4)]
    (info,) = [f for f in report["findings"] if f["rule"].startswith("duplicate")]
    assert info["severity"] == "info" and "launch conditions" in info["message"]


def test_a_ros2_duplicate_is_reported_once(write_tree):
    root = write_tree({
        "src/cams/package.xml": package_xml("cams", "ament_python"),
        "src/cams/setup.py": SETUP,
        "src/cams/cams/__init__.py": "",
        "src/cams/cams/cam.py": ROS2_NODE,
        "src/cams/launch/two.launch.xml": """
            <launch>
              <node pkg="cams" exec="cam" name="cam"/>
              <node pkg="cams" exec="cam" name="cam"/>
            </launch>
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [cams/launch/two.launch.xml]\n",
    })
    assert about(check(root), "DUPLICATE", "duplicate") == [
        ("duplicate-node-names", "cams/launch/two.launch.xml", 2)]



def test_ros2_nodes_of_one_name_one_started_on_the_others_exit_are_no_duplicate(
        write_tree):
    """clearpath_simulator's robot_spawn.launch.py names two generator processes
    ``generate_launch``; the second starts on the exit of the first (``OnProcessExit``),
    so they never run together: no duplicate. Two started by the exits of different
    processes may run together, which is not known: undecided (an info), not an error."""
    root = write_tree({
        "src/cams/package.xml": package_xml("cams", "ament_python"),
        "src/cams/setup.py": SETUP,
        "src/cams/cams/__init__.py": "",
        "src/cams/cams/cam.py": ROS2_NODE,
        "src/cams/launch/chain.launch.py": """
from launch import LaunchDescription
from launch.actions import RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch_ros.actions import Node


def generate_launch_description():
    first = Node(package='cams', executable='cam', name='gen')
    second = Node(package='cams', executable='cam', name='gen')
    third = Node(package='cams', executable='cam', name='other')
    fourth = Node(package='cams', executable='cam', name='shared')
    fifth = Node(package='cams', executable='cam', name='shared')
    return LaunchDescription([
        first, third,
        RegisterEventHandler(OnProcessExit(target_action=first, on_exit=[second])),
        RegisterEventHandler(OnProcessExit(target_action=second, on_exit=[fourth])),
        RegisterEventHandler(OnProcessExit(target_action=third, on_exit=[fifth])),
    ])
""",
        "project.yaml": "project: p\nconfigurations:\n  c: [cams/launch/chain.launch.py]\n",
    })
    report = check(root)
    assert about(report, "DUPLICATE", "duplicate") == [
        ("duplicate-node-names-undecided", "cams/launch/chain.launch.py", 11)]


def test_a_listed_package_missing_from_the_workspace_is_shown(write_tree):
    root = write_tree({"src/cams/package.xml": package_xml("cams"),
                       "project.yaml": "project: p\npackages: [nope]\nconfigurations:\n"
                                       "  c: []\n"})
    assert [code for code, _file, _line in about(check(root), "NOT_FOUND", "missing")] == [
        "PACKAGE_NOT_FOUND"]


DYNAMIC_NODE = """
    #!/usr/bin/env python
    import sys
    import rospy
    from sensor_msgs.msg import Image
    rospy.init_node("cam")
    pub = rospy.Publisher(sys.argv[1], Image, queue_size=10)
    """


def test_a_run_time_name_is_said_once(write_tree):
    # the launched node's name: unresolved-names, per instance; the other node's (not
    # launched): the extractor's diagnostic
    root = ros1_workspace(write_tree, {"one.launch": """
        <launch>
          <node name="cam" pkg="cams" type="cam"/>
        </launch>
        """}, "[cams/launch/one.launch]")
    for script in ("cam", "spare"):
        (root / f"src/cams/scripts/{script}").write_text(DYNAMIC_NODE.lstrip()
                                                        .replace("\n    ", "\n"))
        (root / f"src/cams/scripts/{script}").chmod(0o755)
    assert about(check(root), "DYNAMIC_NAME", "unresolved") == [
        ("PY_DYNAMIC_NAME", "cams/scripts/spare", 6),
        ("unresolved-names", "cams/scripts/cam", 6)]
