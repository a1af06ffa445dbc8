"""The files of other packages' classes a plugin builds (``inherit.built_sources``:
dwa_local_planner's DWAPlannerROS holds base_local_planner's OdometryHelperRos,
LatchedStopRotateController and MapGridVisualizer by value) came in the order of a set
of the class names, which Python's string hashing changes from one run to the next: the
plugin's translation units, and so the order of its calls (``bench/cpp_real.py --json``
on ROS 1 navigation gave two outputs, PYTHONHASHSEED 0 and 4), changed between runs of
the same code on the same tree. They now come in the order of the classes' names."""

from __future__ import annotations

import json
import os
import subprocess
import sys

SCRIPT = """
import json, sys
from haros_arch.plugins.inherit import built_sources
from haros_arch.workspace import scan
ws = scan([sys.argv[1]])
files = ["util/src/{}.cpp".format(n) for n in sys.argv[2:]]
print(json.dumps(built_sources(["plan/src/planner.cpp"], ws, lambda: [files])))
"""
NAMES = ["odometry", "latched", "visualizer", "footprint", "trajectory", "grid"]
CLASSES = ["OdometryHelper", "LatchedController", "GridVisualizer", "FootprintHelper",
           "TrajectoryScorer", "MapGrid"]


def test_the_files_of_the_classes_a_plugin_builds_come_in_one_order(tmp_path) -> None:
    for name, cls in zip(NAMES, CLASSES, strict=True):
        path = tmp_path / "util" / "src" / f"{name}.cpp"
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(f'#include <ros/ros.h>\nnamespace util {{\n{cls}::{cls}() {{\n'
                        f'  ros::NodeHandle nh("~");\n}}\n}}\n')
    members = "".join(f"  util::{cls} member{i}_;\n" for i, cls in enumerate(CLASSES))
    planner = tmp_path / "plan" / "src" / "planner.cpp"
    planner.parent.mkdir(parents=True, exist_ok=True)
    planner.write_text(f"#include <ros/ros.h>\nclass Planner {{\n{members}}};\n")
    for name in ("util", "plan"):
        (tmp_path / name / "package.xml").write_text(
            f"<package format='2'><name>{name}</name><version>1.0.0</version>"
            "<description>d</description><maintainer email='a@b.c'>m</maintainer>"
            "<license>BSD</license></package>")
    outputs = set()
    for seed in range(8):
        env = {**os.environ, "PYTHONHASHSEED": str(seed)}
        done = subprocess.run([sys.executable, "-c", SCRIPT, str(tmp_path), *NAMES],
                              env=env, capture_output=True, text=True, check=True)
        outputs.add(done.stdout)
    assert len(outputs) == 1
    assert len(json.loads(outputs.pop())) == len(NAMES)
