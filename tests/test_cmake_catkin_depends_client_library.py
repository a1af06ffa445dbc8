"""catkin's CATKIN_DEPENDS libraries come with a package (test_cmake_catkin_depends_
libraries), but not those of the client library and its parts (roscpp, xmlrpcpp,
rosconsole, ...), whose API the stand-ins model, even when their source is in the
workspace: ros_comm's tree holds roscpp beside topic_tools, whose
``catkin_package(CATKIN_DEPENDS roscpp xmlrpcpp ...)`` made rosbag's ``play`` (it links
topic_tools) read roscpp's own libros sources, reads of ``/use_sim_time`` and ``?``
included, beside the stand-ins' model of the same API."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

FILES = {
    "roscpp/package.xml": package_xml("roscpp", "catkin"),
    "roscpp/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(roscpp)
        find_package(catkin REQUIRED COMPONENTS xmlrpcpp)
        catkin_package(INCLUDE_DIRS include LIBRARIES roscpp CATKIN_DEPENDS xmlrpcpp)
        add_library(roscpp src/libros/init.cpp)
        """,
    "roscpp/src/libros/init.cpp": """
        #include <ros/ros.h>
        namespace ros {
        bool NodeHandle::ok() const {
          bool use_sim_time = false;
          ros::param::param("/use_sim_time", use_sim_time, false);
          return use_sim_time;
        }
        }
        """,
    "xmlrpcpp/package.xml": package_xml("xmlrpcpp", "catkin"),
    "xmlrpcpp/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(xmlrpcpp)
        find_package(catkin REQUIRED)
        catkin_package(LIBRARIES xmlrpcpp)
        add_library(xmlrpcpp src/XmlRpcDispatch.cpp)
        """,
    "xmlrpcpp/src/XmlRpcDispatch.cpp": "int dispatch() { return 0; }\n",
    "tools/package.xml": package_xml("tools", "catkin"),
    "tools/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(tools)
        find_package(catkin REQUIRED COMPONENTS roscpp xmlrpcpp)
        catkin_package(INCLUDE_DIRS include LIBRARIES tools CATKIN_DEPENDS roscpp xmlrpcpp)
        include_directories(include ${catkin_INCLUDE_DIRS})
        add_library(tools src/shifter.cpp)
        target_link_libraries(tools ${catkin_LIBRARIES})
        """,
    "tools/include/tools/shifter.h": """
        #include <ros/ros.h>
        namespace tools { void shift(ros::NodeHandle& nh); }
        """,
    "tools/src/shifter.cpp": """
        #include <tools/shifter.h>
        #include <std_msgs/String.h>
        namespace tools { ros::Publisher pub;
        void shift(ros::NodeHandle& nh) { pub = nh.advertise<std_msgs::String>("shifted", 1); } }
        """,
    "player/package.xml": package_xml("player", "catkin"),
    "player/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(player)
        find_package(catkin REQUIRED COMPONENTS roscpp tools)
        catkin_package()
        include_directories(${catkin_INCLUDE_DIRS})
        add_executable(play src/play.cpp)
        target_link_libraries(play ${catkin_LIBRARIES})
        """,
    "player/src/play.cpp": """
        #include <ros/ros.h>
        #include <tools/shifter.h>
        int main(int argc, char** argv) {
          ros::init(argc, argv, "play");
          ros::NodeHandle n;
          tools::shift(n);
          while (n.ok()) { ros::spinOnce(); }
        }
        """,
}


def test_the_client_librarys_own_source_is_not_read_with_a_node(write_tree) -> None:
    root = write_tree(FILES)
    ws = scan([str(root)])
    for each in ws.packages.values():
        each.nodes, _ = cmake.parse_package(each, ws)
    node = next(n for n in ws.packages["player"].nodes if n.executable == "play")
    extract_nodes([node], ws, cache_dir=None, jobs=1)
    assert node.sources == ["player/src/play.cpp", "tools/src/shifter.cpp"]
    assert [(c.kind, c.name) for c in node.calls] == [("publish", "shifted")]
    assert node.completeness == "complete"
