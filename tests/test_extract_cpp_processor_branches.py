"""A ROS 1 node that builds its code only for ARM (UbiquityRobotics' raspicam_node, as
TortoiseBot vendors it, bench/README survey F): ``#if defined(__arm__) ||
defined(__aarch64__)`` around the whole node, and under ``#ifdef __x86_64__`` a ``main``
that exits. libclang parses for the machine of the analysis, a PC: the node made no ROS
call and was complete, so each parameter its launch file sets was "set but never read".
A ROS call in a branch of a condition on the processor that the parse leaves out now
makes the node partial (CPP_TARGET_UNKNOWN, said once at the call)."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import load_catalogue, run_rule

NODE = """
#ifdef __x86_64__
#include <stdio.h>
int main(int argc, char** argv) {
  (void)fprintf(stderr, "a fake on this processor\\n");
  return 1;
}
#endif  // __x86_64__

#if defined(__arm__) || defined(__aarch64__)
#include <ros/ros.h>
#include <std_msgs/String.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "camera");
  ros::NodeHandle pnh("~");
  int width;
  pnh.param<int>("width", width, 640);
  ros::Publisher pub = pnh.advertise<std_msgs::String>("image", 1);
  ros::spin();
}
#endif  // __arm__ || __aarch64__
"""

LAUNCH = """<launch>
  <node pkg="cam" type="camera" name="camera">
    <param name="width" value="1280"/>
  </node>
</launch>
"""

# the same choice with the call in a branch that every processor reads: complete
PORTABLE = """
#include <ros/ros.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "camera");
  ros::NodeHandle pnh("~");
  int width;
  pnh.param<int>("width", width, 640);
#if defined(__SSE2__)
  int fast = 1;
#else
  int fast = 0;
#endif
  (void)fast;
  ros::spin();
}
"""


def _model(write_tree, source: str):
    root = write_tree({
        "src/cam/package.xml": package_xml("cam").replace(
            "</package>", "<depend>roscpp</depend><depend>std_msgs</depend></package>"),
        "src/cam/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0)\nproject(cam)\n"
                                  "find_package(catkin REQUIRED COMPONENTS roscpp)\n"
                                  "catkin_package()\n"
                                  "add_executable(camera src/camera.cpp)\n",
        "src/cam/src/camera.cpp": source,
        "src/cam/launch/camera.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [cam/launch/camera.launch]\n",
    })
    return analyse(load(str(root / "project.yaml")),
                   {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))


def _findings(model) -> list[tuple[str, str]]:
    rule = next(r for r in load_catalogue() if r.id == "parameter-set-not-read")
    return [(f.rule, f.message.split(" ")[0]) for f in run_rule(rule, model)]


def test_a_node_built_for_another_processor_is_partial(write_tree) -> None:
    model = _model(write_tree, NODE)
    node = next(n for p in model.packages for n in p.nodes if n.executable == "camera")
    assert node.completeness == "partial"
    said = [d for d in model.diagnostics if d.code == "CPP_TARGET_UNKNOWN"]
    assert [(d.location.file, d.location.line, d.severity) for d in said] == [
        ("cam/src/camera.cpp", 16, "warning")]
    assert "defined(__arm__) || defined(__aarch64__)" in said[0].message
    assert said[0].message.startswith("pnh.param<int>(\"width\", width, 640);")
    assert _findings(model) == [("parameter-set-not-read-undecided", "1")]
    assert not [d for d in model.diagnostics if d.code == "CPP_NODE_PARTIAL"]


def test_a_processor_branch_without_ros_calls_leaves_the_node_complete(write_tree) -> None:
    model = _model(write_tree, PORTABLE)
    node = next(n for p in model.packages for n in p.nodes if n.executable == "camera")
    assert node.completeness == "complete"
    assert not [d for d in model.diagnostics if d.code == "CPP_TARGET_UNKNOWN"]
    assert _findings(model) == []
