"""``find_path`` / ``find_file`` in a package's CMake: a folder of the workspace it is
told to look in is found (or, in a git submodule not checked out, the folder the
build finds once it is); the build machine's own folders are not known here.
darknet_ros 1027a28 sets ``DARKNET_PATH`` with ``find_path(... NAMES "README.md" HINTS
"${CMAKE_CURRENT_SOURCE_DIR}/../darknet/")`` and compiles ``${DARKNET_PATH}/src/*.c``:
the command was not read, the variable expanded empty and 64 CMAKE_SOURCE_MISSING
warnings named ``/src/activation_layer.c`` and the like, files at the root of the
machine; the sources lie in the submodule darknet, not checked out."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.cmake.interpreter import Interpreter
from haros_arch.cmake.lexer import tokenize
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

GITMODULES = """[submodule "engine"]
\tpath = engine
\turl = https://example.invalid/engine.git
"""

CMAKE = """cmake_minimum_required(VERSION 3.5)
project(det)
find_package(catkin REQUIRED COMPONENTS roscpp)
catkin_package()
find_path(ENGINE_PATH
  NAMES "README.md"
  HINTS "${CMAKE_CURRENT_SOURCE_DIR}/../engine/")
find_path(VENDOR_INC vendor.h PATHS /opt/nowhere ${CMAKE_CURRENT_SOURCE_DIR}/third
          PATH_SUFFIXES include)
find_file(VENDOR_SRC NAMES vendor.cpp PATHS ${CMAKE_CURRENT_SOURCE_DIR}/third/src)
find_path(SYSTEM_INC NAMES x.h PATHS /usr/include/not_here)
add_library(det_engine ${ENGINE_PATH}/src/layer.c ${ENGINE_PATH}/src/net.c)
add_executable(det_node src/det_node.cpp ${VENDOR_SRC})
target_link_libraries(det_node det_engine)
"""

NODE = """#include <ros/ros.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "det");
  ros::NodeHandle nh;
  ros::spin();
}
"""


def _tree(write_tree):
    root = write_tree({
        "src/.gitmodules": GITMODULES,
        "src/det/package.xml": package_xml("det").replace(
            "</package>", "<depend>roscpp</depend></package>"),
        "src/det/CMakeLists.txt": CMAKE,
        "src/det/src/det_node.cpp": NODE,
        "src/det/third/include/vendor.h": "int vendor();\n",
        "src/det/third/src/vendor.cpp": "int vendor() { return 1; }\n",
        "src/det/launch/det.launch": '<launch><node pkg="det" type="det_node" name="det"/>'
                                     "</launch>\n",
        "project.yaml": "project: p\ndistro: noetic\nworkspace: src\nconfigurations:\n"
                        "  c: [det/launch/det.launch]\n"})
    os.makedirs(root / "src/engine", exist_ok=True)  # the empty folder git leaves
    return root


def test_find_path_in_a_submodule_not_checked_out(write_tree):
    root = _tree(write_tree)
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    said = [(d.code, d.message) for d in [*model.diagnostics, *config.diagnostics]
            if d.code.startswith("CMAKE_SOURCE")]
    assert said == [("CMAKE_SOURCE_IN_SUBMODULE", "sources of target det_engine lie in "
                     "the git submodule engine (declared at .gitmodules:2), which is not "
                     "checked out here (git submodule update --init); their code is not "
                     "read")]
    (node,) = [n for n in model.nodes if n.package == "det"]
    assert node.completeness == "partial"
    assert "det/third/src/vendor.cpp" in node.sources


def test_find_path_values(write_tree):
    root = _tree(write_tree)
    folder = str(root / "src/det")
    it = Interpreter(folder, {})
    it.workspace_holds = lambda path: path.startswith(str(root / "src") + os.sep)
    it.submodule_of = lambda path: (("engine", ".gitmodules:2")
                                    if path == str(root / "src/engine") else None)
    with open(os.path.join(folder, "CMakeLists.txt")) as handle:
        it.run_file(tokenize(handle.read(), os.path.join(folder, "CMakeLists.txt")))
    assert it.get("ENGINE_PATH") == str(root / "src/engine")
    assert it.get("VENDOR_INC") == str(root / "src/det/third/include")
    assert it.get("VENDOR_SRC") == str(root / "src/det/third/src/vendor.cpp")
    # a folder of the build machine: not known here, not empty
    assert it.get("SYSTEM_INC") is None
    assert it.unknown_reference("${SYSTEM_INC}/x.h")
