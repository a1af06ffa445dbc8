"""Which C++ standard the compiler uses when a package's CMake files ask several: an old
``-std=`` word (in ``CMAKE_CXX_FLAGS`` or ``add_compile_options``) beside
``CMAKE_CXX_STANDARD``. g++ takes the last ``-std=`` of its command line; CMake writes
``CMAKE_CXX_FLAGS``, then the standard's flag, then the compile options (3.28, Jazzy's;
3.22 and 3.25 write the flag after the options), and writes no flag for a standard that
is the compiler's own (17 for g++ 11 and later) under policy CMP0128 NEW
(``cmake_minimum_required(VERSION 3.22)``) unless CXX_STANDARD_REQUIRED. Checked with
CMake 3.25 and 3.28's compile_commands.json. The old reading took the newest of them
all: ``set(CMAKE_CXX_FLAGS "... -std=c++20")`` beside ``set(CMAKE_CXX_STANDARD 17)``
(``cmake_minimum_required(VERSION 3.8)``) parsed as C++20, where g++ gets
``-std=c++20 -std=gnu++17``."""

from __future__ import annotations

import pytest
from conftest import package_xml

from haros_arch.cmake import source_standards
from haros_arch.workspace import scan

CASES = {
    # name: (minimum version, lines before add_executable, {distro: expected})
    "flags_then_prop": ("3.8", 'set(CMAKE_CXX_FLAGS "${CMAKE_CXX_FLAGS} -std=c++20")\n'
                        "set(CMAKE_CXX_STANDARD 17)\n",
                        {"humble": None, "jazzy": None}),
    "flags_no_flag": ("3.22", 'set(CMAKE_CXX_FLAGS "${CMAKE_CXX_FLAGS} -std=c++20")\n'
                      "set(CMAKE_CXX_STANDARD 17)\n",
                      {"humble": "c++20", "jazzy": "c++20"}),
    "flags_required": ("3.22", 'set(CMAKE_CXX_FLAGS "${CMAKE_CXX_FLAGS} -std=c++20")\n'
                       "set(CMAKE_CXX_STANDARD 17)\nset(CMAKE_CXX_STANDARD_REQUIRED ON)\n",
                       {"humble": None, "jazzy": None}),
    "options_new": ("3.8", "add_compile_options(-std=c++2a)\nset(CMAKE_CXX_STANDARD 17)\n",
                    {"humble": None, "jazzy": "c++20"}),
    "options_old": ("3.8", "add_compile_options(-std=c++17)\nset(CMAKE_CXX_STANDARD 20)\n",
                    {"humble": "c++20", "jazzy": None}),
    "flags_older": ("3.8", 'set(CMAKE_CXX_FLAGS "-std=c++14")\nset(CMAKE_CXX_STANDARD 20)\n',
                    {"humble": "c++20", "jazzy": "c++20"}),
    "target_options": ("3.8", "set(CMAKE_CXX_STANDARD 20)\n",
                       {"humble": "c++20", "jazzy": None}),
}


def _workspace(write_tree, distro: str):
    files = {}
    for name, (version, lines, _) in CASES.items():
        files[f"src/{name}/package.xml"] = package_xml(name, "ament_cmake")
        files[f"src/{name}/main.cpp"] = "int main() {}\n"
        extra = "target_compile_options(n PRIVATE -Wall -std=c++17)\n" if (
            name == "target_options") else ""
        files[f"src/{name}/CMakeLists.txt"] = (
            f"cmake_minimum_required(VERSION {version})\nproject({name})\n{lines}"
            f"add_executable(n main.cpp)\n{extra}")
    root = write_tree(files)
    return scan([str(root / "src")], {"ROS_DISTRO": distro})


@pytest.mark.parametrize("distro", ["humble", "jazzy"])
def test_the_standard_is_the_one_the_compile_line_ends_with(write_tree, distro) -> None:
    ws = _workspace(write_tree, distro)
    found = {name: source_standards(ws.packages[name], ws).get(f"{name}/main.cpp")
             for name in CASES}
    assert found == {name: expected[distro] for name, (_, _, expected) in CASES.items()}
