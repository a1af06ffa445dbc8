"""An ``if()`` that reads, through a reference, what ``find_package`` of a package not
read here sets (``"${mongodb_store_VERSION}" VERSION_GREATER "0.5.1"``: jsk_robot_startup's
test around its lightweight_logger nodelet) is not decided: the value is not known, not
the empty text of an unset variable, which decided it false and left the nodelet out."""

from __future__ import annotations

from haros_arch.cmake.interpreter import Interpreter
from haros_arch.cmake.lexer import tokenize


def run(text: str) -> Interpreter:
    it = Interpreter("/pkg", {})
    it.run_file(tokenize(text, "/pkg/CMakeLists.txt"))
    return it


def conditions(it: Interpreter) -> dict[str, list[str]]:
    return {n: [str(c) for c in t.conditions] for n, t in it.targets.items()}


def test_a_version_find_package_sets_leaves_the_test_undecided():
    it = run("""
        find_package(catkin COMPONENTS mongodb_store)
        if (("${mongodb_store_VERSION}" VERSION_GREATER "0.4.3"
             AND "${mongodb_store_VERSION}" VERSION_LESS "0.5.0")
            OR "${mongodb_store_VERSION}" VERSION_GREATER "0.5.1")
          add_executable(logger a.cpp)
        endif()
        """)
    assert list(conditions(it)) == ["logger"]
    assert len(conditions(it)["logger"]) == 1
    assert "mongodb_store_VERSION" in conditions(it)["logger"][0]


def test_one_known_side_still_decides():
    it = run("""
        if ("${other_FOUND}" AND 0)
          add_executable(never a.cpp)
        endif()
        if ("${other_VERSION}" VERSION_GREATER 1 OR 1)
          add_executable(always a.cpp)
        endif()
        """)
    assert conditions(it) == {"always": []}


def test_a_version_the_package_sets_decides():
    it = run("""
        set(mine_VERSION 0.6.0)
        if ("${mine_VERSION}" VERSION_GREATER "0.5.1")
          add_executable(newer a.cpp)
        else()
          add_executable(older a.cpp)
        endif()
        """)
    assert conditions(it) == {"newer": []}


def test_an_unset_variable_of_another_kind_is_empty_as_before():
    it = run("""
        if ("${SOME_OPTION}" STREQUAL "")
          add_executable(plain a.cpp)
        endif()
        """)
    assert list(conditions(it)) == ["plain"]


def test_what_no_find_package_looks_for_is_empty():
    # MoveIt 2's planning_components_tools, an ament package: catkin is never found, so
    # catkin_LIBRARIES is empty and the bullet comparison tool is not built
    it = run("""
        find_package(ament_cmake REQUIRED)
        if("${catkin_LIBRARIES}" MATCHES "moveit_collision_detection_bullet")
          add_executable(compare a.cpp)
        endif()
        find_package(Bullet)
        if("${BULLET_VERSION}" VERSION_GREATER "2.8")
          add_executable(bullet_tool a.cpp)
        endif()
        """)
    assert list(conditions(it)) == ["bullet_tool"]
    assert conditions(it)["bullet_tool"] != []


def test_a_value_computed_from_an_unknown_version_leaves_its_test_undecided():
    """``string(REGEX MATCH "^[0-9]+" ROS2_MAJOR_VERSION "${rclcpp_VERSION}")`` of an
    rclcpp not read here is not known either: ``if(ROS2_MAJOR_VERSION GREATER_EQUAL 28)``
    was decided on the empty match, false, and only the older branch was built. A value
    computed from one (``list(GET ...)``) is not known in turn; a variable set again from
    what is known is known again."""
    it = run("""
        find_package(rclcpp REQUIRED)
        string(REGEX MATCH "^[0-9]+" ROS2_MAJOR_VERSION "${rclcpp_VERSION}")
        if(ROS2_MAJOR_VERSION GREATER_EQUAL 28)
          add_executable(jazzy a.cpp)
        else()
          add_executable(older a.cpp)
        endif()
        string(REGEX REPLACE "^([0-9]+)\\\\..*" "\\\\1" MAJOR "${rclcpp_VERSION}")
        string(REPLACE "." ";" PARTS "${rclcpp_VERSION}.0")
        list(GET PARTS 1 MINOR)
        if("${MAJOR}" LESS 16 OR MINOR GREATER 2)
          add_executable(either a.cpp)
        endif()
        set(MAJOR 30)
        if(MAJOR GREATER 20)
          add_executable(known a.cpp)
        endif()
        """)
    found = conditions(it)
    assert found["jazzy"] == ["if (ROS2_MAJOR_VERSION GREATER_EQUAL 28)"]
    assert found["older"] == ["else (ROS2_MAJOR_VERSION GREATER_EQUAL 28)"]
    assert len(found["either"]) == 1
    assert found["known"] == []


def test_a_text_test_of_what_catkin_found_is_undecided():
    """MoveIt 1's planning_components_tools: ``catkin_LIBRARIES`` holds the libraries
    of the components catkin found (moveit_core's bullet collision library when it was
    built); the reading knows only which packages they are, so the test is not decided
    and the comparison tool may be built (was decided false: its launch file's node
    "not in the workspace")."""
    it = run("""
        find_package(catkin REQUIRED COMPONENTS moveit_core roscpp)
        if("${catkin_LIBRARIES}" MATCHES "moveit_collision_detection_bullet")
          add_executable(compare a.cpp)
        endif()
        if(catkin_LIBRARIES)
          add_executable(linked a.cpp)
        endif()
        """)
    assert list(conditions(it)) == ["compare", "linked"]
    assert len(conditions(it)["compare"]) == 1 and conditions(it)["linked"] == []


def test_the_compiler_s_version_and_identity_are_not_known():
    """jsk_perception builds its DualFisheyeToPanorama nodelet only under a test of the
    compiler's version, OpenCV's and CMake's major version: the compiler's version read
    as empty decided it false, the nodelet's source was left out of the library, and the
    exported class had no code: 'complete' with no call, 13 false parameter-set-not-read
    warnings. CMake's major version is 3 in every ROS distribution."""
    it = run("""
        find_package(OpenCV REQUIRED)
        if("${CMAKE_CXX_COMPILER_VERSION}" VERSION_GREATER "7.0" AND
           "${OpenCV_VERSION}" VERSION_GREATER "2.9.9" AND
           "${CMAKE_MAJOR_VERSION}" VERSION_GREATER "2")
          add_executable(stitcher a.cpp)
        endif()
        if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
          add_executable(clang_only a.cpp)
        endif()
        if("${CMAKE_MAJOR_VERSION}" VERSION_LESS "3")
          add_executable(cmake2 a.cpp)
        endif()
        """)
    found = conditions(it)
    assert sorted(found) == ["clang_only", "stitcher"]
    assert "CMAKE_CXX_COMPILER_VERSION" in found["stitcher"][0]
    assert "CMAKE_CXX_COMPILER_ID" in found["clang_only"][0]
