"""A free function whose name starts with a capital (Google's style) is a definition a
program's code can name, as a lower-case one: cartographer_ros' offline_node_main.cc
calls ``RunOfflineNode`` (offline_node.cc, in the package's library), which builds the
SLAM ``Node`` of node.cc. Read only as a file that defines nothing to tell it by,
offline_node.cc was kept without what it names, so node.cc (the ``/tf`` broadcaster,
the scan subscription) was left out of cartographer_offline_node, and a program that
never calls ``RunOfflineNode`` (cartographer_node) read offline_node.cc's calls. A macro
at the start of a line (``TEST(...)``, in capitals) is still no definition."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.plugins import classes
from haros_arch.workspace import scan
from tests.conftest import package_xml

FILES = {
    "slam/package.xml": package_xml("slam", "catkin"),
    "slam/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(slam)
        find_package(catkin REQUIRED COMPONENTS roscpp)
        catkin_package(INCLUDE_DIRS include LIBRARIES slam)
        include_directories(include ${catkin_INCLUDE_DIRS})
        add_library(slam src/node.cc src/offline_node.cc)
        target_link_libraries(slam ${catkin_LIBRARIES})
        add_executable(slam_node src/node_main.cc)
        target_link_libraries(slam_node slam)
        add_executable(slam_offline_node src/offline_node_main.cc)
        target_link_libraries(slam_offline_node slam)
        """,
    "slam/include/slam/node.h": """
        #include <ros/ros.h>
        namespace slam {
        class Node {
         public:
          explicit Node(ros::NodeHandle& nh);
         private:
          ros::Publisher tf_;
        };
        }
        """,
    "slam/include/slam/offline_node.h": """
        namespace slam { void RunOfflineNode(int rate); }
        """,
    "slam/src/node.cc": """
        #include <slam/node.h>
        #include <std_msgs/String.h>
        namespace slam {
        Node::Node(ros::NodeHandle& nh) {
          tf_ = nh.advertise<std_msgs::String>("tf_out", 10);
        }
        }
        """,
    "slam/src/offline_node.cc": """
        #include <slam/node.h>
        #include <slam/offline_node.h>
        #include <std_msgs/String.h>
        namespace slam {
        void RunOfflineNode(int rate) {
          ros::NodeHandle nh;
          ros::Publisher clock = nh.advertise<std_msgs::String>("clock", 1);
          Node node(nh);
          ros::spin();
        }
        }
        """,
    "slam/src/node_main.cc": """
        #include <slam/node.h>
        int main(int argc, char** argv) {
          ros::init(argc, argv, "slam_node");
          ros::NodeHandle nh;
          slam::Node node(nh);
          ros::spin();
        }
        """,
    "slam/src/offline_node_main.cc": """
        #include <ros/ros.h>
        #include <slam/offline_node.h>
        int main(int argc, char** argv) {
          ros::init(argc, argv, "slam_offline_node");
          slam::RunOfflineNode(10);
        }
        """,
}


def _nodes(write_tree) -> dict:
    ws = scan([str(write_tree(FILES))])
    package = ws.packages["slam"]
    package.nodes, _ = cmake.parse_package(package, ws)
    nodes = {n.executable: n for n in package.nodes}
    extract_nodes(list(nodes.values()), ws, cache_dir=None, jobs=1)
    return nodes


def test_a_node_built_in_a_capitalised_function_main_calls_is_read(write_tree) -> None:
    nodes = _nodes(write_tree)
    offline = nodes["slam_offline_node"]
    assert sorted(offline.sources) == ["slam/src/node.cc", "slam/src/offline_node.cc",
                               "slam/src/offline_node_main.cc"]
    assert sorted((c.kind, c.name) for c in offline.calls) == [
        ("publish", "clock"), ("publish", "tf_out")]
    # the other program never calls RunOfflineNode: not its ``clock``
    online = nodes["slam_node"]
    assert sorted(online.sources) == ["slam/src/node.cc", "slam/src/node_main.cc"]
    assert [(c.kind, c.name) for c in online.calls] == [("publish", "tf_out")]


def test_a_macro_in_capitals_is_no_function_defined(write_tree) -> None:
    # nor a comment's words, nor a function of an unnamed namespace (internal linkage,
    # as a ``static`` one)
    root = write_tree({"t/src/a.cpp": """
        /*********************************************
        Software License Agreement (BSD License)
        *********************************************/
        #include <gtest/gtest.h>
        namespace {
        bool ConvertLocally(int x) {
          return x > 0;
        }
        }  // namespace
        TEST(Suite, Case) {
          EXPECT_TRUE(true);
        }
        PLUGINLIB_EXPORT_CLASS(a::B, c::D)
        std::vector<int> ReadAll(const std::string& path) {
          return {};
        }
        static void HiddenHelper(int x) {
        }
        """})
    ws = scan([str(root)])
    assert classes.free_functions(["t/src/a.cpp"], ws) == {"ReadAll"}
