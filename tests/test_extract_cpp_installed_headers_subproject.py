"""A header a package installs from a sub-project it vendors is not read by that name.

ouster-ros (jazzy-devel eaaf35d) vendors ouster-sdk, a CMake project of its own, and
installs its ``ouster/`` and ``optional-lite/nonstd/`` headers into ``include``. Its node
classes hold the SDK's types. The sub-project's include folders are not given to the
parse (``cmake_includes.cmake_include_dirs``), so those names were empty stand-ins and
the nodes complete; once the installed names were read (``share.include_map``), the
SDK's Eigen tensors and optional-lite failed against the stand-ins and broke the classes
that hold them: every ouster node partial, ``cannot initialize object parameter of type
'const rclcpp_lifecycle::LifecycleNode'``. A header a package installs from a folder of
a sub-project (a ``CMakeLists.txt`` with its own ``project()`` between the package root
and the file) stays an empty stand-in, as its include folder is not given."""

from __future__ import annotations

from pathlib import Path

from haros_arch import cmake, share
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

FILES = {
    "lidar/package.xml": package_xml("lidar", "ament_cmake"),
    "lidar/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.8)
        project(lidar)
        find_package(ament_cmake REQUIRED)
        find_package(rclcpp REQUIRED)
        add_subdirectory(sdk/client)
        add_executable(lidar_node src/lidar_node.cpp)
        ament_target_dependencies(lidar_node rclcpp)
        install(TARGETS lidar_node DESTINATION lib/${PROJECT_NAME})
        install(DIRECTORY include/lidar/ DESTINATION include/lidar/)
        install(DIRECTORY sdk/client/include/vendor DESTINATION include)
        ament_package()
        """,
    "lidar/include/lidar/node.hpp": """
        #include <rclcpp/rclcpp.hpp>
        #include <vendor/types.h>
        namespace lidar {
        class LidarNode : public rclcpp::Node {
        public:
          explicit LidarNode(const rclcpp::NodeOptions & options)
          : rclcpp::Node("lidar", options)
          {
            declare_parameter<std::string>("sensor_hostname", "");
            RCLCPP_INFO(get_logger(), "up");
          }
          vendor::SensorInfo info;
        };
        }
        """,
    "lidar/src/lidar_node.cpp": """
        #include <lidar/node.hpp>
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          rclcpp::spin(std::make_shared<lidar::LidarNode>(rclcpp::NodeOptions()));
          rclcpp::shutdown();
        }
        """,
    "lidar/sdk/client/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.10)
        project(vendor_sdk)
        add_library(vendor_client src/client.cpp)
        target_include_directories(vendor_client PUBLIC include)
        """,
    # two levels down, as ouster-sdk/ouster_client/include: not an include folder of the
    # parse (``headers._library_include_dirs`` takes ``<package>/<folder>/include``);
    # what the parse cannot take: the SDK's own build defines it
    "lidar/sdk/client/include/vendor/types.h": """
        #ifndef VENDOR_SDK_BUILD
        #error "configure the SDK first"
        #endif
        namespace vendor { struct SensorInfo { int mode; }; }
        """,
    "lidar/sdk/client/src/client.cpp": """
        #include "vendor/types.h"
        """,
}


def _node(write_tree):
    root: Path = write_tree(FILES)
    ws = scan([str(root)])
    for each in ws.packages.values():
        each.nodes, _ = cmake.parse_package(each, ws)
    node = next(n for n in ws.packages["lidar"].nodes if n.executable == "lidar_node")
    found = extract_nodes([node], ws, cache_dir=None, jobs=1)
    return node, found, ws


def test_the_sub_project_header_is_installed_but_not_read(write_tree) -> None:
    node, found, ws = _node(write_tree)
    # the package installs it (what ``cmake --install`` writes is unchanged)
    assert "vendor/types.h" in share.include_map(ws.packages["lidar"], ws)
    # but the parse takes it as it takes the sub-project's include folder: not given
    assert any(d.code == "CPP_INCLUDE_MISSING" and "vendor/types.h" in d.message
               for d in found), [d.message for d in found]
    assert not [d for d in found if d.location is not None and d.location.file
                and d.location.file.startswith("lidar/sdk/")], [
        (d.code, d.message) for d in found if d.location is not None
        and (d.location.file or "").startswith("lidar/sdk/")]
    assert [c.name for c in node.calls if c.kind == "declare"] == ["sensor_hostname"]
    assert node.completeness == "complete", node.completeness_reasons


def test_a_header_of_the_package_own_project_is_still_read(write_tree) -> None:
    node, found, _ = _node(write_tree)
    assert not any(d.code == "CPP_INCLUDE_MISSING" and "lidar/node.hpp" in d.message
                   for d in found)
    assert "lidar/src/lidar_node.cpp" in node.sources
