"""An empty source argument names no file (bench/README, survey Z46): Kimera-VIO's
``add_library(${PROJECT_NAME} SHARED "")`` gets its sources from ``target_sources`` in
its subdirectories; the empty string was taken for the package's own folder, a source
missing (CMAKE_SOURCE_MISSING, a false warning)."""

from __future__ import annotations

from test_cmake import workspace_with

from haros_arch.cmake import parse_package


def test_an_empty_source_is_no_file(write_tree):
    ws, pkg = workspace_with(write_tree, """
        project(pkg)
        add_library(${PROJECT_NAME} SHARED "")
        target_sources(${PROJECT_NAME} PRIVATE src/a.cpp "" "src/b.cpp;;")
        add_executable(node src/c.cpp)
        target_link_libraries(node ${PROJECT_NAME})
        """)
    nodes, found = parse_package(pkg, ws)
    assert found == []
    assert [(n.executable, n.sources) for n in nodes] == [("node", ["pkg/src/c.cpp"])]
