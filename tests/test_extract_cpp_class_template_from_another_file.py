"""A class template's constructor that another file of the node calls with its handles
(robot_localization's ``RosFilter<T>``: its nodelets build ``RosEkf``, a
``RosFilter<Ekf>``, with ``(nh, nh_priv, name, args)``, and ros_filter.cpp defines the
template, whose constructor sets ``nhLocal_(nh_priv)``). What the other file passes to
the specialisation is passed to the template's constructor: the reads on ``nhLocal_``
are ``~print_diagnostics``, not ``?/print_diagnostics`` (any parameter of any namespace,
which keeps every private parameter of the configuration's other nodes undecided).
Through the template's delegating constructor (``RosUkf ukf(nh, nhLocal, args)`` of
ukf_localization_node.cpp) it stays ``?``: passing the delegation's arguments on made
the calls of a construction the parse does not resolve (``std::make_unique<RosEkf>``)
vanish, not yet done."""

from __future__ import annotations

import pytest
from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HEADER = """\
#include <ros/ros.h>
#include <string>
#include <vector>
template<class T> class Filter {
 public:
  Filter(ros::NodeHandle nh, ros::NodeHandle nh_priv, std::string name,
         std::vector<double> args);
  Filter(ros::NodeHandle nh, ros::NodeHandle nh_priv, std::vector<double> args);
  void loadParams();
 private:
  ros::NodeHandle nh_;
  ros::NodeHandle nhLocal_;
  T filter_;
};
struct Ukf { int x; };
typedef Filter<Ukf> RosUkf;
"""
FILTER = """\
#include "cam/filter.h"
template<typename T>
Filter<T>::Filter(ros::NodeHandle nh, ros::NodeHandle nh_priv, std::string name,
                  std::vector<double> args) : nh_(nh), nhLocal_(nh_priv) {}
template<typename T>
Filter<T>::Filter(ros::NodeHandle nh, ros::NodeHandle nh_priv, std::vector<double> args)
    : Filter<T>::Filter(nh, nh_priv, ros::this_node::getName(), args) {}
template<typename T>
void Filter<T>::loadParams() {
  bool diagnostics;
  nhLocal_.param("print_diagnostics", diagnostics, true);
}
template class Filter<Ukf>;
"""
MAIN = """\
#include "cam/filter.h"
int main(int argc, char** argv) {
  ros::init(argc, argv, "ukf");
  ros::NodeHandle nh, nhLocal("~");
  std::vector<double> args(3, 0);
  RosUkf ukf(CALL);
  ukf.loadParams();
  ros::spin();
}
"""
CMAKE = """\
cmake_minimum_required(VERSION 3.0)
project(cam)
find_package(catkin REQUIRED roscpp)
include_directories(include)
add_executable(ukf src/main.cpp src/filter.cpp)
"""


@pytest.mark.parametrize("call, name", [('nh, nhLocal, "ukf", args', "~print_diagnostics"),
                                        ("nh, nhLocal, args", "?/print_diagnostics")])
def test_a_class_template_built_in_another_file_has_its_handles(write_tree, call: str,
                                                                name: str) -> None:
    root = write_tree({"cam/package.xml": package_xml("cam", "catkin").replace(
                           "</package>", "<depend>roscpp</depend></package>"),
                       "cam/CMakeLists.txt": CMAKE,
                       "cam/include/cam/filter.h": HEADER,
                       "cam/src/filter.cpp": FILTER,
                       "cam/src/main.cpp": MAIN.replace("CALL", call)})
    files = [str(root / "cam" / "src" / name) for name in ("filter.cpp", "main.cpp")]
    result = extract_cpp(files, scan([str(root)]), cache_dir=None)
    assert sorted((c.kind, c.name) for c in result.calls) == [("read", name)]
