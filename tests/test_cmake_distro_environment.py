"""What a ROS distribution's setup script sets (ROS_DISTRO, ROS_VERSION,
ROS_PYTHON_VERSION) every build of a package has: when the run does not say it, a test
of it is not decided, and each branch's targets are built under their condition."""

from __future__ import annotations

import pytest

from haros_arch.cmake.interpreter import Interpreter
from haros_arch.cmake.lexer import tokenize

# aubo_robot 6709931, aubo_demo/CMakeLists.txt: each executable of the package under a
# test of the distribution's name
PER_DISTRO = """
if("$ENV{ROS_DISTRO}" STREQUAL "noetic")
  add_executable(demo_noetic src/noetic.cpp)
endif()
if($ENV{ROS_DISTRO} STREQUAL "melodic")
  add_executable(demo_melodic src/melodic.cpp)
endif()
set(ROS_VERSION $ENV{ROS_VERSION})
if(ROS_VERSION EQUAL 2)
  add_executable(demo_ros2 src/ros2.cpp)
else()
  add_executable(demo_ros1 src/ros1.cpp)
endif()
if("$ENV{HAROS_TEST_OTHER_SETTING}" STREQUAL "on")
  add_executable(other src/other.cpp)
endif()
"""


def run(env: dict[str, str]) -> Interpreter:
    it = Interpreter("/pkg", env)
    it.run_file(tokenize(PER_DISTRO, "/pkg/CMakeLists.txt"))
    return it


def test_the_distribution_not_said_decides_no_test() -> None:
    """Read as the empty text, no test held: aubo_demo had no program, and its four
    launch files each an error "no program found in its build files"."""
    got = {n: [str(c) for c in t.conditions] for n, t in run({}).targets.items()}
    assert got == {
        "demo_noetic": ['if ($ENV{ROS_DISTRO} STREQUAL noetic)'],
        "demo_melodic": ['if ($ENV{ROS_DISTRO} STREQUAL melodic)'],
        "demo_ros2": ["if (ROS_VERSION EQUAL 2)"],
        "demo_ros1": ["else (ROS_VERSION EQUAL 2)"]}  # any other setting: empty, as CMake


@pytest.mark.parametrize(("env", "built"), [
    ({"ROS_DISTRO": "noetic", "ROS_VERSION": "1"}, ["demo_noetic", "demo_ros1"]),
    ({"ROS_DISTRO": "humble", "ROS_VERSION": "2"}, ["demo_ros2"]),
])
def test_the_distribution_said_decides(env: dict[str, str], built: list[str]) -> None:
    it = run(env)
    assert sorted(it.targets) == sorted(built)
    assert all(not t.conditions for t in it.targets.values())

