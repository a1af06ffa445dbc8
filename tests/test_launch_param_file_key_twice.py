"""A parameter file one of whose mappings writes a key twice: rcl's parser (ROS 2) and
PyYAML (roslaunch's ``<rosparam file>``) keep the later value without a word, so the
earlier is dead. wato_monorepo's nuscenes_config.yaml (fix 7871674c) wrote
``publish_clusters_topic`` twice, the second meant for the points-in-a-box publisher: the
node's two publishers took one topic and the clusters' topic lost its publisher.
LAUNCH_PARAM_FILE_KEY_TWICE at the later key; not for a key written twice with a mapping
both times (rcl merges them), nor for one key in two mappings."""

from __future__ import annotations

import json

from conftest import package_xml
from test_launch_ros1 import load_launch

from haros_arch import safe_yaml
from haros_arch.cli import main

SETUP = """
    from setuptools import setup
    setup(name="dets", packages=["dets"],
          entry_points={"console_scripts": ["dets_node = dets.node:main"]})
    """
NODE = """
    import rclpy
    from sensor_msgs.msg import PointCloud2
    def main():
        rclpy.init()
        node = rclpy.create_node("dets_node")
        clusters = node.declare_parameter("publish_clusters_topic", "c").value
        points = node.declare_parameter("publish_points", "p").value
        node.create_publisher(PointCloud2, clusters, 10)
        node.create_publisher(PointCloud2, points, 10)
    """
LAUNCH = """
    import os
    from ament_index_python.packages import get_package_share_directory
    from launch import LaunchDescription
    from launch_ros.actions import Node

    def generate_launch_description():
        config = os.path.join(get_package_share_directory("dets"), "config", "dets.yaml")
        return LaunchDescription([
            Node(package="dets", executable="dets_node", name="dets_node",
                 parameters=[config]),
            Node(package="dets", executable="dets_node", name="other_node",
                 parameters=[config]),
        ])
    """


def _check(write_tree, config: str) -> list[tuple[str, int, str]]:
    root = write_tree({
        "src/dets/package.xml": package_xml("dets", "ament_python"),
        "src/dets/setup.py": SETUP,
        "src/dets/dets/__init__.py": "",
        "src/dets/dets/node.py": NODE,
        "src/dets/config/dets.yaml": config,
        "src/dets/launch/dets.launch.py": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [dets/launch/dets.launch.py]\n",
    })
    out = root / "check.json"
    main(["check", str(root / "project.yaml"), "--format", "json", "-o", str(out),
          "--fail-on", "never"])
    report = json.loads(out.read_text())
    return [(d["location"]["file"], d["location"]["line"], d["message"])
            for d in report["diagnostics"] if d["code"] == "LAUNCH_PARAM_FILE_KEY_TWICE"]


def test_a_ros2_parameter_written_twice_is_said_once_at_the_later(write_tree):
    found = _check(write_tree, """\
dets_node:
  ros__parameters:
    publish_clusters_topic: /clustered_pc
    publish_clusters_topic: /lidar_points_in_bbox
    frames:
      lidar: top
      lidar: front
""")
    # said once though two nodes are given the file
    assert found == [
        ("dets/config/dets.yaml", 4,
         "key publish_clusters_topic is written again here (first at line 3) in the same "
         "mapping of this parameter file: rcl keeps the later value, the first is never "
         "used"),
        ("dets/config/dets.yaml", 7,
         "key frames.lidar is written again here (first at line 6) in the same mapping of "
         "this parameter file: rcl keeps the later value, the first is never used")]


def test_sections_written_twice_and_keys_of_other_mappings_are_not_said(write_tree):
    # rcl merges a node's two sections, and its ros__parameters; one key under two nodes
    # (or two namespaces) is two parameters
    assert _check(write_tree, """\
dets_node:
  ros__parameters:
    publish_clusters_topic: /clustered_pc
other_node:
  ros__parameters:
    publish_clusters_topic: /clustered_pc
dets_node:
  ros__parameters:
    publish_points: /lidar_points_in_bbox
    a:
      x: 1
    b:
      x: 1
""") == []


def test_a_rosparam_file_key_written_twice_is_said(write_tree):
    model = load_launch(write_tree, """<launch>
          <node pkg="amcl" type="amcl" name="amcl">
            <rosparam file="$(find pkg)/config/amcl.yaml" command="load"/>
          </node>
        </launch>""", extra={"src/pkg/config/amcl.yaml": (
        "kld_err: 0.02\nkld_err: 0.99\nlaser:\n  max_range: 10\n  max_range: 12\n")})
    said = [(d.location.file, d.location.line, d.message) for d in model.diagnostics
            if d.code == "LAUNCH_PARAM_FILE_KEY_TWICE"]
    assert said == [
        ("pkg/config/amcl.yaml", 2,
         "key kld_err is written again here (first at line 1) in the same mapping of "
         "this parameter file: roslaunch (PyYAML) keeps the later value, the first is "
         "never used"),
        ("pkg/config/amcl.yaml", 5,
         "key laser/max_range is written again here (first at line 4) in the same mapping "
         "of this parameter file: roslaunch (PyYAML) keeps the later value, the first is "
         "never used")]
    # the model keeps the later value, as roslaunch does
    assert [(p.name, p.value) for p in model.params if p.name.endswith("kld_err")] == [
        ("/amcl/kld_err", 0.99)]


def test_keys_twice_reads_no_yaml_as_nothing():
    assert safe_yaml.keys_twice("a: [1\n") == []
    assert safe_yaml.keys_twice("a: 1\n<<: {b: 2}\nb: 3\n") == []
    assert safe_yaml.keys_twice("- a: 1\n  a: 2\n") == [(("a",), 1, 2)]


def test_a_rosparam_file_mapping_written_twice_is_said_as_pyyaml_replaces_it(write_tree):
    model = load_launch(write_tree, """<launch>
          <node pkg="move_base" type="move_base" name="move_base">
            <rosparam file="$(find pkg)/config/costmap.yaml" command="load"/>
          </node>
        </launch>""", extra={"src/pkg/config/costmap.yaml": (
        "local_costmap:\n  width: 4\n  height: 4\nglobal_costmap:\n  width: 40\n"
        "local_costmap:\n  resolution: 0.05\n")})
    said = [(d.location.line, d.message.split(" is written")[0]) for d in model.diagnostics
            if d.code == "LAUNCH_PARAM_FILE_KEY_TWICE"]
    assert said == [(6, "key local_costmap")]
    # the first mapping's keys are gone, as roslaunch loads the file
    assert sorted(p.name for p in model.params if "local_costmap" in p.name) == [
        "/move_base/local_costmap/resolution"]
