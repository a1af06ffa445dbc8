"""Include folders a package's CMake files give deeper than ``<pkg>/<dir>/include``
(``extract.cpp.cmake_includes``): found by the parse, except a sub-project's."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.extract.cpp.cmake_includes import cmake_include_dirs
from haros_arch.workspace import scan

CMAKE = """\
cmake_minimum_required(VERSION 3.8)
project(cam)
find_package(rclcpp REQUIRED)
add_subdirectory(lib/sdk)
# include_directories(src/old/include)
add_library(cam_component SHARED src/cam/src/cam_node.cpp)
target_include_directories(cam_component PUBLIC
    ${CMAKE_CURRENT_SOURCE_DIR}/src/common
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/src/cam/include>
    ${OTHER_INCLUDE_DIRS}
    lib/sdk/include
)
"""
HEADER = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
namespace cam {
class CamNode : public rclcpp::Node {
public:
  explicit CamNode(const rclcpp::NodeOptions & options);
private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_pub_;
};
}
"""
SOURCE = """\
#include "cam_node.hpp"
namespace cam {
CamNode::CamNode(const rclcpp::NodeOptions & options) : Node("cam", options) {
  status_pub_ = create_publisher<std_msgs::msg::String>("~/status", 10);
}
}
"""


def _package(tmp_path):
    root = tmp_path / "cam"
    files = {
        "package.xml": package_xml("cam", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"),
        "CMakeLists.txt": CMAKE,
        "src/cam/include/cam_node.hpp": HEADER,
        "src/cam/src/cam_node.cpp": SOURCE,
        "src/common/.keep": "",
        "src/old/include/.keep": "",
        "lib/sdk/CMakeLists.txt": "project(sdk)\ninclude_directories(include)\n",
        "lib/sdk/include/sdk.hpp": "int sdk();\n",
    }
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return root


def test_the_folders_a_package_cmake_gives_except_a_sub_project_s(tmp_path) -> None:
    root = _package(tmp_path)
    ws = scan([str(tmp_path)])
    # commented out, another variable's, and the sub-project's (given by either file)
    # are not searched
    assert cmake_include_dirs(str(root), ws) == [
        str(root / "src" / "common"), str(root / "src" / "cam" / "include")]


def test_a_class_declared_in_a_folder_the_cmake_gives_is_known(tmp_path) -> None:
    root = _package(tmp_path)
    source = os.path.join(root, "src", "cam", "src", "cam_node.cpp")
    result = extract_cpp([source], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name, c.type) for c in result.calls if c.kind == "publish"] == [
        ("publish", "~status", "std_msgs/msg/String")]
    assert not {"CPP_INCLUDE_MISSING", "CPP_PARSE_ERROR"} & {
        d.code for d in result.diagnostics}


GEO_CMAKE = """\
cmake_minimum_required(VERSION 3.5)
set(PROJECT_NAME geo)
project(${PROJECT_NAME})
find_package(rclcpp REQUIRED)
include_directories(
  include
  include/${PROJECT_NAME}
)
add_executable(${PROJECT_NAME}_node src/geo.cpp)
"""


def test_the_project_name_in_an_include_folder_is_the_package_s(tmp_path) -> None:
    """aerostack2's ``include_directories(include include/${PROJECT_NAME})``, its sources
    including ``"geo_node.hpp"`` from ``include/geo/``: ament_package() requires the project
    to be named as the package."""
    root = tmp_path / "geo"
    files = {
        "package.xml": package_xml("geo", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"),
        "CMakeLists.txt": GEO_CMAKE,
        "include/geo/geo_node.hpp": HEADER.replace("cam", "geo").replace("Cam", "Geo"),
        "src/geo.cpp": SOURCE.replace("cam", "geo").replace("Cam", "Geo"),
    }
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    ws = scan([str(tmp_path)])
    assert cmake_include_dirs(str(root), ws) == [
        str(root / "include"), str(root / "include" / "geo")]
    result = extract_cpp([str(root / "src" / "geo.cpp")], ws, cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "~status")]
    assert not {"CPP_INCLUDE_MISSING", "CPP_PARSE_ERROR"} & {
        d.code for d in result.diagnostics}


LIB_HEADER = """\
#pragma once
#include <geometry/point.h>
namespace gait {
class Planner {
public:
  geometry::Point next() const { return geometry::Point{}; }
};
}
"""
POINT = """\
#pragma once
namespace geometry { struct Point { double x = 0.0; }; }
"""
USER_CMAKE = """\
cmake_minimum_required(VERSION 3.8)
project(walker)
find_package(rclcpp REQUIRED)
find_package(gait REQUIRED)
find_package(other REQUIRED)
include_directories(include ${gait_INCLUDE_DIRS}/gait/ ${other_INCLUDE_DIRS}/x)
add_executable(walker src/walker.cpp)
"""
WALKER = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>
#include <gait/planner/planner.h>
class Walker : public rclcpp::Node {
public:
  Walker() : Node("walker") {
    rate_ = declare_parameter("rate", 50.0);
    pub_ = create_publisher<std_msgs::msg::Float64>("x", 1);
  }
private:
  gait::Planner planner_;
  double rate_;
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr pub_;
};
"""


def test_a_folder_of_another_package_s_exported_include(tmp_path) -> None:
    """champ_base's ``include_directories(${champ_INCLUDE_DIRS}/champ/)``: libchamp's
    headers include each other from ``champ/include/champ`` (``<geometry/geometry.h>``);
    not searched, the planner's header lost its includes, its class was declared
    permissively, then redefined, and the node's class was invalid (CPP_NODE_PARTIAL).
    A variable of no workspace package stays unread."""
    files = {
        "gait/package.xml": package_xml("gait", "ament_cmake"),
        "gait/CMakeLists.txt": "project(gait)\nament_export_include_directories(include)\n",
        "gait/include/gait/planner/planner.h": LIB_HEADER,
        "gait/include/gait/geometry/point.h": POINT,
        "walker/package.xml": package_xml("walker", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend>"
            "<depend>gait</depend></package>"),
        "walker/CMakeLists.txt": USER_CMAKE,
        "walker/src/walker.cpp": WALKER,
    }
    for name, text in files.items():
        path = tmp_path / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    ws = scan([str(tmp_path)])
    assert cmake_include_dirs(str(tmp_path / "walker"), ws) == [
        str(tmp_path / "gait" / "include" / "gait")]
    result = extract_cpp([str(tmp_path / "walker" / "src" / "walker.cpp")], ws,
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("declare", "rate"), ("publish", "x")]
    assert [d.code for d in result.diagnostics if d.code.startswith("CPP_")] == []


DRIVER_CMAKE = """\
cmake_minimum_required(VERSION 3.0.2)
project(imu_driver)
find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
catkin_package()
set(SDK_INC sdk/C/Library/Include)
set(SDK_UTIL_INC sdk/C/Utilities/Include)
set(SDK_INCS ${SDK_INC} ${SDK_UTIL_INC})
set(OLD_INC sdk/old)
set(OLD_INC sdk/older)
set(USER_INC sdk/user CACHE PATH "the user functions")
include_directories(include/${PROJECT_NAME} ${SDK_INCS} ${OLD_INC} ${USER_INC}
                    ${catkin_INCLUDE_DIRS})
add_executable(imu_node src/imu_node.cpp)
"""
SDK_HEADER = """\
#ifndef SDK_H
#define SDK_H
typedef unsigned char u8;
typedef unsigned short u16;
#define SDK_OK 0
int sdk_open(u16 port);
#endif
"""
DRIVER_SOURCE = """\
#include <ros/ros.h>
#include <std_msgs/UInt8.h>
#include "sdk.h"
#include "byteswap.h"
int main(int argc, char** argv) {
  ros::init(argc, argv, "imu");
  ros::NodeHandle nh("~");
  u16 port = 0;
  nh.param("port", port, port);
  if (sdk_open(port) != SDK_OK) {
    return 1;
  }
  u8 status = swap_byte(SDK_OK);
  ros::Publisher pub = nh.advertise<std_msgs::UInt8>("status", 1);
  ros::spin();
  return status;
}
"""


def test_include_folders_given_through_set_variables(tmp_path) -> None:
    """microstrain_mips' ``set(MIPLIBINC MIPSDK/C/Library/Include)`` then
    ``include_directories(include/${PROJECT_NAME} ${MIPLIBINC} ${MIPUTILINC} ...)``: the
    SDK's headers were missing (``u8``, ``u16`` unknown types in every function of the
    driver, which advertises and reads its parameters: the node partial). A variable set
    to one value (in turn through another) is that value; one set to two values, or a
    cache entry's default, is not known."""
    root = tmp_path / "imu_driver"
    files = {
        "package.xml": package_xml("imu_driver", "catkin"),
        "CMakeLists.txt": DRIVER_CMAKE,
        "sdk/C/Library/Include/sdk.h": SDK_HEADER,
        "sdk/C/Utilities/Include/byteswap.h": "unsigned char swap_byte(unsigned char b);\n",
        "sdk/old/.keep": "", "sdk/older/.keep": "", "sdk/user/.keep": "",
        "src/imu_node.cpp": DRIVER_SOURCE,
    }
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    ws = scan([str(tmp_path)])
    assert cmake_include_dirs(str(root), ws) == [
        str(root / "sdk" / "C" / "Library" / "Include"),
        str(root / "sdk" / "C" / "Utilities" / "Include")]
    result = extract_cpp([str(root / "src" / "imu_node.cpp")], ws, cache_dir=None)
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "~status"), ("read", "~port")]
    assert not {"CPP_INCLUDE_MISSING", "CPP_PARSE_ERROR", "CPP_NODE_PARTIAL"} & {
        d.code for d in result.diagnostics}


def _detector(tmp_path, name: str, member: str, topic: str) -> str:
    """A catkin package ``name`` whose node includes its own ``"Globals.h"`` (from
    ``include/``, or ``include/<name>`` as rwth_ground_plane's CMake gives it) and
    publishes ``topic`` after reading ``Globals::<member>``."""
    root = tmp_path / name
    root.mkdir()
    (root / "package.xml").write_text(package_xml(name))
    folder = "include" if name == "upper_body" else f"include/{name}"
    (root / "CMakeLists.txt").write_text(
        f"project({name})\nfind_package(catkin REQUIRED COMPONENTS roscpp)\n"
        f"include_directories(include {folder})\n"
        f"add_executable(node src/node.cpp)\n")
    (root / folder).mkdir(parents=True, exist_ok=True)
    (root / folder / "Globals.h").write_text(
        f"#pragma once\nclass Globals {{ public: static double {member}; }};\n")
    (root / "src").mkdir()
    source = root / "src" / "node.cpp"
    source.write_text(
        "#include <ros/ros.h>\n#include <std_msgs/Float64.h>\n#include \"Globals.h\"\n"
        f"double Globals::{member};\n"
        "int main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"node\");\n"
        "  ros::NodeHandle n;\n"
        f"  n.param(\"{member}\", Globals::{member}, 1.0);\n"
        f"  ros::Publisher pub = n.advertise<std_msgs::Float64>(\"{topic}\", 1);\n"
        "}\n")
    return str(source)


def test_each_unit_reads_its_own_package_header_of_a_name_two_packages_hold(
        tmp_path) -> None:
    """spencer_people_tracking (survey Z39): rwth_ground_plane and
    rwth_upper_body_detector each have a ``Globals.h`` on their CMake include path; in
    one batch the search order was the first package's, and the upper-body detector's
    units read the ground plane's class (20 errors in the function that reads its
    parameters, the node partial with none of them)."""
    from haros_arch.extract.cpp import extract_cpp_nodes
    ground = _detector(tmp_path, "ground_plane", "camera_height", "ground")
    upper = _detector(tmp_path, "upper_body", "distance_range", "detections")
    batch = extract_cpp_nodes([[ground], [upper]], scan([str(tmp_path)]), cache_dir=None,
                              distro="noetic")
    for result, (member, topic) in zip(batch.results, (("camera_height", "ground"),
                                                       ("distance_range", "detections")),
                                       strict=True):
        assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []
        assert [(c.kind, c.name) for c in result.calls] == [("read", member),
                                                            ("publish", topic)]


APPENDED_CMAKE = """\
cmake_minimum_required(VERSION 3.0.2)
project(legged)
find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
set(includePath)
list(APPEND includePath "/usr/include/eigen3")
if(USE_SDK)
    list(APPEND includePath "${SDK_DIR}/include")
endif()
catkin_package(INCLUDE_DIRS include LIBRARIES ${PROJECT_NAME})
list(APPEND includePath include/legged src)
list( APPEND includePath "config/")
set_target_properties(legged PROPERTIES LINKER_LANGUAGE CXX)
add_executable(legged_node src/node.cpp)
target_include_directories(legged_node PUBLIC ${includePath} ${catkin_INCLUDE_DIRS})
"""


def test_include_folders_a_variable_gathers_with_list_append(tmp_path) -> None:
    """quadruped-robot's ``list(APPEND includePath include/quadruped src)`` (after a
    ``set(includePath)`` and other appends), then ``target_include_directories(quadruped
    PUBLIC ${includePath} ...)``: its sources include ``"controllers/x.hpp"`` from
    ``include/quadruped``, which was missing (survey R: 25 places of each simulated
    robot's node where a call may be missing). Every word appended is a folder given."""
    root = tmp_path / "legged"
    files = {
        "package.xml": package_xml("legged", "catkin"),
        "CMakeLists.txt": APPENDED_CMAKE,
        "include/legged/controllers/command.hpp": (
            "#pragma once\n#include <string>\n"
            "namespace legged { const std::string kCommandTopic = \"joy\"; }\n"),
        "config/.keep": "",
        "src/node.cpp": (
            "#include <ros/ros.h>\n#include <std_msgs/String.h>\n"
            "#include \"controllers/command.hpp\"\n"
            "int main(int argc, char** argv) {\n"
            "  ros::init(argc, argv, \"legged\");\n"
            "  ros::NodeHandle nh;\n"
            "  ros::Publisher pub = nh.advertise<std_msgs::String>(legged::kCommandTopic, 1);\n"
            "}\n"),
    }
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    ws = scan([str(tmp_path)])
    assert cmake_include_dirs(str(root), ws) == [
        str(root / "include" / "legged"), str(root / "src"), str(root / "config")]
    result = extract_cpp([str(root / "src" / "node.cpp")], ws, cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "joy")]
    assert not {"CPP_INCLUDE_MISSING", "CPP_PARSE_ERROR", "CPP_NODE_PARTIAL"} & {
        d.code for d in result.diagnostics}


def test_the_package_root_the_cmake_gives_as_an_include_folder(tmp_path) -> None:
    """hebi_cpp_api_examples' ``include_directories(. ${catkin_INCLUDE_DIRS})``, its
    nodes including ``"src/util/odom_publisher.hpp"`` from the package root: the class
    that advertises the odometry was unknown and 14 nodes partial. The root given as
    ``${PROJECT_SOURCE_DIR}`` is the same folder."""
    from haros_arch.extract.cpp import extract_cpp_nodes
    sources = []
    for name, folder in (("base", "."), ("arm", "${PROJECT_SOURCE_DIR}")):
        root = tmp_path / name
        (root / "src" / "util").mkdir(parents=True)
        (root / "package.xml").write_text(package_xml(name))
        (root / "CMakeLists.txt").write_text(
            f"project({name})\nfind_package(catkin REQUIRED COMPONENTS roscpp std_msgs)\n"
            f"include_directories(\n  {folder}\n  ${{catkin_INCLUDE_DIRS}}\n)\n"
            "add_executable(node src/node.cpp src/util/helper.cpp)\n")
        (root / "src" / "util" / "helper.hpp").write_text(
            "#pragma once\n#include <ros/ros.h>\nnamespace acme {\nclass Helper {\n"
            "public:\n  explicit Helper(ros::NodeHandle& nh);\nprivate:\n"
            "  ros::Publisher pub_;\n};\n}\n")
        (root / "src" / "util" / "helper.cpp").write_text(
            "#include \"src/util/helper.hpp\"\n#include <std_msgs/String.h>\n"
            "namespace acme {\nHelper::Helper(ros::NodeHandle& nh) {\n"
            f"  pub_ = nh.advertise<std_msgs::String>(\"{name}_odom\", 10);\n}}\n}}\n")
        (root / "src" / "node.cpp").write_text(
            "#include <ros/ros.h>\n#include \"src/util/helper.hpp\"\n"
            "int main(int argc, char** argv) {\n  ros::init(argc, argv, \"node\");\n"
            "  ros::NodeHandle nh;\n  acme::Helper helper(nh);\n  ros::spin();\n}\n")
        sources.append([str(root / "src" / "node.cpp"),
                        str(root / "src" / "util" / "helper.cpp")])
    batch = extract_cpp_nodes(sources, scan([str(tmp_path)]), cache_dir=None,
                              distro="noetic")
    for result, name in zip(batch.results, ("base", "arm"), strict=True):
        assert not {"CPP_INCLUDE_MISSING", "CPP_PARSE_ERROR", "CPP_NODE_TO_UNKNOWN"} & {
            d.code for d in result.diagnostics}
        assert [(c.kind, c.name) for c in result.calls] == [("publish", f"{name}_odom")]
