"""A function a library file declares ``static`` cannot be called from another file:
ros_canopen's ros_chain.cpp defines ``static ... create(nh, name, ...)`` beside its
RosChain class, and every node of pilz_robots that links canopen_chain_node's libraries
and writes ``create`` anywhere (``TypeGuard::create<T>()``) took ros_chain.cpp for one of
its sources: RosChain's services and its plugin loads became the node's, which made it
partial. A function the file exports still pulls it in."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.workspace import scan
from tests.conftest import package_xml

FILES = {
    "chain/package.xml": package_xml("chain", "catkin"),
    "chain/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(chain)
        find_package(catkin REQUIRED COMPONENTS roscpp)
        catkin_package(INCLUDE_DIRS include LIBRARIES chain)
        include_directories(include ${catkin_INCLUDE_DIRS})
        add_library(chain src/chain.cpp src/shared.cpp)
        """,
    "chain/include/chain/chain.h": """
        #pragma once
        #include <ros/ros.h>
        namespace chain {
        class Chain { public: void setup(ros::NodeHandle& nh); ros::Publisher pub_; };
        }
        """,
    "chain/include/chain/announce.h": """
        #pragma once
        #include <ros/ros.h>
        namespace chain { void announce(ros::NodeHandle& nh); }
        """,
    "chain/src/chain.cpp": """
        #include <chain/chain.h>
        #include <std_msgs/String.h>
        namespace chain {
        static ros::Publisher create(ros::NodeHandle& nh, const std::string& name) {
          return nh.advertise<std_msgs::String>(name, 1);
        }
        void Chain::setup(ros::NodeHandle& nh) { pub_ = create(nh, "chain_state"); }
        }
        """,
    "chain/src/shared.cpp": """
        #include <chain/announce.h>
        #include <std_msgs/String.h>
        namespace chain {
        void announce(ros::NodeHandle& nh) {
          static ros::Publisher pub = nh.advertise<std_msgs::String>("announced", 1);
        }
        }
        """,
    "observer/package.xml": package_xml("observer", "catkin").replace(
        "</package>", "<depend>chain</depend></package>"),
    "observer/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(observer)
        find_package(catkin REQUIRED COMPONENTS roscpp chain)
        catkin_package()
        include_directories(${catkin_INCLUDE_DIRS})
        add_executable(observer src/observer.cpp)
        target_link_libraries(observer ${catkin_LIBRARIES})
        add_executable(announcer src/announcer.cpp)
        target_link_libraries(announcer ${catkin_LIBRARIES})
        """,
    "observer/src/observer.cpp": """
        #include <ros/ros.h>
        struct Guard { template <typename T> static Guard create() { return Guard(); } };
        int main(int argc, char** argv) {
          ros::init(argc, argv, "observer");
          Guard g = Guard::create<int>();
          ros::spin();
        }
        """,
    "observer/src/announcer.cpp": """
        #include <ros/ros.h>
        #include <chain/announce.h>
        int main(int argc, char** argv) {
          ros::init(argc, argv, "announcer");
          ros::NodeHandle nh;
          chain::announce(nh);
          ros::spin();
        }
        """,
}


def test_a_static_function_of_a_library_file_names_it_for_no_other_file(write_tree) -> None:
    root = write_tree(FILES)
    ws = scan([str(root)])
    for each in ws.packages.values():
        each.nodes, _ = cmake.parse_package(each, ws)
    nodes = {n.executable: n for n in ws.packages["observer"].nodes}
    assert nodes["observer"].sources == ["observer/src/observer.cpp"]
    assert nodes["announcer"].sources == ["observer/src/announcer.cpp", "chain/src/shared.cpp"]
