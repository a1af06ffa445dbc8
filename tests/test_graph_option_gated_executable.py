"""A launch file that starts a program its package's CMakeLists.txt makes only when an
option is given otherwise than its default (cartographer_ros c138034: ``option(BUILD_GRPC
... false)``, then ``if (${BUILD_GRPC}) google_binary(cartographer_grpc_node ...)``, and
grpc_demo_backpack_2d.launch starts cartographer_grpc_node). It was NODE_NOT_FOUND, "not
in the workspace", and a launch-missing-reference error; the program is in the
workspace, built with ``-DBUILD_GRPC=ON``: NODE_BUILT_BY_OPTION says so (a warning, its
interface unknown), and no error. A program of a branch decided by a variable the
CMake files set themselves, and one no branch makes, stay NODE_NOT_FOUND."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue

CMAKE = """cmake_minimum_required(VERSION 3.5)
project(mapper)
find_package(catkin REQUIRED COMPONENTS roscpp)
catkin_package()
option(BUILD_GRPC "build the gRPC node" false)
option(WITH_VIEWER "build the viewer" ON)
set(LEGACY OFF)
add_executable(mapper_node src/node.cpp)
if (${BUILD_GRPC})
  add_executable(mapper_grpc_node src/grpc.cpp)
  install(TARGETS mapper_grpc_node RUNTIME DESTINATION bin)
endif()
if(WITH_VIEWER)
  add_executable(viewer src/node.cpp)
else()
  add_executable(${PROJECT_NAME}_headless src/node.cpp)
endif()
if(LEGACY)
  add_executable(legacy_node src/node.cpp)
endif()
"""

LAUNCH = """<launch>
  <node pkg="mapper" type="mapper_node" name="mapper"/>
  <node pkg="mapper" type="mapper_grpc_node" name="grpc"/>
  <node pkg="mapper" type="mapper_headless" name="headless"/>
  <node pkg="mapper" type="legacy_node" name="legacy"/>
  <node pkg="mapper" type="nowhere_node" name="nowhere"/>
</launch>
"""

NODE = """#include <ros/ros.h>
int main(int argc, char **argv) {
  ros::init(argc, argv, "mapper");
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<std_msgs::String>("map_info", 1);
  ros::spin();
}
"""


def _model(write_tree):
    root = write_tree({
        "src/mapper/package.xml": package_xml("mapper", "catkin"),
        "src/mapper/CMakeLists.txt": CMAKE,
        "src/mapper/src/node.cpp": NODE,
        "src/mapper/src/grpc.cpp": NODE,
        "src/mapper/launch/all.launch": LAUNCH,
        "project.yaml": "project: p\ndistro: noetic\n"
                        "configurations:\n  c: [mapper/launch/all.launch]\n",
    })
    return analyse(load(str(root / "project.yaml")),
                   {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))


def test_a_program_an_option_keeps_from_the_default_build(write_tree) -> None:
    model = _model(write_tree)
    config = model.configuration("c")
    said = [(d.code, d.location.line, d.severity, d.message) for d in config.diagnostics
            if d.code.startswith("NODE_")]
    assert [(code, line, severity) for code, line, severity, _ in said] == [
        ("NODE_BUILT_BY_OPTION", 3, "warning"), ("NODE_BUILT_BY_OPTION", 4, "warning"),
        ("NODE_NOT_FOUND", 5, "warning"), ("NODE_NOT_FOUND", 6, "warning")]
    assert ("node type mapper/mapper_grpc_node is built only when the CMake option "
            "BUILD_GRPC is given a value other than its default false "
            "(mapper/CMakeLists.txt:5)") in said[0][3]
    assert "option WITH_VIEWER is given a value other than its default ON" in said[1][3]
    # the node of the default build is read; the gated ones are kept, of unknown interface
    nodes = {i.name: i for i in config.nodes}
    assert nodes["/mapper"].node is not None and nodes["/grpc"].node is None
    # no missing reference for the gated programs: the two others stay one
    missing = [f for f in run_catalogue(model) if f.rule == "launch-missing-reference"]
    assert sorted(f.location.line for f in missing) == [5, 6]
    text = " ".join(f.message for f in missing)
    assert "legacy_node" in text and "nowhere_node" in text
