"""The C++ standard a package's CMake files ask is the parse's ``-std`` where no
compile_commands.json gives the flags (``cmake.source_standards``): a target's
``CXX_STANDARD`` (from ``CMAKE_CXX_STANDARD`` when the target is made, or
``set_property`` / ``set_target_properties``), ``target_compile_features(cxx_std_NN)``
(PUBLIC and INTERFACE ones also for the targets that link the library) and a ``-std=``
in ``CMAKE_CXX_FLAGS``; the one the compiler takes wins (the last ``-std=`` of the compile
line: test_extract_cpp_cmake_standard_order). One older than the parse's
default (C++17, which the stand-ins are written for) leaves the default. vortex's
packages ask C++20 (``set(CMAKE_CXX_STANDARD 20)``) and were parsed as C++17, so code
under ``#if __cplusplus >= 202002L`` (or using ``concept``) was read wrong."""

from __future__ import annotations

import json
import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import scan

CMAKE = """
cmake_minimum_required(VERSION 3.8)
project(stds)
find_package(ament_cmake REQUIRED)
add_executable(plain src/plain.cpp)
add_executable(prop src/prop.cpp)
set_property(TARGET prop PROPERTY CXX_STANDARD 20)
add_executable(props src/props.cpp)
set_target_properties(props PROPERTIES CXX_STANDARD 23 CXX_STANDARD_REQUIRED ON)
add_library(lib src/lib.cpp)
target_compile_features(lib PUBLIC cxx_std_23)
add_executable(linked src/linked.cpp)
target_link_libraries(linked lib)
add_library(quiet src/quiet.cpp)
target_compile_features(quiet PRIVATE cxx_std_20)
add_executable(not_linked src/not_linked.cpp)
target_link_libraries(not_linked quiet)
add_executable(old src/old.cpp)
target_compile_features(old PRIVATE cxx_std_14)
set(CMAKE_CXX_FLAGS "${CMAKE_CXX_FLAGS} -Wall -std=gnu++2a")
add_executable(flags src/flags.cpp)
set(CMAKE_CXX_FLAGS "-Wall")
set(CMAKE_CXX_STANDARD 20)
add_executable(twenty src/twenty.cpp)
ament_package()
"""

NODE = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("n");
#if __cplusplus >= 202002L
  auto pub = node->create_publisher<std_msgs::msg::String>("cxx20", 10);
#else
  auto pub = node->create_publisher<std_msgs::msg::String>("cxx17", 10);
#endif
  rclcpp::spin(node);
}
"""

SOURCES = ("plain", "prop", "props", "lib", "linked", "quiet", "not_linked", "old",
           "flags", "twenty")


def _tree(write_tree):
    return write_tree({
        "src/stds/package.xml": package_xml("stds", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"),
        "src/stds/CMakeLists.txt": CMAKE,
        **{f"src/stds/src/{name}.cpp": NODE for name in SOURCES},
        "project.yaml": "project: p\nconfigurations: {}\n",
    })


def test_the_standard_of_each_source(write_tree) -> None:
    from haros_arch.cmake import source_standards

    root = _tree(write_tree)
    ws = scan([str(root / "src")])
    found = source_standards(ws.packages["stds"], ws)
    assert found == {
        "stds/src/prop.cpp": "c++20", "stds/src/props.cpp": "c++23",
        "stds/src/lib.cpp": "c++23", "stds/src/linked.cpp": "c++23",
        "stds/src/quiet.cpp": "c++20", "stds/src/twenty.cpp": "c++20"}
    # (flags.cpp: CMake gives every target of the directory its CMAKE_CXX_FLAGS at the
    # directory's end, "-Wall", not the "-std=gnu++2a" set when the target was made)


def test_the_sources_are_parsed_with_it(write_tree) -> None:
    root = _tree(write_tree)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    nodes = {n.executable: n for p in model.packages for n in p.nodes}
    published = {name: [c.name for c in node.calls if c.kind == "publish"]
                 for name, node in nodes.items()}
    assert published == {
        "plain": ["cxx17"], "prop": ["cxx20"], "props": ["cxx20"], "linked": ["cxx20"],
        "not_linked": ["cxx17"], "old": ["cxx17"], "flags": ["cxx17"], "twenty": ["cxx20"]}


def test_a_compile_command_of_cxx20_is_parsed(write_tree) -> None:
    """A compile command's ``-std=c++20`` was taken, but libclang refused every unit
    parsed so with the precompiled stand-ins (made without the detailed preprocessing
    record the parse asks): ``CPP_PARSE_FAILED``, no call."""
    root = _tree(write_tree)
    source = root / "src/stds/src/plain.cpp"
    entry = {"directory": str(root / "src"), "file": str(source),
             "arguments": ["c++", "-std=c++20", "-c", str(source)]}
    (root / "src/compile_commands.json").write_text(json.dumps([entry]))
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    plain = next(n for p in model.packages for n in p.nodes if n.executable == "plain")
    assert [c.name for c in plain.calls if c.kind == "publish"] == ["cxx20"]
    assert not [d for d in model.diagnostics if d.code == "CPP_PARSE_FAILED"]


CONCEPTS = """
#include <concepts>
#include <Eigen/Dense>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <vector>

template<class T> concept Sized = requires(T v) {
  { v.size() } -> std::convertible_to<std::size_t>;
};

template<std::integral Q, Sized V>
void advertise(rclcpp::Node& node, Q depth, const V& topics) {
  static_assert(std::same_as<Q, int> && !std::floating_point<Q>);
  Eigen::Vector<double, 3> offset = Eigen::Vector3<double>::Zero();
  auto pub = node.create_publisher<std_msgs::msg::String>("sized", depth + topics.size());
}

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("n");
  advertise(*node, 10, std::vector<int>{});
  rclcpp::spin(node);
}
"""


def test_the_standard_s_concepts(write_tree) -> None:
    """vortex-utils' and vortex-vkf's concepts (``std::convertible_to``, ...) of
    ``<concepts>``, which the stand-ins lacked: a C++20 unit reads them; and Eigen
    3.4's alias templates (``Eigen::Vector<double, 3>``)."""
    root = write_tree({
        "src/conc/package.xml": package_xml("conc", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"),
        "src/conc/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(conc)\n"
                                   "set(CMAKE_CXX_STANDARD 20)\n"
                                   "add_executable(conc src/conc.cpp)\nament_package()\n",
        "src/conc/src/conc.cpp": CONCEPTS,
        "project.yaml": "project: p\nconfigurations: {}\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    (node,) = [n for p in model.packages for n in p.nodes]
    assert [c.name for c in node.calls if c.kind == "publish"] == ["sized"]
    assert [(d.location.line, d.message) for d in model.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_INCLUDE_MISSING", "CPP_NAMES_DECLARED")] == []
    assert node.completeness == "complete"
