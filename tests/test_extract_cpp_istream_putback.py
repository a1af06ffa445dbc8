"""std::istream's ``putback``, ``unget`` and ``get(char&)``: denso_robot_core_test's
main() writes ``std::cin.putback('\\n')`` before it makes its publishers; the std
stand-in's istream had none of them, so main()'s C++ error made the node partial
(CPP_NODE_PARTIAL) though nothing of ROS was hidden there."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

FILES = {
    "asker/package.xml": package_xml("asker", "catkin").replace(
        "<export>", "<depend>roscpp</depend><depend>std_msgs</depend><export>"),
    "asker/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(asker)
        find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
        add_executable(asker src/asker.cpp)
        """,
    "asker/src/asker.cpp": """
        #include <ros/ros.h>
        #include <std_msgs/Int32.h>
        #include <iostream>
        int main(int argc, char ** argv)
        {
          ros::init(argc, argv, "asker");
          ros::NodeHandle nh;
          std::cin.putback('\\n');
          char c;
          std::cin.get(c);
          std::cin.unget();
          ros::Publisher pub = nh.advertise<std_msgs::Int32>("answer", 1);
          ros::spin();
        }
        """,
}


def test_a_character_put_back_is_no_error(write_tree) -> None:
    ws = scan([str(write_tree(FILES))])
    pkg = ws.packages["asker"]
    pkg.nodes, _ = cmake.parse_package(pkg, ws)
    found = extract_nodes(pkg.nodes, ws, cache_dir=None, jobs=1)
    node = pkg.nodes[0]
    assert [(c.kind, c.name) for c in node.calls] == [("publish", "answer")]
    assert "CPP_NODE_PARTIAL" not in [d.code for d in found]
    assert node.completeness == "complete"
