"""A target whose sources lie outside the workspace by an absolute path the CMake file
writes (an SDK installed where the robot is built: autonav's VectorNav library,
``/usr/local/vectornav/cpp/src/*.cpp``) was one CMAKE_SOURCE_MISSING warning per file
(23 there), as if the package had lost them. It is one info for the target,
CMAKE_SOURCE_OUTSIDE; like an installed library's, that code is taken to make no ROS
call of its own, so the node that links it stays whole. A file of the workspace that is
not there stays missing."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

CMAKE = """\
cmake_minimum_required(VERSION 3.0)
project(drv)
find_package(catkin REQUIRED COMPONENTS roscpp)
catkin_package()
set(SDK /nonexistent-sdk-for-haros-test/vectornav)
add_library(vectornav ${SDK}/src/attitude.cpp ${SDK}/src/conversions.cpp ${SDK}/src/port.cpp)
add_executable(drv_node src/drv_node.cpp)
target_link_libraries(drv_node vectornav)
add_executable(other_node src/gone.cpp)
"""
NODE = """\
#include <ros/ros.h>
int main(int argc, char ** argv) {
  ros::init(argc, argv, "drv");
  ros::NodeHandle nh;
  ros::spin();
}
"""


def test_sources_outside_the_workspace_are_not_here_not_missing(write_tree):
    root = write_tree({
        "src/drv/package.xml": package_xml("drv").replace(
            "</package>", "<depend>roscpp</depend></package>"),
        "src/drv/CMakeLists.txt": CMAKE,
        "src/drv/src/drv_node.cpp": NODE,
        "src/drv/launch/drv.launch": '<launch><node pkg="drv" type="drv_node" name="drv"/>'
                                     "</launch>\n",
        "project.yaml": "project: p\ndistro: noetic\nworkspace: src\nconfigurations:\n"
                        "  c: [drv/launch/drv.launch]\n"})
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    said = [(d.code, d.severity, d.message) for d in (*model.diagnostics, *config.diagnostics)
            if d.code.startswith("CMAKE_SOURCE")]
    assert said == [
        ("CMAKE_SOURCE_OUTSIDE", "info", "sources of target vectornav lie outside the "
         "workspace, in /nonexistent-sdk-for-haros-test/vectornav/src, and are not here; "
         "their code is not read"),
        ("CMAKE_SOURCE_MISSING", "warning", "source file drv/src/gone.cpp of target "
         "other_node does not exist")]
    node = next(n for n in model.nodes if n.executable == "drv_node")
    assert node.completeness != "partial"
