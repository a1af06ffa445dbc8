"""A static method runs where code may call it: C++ calls one by its bare name only in
its own class, elsewhere through its class's name. Code the parse leaves unread (an
error's statement, an opaque constructor's class) that writes the bare name alone calls
no static method of another class. scenario_simulator_v2's preprocessor builds an
``OpenScenario`` whose constructor it does not read; the class's text writes ``load``,
which started traffic_simulator's ``LaneletLoader::load()`` (a class with static methods
only, which no file constructs), and from it the whole simulator API and concealer's
``FieldOperatorApplication`` node (``/simulation/concealer_user``), a process the
preprocessor never builds. Written with its class, or in its class's own code, the call
may still be there: the method runs."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """#pragma once
#include <ros/ros.h>
#include <std_msgs/String.h>
namespace p {
class Loader {
 public:
  static void load();
  static void reload();
  static void refresh();
};
}  // namespace p
"""
LIBRARY = """#include "p/loader.h"
namespace p {
void Loader::load() {
  ros::NodeHandle n;
  n.advertise<std_msgs::String>("/loader/loaded", 1);
}
void Loader::reload() {
  ros::NodeHandle n;
  n.advertise<std_msgs::String>("/loader/reloaded", 1);
}
void Loader::refresh() {
  ros::NodeHandle n;
  n.advertise<std_msgs::String>("/loader/refreshed", 1);
  reload(undeclared_count);
}
}  // namespace p
"""
NODE = """#include "p/loader.h"
int main(int argc, char** argv) {
  ros::init(argc, argv, "planner");
  ros::NodeHandle nh("~");
  nh.advertise<std_msgs::String>("/planner/out", 1);
  undeclared_store.load(undeclared_thing);
  ros::spin();
}
"""
CMAKE = """cmake_minimum_required(VERSION 3.0.2)
project(p)
find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
catkin_package()
include_directories(include)
add_library(loader src/loader.cpp)
add_executable(node src/node.cpp)
target_link_libraries(node loader)
"""


def _names(write_tree, node: str = NODE) -> set[str]:
    root = write_tree({"p/package.xml": package_xml("p", "catkin"),
                       "p/CMakeLists.txt": CMAKE,
                       "p/include/p/loader.h": HEADER,
                       "p/src/loader.cpp": LIBRARY,
                       "p/src/node.cpp": node})
    sources = [str(root / "p" / "src" / name) for name in ("node.cpp", "loader.cpp")]
    result = extract_cpp(sources, scan([str(root)]), cache_dir=None, jobs=1)
    return {c.name for c in result.calls}


def test_a_bare_name_by_an_error_calls_no_static_method_of_another_class(
        write_tree) -> None:
    names = _names(write_tree)
    assert "/planner/out" in names, names
    # ``undeclared_store.load(...)`` calls no ``Loader::load``; nothing runs refresh()
    assert not {"/loader/loaded", "/loader/reloaded", "/loader/refreshed"} & names, names


def test_a_static_method_written_with_its_class_or_in_it_may_run(write_tree) -> None:
    node = NODE.replace("undeclared_store.load(undeclared_thing);",
                        "p::Loader::load(undeclared_thing);\n"
                        "  p::Loader::refresh();")
    names = _names(write_tree, node)
    # with its class's name by the error, load() may be called; refresh() runs, and
    # the bare ``reload`` by the error in its own class's code may call reload()
    assert {"/planner/out", "/loader/loaded", "/loader/refreshed",
            "/loader/reloaded"} <= names, names
