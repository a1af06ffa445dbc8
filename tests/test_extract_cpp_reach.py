"""The functions of another package's headers a unit's own code cannot reach by name
are not walked in that unit (``extract.cpp.reach``): navigation2's units each include
nav2_ros_common's lifecycle node, action server and factories, and walked every inline
function of them again. Its own package's headers are its code (a library source that
only includes them compiles them: tests/test_extract_cpp_several_nodes.py).
What the unit names is walked as before: a class it builds (its
constructors, virtual and static methods, field initialisers), a method or free function
it calls, a class named through an alias, a function a macro it expands calls, a class
a reached class holds; not a class only a comment names. What it does not name makes no
call of this node here (the units that call it walk it)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp, visitor
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """#pragma once
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
namespace rp {
class Held {
public:
  explicit Held(rclcpp::Node * node) { node->declare_parameter<int>("held_param", 0); }
};
class Used {
public:
  explicit Used(rclcpp::Node * node) : node_(node), held_(node) {
    node_->declare_parameter<int>("used_rate", 1);
  }
  void start() { pub_ = node_->create_publisher<std_msgs::msg::String>("used_out", 10); }
  void never() { node_->create_publisher<std_msgs::msg::String>("never_out", 10); }
  virtual void on_tick() { node_->declare_parameter<int>("virtual_param", 0); }
  static void describe(rclcpp::Node * node) { node->declare_parameter<int>("static_param", 0); }
  virtual ~Used() = default;
  rclcpp::Node * node_;
  Held held_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
class Unused {
public:
  explicit Unused(rclcpp::Node * node) { node->declare_parameter<int>("unused_param", 0); }
};
class Commented {
public:
  explicit Commented(rclcpp::Node * node) { node->declare_parameter<int>("comment_param", 0); }
};
class AliasTarget {
public:
  explicit AliasTarget(rclcpp::Node * node) { node->declare_parameter<int>("alias_param", 0); }
};
using Alias = AliasTarget;
inline void helper_by_macro(rclcpp::Node * node) {
  node->declare_parameter<int>("macro_param", 0);
}
inline void helper_unused(rclcpp::Node * node) { node->declare_parameter<int>("dead_param", 0); }
}  // namespace rp
#define RP_SETUP(node) rp::helper_by_macro(node)
"""

NODE = """#include "rp/tools.hpp"
class TheNode : public rclcpp::Node {
public:
  TheNode() : rclcpp::Node("the_node"), used_(this) {
    used_.start();
    rp::Alias made(this);
    RP_SETUP(this);
    // rp::Commented is not built here; /* nor is rp::Commented */
  }
  rp::Used used_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<TheNode>());
}
"""

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(rp)
find_package(ament_cmake REQUIRED)
find_package(rclcpp REQUIRED)
find_package(std_msgs REQUIRED)
find_package(rp_tools REQUIRED)
add_executable(the_node src/the_node.cpp)
ament_target_dependencies(the_node rclcpp std_msgs rp_tools)
ament_package()
"""

TOOLS = """cmake_minimum_required(VERSION 3.8)
project(rp_tools)
find_package(ament_cmake REQUIRED)
install(DIRECTORY include/ DESTINATION include)
ament_export_include_directories(include)
ament_package()
"""


def _extract(write_tree, monkeypatch):
    root = write_tree({"rp/package.xml": package_xml("rp", "ament_cmake"),
                       "rp/CMakeLists.txt": CMAKE,
                       "rp_tools/package.xml": package_xml("rp_tools", "ament_cmake"),
                       "rp_tools/CMakeLists.txt": TOOLS,
                       "rp_tools/include/rp/tools.hpp": HEADER,
                       "rp/src/the_node.cpp": NODE})
    left: list[str] = []
    run = visitor.CallFinder.run

    def spied(self: visitor.CallFinder) -> None:
        run(self)
        left.extend(f.spelling for f in self.unreached)

    monkeypatch.setattr(visitor.CallFinder, "run", spied)
    result = extract_cpp([str(root / "rp" / "src" / "the_node.cpp")], scan([str(root)]),
                         cache_dir=None, distro="jazzy")
    return result, left


def test_what_the_unit_names_is_walked_and_the_rest_is_not(write_tree, monkeypatch) -> None:
    result, left = _extract(write_tree, monkeypatch)
    names = {c.name for c in result.calls}
    assert {"used_rate", "used_out", "held_param", "virtual_param",
            "alias_param", "macro_param"} <= names, names
    # a method of a class the unit builds that nothing calls runs nowhere in the node;
    # nor does a static method (walked with its class, ``left``), which runs on no object
    assert not {"never_out", "unused_param", "dead_param", "comment_param",
                "static_param"} & names, names
    assert sorted(left) == ["Commented", "Unused", "helper_unused", "never"], left
