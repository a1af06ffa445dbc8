"""The wide streams of the std stand-in: bcap_service (denso_robot_ros) writes its
service options with ``std::wstringstream ss2; ss2 << L",WDT=" << m_wdt;`` and passes
``ss2.str().c_str()`` on; the stand-in had no wide stream, so the function's C++ errors
(25 CPP_PARSE_ERROR infos there) made a function that reads parameters a place where a
call may be missing."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

FILES = {
    "wide/package.xml": package_xml("wide", "catkin").replace(
        "<export>", "<depend>roscpp</depend><depend>std_msgs</depend><export>"),
    "wide/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(wide)
        find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
        add_executable(wide src/wide.cpp)
        """,
    "wide/src/wide.cpp": """
        #include <ros/ros.h>
        #include <std_msgs/Int32.h>
        #include <sstream>
        #include <iostream>
        #include <string>
        void take(const wchar_t* text);
        int main(int argc, char ** argv)
        {
          ros::init(argc, argv, "wide");
          ros::NodeHandle nh;
          int wdt = 400;
          std::wstringstream ss;
          ss << L",WDT=" << wdt << L",Timeout=" << 1.5 << std::endl;
          take(ss.str().c_str());
          std::wostringstream out;
          out << std::to_wstring(wdt);
          std::wstring all = out.str() + L"x";
          std::wcout << all << std::endl;
          std::wistringstream in(all);
          int back = 0;
          in >> back;
          ros::Publisher pub = nh.advertise<std_msgs::Int32>("answer", 1);
          ros::spin();
        }
        """,
}


def test_wide_streams_are_no_error(write_tree) -> None:
    ws = scan([str(write_tree(FILES))])
    pkg = ws.packages["wide"]
    pkg.nodes, _ = cmake.parse_package(pkg, ws)
    found = extract_nodes(pkg.nodes, ws, cache_dir=None, jobs=1)
    node = pkg.nodes[0]
    assert [(c.kind, c.name) for c in node.calls] == [("publish", "answer")]
    assert [d.message for d in found if d.code in ("CPP_NODE_PARTIAL", "CPP_PARSE_ERROR",
                                                     "CPP_ERROR_NEAR_CALL")] == []
    assert node.completeness == "complete"
