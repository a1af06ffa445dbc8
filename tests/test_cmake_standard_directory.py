"""The C++ standard a directory asks as well as its targets (followups10 left these):
``add_compile_options(-std=c++20)`` starts the options of the targets the directory (and
its subdirectories) makes after it; ``CMAKE_CXX_FLAGS`` is the directory's as it is at the
end of its CMakeLists.txt, as CMake reads it at generation (a ``set`` after the target
counts), beside its value when the target is made; and a standard set in a branch of an
``if()`` the reading cannot decide (``set(CMAKE_CXX_STANDARD 20)`` on one side, 17 on the
other) is the newest either branch asks, the safe parse (a newer standard takes what
an older one does, in the code ROS packages write)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.cmake import source_standards
from haros_arch.workspace import scan

CMAKE = """
cmake_minimum_required(VERSION 3.8)
project(stds)
find_package(ament_cmake REQUIRED)
add_executable(before src/before.cpp)
add_compile_options(-Wall -std=c++20)
add_executable(options src/options.cpp)
add_subdirectory(sub)
if(EXISTS "/opt/vendor/sdk/include")
  set(CMAKE_CXX_STANDARD 23)
else()
  set(CMAKE_CXX_STANDARD 17)
endif()
add_executable(branches src/branches.cpp)
ament_package()
"""

SUB = """
add_executable(inherited ../src/inherited.cpp)
add_executable(late ../src/late.cpp)
set(CMAKE_CXX_FLAGS "${CMAKE_CXX_FLAGS} -std=c++2b")
"""

LATE_ONLY = """
cmake_minimum_required(VERSION 3.8)
project(other)
find_package(ament_cmake REQUIRED)
add_executable(first src/first.cpp)
set(CMAKE_CXX_FLAGS "${CMAKE_CXX_FLAGS} -O2 -std=gnu++20")
ament_package()
"""


def test_a_directory_asks_the_standard(write_tree) -> None:
    root = write_tree({
        "src/stds/package.xml": package_xml("stds", "ament_cmake"),
        "src/stds/CMakeLists.txt": CMAKE,
        "src/stds/sub/CMakeLists.txt": SUB,
        **{f"src/stds/src/{name}.cpp": "int main() {}\n" for name in (
            "before", "options", "inherited", "late", "branches")},
        "src/other/package.xml": package_xml("other", "ament_cmake"),
        "src/other/CMakeLists.txt": LATE_ONLY,
        "src/other/src/first.cpp": "int main() {}\n",
    })
    ws = scan([str(root / "src")])
    assert source_standards(ws.packages["stds"], ws) == {
        # made before add_compile_options: not its
        "stds/src/options.cpp": "c++20",
        # the subdirectory's targets take the parent's options, and its own
        # CMAKE_CXX_FLAGS at its end (C++23), set after them; CMake writes the flags
        # first, the options after them: g++ gets "-std=c++2b -Wall -std=c++20"
        "stds/src/inherited.cpp": "c++20", "stds/src/late.cpp": "c++20",
        # the newest of the two branches, 23, written before the options' c++20 by
        # CMake 3.28 (no distribution: the newest CMake's order)
        "stds/src/branches.cpp": "c++20"}
    humble = scan([str(root / "src")], {"ROS_DISTRO": "humble"})
    # CMake 3.22 writes the standard's flag after the options: the newest branch's
    assert source_standards(humble.packages["stds"], humble)["stds/src/branches.cpp"] == (
        "c++23")
    # the flags set after the only target, at the end of the top-level file
    assert source_standards(ws.packages["other"], ws) == {"other/src/first.cpp": "c++20"}
