"""roscpp's ``resolveName(name)`` (and ``ros::names::resolve(name)``) resolves and remaps
``name`` for the code, which may join several such names into one topic: people's
face_detector subscribes ``clean(camera + "/" + rgb_ns + "/" + image_topic)``, each part
resolved from a name its launch file remaps (``camera:=wide_stereo``, ``rgb_ns:=rgb``,
``image_topic:=image_rect``). The topic was read as the names written
(``/camera/rgb_ns/image_topic``, wrong wherever the launch file remaps them) and each of
those remaps reported as changing no name (25 remap-unused warnings). Now a resolved name
that begins the topic is remapped with the node's remaps, one appended is unknown (the
piece the remaps give it), and a remap of a name the code resolves is one it uses."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

NODE = """
#include <ros/ros.h>
#include <sensor_msgs/Image.h>

class Detector {
 public:
  explicit Detector(ros::NodeHandle& nh) : nh_(nh) {
    camera_ = nh_.resolveName("camera");
    image_ = nh_.resolveName("image_topic");
    topic_ = ros::names::clean(camera_ + "/rgb/" + image_);
    sub_ = nh_.subscribe(topic_, 3, &Detector::onImage, this);
  }
  void onImage(const sensor_msgs::Image::ConstPtr& msg) {}
 private:
  ros::NodeHandle nh_;
  std::string camera_, image_, topic_;
  ros::Subscriber sub_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "detector");
  ros::NodeHandle nh;
  Detector detector(nh);
  ros::spin();
}
"""

LAUNCH = """<launch>
  <node pkg="faces" type="detector" name="detector">
    <remap from="camera" to="head_camera"/>
    <remap from="image_topic" to="image_rect"/>
    <remap from="depth_topic" to="depth/image"/>
  </node>
</launch>
"""


def test_resolved_names_take_the_node_s_remaps(write_tree: Any) -> None:
    root: Path = write_tree({
        "src/faces/package.xml": package_xml("faces"),
        "src/faces/CMakeLists.txt": "project(faces)\nfind_package(catkin REQUIRED roscpp)\n"
                                    "add_executable(detector src/detector.cpp)\n",
        "src/faces/src/detector.cpp": NODE,
        "src/faces/launch/faces.launch": LAUNCH,
        "project.yaml": "project: p\ndistro: noetic\n"
                        "configurations:\n  c: [faces/launch/faces.launch]\n",
    })
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    # the name it begins with, remapped; the piece appended after it, unknown
    assert sorted(t.name for t in config.topics) == ["/head_camera/rgb/?"]
    (node,) = next(p for p in model.packages if p.name == "faces").nodes
    assert sorted(c.name for c in node.calls if c.resolved) == ["camera", "image_topic"]
    assert not [p for p in config.parameters if "camera" in p.name or "image" in p.name]
    found: dict[str, list[str]] = {}
    for finding in run_catalogue(model, project):
        found.setdefault(finding.rule, []).append(finding.message)
    # the remaps of the names it resolves are used; the third one is not
    assert [m.split(" ")[0] for m in found["remap-unused"]] == ["depth_topic:=depth/image"]
