"""The macros a package's CMake files define are applied to the parse of the sources of
the targets they belong to, where no compile_commands.json gives the flags
(``build_macros.cmake_flags``, from ``cmake.source_definitions``):

- ``add_definitions(-DX)`` / ``add_compile_definitions(X=v)``: every target of the
  directory (also one made before the command), and of the subdirectories added after;
- ``target_compile_definitions(t PRIVATE|PUBLIC|INTERFACE ...)``: t's own sources for
  PRIVATE and PUBLIC, the targets that link t for PUBLIC and INTERFACE;
- a value as the compiler gets it (``TOPIC="${topic_name}"``, a quoted argument's
  escapes); one that reads a variable never set is defined, its value unknown (``?``),
  not empty, and a block whose ``#if`` tests that value is said (``CPP_BUILD_MACRO``);
- one under an ``if()`` that is not decided is not applied, and a block under it is
  still said, but a macro defined only for other targets is known absent and not said.
depthai_examples names its network file ``BLOB_NAME``, a ``target_compile_definitions``
per node; livox_ros_driver2 chooses its ROS 2 code with ``add_definitions``.
"""

from __future__ import annotations

import json
import os

from conftest import package_xml

from haros_arch.extract.cpp.build_macros import cmake_flags
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import scan

CMAKE = r"""
cmake_minimum_required(VERSION 3.8)
project(defs)
find_package(ament_cmake REQUIRED)
set(topic_name "chatter")
add_definitions(-DUSE_FAST -Wall)
add_compile_definitions(PREFIX="robot/" "QUOTED=\"q/\"")
add_executable(talker src/talker.cpp)
target_compile_definitions(talker PRIVATE TOPIC="${topic_name}"
                           UNKNOWN_TOPIC="${NOT_SET_ANYWHERE}" LEVEL=${NOT_SET_LEVEL})
add_executable(other src/other.cpp)
if($ENV{HAROS_TEST_UNSET} STREQUAL "x")
  target_compile_definitions(other PRIVATE MAYBE)
endif()
add_library(helper src/helper.cpp)
target_compile_definitions(helper PUBLIC HELPER_ON INTERFACE IFACE_ON PRIVATE HELPER_PRIVATE)
target_link_libraries(other helper)
add_subdirectory(sub)
add_definitions(-DLATE)
ament_package()
"""

TALKER = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <string>
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("talker");
#ifdef USE_FAST
  auto fast = node->create_publisher<std_msgs::msg::String>(PREFIX "fast", 10);
#endif
  auto pub = node->create_publisher<std_msgs::msg::String>(TOPIC, 10);
  auto q = node->create_publisher<std_msgs::msg::String>(QUOTED "x", 10);
  std::string u(UNKNOWN_TOPIC);
  auto upub = node->create_publisher<std_msgs::msg::String>(u, 10);
#ifdef LATE
  auto late = node->create_publisher<std_msgs::msg::String>("late", 10);
#endif
#ifdef SUB_ONLY
  auto wrong = node->create_publisher<std_msgs::msg::String>("sub_only", 10);
#endif
#ifdef UNKNOWN_TOPIC
  auto defined = node->create_publisher<std_msgs::msg::String>("defined", 10);
#endif
#if LEVEL >= 2
  auto level = node->create_publisher<std_msgs::msg::String>("level", 10);
#endif
  rclcpp::spin(node);
}
"""

OTHER = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("other");
#ifdef MAYBE
  auto m = node->create_publisher<std_msgs::msg::String>("maybe", 10);
#endif
#if defined(HELPER_ON) && defined(IFACE_ON) && !defined(HELPER_PRIVATE)
  auto h = node->create_publisher<std_msgs::msg::String>("helper_linked", 10);
#endif
  rclcpp::spin(node);
}
"""

SUBNODE = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("subnode");
#if defined(SUB_ONLY) && defined(USE_FAST) && !defined(LATE)
  auto s = node->create_publisher<std_msgs::msg::String>("sub_ok", 10);
#endif
  rclcpp::spin(node);
}
"""


def _tree(write_tree):
    return write_tree({
        "src/defs/package.xml": package_xml("defs", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"),
        "src/defs/CMakeLists.txt": CMAKE,
        "src/defs/sub/CMakeLists.txt": "add_definitions(-DSUB_ONLY)\n"
                                       "add_executable(subnode ../src/subnode.cpp)\n",
        "src/defs/src/talker.cpp": TALKER,
        "src/defs/src/other.cpp": OTHER,
        "src/defs/src/helper.cpp": "int helper() { return 1; }\n",
        "src/defs/src/subnode.cpp": SUBNODE,
        "project.yaml": "project: p\nconfigurations: {}\n",
    })


def _model(root):
    return analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                   Options(cache_dir=None))


def test_flags_per_source(write_tree) -> None:
    root = _tree(write_tree)
    ws = scan([str(root / "src")])
    src = root / "src" / "defs" / "src"
    assert cmake_flags(str(src / "talker.cpp"), ws) == [
        "-DUSE_FAST", '-DPREFIX="robot/"', '-DQUOTED="q/"', "-DLATE", '-DTOPIC="chatter"',
        "-DUNKNOWN_TOPIC=(haros_cmake_value_unknown_UNKNOWN_TOPIC)",
        "-DLEVEL=(haros_cmake_value_unknown_LEVEL)"]
    # MAYBE is under an undecided condition; the library's PUBLIC and INTERFACE ones
    assert cmake_flags(str(src / "other.cpp"), ws) == [
        "-DUSE_FAST", '-DPREFIX="robot/"', '-DQUOTED="q/"', "-DLATE", "-DHELPER_ON",
        "-DIFACE_ON"]
    assert cmake_flags(str(src / "helper.cpp"), ws) == [
        "-DUSE_FAST", '-DPREFIX="robot/"', '-DQUOTED="q/"', "-DLATE", "-DHELPER_ON",
        "-DHELPER_PRIVATE"]
    # added before LATE: not given it
    assert cmake_flags(str(src / "subnode.cpp"), ws) == [
        "-DUSE_FAST", '-DPREFIX="robot/"', '-DQUOTED="q/"', "-DSUB_ONLY"]


def test_calls_read_with_the_targets_macros(write_tree) -> None:
    model = _model(_tree(write_tree))
    nodes = {n.executable: n for p in model.packages for n in p.nodes}
    assert sorted(c.name for c in nodes["talker"].calls if c.kind == "publish") == [
        "?", "chatter", "defined", "late", "q/x", "robot/fast"]
    assert [c.name for c in nodes["other"].calls if c.kind == "publish"] == ["helper_linked"]
    assert [c.name for c in nodes["subnode"].calls if c.kind == "publish"] == ["sub_ok"]
    said = sorted((d.location.file, d.location.line) for d in model.diagnostics
                  if d.code == "CPP_BUILD_MACRO")
    # MAYBE: not decided; LEVEL: a value not known, tested by #if (not UNKNOWN_TOPIC:
    # only whether it is defined, which it is)
    assert said == [("defs/src/other.cpp", 7), ("defs/src/talker.cpp", 24)]
    assert nodes["talker"].completeness == "partial"
    assert nodes["subnode"].completeness == "complete"
    assert nodes["other"].completeness == "partial"


def test_a_compile_commands_json_gives_the_flags_instead(write_tree) -> None:
    root = _tree(write_tree)
    source = root / "src/defs/src/talker.cpp"
    entry = {"directory": str(root / "src"), "file": str(source),
             "arguments": ["c++", '-DTOPIC="given"', '-DPREFIX="p/"', '-DQUOTED=""', "-c",
                           str(source)]}
    (root / "src/compile_commands.json").write_text(json.dumps([entry]))
    model = _model(root)
    talker = next(n for p in model.packages for n in p.nodes if n.executable == "talker")
    # the build's own flags only: no USE_FAST, LATE; UNKNOWN_TOPIC not defined at all
    assert sorted(c.name for c in talker.calls if c.kind == "publish") == ["?", "given", "x"]


UNSURE = r"""
cmake_minimum_required(VERSION 3.8)
project(unsure)
if("${tf2_geometry_msgs_VERSION}" VERSION_GREATER "0.12.0")
  set(USE_NEW 1)
else()
  set(USE_NEW 0)
endif()
set(GIT_VERSION ${GIT_VERSION_OUT})
string(REPLACE "v" "" CLEAN_VERSION "${GIT_VERSION}")
if("$ENV{HAROS_TEST_UNSET_DISTRO}" STRLESS "humble")
  add_definitions(-DPRE_HUMBLE)
endif()
set(KNOWN 3)
add_definitions(-DREMOVED -DKEPT)
add_executable(n src/n.cpp)
remove_definitions(-DREMOVED)
target_compile_definitions(n PRIVATE USE_NEW=${USE_NEW} VERSION="${CLEAN_VERSION}"
                           KNOWN=${KNOWN})
"""


def test_values_decided_on_what_is_not_known_are_unknown(write_tree) -> None:
    """A variable set in a branch an if() chose on an unset variable (marti's
    ``USE_NEW_TF2_TOMSG``), or from one (microstrain's git version, read by
    execute_process), gives an unknown value, not 0 or ""; a definition under such a test
    (rtabmap's ``if("$ENV{ROS_DISTRO}" STRLESS "humble")``) is not applied; one
    ``remove_definitions`` takes out is not either."""
    root = write_tree({
        "src/unsure/package.xml": package_xml("unsure", "ament_cmake"),
        "src/unsure/CMakeLists.txt": UNSURE,
        "src/unsure/src/n.cpp": "int main() { return 0; }\n",
    })
    ws = scan([str(root / "src")])
    assert cmake_flags(str(root / "src/unsure/src/n.cpp"), ws) == [
        "-DKEPT", "-DUSE_NEW=(haros_cmake_value_unknown_USE_NEW)",
        "-DVERSION=(haros_cmake_value_unknown_VERSION)", "-DKNOWN=3"]


OPTIONS = r"""
cmake_minimum_required(VERSION 3.8)
project(opts)
add_executable(early src/early.cpp)
add_compile_options(-Wall -D__ROS_VERSION=2 -DWITH_X)
add_executable(late src/late.cpp)
target_compile_options(late PRIVATE -O2 -DLATE_ONLY=1)
add_subdirectory(sub)
"""


def test_add_compile_options_defines_for_the_targets_made_after(write_tree) -> None:
    """``add_compile_options(-DX)`` defines X for the targets of its directory and
    subdirectories made after it (the directory's COMPILE_OPTIONS start a target's own),
    ``target_compile_options(t -DX)`` for t's sources: sick_scan_xd chooses its ROS 2
    code with ``add_compile_options(-D__ROS_VERSION=${ROS_VERSION})``; other options
    are no definitions."""
    root = write_tree({
        "src/opts/package.xml": package_xml("opts", "ament_cmake"),
        "src/opts/CMakeLists.txt": OPTIONS,
        "src/opts/sub/CMakeLists.txt": "add_executable(inner ../src/inner.cpp)\n",
        "src/opts/src/early.cpp": "int main() { return 0; }\n",
        "src/opts/src/late.cpp": "int main() { return 0; }\n",
        "src/opts/src/inner.cpp": "int main() { return 0; }\n",
    })
    ws = scan([str(root / "src")])
    src = root / "src/opts/src"
    assert cmake_flags(str(src / "early.cpp"), ws) == []
    assert cmake_flags(str(src / "late.cpp"), ws) == [
        "-D__ROS_VERSION=2", "-DWITH_X", "-DLATE_ONLY=1"]
    assert cmake_flags(str(src / "inner.cpp"), ws) == ["-D__ROS_VERSION=2", "-DWITH_X"]


BRANCHES = r"""
cmake_minimum_required(VERSION 3.8)
project(branches)
find_package(ament_cmake REQUIRED)
set(ROS_VERSION 2)
if(ROS_VERSION EQUAL 0)
  add_compile_options(-DROSSIMU)
elseif(ROS_VERSION EQUAL 2)
  add_compile_options(-DROS2_BUILD)
else()
  add_definitions(-DROS1_BUILD)
endif()
if($ENV{HAROS_TEST_UNSET} STREQUAL "x")
  add_compile_options(-DMAYBE)
endif()
add_executable(node src/node.cpp)
ament_package()
"""

BRANCHES_NODE = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("node");
#ifdef ROSSIMU
  auto simu = node->create_publisher<std_msgs::msg::String>("simu", 10);
#endif
#ifdef ROS1_BUILD
  auto one = node->create_publisher<std_msgs::msg::String>("one", 10);
#endif
#ifdef ROS2_BUILD
  auto two = node->create_publisher<std_msgs::msg::String>("two", 10);
#endif
#ifdef MAYBE
  auto maybe = node->create_publisher<std_msgs::msg::String>("maybe", 10);
#endif
  rclcpp::spin(node);
}
"""


def test_a_macro_of_a_branch_not_taken_is_known_absent(write_tree) -> None:
    """A macro that only branches the reading decided not taken define (on a variable it
    set itself) is absent, not undecided: sick_scan_xd's ``if(ROS_VERSION EQUAL 0)
    add_compile_options(-DROSSIMU)`` made no CPP_BUILD_MACRO once ROS_VERSION is 2; one
    under a test of what is not known still is."""
    root = write_tree({
        "src/branches/package.xml": package_xml("branches", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"),
        "src/branches/CMakeLists.txt": BRANCHES,
        "src/branches/src/node.cpp": BRANCHES_NODE,
        "project.yaml": "project: p\nconfigurations: {}\n",
    })
    model = _model(root)
    node = next(n for p in model.packages for n in p.nodes if n.executable == "node")
    assert [c.name for c in node.calls if c.kind == "publish"] == ["two"]
    said = [d.location.line for d in model.diagnostics if d.code == "CPP_BUILD_MACRO"]
    assert said == [16]  # MAYBE only


EITHER = r"""
cmake_minimum_required(VERSION 3.8)
project(either)
if(DEFINED ENV{HAROS_TEST_UNSET_BACKEND})
  set(BACKEND 1)
else()
  set(BACKEND 0)
endif()
if(WITH_EXTRA)
  set(EXTRA_FLAG -DEXTRA)
endif()
if(BACKEND EQUAL 2)
  add_definitions(-DBACKEND_TWO)
endif()
add_definitions(-DBACKEND=${BACKEND} ${EXTRA_FLAG} -DBASE)
add_executable(n src/n.cpp)
"""


def test_a_value_set_under_a_test_not_decided_is_unknown(write_tree) -> None:
    """A variable an if() the reading cannot decide sets in its branches (``if(DEFINED
    ENV{X})`` with X not in the run's environment) is either value: a definition that
    reads it is defined with its value unknown, not the last branch's 0; one a branch
    not taken on any path would define is known absent (no flag either way)."""
    root = write_tree({
        "src/either/package.xml": package_xml("either", "ament_cmake"),
        "src/either/CMakeLists.txt": EITHER,
        "src/either/src/n.cpp": "int main() { return 0; }\n",
    })
    ws = scan([str(root / "src")], {})
    assert cmake_flags(str(root / "src/either/src/n.cpp"), ws) == [
        "-DBACKEND=(haros_cmake_value_unknown_BACKEND)", "-DBASE"]
    # the environment the run is given decides it
    ws = scan([str(root / "src")], {"HAROS_TEST_UNSET_BACKEND": "x"})
    assert cmake_flags(str(root / "src/either/src/n.cpp"), ws) == [
        "-DBACKEND=1", "-DBASE"]


GUARDED = r"""
cmake_minimum_required(VERSION 3.8)
project(guarded)
find_package(CUDA)
if(CUDA_FOUND)
  add_executable(model_a src/a.cpp)
  target_compile_definitions(model_a PRIVATE USE_MODEL_A)
  add_definitions(-DWITH_GPU)
  add_executable(model_b src/b.cpp)
  if(WITH_EXTRA)
    target_compile_definitions(model_b PRIVATE EXTRA)
  endif()
endif()
add_executable(plain src/plain.cpp)
if(CUDA_FOUND)
  target_compile_definitions(plain PRIVATE ONLY_WITH_CUDA)
endif()
"""


def test_a_macro_under_the_test_its_target_is_made_under_is_given(write_tree) -> None:
    """autorally's ``if(CUDA_FOUND)`` (not decided: no CUDA here) around both
    ``cuda_add_executable(path_integral_bf ...)`` and its ``target_compile_definitions(
    ... USE_BASIS_FUNC_MODEL__)``: where the target exists the macro is defined, and its
    model's constants with it. A macro under a further test not decided, or under a test
    its target is not made under, is still not applied."""
    root = write_tree({
        "src/guarded/package.xml": package_xml("guarded", "ament_cmake"),
        "src/guarded/CMakeLists.txt": GUARDED,
        "src/guarded/src/a.cpp": "int main() { return 0; }\n",
        "src/guarded/src/b.cpp": "int main() { return 0; }\n",
        "src/guarded/src/plain.cpp": "int main() { return 0; }\n",
    })
    ws = scan([str(root / "src")])
    src = root / "src" / "guarded" / "src"
    # add_definitions: every target of the directory, those made before it too
    assert cmake_flags(str(src / "a.cpp"), ws) == ["-DWITH_GPU", "-DUSE_MODEL_A"]
    # EXTRA: under a test of its own
    assert cmake_flags(str(src / "b.cpp"), ws) == ["-DWITH_GPU"]
    # plain is made on every path: WITH_GPU and ONLY_WITH_CUDA may not be given it
    assert cmake_flags(str(src / "plain.cpp"), ws) == []


BOTH_WAYS = r"""
cmake_minimum_required(VERSION 3.8)
project(both)
set(blob "net.blob")
if(ament_cmake_FOUND)
  add_definitions(-DROS2_ONLY)
  add_executable(node_x src/ros2.cpp)
  target_compile_definitions(node_x PRIVATE BLOB_NAME="${blob}" ROS_VERSION_2)
elseif(CATKIN_DEVEL_PREFIX)
  add_executable(node_x src/ros1.cpp)
  target_compile_definitions(node_x PRIVATE BLOB_NAME="${blob}")
  if(WITH_EXTRA)
    target_compile_definitions(node_x PRIVATE EXTRA)
  endif()
endif()
"""


def test_a_target_made_in_both_branches_gets_its_branchs_macros(write_tree) -> None:
    """depthai_examples makes stereo_inertial_node in both branches of
    ``if(ament_cmake_FOUND)`` (not decided), each from its own source, and defines
    BLOB_NAME for it in each: the ROS 1 source, compiled only in the ``else``, gets that
    branch's definition (without it ``std::string nnName(BLOB_NAME);`` declared a
    function, and the parse of main stopped there); not the other branch's, nor one
    under a further test."""
    root = write_tree({
        "src/both/package.xml": package_xml("both", "catkin"),
        "src/both/CMakeLists.txt": BOTH_WAYS,
        "src/both/src/ros1.cpp": "int main() { return 0; }\n",
        "src/both/src/ros2.cpp": "int main() { return 0; }\n",
    })
    ws = scan([str(root / "src")])
    src = root / "src" / "both" / "src"
    assert cmake_flags(str(src / "ros1.cpp"), ws) == ['-DBLOB_NAME="net.blob"']
