"""A ROS 1 ``<remap>`` element is one remap, whichever namespaces the nodes it reaches
resolve it in. autoware_mini (UT-ADL, f0a4c3e) writes ``<remap from="detected_objects"
to="/detection/detected_objects"/>`` in its ``lidar`` group: cluster_detector there
publishes ``detected_objects``; ground_removal, in the nested group ``center``, resolves
the source to ``/detection/lidar/center/detected_objects`` and does not use it. The
remap was judged per name it resolved to, and the nested node's half reported as a remap
that changes no name, though the element renames the cluster detector's topic. Two
elements of one text stay two remaps (jackal's teleop.launch), and a finding about a
remap points at its element, where it is fixed."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.model.load import from_data
from haros_arch.model.serialise import model_to_data
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

NODE = """#!/usr/bin/env python
import rospy
from std_msgs.msg import String
rospy.init_node('{name}')
pub = rospy.Publisher('{topic}', String, queue_size=1)
rospy.spin()
"""


def _analyse(write_tree, launch: str):
    root = write_tree({
        "src/robot/package.xml": package_xml("robot"),
        "src/robot/CMakeLists.txt": "project(robot)\ncatkin_install_python(PROGRAMS "
                                    "nodes/cluster.py nodes/ground.py DESTINATION bin)\n",
        "src/robot/nodes/cluster.py": NODE.format(name="cluster", topic="detected_objects"),
        "src/robot/nodes/ground.py": NODE.format(name="ground", topic="points_ground"),
        "src/robot/launch/detection.launch": launch,
        "project.yaml": "project: p\nconfigurations:\n  c: [robot/launch/detection.launch]\n",
    })
    return analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))


GROUP = """<launch>
  <group ns="lidar">
    <remap from="detected_objects" to="/detection/detected_objects"/>
    <group ns="center">
      <node pkg="robot" type="ground.py" name="ground"/>
    </group>
    <node pkg="robot" type="cluster.py" name="cluster"/>
  </group>
</launch>
"""


def test_a_group_remap_used_by_one_node_it_reaches_is_used(write_tree) -> None:
    model = _analyse(write_tree, GROUP)
    (config,) = model.configurations
    (remap,) = config.remaps
    assert sorted(n.name for n in remap.nodes) == ["/lidar/center/ground", "/lidar/cluster"]
    assert [n.name for n in remap.users] == ["/lidar/cluster"]
    assert (remap.location.file, remap.location.line) == ("robot/launch/detection.launch", 3)
    assert not [f for f in run_catalogue(model) if f.rule.startswith("remap-unused")]


def test_the_element_is_kept_in_a_saved_model(write_tree) -> None:
    model = _analyse(write_tree, GROUP)
    again = from_data(json.loads(json.dumps(model_to_data(model))))
    (remap,) = again.configurations[0].remaps
    assert [n.name for n in remap.users] == ["/lidar/cluster"]
    assert remap.location.line == 3


def test_two_elements_of_one_text_are_two_remaps(write_tree) -> None:
    # the same text written for each node: each element is judged by its own node, and
    # the finding points at the element no node uses
    model = _analyse(write_tree, """<launch>
  <group ns="lidar">
    <node pkg="robot" type="cluster.py" name="cluster">
      <remap from="detected_objects" to="/detection/detected_objects"/>
    </node>
    <node pkg="robot" type="ground.py" name="ground">
      <remap from="detected_objects" to="/detection/detected_objects"/>
    </node>
  </group>
</launch>
""")
    (config,) = model.configurations
    assert sorted((r.location.line, [n.name for n in r.users]) for r in config.remaps) == [
        (4, ["/lidar/cluster"]), (7, [])]
    (finding,) = [f for f in run_catalogue(model) if f.rule == "remap-unused"]
    assert "/lidar/ground" in finding.message
    assert (finding.location.file, finding.location.line) == ("robot/launch/detection.launch", 7)


def test_an_unread_include_near_any_node_of_the_element_may_use_it(write_tree) -> None:
    # the element reaches /lidar/center/ground first and /lidar/other; an include not
    # read in /lidar/other may start the node that uses the name: undecided, not reported
    model = _analyse(write_tree, """<launch>
  <group ns="lidar">
    <remap from="detected_objects" to="/detection/detected_objects"/>
    <group ns="center">
      <node pkg="robot" type="ground.py" name="ground"/>
    </group>
    <group ns="other">
      <node pkg="robot" type="ground.py" name="ground2"/>
      <include file="$(find missing_detector)/launch/detector.launch"/>
    </group>
  </group>
</launch>
""")
    (remap,) = model.configurations[0].remaps
    assert [n.name for n in remap.nodes] == ["/lidar/center/ground", "/lidar/other/ground2"]
    assert remap.users == [] and remap.unseen
    rules = [f.rule for f in run_catalogue(model) if f.rule.startswith("remap-unused")]
    assert rules == ["remap-unused-undecided"]
