"""A header another package includes by the name its package installs it under.

zed-ros2-wrapper's zed_components keeps its headers in ``src/zed_camera/include/`` and
``src/tools/include/`` and installs those folders' contents into
``include/zed_components/``; zed_debug includes ``<zed_components/zed_camera_component.hpp>``
and builds ``stereolabs::ZedCamera`` in its ``main()``. No include folder of the sources
holds that name, so the header was an empty stand-in and the class given the node
unknown: the node partial for it (``CPP_NODE_TO_UNKNOWN``). The names a package's
``install(DIRECTORY|FILES ... DESTINATION include[/sub])`` rules give its headers are
read (``share.include_map``) for the packages being extracted and those they build on."""

from __future__ import annotations

from pathlib import Path

from haros_arch import cmake, share
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

FILES = {
    "cam/package.xml": package_xml("cam", "ament_cmake"),
    "cam/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.8)
        project(cam)
        find_package(ament_cmake REQUIRED)
        find_package(rclcpp REQUIRED)
        add_library(camera SHARED src/camera/src/camera.cpp)
        target_include_directories(camera PUBLIC
            ${CMAKE_CURRENT_SOURCE_DIR}/src/camera/include)
        ament_target_dependencies(camera rclcpp)
        install(TARGETS camera LIBRARY DESTINATION lib)
        install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/src/camera/include/
            DESTINATION include/${PROJECT_NAME}/)
        ament_export_include_directories(include)
        ament_export_libraries(camera)
        ament_package()
        """,
    "cam/src/camera/include/camera.hpp": """
        #include "rclcpp/rclcpp.hpp"
        namespace vendor {
        class Camera : public rclcpp::Node {
        public:
          explicit Camera(const rclcpp::NodeOptions & options);
        };
        }
        """,
    "cam/src/camera/src/camera.cpp": """
        #include "camera.hpp"
        namespace vendor {
        Camera::Camera(const rclcpp::NodeOptions & options)
        : rclcpp::Node("camera", options)
        {
          declare_parameter<double>("frame_rate", 15.0);
        }
        }
        """,
    "dbg/package.xml": """<?xml version="1.0"?>
        <package format="3"><name>dbg</name><version>0.1.0</version>
        <description>d</description><maintainer email="a@b.c">m</maintainer>
        <license>MIT</license><depend>rclcpp</depend><depend>cam</depend>
        <export><build_type>ament_cmake</build_type></export></package>
        """,
    "dbg/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.8)
        project(dbg)
        find_package(ament_cmake REQUIRED)
        find_package(rclcpp REQUIRED)
        find_package(cam REQUIRED)
        add_executable(dbg_proc src/dbg_proc.cpp)
        ament_target_dependencies(dbg_proc rclcpp cam)
        install(TARGETS dbg_proc DESTINATION lib/${PROJECT_NAME})
        ament_package()
        """,
    "dbg/src/dbg_proc.cpp": """
        #include <rclcpp/rclcpp.hpp>
        #include <cam/camera.hpp>
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          rclcpp::NodeOptions options;
          auto node = std::make_shared<vendor::Camera>(options);
          rclcpp::spin(node);
          rclcpp::shutdown();
        }
        """,
}


def _node(write_tree, files: dict[str, str]):
    root: Path = write_tree(files)
    ws = scan([str(root)])
    for each in ws.packages.values():
        each.nodes, _ = cmake.parse_package(each, ws)
    node = next(n for n in ws.packages["dbg"].nodes if n.executable == "dbg_proc")
    found = extract_nodes([node], ws, cache_dir=None, jobs=1)
    return node, found, ws


def test_the_include_map_names_what_a_package_installs(write_tree) -> None:
    _, _, ws = _node(write_tree, FILES)
    found = share.include_map(ws.packages["cam"], ws)
    assert found == {"cam/camera.hpp": str(Path(ws.packages["cam"].root)
                                           / "src/camera/include/camera.hpp")}
    assert share.include_map(ws.packages["dbg"], ws) == {}


def test_a_header_included_by_its_installed_name_is_read(write_tree) -> None:
    node, found, _ = _node(write_tree, FILES)
    assert not [d for d in found if d.code in ("CPP_INCLUDE_MISSING", "CPP_NODE_TO_UNKNOWN")], [
        d.message for d in found if d.code in ("CPP_INCLUDE_MISSING", "CPP_NODE_TO_UNKNOWN")]
    assert "cam/src/camera/src/camera.cpp" in node.sources
    assert [c.name for c in node.calls if c.kind == "declare"] == ["frame_rate"]
    assert node.completeness == "complete", node.completeness_reasons


def test_a_name_no_package_installs_is_still_missing(write_tree) -> None:
    files = dict(FILES)
    files["dbg/src/dbg_proc.cpp"] = FILES["dbg/src/dbg_proc.cpp"].replace(
        "<cam/camera.hpp>", "<cam/other.hpp>")
    node, found, _ = _node(write_tree, files)
    assert any(d.code == "CPP_INCLUDE_MISSING" and "cam/other.hpp" in d.message
               for d in found)
    assert node.completeness == "partial"
