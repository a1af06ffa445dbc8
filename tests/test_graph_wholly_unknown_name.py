"""A name wholly unknown (``?``: VINS-Mono's feature_tracker subscribes ``IMAGE_TOPIC``,
read from its own YAML file with ``cv::FileStorage``, on ``NodeHandle("~")``; the value
is ``/cam0/image_raw``) may be global, which roscpp, rospy and rcl take as it is on any
handle: it is in no namespace, ``?``, and may stand for any topic of its type. A name
only partly unknown keeps what is known (``cam/?`` on the private handle stays the
node's). The checks then say "undecided", not "nothing subscribes"."""

from __future__ import annotations

import os

from conftest import package_xml
from test_graph import call, graph, node

from haros_arch.graph import find_candidates
from haros_arch.launch.model import NodeDecl
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

TRACKER = """\
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <iostream>
#include <string>

void img_callback(const sensor_msgs::ImageConstPtr &msg) {}

int main(int argc, char **argv) {
  ros::init(argc, argv, "feature_tracker");
  ros::NodeHandle n("~");
  std::string image_topic;
  std::cin >> image_topic;  // from a file the tool does not read
  ros::Subscriber sub_img = n.subscribe(image_topic, 100, img_callback);
  ros::Subscriber sub_cam = n.subscribe("cam/" + image_topic, 100, img_callback);
  ros::spin();
}
"""

CAMERA = """#!/usr/bin/env python
import rospy
from sensor_msgs.msg import Image
rospy.init_node('camera')
pub = rospy.Publisher('/cam0/image_raw', Image, queue_size=1)
sub = rospy.Subscriber('/cam1/image_raw', Image, lambda m: None)
rospy.spin()
"""

CMAKE = """\
cmake_minimum_required(VERSION 3.0.2)
project(vins)
find_package(catkin REQUIRED COMPONENTS roscpp sensor_msgs)
catkin_package()
add_executable(tracker src/tracker.cpp)
"""

LAUNCH = """<launch>
  <node pkg="vins" type="camera.py" name="camera"/>
  <group ns="vins">
    <node pkg="vins" type="tracker" name="feature_tracker"/>
  </group>
</launch>
"""


def test_a_wholly_unknown_name_on_a_private_handle_may_be_global(write_tree):
    root = write_tree({
        "src/vins/package.xml": package_xml("vins"),
        "src/vins/CMakeLists.txt": CMAKE,
        "src/vins/src/tracker.cpp": TRACKER,
        "src/vins/scripts/camera.py": CAMERA,
        "src/vins/launch/vins.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [vins/launch/vins.launch]\n",
    })
    os.chmod(root / "src/vins/scripts/camera.py", 0o755)
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    tracker = config.node("/vins/feature_tracker")
    assert tracker is not None and tracker.is_complete
    names = sorted((link.rosname.given, link.rosname.full) for link in tracker.links
                   if link.kind == "subscribe")
    # the whole name unknown: in no namespace; "cam/" known: the private handle's
    assert names == [("~?", "?"), ("~cam/?", "/vins/feature_tracker/cam/?")]
    unknown = next(link.resource for link in tracker.links if link.rosname.full == "?")
    assert [c.name for c in unknown.candidates] == ["/cam0/image_raw", "/cam1/image_raw"]
    found: dict[str, list[str]] = {}
    for finding in run_catalogue(model, project):
        found.setdefault(finding.rule, []).append(finding.message)
    # the camera's topic may be the one the tracker subscribes: not a finding, undecided
    assert "publisher-without-subscriber" not in found
    assert any("/cam0/image_raw" in m
               for m in found.get("publisher-without-subscriber-undecided", []))
    # a node that subscribes "?" may be a subscriber of any image topic, never its
    # publisher: nothing publishes /cam1/image_raw, a finding still; nor does anything
    # publish a name below the tracker's cam/, whatever its "?" stands for
    assert sorted(found["subscriber-without-publisher"]) == [
        "/camera subscribes to /cam1/image_raw but nothing publishes it",
        "/vins/feature_tracker subscribes to /vins/feature_tracker/cam/? but nothing "
        "publishes it"]
    # the unknown names are still reported as unknown, neither dropped
    assert sorted(m.rsplit(" ", 1)[-1] for m in found["unresolved-names"]) == [
        "/vins/feature_tracker/cam/?", "?"]


def test_a_wholly_unknown_name_in_a_namespace_ros1_and_ros2():
    # ROS 1 handle in a namespace (``NodeHandle(nh, "cam")``): the name is joined to it
    # (``cam/?``), roscpp takes a global name as it is; ROS 2 names too
    ros1 = node("p", "one", call("subscribe", "cam/?", "sensor_msgs/Image"),
                call("subscribe", "cam/left_?", "sensor_msgs/Image"))
    ros1.calls[0].handle_namespace = ros1.calls[1].handle_namespace = "cam"
    ros2 = node("p", "two", call("publish", "?", "sensor_msgs/msg/Image"),
                call("publish", "left_?", "sensor_msgs/msg/Image"))
    config = graph([NodeDecl("/r/one", "p", "one", "/r/"),
                    NodeDecl("/r/two", "p", "two", "/r/", ros_version=2)],
                   nodes=[ros1, ros2])
    assert sorted((link.node.name, link.rosname.full) for link in config.links) == [
        ("/r/one", "/r/cam/left_?"), ("/r/one", "?"),
        ("/r/two", "/r/left_?"), ("/r/two", "?")]
    find_candidates(config)
    # two unknown names are two topics, never one, each may be any of its type
    (one, two) = [t for t in config.topics if t.name == "?"]
    assert one is not two and one.is_unresolved and one.is_disconnected
