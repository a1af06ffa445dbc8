"""A target that links a library of another workspace package by the library target's
bare name runs that library's code (motoman_driver:
``target_link_libraries(motoman_industrial_robot_client industrial_robot_client)``, a
library industrial_core builds and, to keep its byte-swapped twin out, does not export
through ``catkin_package(LIBRARIES)``: motoman's robot_state node lost the
``robot_status`` publisher of industrial_robot_client's RobotStatusRelayHandler, and
``/robot_status`` had no publisher). A name no workspace package builds stays a system
library."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

FILES = {
    "client/package.xml": package_xml("client", "catkin"),
    "client/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(client)
        find_package(catkin REQUIRED COMPONENTS roscpp)
        catkin_package(INCLUDE_DIRS include LIBRARIES ${PROJECT_NAME}_dummy)
        include_directories(include ${catkin_INCLUDE_DIRS})
        add_library(${PROJECT_NAME}_dummy src/dummy.cpp)
        add_library(${PROJECT_NAME} src/status.cpp)
        add_library(${PROJECT_NAME}_bswap src/status.cpp)
        """,
    "client/src/dummy.cpp": "int dummy() { return 0; }\n",
    "client/include/client/status.h": """
        #include <ros/ros.h>
        namespace client { class StatusRelay { public: void init(); ros::NodeHandle node_;
                                               ros::Publisher pub_; }; }
        """,
    "client/src/status.cpp": """
        #include <client/status.h>
        #include <std_msgs/String.h>
        namespace client {
        void StatusRelay::init() { pub_ = node_.advertise<std_msgs::String>("robot_status", 1); }
        }
        """,
    "driver/package.xml": package_xml("driver", "catkin").replace(
        "</package>", "<depend>client</depend></package>"),
    "driver/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(driver)
        find_package(catkin REQUIRED COMPONENTS roscpp client)
        catkin_package()
        include_directories(${catkin_INCLUDE_DIRS})
        add_library(driver_client src/state.cpp)
        target_link_libraries(driver_client client pthread)
        add_executable(robot_state src/state_node.cpp)
        target_link_libraries(robot_state driver_client ${catkin_LIBRARIES})
        """,
    "driver/src/state.cpp": """
        #include <client/status.h>
        namespace driver {
        class State { public: void init(); client::StatusRelay relay_; };
        void State::init() { relay_.init(); }
        }
        """,
    "driver/src/state_node.cpp": """
        #include <ros/ros.h>
        namespace driver { class State { public: void init(); }; }
        int main(int argc, char** argv) {
          ros::init(argc, argv, "state");
          driver::State s;
          s.init();
          ros::spin();
        }
        """,
}


def test_a_library_of_another_package_linked_by_its_name(write_tree) -> None:
    root = write_tree(FILES)
    ws = scan([str(root)])
    for each in ws.packages.values():
        each.nodes, _ = cmake.parse_package(each, ws)
    node = next(n for n in ws.packages["driver"].nodes if n.executable == "robot_state")
    extract_nodes([node], ws, cache_dir=None, jobs=1)
    assert node.sources == ["driver/src/state_node.cpp", "driver/src/state.cpp",
                            "client/src/status.cpp"]
    assert [(c.kind, c.name) for c in node.calls] == [("publish", "robot_status")]
