"""catkin's devel space is in the build folder (``CATKIN_DEVEL_PREFIX``, by default
``${CMAKE_BINARY_DIR}/devel``): a source a custom command writes there is generated at
build time, not missing. cpr_multimaster_tools' message_relay writes its message
processors to ``${CATKIN_DEVEL_PREFIX}/${CATKIN_GLOBAL_INCLUDE_DESTINATION}/...`` and
builds libraries of them; with both variables unset the paths became
``//message_relay/...`` and each was a CMAKE_SOURCE_MISSING warning (20 there). A source
of the package that is not there stays missing."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.cmake import parse_package
from haros_arch.workspace import scan

CMAKE = """
    cmake_minimum_required(VERSION 3.0.2)
    project(pkg)
    find_package(catkin REQUIRED COMPONENTS roscpp)
    catkin_package()
    set(GEN_DIR ${CATKIN_DEVEL_PREFIX}/${CATKIN_GLOBAL_INCLUDE_DESTINATION})
    set(OUT ${GEN_DIR}/${PROJECT_NAME}/processor/made.cpp)
    add_custom_command(OUTPUT ${OUT} COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/gen.py ${OUT})
    add_executable(relay src/relay.cpp ${OUT})
    add_library(lost ${CATKIN_PACKAGE_INCLUDE_DESTINATION}/lost.cpp)
    """


def test_a_source_written_to_the_devel_space_is_not_missing(write_tree):
    root = write_tree({"src/pkg/package.xml": package_xml("pkg"),
                       "src/pkg/CMakeLists.txt": CMAKE,
                       "src/pkg/src/relay.cpp": "int main() { return 0; }\n"})
    ws = scan([str(root / "src")], {})
    nodes, found = parse_package(ws.packages["pkg"], ws)
    assert [(d.code, d.location.line, d.message) for d in found] == [
        ("CMAKE_SOURCE_MISSING", 9,
         "source file pkg/include/pkg/lost.cpp of target lost does not exist")]
    assert [(n.executable, n.sources) for n in nodes] == [("relay", ["pkg/src/relay.cpp"])]
