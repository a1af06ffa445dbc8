"""A relative source CMake does not find in the source folder is looked up in the binary
folder, where a configure_file may have written it: jsk_topic_tools' ``jsk_nodelet``
macro configures ``JSK_NODELET_<pkg>_<name>.cpp`` from a template and builds
``add_executable(<target> <target>.cpp)`` of it, which was one CMAKE_SOURCE_MISSING
warning per nodelet (12 in POLARIS_GEM_e2's copy of jsk_topic_tools). A source that is
in neither folder stays missing."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.cmake import parse_package
from haros_arch.workspace import scan

CMAKE = """
    project(pkg)
    macro(single_exec name)
      configure_file(${PROJECT_SOURCE_DIR}/cmake/exec.cpp.in ${name}.cpp)
      add_executable(${name} ${name}.cpp)
    endmacro()
    single_exec(relay)
    add_executable(lost lost.cpp)
    configure_file(cmake/exec.cpp.in src/made.cpp)
    add_executable(both src/a.cpp)
    target_sources(both PRIVATE src/made.cpp)
    """


def test_a_source_configure_file_wrote_in_the_binary_folder_is_not_missing(write_tree):
    root = write_tree({"src/pkg/package.xml": package_xml("pkg"),
                       "src/pkg/CMakeLists.txt": CMAKE,
                       "src/pkg/cmake/exec.cpp.in": "int main() { return 0; }\n",
                       "src/pkg/src/a.cpp": "int main() {}\n"})
    ws = scan([str(root / "src")], {})
    nodes, found = parse_package(ws.packages["pkg"], ws)
    assert [(d.code, d.location.line) for d in found] == [("CMAKE_SOURCE_MISSING", 7)]
    assert [(n.executable, n.sources) for n in nodes] == [
        ("relay", []), ("lost", []), ("both", ["pkg/src/a.cpp"])]
