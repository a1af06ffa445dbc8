"""A library file whose ROS calls are in a template of its package's headers, which it
includes through another header of the package, makes ROS calls: iiwa_ros'
state/joint_position.cpp calls ``State<M>::init``, which subscribes, written in
iiwa_ros.hpp that it includes through state/joint_position.hpp and
generic_state.hpp. Looking one include deep, the file was taken for one that names
no ROS client library and left out of iiwa_hw's node, which lost its subscriptions
and its command publisher. A file of the library whose headers never reach ROS stays
out."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

FILES = {
    "arm_ros/package.xml": package_xml("arm_ros", "catkin"),
    "arm_ros/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(arm_ros)
        find_package(catkin REQUIRED COMPONENTS roscpp)
        catkin_package(INCLUDE_DIRS include LIBRARIES ${PROJECT_NAME})
        include_directories(include ${catkin_INCLUDE_DIRS})
        add_library(${PROJECT_NAME} src/state/position.cpp src/checksum.cpp)
        """,
    "arm_ros/include/arm_ros/arm_ros.hpp": """
        #pragma once
        #include <ros/ros.h>
        namespace arm_ros {
        template <typename M> class State {
         public:
          void init(const std::string& topic) {
            ros::NodeHandle nh;
            sub_ = nh.subscribe<M>(topic, 1, &State<M>::set, this);
          }
          void set(const M&) {}
         private:
          ros::Subscriber sub_;
        };
        }
        """,
    "arm_ros/include/arm_ros/state/generic_state.hpp": """
        #pragma once
        #include "arm_ros/arm_ros.hpp"
        namespace arm_ros { namespace state { class GenericState {}; } }
        """,
    "arm_ros/include/arm_ros/state/position.hpp": """
        #pragma once
        #include <std_msgs/Float64.h>
        #include "arm_ros/state/generic_state.hpp"
        namespace arm_ros { namespace state {
        class Position : public GenericState {
         public:
          void init();
         private:
          State<std_msgs::Float64> state_;
        };
        } }
        """,
    "arm_ros/src/state/position.cpp": """
        #include "arm_ros/state/position.hpp"
        namespace arm_ros { namespace state {
        void Position::init() { state_.init("state/position"); }
        } }
        """,
    "arm_ros/include/arm_ros/checksum.hpp": """
        #pragma once
        namespace arm_ros { int checksum(const char* data); }
        """,
    "arm_ros/src/checksum.cpp": """
        #include "arm_ros/checksum.hpp"
        namespace arm_ros {
        int checksum(const char* data) { int s = 0; while (*data) s += *data++; return s; }
        }
        """,
    "arm_hw/package.xml": package_xml("arm_hw", "catkin").replace(
        "</package>", "<depend>arm_ros</depend></package>"),
    "arm_hw/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(arm_hw)
        find_package(catkin REQUIRED COMPONENTS roscpp arm_ros)
        catkin_package()
        include_directories(${catkin_INCLUDE_DIRS})
        add_executable(arm_hw src/main.cpp)
        target_link_libraries(arm_hw ${catkin_LIBRARIES})
        """,
    "arm_hw/src/main.cpp": """
        #include <ros/ros.h>
        #include <arm_ros/state/position.hpp>
        #include <arm_ros/checksum.hpp>
        int main(int argc, char** argv) {
          ros::init(argc, argv, "arm_hw");
          arm_ros::state::Position position;
          position.init();
          ros::spin();
          return arm_ros::checksum("x");
        }
        """,
}


def test_a_library_file_calling_ros_through_its_headers_runs(write_tree) -> None:
    root = write_tree(FILES)
    ws = scan([str(root)])
    for each in ws.packages.values():
        each.nodes, _ = cmake.parse_package(each, ws)
    node = next(n for n in ws.packages["arm_hw"].nodes if n.executable == "arm_hw")
    assert node.sources == ["arm_hw/src/main.cpp", "arm_ros/src/state/position.cpp"]
    extract_nodes([node], ws, cache_dir=None, jobs=1)
    assert [(c.kind, c.name) for c in node.calls] == [("subscribe", "state/position")]
