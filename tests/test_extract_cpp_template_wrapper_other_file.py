"""A function template declared in a header and defined, with its explicit
instantiations, in a source file of the node (abb_robot_cpp_utilities'
``getParameter<type>(nh, key, value[, default])``, parameters.cpp:129-, four overloads
over scalars and vectors): the overloads a node calls read the names its files pass; an
overload no file of the node calls (a template runs only where a specialisation of it
is called or named) makes no call. It made a read of ``?/?`` each, which undecided every
parameter a launch file sets for the node."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp_nodes
from haros_arch.workspace import scan

HEADER = """#include <string>
#include <vector>
#include <ros/ros.h>
namespace util {
template <typename T>
void getParameter(ros::NodeHandle& nh, const std::string& key, T& value, const T& fallback);
template <typename T>
void getParameter(ros::NodeHandle& nh, const std::string& key, std::vector<T>& value);
}
"""

SOURCE = """#include "pkg/parameters.h"
namespace util {
template <typename T>
void getParameter(ros::NodeHandle& nh, const std::string& key, T& value, const T& fallback) {
  nh.param<T>(key, value, fallback);
}
template <typename T>
void getParameter(ros::NodeHandle& nh, const std::string& key, std::vector<T>& value) {
  if (!nh.getParam(key, value)) { throw std::runtime_error("missing"); }
}
template void getParameter<int>(ros::NodeHandle&, const std::string&, int&, const int&);
template void getParameter<std::string>(ros::NodeHandle&, const std::string&, std::string&,
                                        const std::string&);
template void getParameter<int>(ros::NodeHandle&, const std::string&, std::vector<int>&);
}
"""

MAIN = """#include "pkg/parameters.h"
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  ros::NodeHandle nh("~");
  int port;
  std::string ip;
  util::getParameter(nh, "robot_port", port, 80);
  util::getParameter(nh, "robot_ip", ip, std::string{"127.0.0.1"});
  ros::spin();
}
"""


def _calls(tmp_path, header: str, source: str, main: str) -> list[tuple[str, str]]:
    package = tmp_path / "src" / "pkg"
    (package / "src").mkdir(parents=True)
    (package / "include" / "pkg").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="2"><name>pkg</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>BSD</license><depend>roscpp</depend></package>\n')
    (package / "include" / "pkg" / "parameters.h").write_text(header)
    (package / "src" / "parameters.cpp").write_text(source)
    (package / "src" / "main.cpp").write_text(main)
    src = package / "src"
    batch = extract_cpp_nodes([[str(src / "main.cpp"), str(src / "parameters.cpp")]],
                              scan([str(tmp_path)]), cache_dir=None, jobs=1)
    return sorted((c.kind, c.name) for c in batch.results[0].calls)


def test_an_overload_of_a_template_no_file_calls_makes_no_call(tmp_path) -> None:
    assert _calls(tmp_path / "a", HEADER, SOURCE, MAIN) == [
        ("read", "~robot_ip"), ("read", "~robot_port")]
    # the vector overload called only by a function of its own file, which the node
    # calls: it runs there (``INSTANTIATED``), its read made
    assert _calls(
        tmp_path / "b", HEADER.replace("}\n", "void readAll(ros::NodeHandle& nh);\n}\n"),
        SOURCE.replace(
            "template void getParameter<int>(ros::NodeHandle&, const std::string&, int&",
            "void readAll(ros::NodeHandle& nh) {\n  std::vector<int> ids;\n"
            "  getParameter(nh, \"ids\", ids);\n}\n"
            "template void getParameter<int>(ros::NodeHandle&, const std::string&, int&"),
        MAIN.replace("  ros::spin();", "  util::readAll(nh);\n  ros::spin();")) == [
        ("read", "~ids"), ("read", "~robot_ip"), ("read", "~robot_port")]
