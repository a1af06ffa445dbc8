"""catkin_simple (catkin/catkin_simple and ethz-asl's fork): ``catkin_simple()`` finds the
package's catkin build dependencies as catkin's components, and ``cs_add_executable`` /
``cs_add_library`` link ``${catkin_LIBRARIES}`` (unless ``NO_AUTO_LINK``). maplab's
nodes (maplab_node, rovioli, maplab_server_node) are built so: their
``RVizVisualizationSink`` of the workspace package ``visualization`` was "built here and
its code not read", the nodes partial, as the links were not made."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

SINK = """
#include <ros/ros.h>
namespace viz { class Sink { public: Sink(); ros::NodeHandle node_; ros::Publisher pub_; }; }
"""

FILES = {
    "viz/package.xml": package_xml("viz", "catkin").replace(
        "</package>", "<depend>roscpp</depend><buildtool_depend>catkin_simple"
                      "</buildtool_depend></package>"),
    "viz/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(viz)
        find_package(catkin_simple REQUIRED)
        catkin_simple(ALL_DEPS_REQUIRED)
        cs_add_library(${PROJECT_NAME} src/sink.cc)
        cs_install()
        cs_export()
        """,
    "viz/include/viz/sink.h": SINK,
    "viz/src/sink.cc": """
        #include <viz/sink.h>
        #include <visualization_msgs/MarkerArray.h>
        namespace viz {
        Sink::Sink() { pub_ = node_.advertise<visualization_msgs::MarkerArray>("markers", 1); }
        }
        """,
    "plain/package.xml": package_xml("plain", "cmake"),
    "plain/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(plain)
        add_library(plain src/plain.cc)
        """,
    "plain/src/plain.cc": "int plain() { return 0; }\n",
    "app/package.xml": package_xml("app", "catkin").replace(
        "</package>", "<depend>roscpp</depend><depend>viz</depend><depend>plain</depend>"
                      "<buildtool_depend>catkin_simple</buildtool_depend></package>"),
    "app/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(app)
        find_package(catkin_simple REQUIRED)
        catkin_simple(ALL_DEPS_REQUIRED)
        cs_add_library(${PROJECT_NAME}_lib src/flow.cc)
        cs_add_executable(${PROJECT_NAME} app/main.cc)
        target_link_libraries(${PROJECT_NAME} ${PROJECT_NAME}_lib)
        cs_add_executable(alone app/main.cc src/flow.cc NO_AUTO_LINK)
        cs_install()
        cs_export()
        """,
    "app/src/flow.cc": """
        #include <viz/sink.h>
        void start() { viz::Sink sink; }
        """,
    "app/app/main.cc": """
        #include <ros/ros.h>
        void start();
        int main(int argc, char** argv) {
          ros::init(argc, argv, "app");
          start();
          ros::spin();
        }
        """,
}


def test_cs_targets_link_the_catkin_build_dependencies(write_tree) -> None:
    root = write_tree(FILES)
    ws = scan([str(root)])
    for each in ws.packages.values():
        if each.build_type in cmake.CMAKE_BUILD_TYPES:
            each.nodes, _ = cmake.parse_package(each, ws)
    nodes = {n.executable: n for n in ws.packages["app"].nodes}
    interpreter, _ = cmake.interpret(ws.packages["app"], ws)
    # the catkin build dependencies; plain, which the workspace builds without catkin,
    # is no catkin project
    assert interpreter.get("app_CATKIN_BUILD_DEPENDS") == "roscpp;viz"
    assert interpreter.get("app_LIBRARIES") == "app_lib"
    extract_nodes(list(nodes.values()), ws, cache_dir=None, jobs=1)
    app = nodes["app"]
    assert app.sources == ["app/app/main.cc", "app/src/flow.cc", "viz/src/sink.cc"]
    assert [(c.kind, c.name) for c in app.calls] == [("publish", "markers")]
    assert app.completeness == "complete", app.completeness_reasons
    # NO_AUTO_LINK: only what the package links itself
    assert nodes["alone"].sources == ["app/app/main.cc", "app/src/flow.cc"]
    assert nodes["alone"].calls == []
