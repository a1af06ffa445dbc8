"""An include folder outside every package that a package's CMake names by a path up
from its own folder (bench/README, helper surveyP): hexapod-ros2-control keeps the
firmware's control code in ``shared/motion_core`` beside ``src/``, and its ROS nodes
compile it (``set(FW_SRC ${CMAKE_CURRENT_SOURCE_DIR}/../../shared/motion_core)``,
``target_include_directories(firmware_bridge_node PRIVATE ${FW_SRC})``). The folder was
dropped (only a package's own folders were taken), so every header of it was missing,
its names unknown, and the node made of them partial. A folder of no workspace tree
(an installed library's) is still not searched."""

from __future__ import annotations

import pytest
from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

CMAKE = """\
cmake_minimum_required(VERSION 3.16)
project(bridge CXX)
find_package(rclcpp REQUIRED)
find_package(std_msgs REQUIRED)
set(REPO_ROOT ${CMAKE_CURRENT_SOURCE_DIR}/../..)
set(FW_SRC ${REPO_ROOT}/shared/motion_core)
add_executable(bridge_node src/bridge_node.cpp ${FW_SRC}/pipeline.cpp)
target_include_directories(bridge_node PRIVATE ${FW_SRC} @OUTSIDE@)
ament_target_dependencies(bridge_node rclcpp std_msgs)
install(TARGETS bridge_node DESTINATION lib/${PROJECT_NAME})
"""
PIPELINE = """\
#pragma once
#include <string>
namespace hexa {
struct Pipeline {
  std::string topic() const;
  int tick(int now);
};
}
"""
NODE = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include "pipeline.hpp"
class Bridge : public rclcpp::Node {
 public:
  Bridge() : rclcpp::Node("bridge") {
    pub_ = create_publisher<std_msgs::msg::String>("out", 10);
    tick_ = pipeline_.tick(0);
  }
 private:
  hexa::Pipeline pipeline_;
  int tick_ = 0;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Bridge>());
}
"""


def _repository(tmp_path, outside: str = ""):
    repo = tmp_path / "repo"
    files = {
        "src/bridge/package.xml": package_xml("bridge", "ament_cmake"),
        "src/bridge/CMakeLists.txt": CMAKE.replace("@OUTSIDE@", outside),
        "src/bridge/src/bridge_node.cpp": NODE,
        "shared/motion_core/pipeline.hpp": PIPELINE,
        "shared/motion_core/pipeline.cpp": '#include "pipeline.hpp"\n',
    }
    for name, text in files.items():
        path = repo / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return repo


ERRORS = ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED", "CPP_INCLUDE_MISSING")


@pytest.mark.parametrize("top", ["repo", "repo/src"])
def test_a_shared_folder_of_the_repository_is_searched(tmp_path, top: str) -> None:
    repo = _repository(tmp_path)
    source = repo / "src" / "bridge" / "src" / "bridge_node.cpp"
    ws = scan([str(tmp_path / top)], {"ROS_VERSION": "2", "ROS_DISTRO": "jazzy"})
    result = extract_cpp([str(source)], ws, cache_dir=None, distro="jazzy")
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ERRORS] == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "out")]


def test_a_folder_of_no_workspace_tree_is_not(tmp_path) -> None:
    # the same headers in a folder outside the repository, which the build names too:
    # not read (an installed library's headers are the stand-ins')
    elsewhere = tmp_path / "opt" / "lib"
    elsewhere.mkdir(parents=True)
    (elsewhere / "other.hpp").write_text("#pragma once\nnamespace other { int f(); }\n")
    repo = _repository(tmp_path, outside=str(elsewhere))
    node = repo / "src" / "bridge" / "src" / "bridge_node.cpp"
    node.write_text('#include "other.hpp"\n' + NODE)
    ws = scan([str(repo / "src")], {"ROS_VERSION": "2", "ROS_DISTRO": "jazzy"})
    result = extract_cpp([str(node)], ws, cache_dir=None, distro="jazzy")
    assert [d.message for d in result.diagnostics if d.code == "CPP_INCLUDE_MISSING"] == [
        "header other.hpp not found; an empty stand-in was used"]
