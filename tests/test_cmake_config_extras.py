"""A workspace package's CMake config extras (ament's ``CONFIG_EXTRAS``, catkin's
``CFG_EXTRAS``) run in the packages that find it, as the installed package's config runs
them: the macros they define are the finder's. Autoware's nodes register through
autoware_agnocast_wrapper's ``autoware_agnocast_wrapper_register_node(lib PLUGIN ...
EXECUTABLE ...)``, which falls back to ``rclcpp_components_register_node``: 13
executables of autoware_core (the map loaders, ekf_localizer, ndt_scan_matcher, the
velocity smoother, ...) were not known, and every launch file starting one said it
missing and of unknown interface."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.workspace import scan
from tests.conftest import package_xml

WRAPPER_MACRO = """
macro(wrapper_register_node target)
  if(NOT TARGET ${target})
    message(FATAL_ERROR "wrapper_register_node: no target ${target}")
  endif()
  cmake_parse_arguments(ARGS "" "PLUGIN;EXECUTABLE;EXECUTOR" "" ${ARGN})
  if("${ARGS_EXECUTOR}" STREQUAL "")
    set(ARGS_EXECUTOR "SingleThreadedExecutor")
  endif()
  if(DEFINED ENV{USE_OTHER_MIDDLEWARE} AND "$ENV{USE_OTHER_MIDDLEWARE}" STREQUAL "1")
    add_executable(${ARGS_EXECUTABLE}_other main.cpp)
  else()
    rclcpp_components_register_node(${target}
      PLUGIN ${ARGS_PLUGIN}
      EXECUTABLE ${ARGS_EXECUTABLE}
      EXECUTOR ${ARGS_EXECUTOR})
  endif()
endmacro()
"""


def _consumer(finds: str, package_file: str = "") -> dict[str, str]:
    return {
        "talker/package.xml": package_file or (
            '<?xml version="1.0"?>\n<package format="3"><name>talker</name>'
            "<version>0.1.0</version><description>d</description>"
            '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
            "<buildtool_depend>ament_cmake_auto</buildtool_depend>"
            "<depend>wrapper</depend><depend>rclcpp_components</depend>"
            "<export><build_type>ament_cmake</build_type></export></package>\n"),
        "talker/CMakeLists.txt": f"""
            cmake_minimum_required(VERSION 3.14)
            project(talker)
            {finds}
            ament_auto_add_library(talker_component SHARED src/talker.cpp)
            wrapper_register_node(talker_component
              PLUGIN "demo::Talker"
              EXECUTABLE talker_node)
            ament_auto_package()
            """,
        "talker/src/talker.cpp": """
            #include <rclcpp/rclcpp.hpp>
            #include <rclcpp_components/register_node_macro.hpp>
            namespace demo {
            class Talker : public rclcpp::Node {
             public:
              explicit Talker(const rclcpp::NodeOptions & options) : Node("talker", options) {}
            };
            }
            RCLCPP_COMPONENTS_REGISTER_NODE(demo::Talker)
            """,
    }


def _provider(ending: str) -> dict[str, str]:
    return {
        "wrapper/package.xml": package_xml("wrapper", "ament_cmake"),
        "wrapper/CMakeLists.txt": f"""
            cmake_minimum_required(VERSION 3.14)
            project(wrapper)
            find_package(ament_cmake_auto REQUIRED)
            list(APPEND ${{PROJECT_NAME}}_CONFIG_EXTRAS
              "cmake/wrapper_config_extras.cmake"
            )
            {ending}
            """,
        "wrapper/cmake/wrapper_config_extras.cmake": """
            set(wrapper_TEMPLATE "${wrapper_DIR}/../templates/main.cpp.in")
            include("${wrapper_DIR}/wrapper_register_node.cmake")
            """,
        "wrapper/cmake/wrapper_register_node.cmake": WRAPPER_MACRO,
    }


def _executables(root, name: str = "talker") -> list[str]:
    ws = scan([str(root)], {})
    nodes, _ = cmake.parse_package(ws.packages[name], ws)
    return sorted(n.executable for n in nodes if n.executable)


def test_a_build_dependencys_extras_define_the_macro_that_registers_the_node(
        write_tree) -> None:
    root = write_tree({**_provider("ament_auto_package()"),
                       **_consumer("find_package(ament_cmake_auto REQUIRED)\n"
                                   "            ament_auto_find_build_dependencies()")})
    assert "talker_node" in _executables(root)


def test_a_found_package_whose_extras_a_wrapper_of_ament_package_hands_on(
        write_tree) -> None:
    """The provider ends with a command not known here (Autoware's
    ``autoware_ament_auto_package()``): what ``${PROJECT_NAME}_CONFIG_EXTRAS`` holds at
    the end of its reading is handed on; the finder names it in ``find_package``."""
    root = write_tree({**_provider("autoware_ament_auto_package()"),
                       **_consumer("find_package(wrapper REQUIRED)")})
    assert "talker_node" in _executables(root)


def test_autoware_package_finds_the_build_dependencies(write_tree) -> None:
    root = write_tree({**_provider("autoware_ament_auto_package()"),
                       **_consumer("find_package(autoware_cmake REQUIRED)\n"
                                   "            autoware_package()")})
    assert "talker_node" in _executables(root)


def test_no_extras_without_a_find(write_tree) -> None:
    """A package that finds neither the provider nor its build dependencies does not
    get the macro: the call is an unknown command, no executable."""
    root = write_tree({**_provider("ament_auto_package()"),
                       **_consumer("find_package(ament_cmake_auto REQUIRED)")})
    assert "talker_node" not in _executables(root)


def test_catkin_cfg_extras_of_a_component(write_tree) -> None:
    root = write_tree({
        "tools/package.xml": package_xml("tools", "catkin"),
        "tools/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.0.2)
            project(tools)
            find_package(catkin REQUIRED)
            catkin_package(CFG_EXTRAS tools-extras.cmake)
            """,
        "tools/cmake/tools-extras.cmake": """
            function(tools_add_node name source)
              add_executable(${name}_node ${source})
            endfunction()
            """,
        "robot/package.xml": package_xml("robot", "catkin"),
        "robot/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.0.2)
            project(robot)
            find_package(catkin REQUIRED COMPONENTS roscpp tools)
            catkin_package()
            tools_add_node(driver src/driver.cpp)
            """,
        "robot/src/driver.cpp": """
            #include <ros/ros.h>
            int main(int argc, char** argv) { ros::init(argc, argv, "driver"); }
            """,
    })
    # (without the extras, a guess from the unknown command: ``driver``)
    assert _executables(root, "robot") == ["driver_node"]


def test_extras_at_the_package_root_include_from_its_cmake_folder(write_tree) -> None:
    """autoware_cmake keeps its extras at its root and includes
    ``${autoware_cmake_DIR}/autoware_package.cmake``: installed, both sit in
    share/autoware_cmake/cmake, so ``<pkg>_DIR`` is the package's cmake folder."""
    root = write_tree({
        "builder/package.xml": package_xml("builder", "ament_cmake"),
        "builder/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.14)
            project(builder)
            list(APPEND ${PROJECT_NAME}_CONFIG_EXTRAS "builder-extras.cmake")
            ament_auto_package(INSTALL_TO_SHARE cmake)
            """,
        "builder/builder-extras.cmake": 'include("${builder_DIR}/builder_node.cmake")\n',
        "builder/cmake/builder_node.cmake": """
            macro(builder_node target)
              cmake_parse_arguments(ARGS "" "PLUGIN;EXECUTABLE" "" ${ARGN})
              rclcpp_components_register_node(${target}
                PLUGIN ${ARGS_PLUGIN} EXECUTABLE ${ARGS_EXECUTABLE})
            endmacro()
            """,
        **{path.replace("wrapper_register_node", "builder_node"): text.replace(
            "wrapper_register_node", "builder_node") for path, text in _consumer(
                "find_package(builder REQUIRED)").items()},
    })
    assert "talker_node" in _executables(root)
