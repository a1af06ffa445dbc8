"""``find_package(pkg)`` of a workspace package that the package declares a build
dependency on finds it: catkin and colcon build it first. humanoid_op_ros'
nimbro_topic_transport depends on plot_msgs ("not a hard dependency") and adds
``-DWITH_PLOTTING=1`` under ``if(plot_msgs_FOUND)``, which chooses its udp_receiver's
``/plot`` publisher: the condition was not decided, the macro not applied
(CPP_BUILD_MACRO), the node partial. Without the declared dependency the build order
does not say, and it stays so."""

from __future__ import annotations

import json

import pytest
from conftest import package_xml

from haros_arch.cli import main

CMAKE = """
cmake_minimum_required(VERSION 3.0.2)
project(relay)
find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
catkin_package()
find_package(plot_msgs)
if(plot_msgs_FOUND)
  add_definitions(-DWITH_PLOTTING=1)
endif()
include_directories(${catkin_INCLUDE_DIRS})
add_executable(receiver src/receiver.cpp)
target_link_libraries(receiver ${catkin_LIBRARIES})
"""

SOURCE = """
#include <ros/ros.h>
#include <std_msgs/String.h>
int main(int argc, char **argv) {
  ros::init(argc, argv, "receiver");
  ros::NodeHandle nh;
  ros::Publisher out = nh.advertise<std_msgs::String>("out", 1);
#if WITH_PLOTTING
  ros::Publisher plot = nh.advertise<std_msgs::String>("/plot", 1000);
#endif
  ros::spin();
}
"""

PLOT_CMAKE = """
cmake_minimum_required(VERSION 3.0.2)
project(plot_msgs)
find_package(catkin REQUIRED)
catkin_package()
"""


def _manifest(depends: str) -> str:
    return ('<?xml version="1.0"?>\n<package format="2"><name>relay</name>'
            "<version>0.1.0</version><description>d</description>"
            '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
            "<buildtool_depend>catkin</buildtool_depend><depend>roscpp</depend>"
            f"<depend>std_msgs</depend>{depends}</package>\n")


def _extract(write_tree, depends: str):
    root = write_tree({
        "src/relay/package.xml": _manifest(depends),
        "src/relay/CMakeLists.txt": CMAKE,
        "src/relay/src/receiver.cpp": SOURCE,
        "src/plot_msgs/package.xml": package_xml("plot_msgs"),
        "src/plot_msgs/CMakeLists.txt": PLOT_CMAKE,
        "src/relay/launch/relay.launch":
            '<launch><node name="receiver" pkg="relay" type="receiver"/></launch>\n',
        "project.yaml": "project: p\nconfigurations:\n  c: [relay/launch/relay.launch]\n"})
    out = root / "model.json"
    main(["extract", str(root / "project.yaml"), "-o", str(out), "--no-cache"])
    data = json.loads(out.read_text())
    (config,) = data["configurations"]
    (node,) = config["nodes"]
    published = sorted(link["name"] for link in config["links"] if link["kind"] == "publish")
    codes = {d["code"] for d in data["diagnostics"]} | {
        d["code"] for d in config["diagnostics"]}
    return node["completeness"], published, codes


@pytest.mark.parametrize("kind", ["depend", "build_depend"])
def test_a_declared_workspace_dependency_is_found(write_tree, kind):
    completeness, published, codes = _extract(write_tree, f"<{kind}>plot_msgs</{kind}>")
    assert published == ["/out", "/plot"]
    assert completeness == "complete" and "CPP_BUILD_MACRO" not in codes


def test_an_undeclared_one_is_not_known(write_tree):
    completeness, published, codes = _extract(write_tree, "")
    assert "/out" in published
    assert completeness == "partial" and "CPP_BUILD_MACRO" in codes
