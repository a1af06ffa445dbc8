"""The packages a catkin package's CMake files find as catkin's components
(``Interpreter.catkin_components``): the ROS packages its build uses, declared in its
package.xml or not."""

from __future__ import annotations

import pytest

from haros_arch.cmake.interpreter import Interpreter
from haros_arch.cmake.lexer import tokenize


@pytest.mark.parametrize("call", [
    "find_package(catkin REQUIRED COMPONENTS roscpp moveit_ros_planning_interface)",
    # vizzy_demos f151bb2: CMake's ``REQUIRED [[COMPONENTS] components...]``
    "find_package(catkin REQUIRED roscpp\n  moveit_ros_planning_interface)",
])
def test_the_packages_catkin_finds(call: str) -> None:
    it = Interpreter("/pkg", {})
    it.run_file(tokenize(f"project(p)\n{call}\nfind_package(Boost REQUIRED system)\n",
                         "/pkg/CMakeLists.txt"))
    assert it.catkin_components == ["roscpp", "moveit_ros_planning_interface"]
    assert "moveit_ros_planning_interface" in it.found_packages
