"""The include folders the interpreted CMake files give a target come first
(``cmake.source_include_dirs``): one tree that keeps a package's ROS 1, ROS 2 and SDK
variants of the same headers (foxglove_bridge's ``ros1_foxglove_bridge/include``,
``ros2_foxglove_bridge/include``, ``ros2_foxglove_bridge_sdk/include``, each with
``foxglove_bridge/param_utils.hpp``) is parsed with the variant its build names, not
with the first one in name order."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch import cmake
from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

CMAKE = """\
cmake_minimum_required(VERSION 3.10)
project(bridge)
option(USE_SDK "Build with the SDK" OFF)
if("$ENV{ROS_VERSION}" STREQUAL "1")
  add_library(bridge_nodelet ros1_bridge/src/bridge.cpp)
  target_include_directories(bridge_nodelet PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/ros1_bridge/include>)
elseif(DEFINED ENV{AMENT_PREFIX_PATH})
  find_package(rclcpp REQUIRED)
  add_library(base SHARED base/src/base.cpp)
  target_include_directories(base PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/base/include>
    $<INSTALL_INTERFACE:include>)
  if(USE_SDK)
    add_library(bridge_component SHARED sdk_bridge/src/bridge.cpp)
    target_include_directories(bridge_component PUBLIC
      $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/sdk_bridge/include>)
  else()
    add_library(bridge_component SHARED ros2_bridge/src/bridge.cpp)
    target_include_directories(bridge_component PUBLIC
      $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/ros2_bridge/include>
      ${rclcpp_INCLUDE_DIRS})
    target_link_libraries(bridge_component base)
  endif()
  add_executable(bridge ros2_bridge/src/main.cpp)
  target_link_libraries(bridge bridge_component)
endif()
"""
PARAMS = """\
#pragma once
namespace bridge {{
constexpr char PARAM_PORT[] = "{name}";
}}
"""
SOURCE = """\
#include <rclcpp/rclcpp.hpp>
#include <bridge/common.hpp>
#include <bridge/params.hpp>
void declare(rclcpp::Node* node) {
  node->declare_parameter(bridge::PARAM_PORT, bridge::DEFAULT_PORT);
}
"""


def _package(tmp_path):
    root = tmp_path / "bridge"
    files = {
        "package.xml": package_xml("bridge", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend></package>"),
        "CMakeLists.txt": CMAKE,
        "base/include/bridge/common.hpp":
            "#pragma once\nnamespace bridge { constexpr int DEFAULT_PORT = 8765; }\n",
        "base/src/base.cpp": "#include <bridge/common.hpp>\n",
        # in name order before the build's: ros1_bridge, then ros2_bridge, sdk_bridge
        "ros1_bridge/include/bridge/params.hpp": "#pragma once\n#include <ros/ros.h>\n",
        "ros1_bridge/src/bridge.cpp": "",
        "ros2_bridge/include/bridge/params.hpp": PARAMS.format(name="port"),
        "ros2_bridge/src/bridge.cpp": SOURCE,
        "ros2_bridge/src/main.cpp": "int main() { return 0; }\n",
        "sdk_bridge/include/bridge/params.hpp": PARAMS.format(name="sdk_port"),
        "sdk_bridge/src/bridge.cpp": SOURCE,
    }
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return root


ROS2 = {"ROS_VERSION": "2", "ROS_DISTRO": "jazzy"}


def test_a_source_s_include_folders_are_its_targets_as_the_build_decides(tmp_path) -> None:
    root = _package(tmp_path)
    ws = scan([str(tmp_path)], ROS2)
    folders = cmake.source_include_dirs(ws.packages["bridge"], ws)
    # its own PUBLIC folder (not the variable not known), then its linked library's; the
    # targets are under ``if(DEFINED ENV{AMENT_PREFIX_PATH})``, not decided here, and so
    # are their folders; not the SDK's, in the branch not taken
    assert folders["bridge/ros2_bridge/src/bridge.cpp"] == [
        str(root / "ros2_bridge" / "include"), str(root / "base" / "include")]
    assert folders["bridge/ros2_bridge/src/main.cpp"] == [
        str(root / "ros2_bridge" / "include"), str(root / "base" / "include")]
    assert "bridge/sdk_bridge/src/bridge.cpp" not in folders
    assert "bridge/ros1_bridge/src/bridge.cpp" not in folders


def test_a_run_naming_no_ros_version_gives_the_folders_of_each_build(tmp_path) -> None:
    # no ROS_VERSION: ``if("$ENV{ROS_VERSION}" STREQUAL "1")`` is not decided, and the
    # folders given in its ``elseif`` branch are that branch's, as its targets are (they
    # carried the ``if`` too, so no target was under them and the ROS 1 variant of
    # params.hpp, first in name order, was parsed: foxglove_bridge read with no distro)
    root = _package(tmp_path)
    ws = scan([str(tmp_path)], {"PATH": os.environ.get("PATH", "")})
    folders = cmake.source_include_dirs(ws.packages["bridge"], ws)
    assert folders["bridge/ros2_bridge/src/bridge.cpp"] == [
        str(root / "ros2_bridge" / "include"), str(root / "base" / "include")]
    assert folders["bridge/ros1_bridge/src/bridge.cpp"] == [
        str(root / "ros1_bridge" / "include")]


def test_the_variant_of_a_header_the_build_names_is_parsed(tmp_path) -> None:
    root = _package(tmp_path)
    source = os.path.join(root, "ros2_bridge", "src", "bridge.cpp")
    result = extract_cpp([source], scan([str(tmp_path)], ROS2), cache_dir=None,
                         distro="jazzy")
    assert [(c.kind, c.name) for c in result.calls] == [("declare", "port")]
    assert not {"CPP_PARSE_ERROR", "CPP_NAMES_DECLARED"} & {
        d.code for d in result.diagnostics}


OWNER_LESS = """\
#include <map>
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
namespace bridge {
using Handle = std::weak_ptr<void>;
using Publishers = std::map<Handle, rclcpp::Publisher<std_msgs::msg::String>::SharedPtr,
                            std::owner_less<>>;
class Bridge : public rclcpp::Node {
public:
  Bridge() : Node("bridge") {
    declare_parameter("port", 8765);
    pub_ = create_publisher<std_msgs::msg::String>("status", 10);
  }
private:
  Publishers by_client_;
  std::map<Handle, int, std::owner_less<Handle>> counts_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
}
"""


def test_a_map_ordered_by_owner_keeps_its_class_valid(tmp_path) -> None:
    """foxglove_bridge's ``std::map<ConnectionHandle, Subscription, std::owner_less<>>``
    members: without ``std::owner_less`` the class's members are errors, near its ROS
    calls (the node partial; with foxglove_bridge's other unknown names, the class
    invalid and its every parameter read lost)."""
    root = tmp_path / "bridge"
    (root / "src").mkdir(parents=True)
    (root / "package.xml").write_text(package_xml("bridge", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"))
    (root / "src" / "bridge.cpp").write_text(OWNER_LESS)
    result = extract_cpp([str(root / "src" / "bridge.cpp")], scan([str(tmp_path)], ROS2),
                         cache_dir=None, distro="jazzy")
    assert [(c.kind, c.name) for c in result.calls] == [
        ("declare", "port"), ("publish", "status")]
    assert not {"CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL"} & {
        d.code for d in result.diagnostics}
