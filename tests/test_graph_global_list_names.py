"""A call named by each element of a list parameter, made on a handle with a namespace:
an element that is a global name is that name, not one in the handle's namespace, as a
single parameter's global value already was (``build._filled``). PX4-Avoidance's global
planner subscribes each of its ``~pointcloud_topics`` (``[/camera/depth/points]``) on its
private handle: the subscription was ``/global_planner_node/camera/depth/points``."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

PLANNER_MODEL = {
    "schema": "haros-arch-model/2", "package": "planner", "distro": "noetic", "nodes": [{
        "package": "planner", "executable": "planner", "rosname": "planner", "calls": [
            {"kind": "read", "name": "~pointcloud_topics", "type": "str[]"},
            {"kind": "subscribe", "name": "~?", "type": "sensor_msgs/PointCloud2",
             "name_param": "~pointcloud_topics", "name_each": ".",
             "handle_namespace": "~"},
            {"kind": "read", "name": "~sources", "type": "str"},
            {"kind": "subscribe", "name": "~?", "type": "sensor_msgs/LaserScan",
             "name_param": "~sources", "name_each": " ", "handle_namespace": "~"}]}]}

LAUNCH = """
<launch>
  <node pkg="planner" type="planner" name="planner">
    <rosparam param="pointcloud_topics">[/camera/depth/points, front/points]</rosparam>
    <param name="sources" value="/scan rear_scan"/>
  </node>
</launch>
"""


def test_a_global_element_of_a_list_names_its_call_whole(write_tree) -> None:
    root = write_tree({
        "src/robot/package.xml": package_xml("robot"),
        "src/robot/CMakeLists.txt": "project(robot)\n",
        "src/robot/launch/planner.launch": LAUNCH,
        "models/planner.json": json.dumps(PLANNER_MODEL),
        "project.yaml": "project: p\nmodels: [models]\n"
                        "configurations:\n  c:\n    launch: [robot/launch/planner.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    (node,) = config.nodes
    assert sorted((link.type, link.name) for link in node.subscribers) == [
        ("sensor_msgs/LaserScan", "/planner/rear_scan"),
        ("sensor_msgs/LaserScan", "/scan"),
        ("sensor_msgs/PointCloud2", "/camera/depth/points"),
        ("sensor_msgs/PointCloud2", "/planner/front/points"),
    ]
