"""Benchmark: the whole build-file stage on a synthetic 100-package workspace.

Writes a workspace to a temporary folder (catkin packages with macros in loops,
includes and subdirectories; ament_cmake packages with components; nodelet packages;
ament_python packages), then times ``workspace.scan`` plus the build-file entry of
every package. Prints packages per second and the total. Run:

    .venv/bin/python bench/build_files.py [PACKAGES]
"""

from __future__ import annotations

import os
import sys
import tempfile
import time

from haros_arch import cmake, pysetup
from haros_arch.workspace import scan

MANIFEST = """<?xml version="1.0"?>
<package format="3"><name>{name}</name><version>1.0.0</version>
<description>synthetic</description><maintainer email="a@b.c">m</maintainer>
<license>MIT</license><buildtool_depend>{tool}</buildtool_depend>
<export>{export}</export></package>
"""

CATKIN = """cmake_minimum_required(VERSION 3.0.2)
project({name})
find_package(catkin REQUIRED COMPONENTS roscpp std_msgs nodelet)
set(CMAKE_MODULE_PATH ${{CMAKE_MODULE_PATH}} ${{PROJECT_SOURCE_DIR}}/cmake)
include(Helpers)
catkin_package(LIBRARIES ${{PROJECT_NAME}}_nodelets)
macro(node_from_dir T)
  add_executable(${{T}} src/${{T}}/${{T}}.cpp src/common.cpp)
  target_link_libraries(${{T}} ${{catkin_LIBRARIES}})
  install(TARGETS ${{T}} RUNTIME DESTINATION ${{CATKIN_PACKAGE_BIN_DESTINATION}})
endmacro()
set(NODES {nodes})
list(LENGTH NODES COUNT)
foreach(n IN LISTS NODES)
  string(TOUPPER ${{n}} UPPER)
  if(NOT UPPER STREQUAL "SKIP" AND COUNT GREATER 0)
    node_from_dir(${{n}})
  endif()
endforeach()
add_library(${{PROJECT_NAME}}_nodelets src/nodelets.cpp)
file(GLOB TOOL_SOURCES src/tools/*.cpp)
add_subdirectory(tools)
if(CATKIN_ENABLE_TESTING)
  add_executable(${{PROJECT_NAME}}_test test/test.cpp)
endif()
catkin_install_python(PROGRAMS scripts/monitor.py
  DESTINATION ${{CATKIN_PACKAGE_BIN_DESTINATION}})
"""

AMENT = """cmake_minimum_required(VERSION 3.16)
project({name})
find_package(ament_cmake REQUIRED)
find_package(rclcpp_components REQUIRED)
function(component plugin exe)
  cmake_parse_arguments(ARG "" "" "FILES" ${{ARGN}})
  add_library(${{exe}}_component SHARED ${{ARG_FILES}})
  target_include_directories(${{exe}}_component PUBLIC
    "$<BUILD_INTERFACE:${{CMAKE_CURRENT_SOURCE_DIR}}/include>")
  rclcpp_components_register_node(${{exe}}_component PLUGIN "${{plugin}}" EXECUTABLE ${{exe}})
endfunction()
foreach(i RANGE 1 {count})
  component("{name}::Node${{i}}" node_${{i}} FILES src/node_${{i}}.cpp)
endforeach()
ament_package()
"""


def write(path: str, text: str, mode: int | None = None) -> None:
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as handle:
        handle.write(text)
    if mode is not None:
        os.chmod(path, mode)


def make_workspace(root: str, count: int) -> None:
    for index in range(count):
        name = f"pkg_{index:03d}"
        base = os.path.join(root, "src", name)
        kind = index % 4
        if kind in (0, 1):  # catkin with nodelets
            nodes = [f"node_{k}" for k in range(8)]
            export = '<nodelet plugin="${prefix}/plugins.xml"/>'
            write(f"{base}/package.xml", MANIFEST.format(name=name, tool="catkin", export=export))
            write(f"{base}/CMakeLists.txt", CATKIN.format(name=name, nodes=" ".join(nodes)))
            write(f"{base}/cmake/Helpers.cmake", "macro(helper)\nendmacro()\n" * 5)
            write(f"{base}/tools/CMakeLists.txt",
                  "add_executable(${PROJECT_NAME}_tool ${TOOL_SOURCES})\n")
            for node in nodes:
                write(f"{base}/src/{node}/{node}.cpp", "int main() { return 0; }\n")
            write(f"{base}/src/common.cpp", "int common() { return 0; }\n")
            write(f"{base}/test/test.cpp", "int main() { return 0; }\n")
            write(f"{base}/src/tools/tool.cpp", "int main() { return 0; }\n")
            write(f"{base}/src/nodelets.cpp",
                  f"PLUGINLIB_EXPORT_CLASS({name}::Filter, nodelet::Nodelet)\n")
            write(f"{base}/plugins.xml",
                  f'<library path="lib/lib{name}_nodelets"><class name="{name}/Filter" '
                  f'type="{name}::Filter" base_class_type="nodelet::Nodelet"/></library>\n')
            write(f"{base}/scripts/monitor.py", "#!/usr/bin/env python3\n", 0o755)
        elif kind == 2:  # ament_cmake components
            write(f"{base}/package.xml", MANIFEST.format(
                name=name, tool="ament_cmake", export="<build_type>ament_cmake</build_type>"))
            write(f"{base}/CMakeLists.txt", AMENT.format(name=name, count=6))
            for k in range(1, 7):
                write(f"{base}/src/node_{k}.cpp",
                      f"RCLCPP_COMPONENTS_REGISTER_NODE({name}::Node{k})\n")
        else:  # ament_python
            write(f"{base}/package.xml", MANIFEST.format(
                name=name, tool="ament_python", export="<build_type>ament_python</build_type>"))
            scripts = ",\n".join(f"            'n{k} = {name}.n{k}:main'" for k in range(6))
            write(f"{base}/setup.py",
                  f"from setuptools import setup\npackage_name = '{name}'\nsetup(\n"
                  f"    name=package_name,\n    entry_points={{\n        'console_scripts': [\n"
                  f"{scripts}\n        ],\n    }},\n)\n")
            for k in range(6):
                write(f"{base}/{name}/n{k}.py", "def main():\n    pass\n")
            write(f"{base}/{name}/__init__.py", "")


def main() -> None:
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 100
    with tempfile.TemporaryDirectory() as tmp:
        make_workspace(tmp, count)
        start, cpu = time.perf_counter(), time.process_time()
        ws = scan([os.path.join(tmp, "src")], {})
        nodes = diagnostics = 0
        for package in ws.packages.values():
            entry = pysetup.parse_package if package.build_type == "ament_python" else (
                cmake.parse_package)
            found_nodes, found = entry(package, ws)
            nodes += len(found_nodes)
            diagnostics += len(found)
        total, cpu = time.perf_counter() - start, time.process_time() - cpu
    print(f"packages: {len(ws.packages)}  nodes: {nodes}  diagnostics: {diagnostics}")
    print(f"build-file stage: {total:.3f} s total ({cpu:.3f} s CPU), "
          f"{len(ws.packages) / total:.0f} packages/s")


if __name__ == "__main__":
    main()
