"""A target's COMPILE_DEFINITIONS property defines macros for its sources, as
target_compile_definitions does. ethzasl_sensor_fusion (f58a07e) builds its two nodes
from one main.cpp: ``add_executable(pose_sensor src/main.cpp ...)``, ``set_property(TARGET
pose_sensor PROPERTY COMPILE_DEFINITIONS POSE_MEAS)``, and main.cpp builds the filter only
under ``#ifdef POSE_MEAS`` / ``#include "pose_measurements.h"``. The property was not
read: both nodes were complete with neither measurement class, and 52 parameters their
YAML sets (the class reads them) were "set but never read". A macro given to one target
alone is applied; one the targets compiling a shared source give differently is not (a
unit is parsed once), so a block under it that includes a workspace header holding ROS
calls is said (CPP_BUILD_MACRO) and the node is partial: its parameters undecided."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue

MAIN = """
#include <ros/ros.h>
#ifdef POSE_MEAS
#include "pose_measurements.h"
#endif
#ifdef POSITION_MEAS
#include "position_measurements.h"
#endif
int main(int argc, char** argv) {
  ros::init(argc, argv, "ssf_core");
#ifdef POSE_MEAS
  PoseMeasurements meas;
#endif
#ifdef POSITION_MEAS
  PositionMeasurements meas;
#endif
  ros::spin();
}
"""

HEADER = """
#include <ros/ros.h>
class NAMEMeasurements {
 public:
  NAMEMeasurements() {
    ros::NodeHandle pnh("~");
    pnh.param("init/p_ci/x", x_, 0.0);
  }
  double x_;
};
"""

CMAKE = """cmake_minimum_required(VERSION 3.0.2)
project(ssf)
find_package(catkin REQUIRED COMPONENTS roscpp)
catkin_package()
add_executable(pose_sensor src/main.cpp)
set_property(TARGET pose_sensor PROPERTY COMPILE_DEFINITIONS POSE_MEAS)
OTHER
"""

LAUNCH = """<launch>
  <node name="pose_sensor" pkg="ssf" type="pose_sensor">
    <param name="init/p_ci/x" value="1.0"/>
  </node>
</launch>
"""


def _model(write_tree, other: str):
    root = write_tree({
        "src/ssf/package.xml": package_xml("ssf"),
        "src/ssf/CMakeLists.txt": CMAKE.replace("OTHER", other),
        "src/ssf/src/main.cpp": MAIN,
        "src/ssf/src/pose_measurements.h": HEADER.replace("NAME", "Pose"),
        "src/ssf/src/position_measurements.h": HEADER.replace("NAME", "Position"),
        "src/ssf/launch/pose.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [ssf/launch/pose.launch]\n",
    })
    return analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                   Options(cache_dir=None))


def _node(model, name: str):
    return next(n for p in model.packages for n in p.nodes if n.executable == name)


def test_the_property_of_a_target_defines_its_macro(write_tree) -> None:
    model = _model(write_tree, "")
    node = _node(model, "pose_sensor")
    assert ("read", "~init/p_ci/x") in {(c.kind, c.name) for c in node.calls}
    assert node.completeness == "complete"
    assert not [f for f in run_catalogue(model) if f.rule == "parameter-set-not-read"]


def test_a_source_two_targets_build_with_other_macros_is_partial(write_tree) -> None:
    model = _model(write_tree, 'add_executable(position_sensor src/main.cpp)\n'
                               'set_target_properties(position_sensor PROPERTIES '
                               'COMPILE_DEFINITIONS "POSITION_MEAS;X=1" OUTPUT_NAME p)\n')
    node = _node(model, "pose_sensor")
    assert node.completeness == "partial"
    # (said for each of the two nodes that compile main.cpp)
    said = sorted({(d.location.line, d.message.split(":")[0]) for d in model.diagnostics
                   if d.code == "CPP_BUILD_MACRO"})
    assert said == [(3, '#include "pose_measurements.h" (pnh.param("init/p_ci/x", x_, 0.0);)'),
                    (6, '#include "position_measurements.h" '
                        '(pnh.param("init/p_ci/x", x_, 0.0);)')]
    rules = sorted(f.rule for f in run_catalogue(model) if "parameter-set" in f.rule)
    assert rules == ["parameter-set-not-read-undecided"]
