"""A workspace package's headers where its ``catkin_package(INCLUDE_DIRS ...)`` exports
them, whatever the folder is called: open_vins' ov_core keeps its headers in ``src/``
and exports that folder from cmake/ROS1.cmake, which its CMakeLists.txt includes;
ov_msckf's nodes include ``utils/opencv_yaml_parse.h`` through ``${catkin_INCLUDE_DIRS}``.
The header was not found, so ``ov_core::YamlParser`` was unknown and every node that
builds one partial (CPP_NODE_PARTIAL on 10 of open_vins' nodes)."""

from __future__ import annotations

import os

from haros_arch.extract.cpp import extract_cpp
from haros_arch.extract.cpp.cmake_includes import cmake_include_dirs, exported_include_dirs
from haros_arch.workspace import scan

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "exported_includes")
CORE = os.path.join(ROOT, "src", "vio_core")


def test_a_cmake_file_names_folders_from_the_cmakelists_that_includes_it() -> None:
    # cmake/ROS1.cmake writes ``src`` and ``src/``: CMake's current source folder is
    # vio_core's, the including CMakeLists.txt's (it was vio_core/cmake/src: no folder)
    workspace = scan([ROOT])
    assert cmake_include_dirs(CORE, workspace) == [os.path.join(CORE, "src")]
    assert exported_include_dirs(CORE, workspace) == [os.path.join(CORE, "src")]


def test_a_node_reads_the_headers_its_dependency_exports() -> None:
    found = extract_cpp([os.path.join(ROOT, "src", "vio_app", "src", "estimator.cpp")],
                        scan([ROOT]), cache_dir=None)
    assert sorted((c.kind, c.name) for c in found.calls) == [
        ("publish", "~status"), ("read", "~config_path")]
    assert not [d for d in found.diagnostics if d.code in (
        "CPP_INCLUDE_MISSING", "CPP_CLASS_UNSEEN", "CPP_PARSE_ERROR")]
