"""The CMake interpreter on inline programs: variables, scopes, commands, conditions, bounds."""

from __future__ import annotations

import pytest

from haros_arch.cmake import interpreter as interp
from haros_arch.cmake.interpreter import Interpreter
from haros_arch.cmake.lexer import tokenize


def run(text: str, folder: str = "/pkg", env: dict | None = None) -> Interpreter:
    it = Interpreter(folder, env or {})
    it.run_file(tokenize(text, f"{folder}/CMakeLists.txt"))
    return it


@pytest.mark.parametrize(("program", "name", "value"), [
    ("set(L a b c)\nlist(REVERSE L)", "L", "c;b;a"),
    ("set(L b a c)\nlist(SORT L)", "L", "a;b;c"),
    ("set(L a b c)\nlist(SUBLIST L 1 -1 OUT)", "OUT", "b;c"),
    ("set(L a b c)\nlist(FIND L c OUT)", "OUT", "2"),
    ("set(L a b c)\nlist(REMOVE_AT L 0 -1)", "L", "b"),
    ("set(L a b c)\nlist(POP_FRONT L OUT)", "OUT", "a"),
    ("set(L a b)\nlist(PREPEND L z)", "L", "z;a;b"),
    ("set(L a b)\nlist(JOIN L - OUT)", "OUT", "a-b"),
    ("set(L Ab cD)\nlist(TRANSFORM L TOLOWER)", "L", "ab;cd"),
    ("set(L x_node y_node)\nlist(TRANSFORM L REPLACE \"_node$\" \"\")", "L", "x;y"),
    ("set(L a.cpp b.h c.cpp)\nlist(FILTER L INCLUDE REGEX \"\\\\.cpp$\")", "L", "a.cpp;c.cpp"),
    ('string(REGEX MATCH "[0-9]+" OUT "v12.3")', "OUT", "12"),
    ('string(REGEX MATCHALL "[0-9]+" OUT "v12.3")', "OUT", "12;3"),
    ('string(REGEX REPLACE "(.*)_node" "\\\\1" OUT "talker_node")', "OUT", "talker"),
    ('string(SUBSTRING "talker" 0 4 OUT)', "OUT", "talk"),
    ('string(STRIP "  x  " OUT)', "OUT", "x"),
    ('string(FIND "a/b/c" "/" OUT REVERSE)', "OUT", "3"),
    ('string(LENGTH "four" OUT)', "OUT", "4"),
    ('string(MAKE_C_IDENTIFIER "my-node.1" OUT)', "OUT", "my_node_1"),
    ('string(JOIN "," OUT a b)', "OUT", "a,b"),
    ('set(OUT x)\nstring(APPEND OUT y z)', "OUT", "xyz"),
    ('string(GENEX_STRIP "a$<CONFIG:Debug>b" OUT)', "OUT", "ab"),
    ('math(EXPR OUT "(3 + 4) * 2 % 5")', "OUT", "4"),
    ('math(EXPR OUT "1 << 4" OUTPUT_FORMAT HEXADECIMAL)', "OUT", "0x10"),
    # C's integer rules: toward zero, and exact past a float's 53 bits
    ('math(EXPR OUT "-7 / 2")', "OUT", "-3"),
    ('math(EXPR OUT "-7 % 2")', "OUT", "-1"),
    ('math(EXPR OUT "9007199254740993 / 1")', "OUT", "9007199254740993"),
    ('math(EXPR OUT "9007199254740993 % 10")', "OUT", "3"),
    ("get_filename_component(OUT src/nodes/talker.cpp NAME_WE)", "OUT", "talker"),
    ("get_filename_component(OUT src/nodes/talker.cpp DIRECTORY)", "OUT", "src/nodes"),
    ('set(X "a;b")\nset(Y ${X} c)', "Y", "a;b;c"),
    ('set(ENV_VALUE $ENV{ROBOT})', "ENV_VALUE", "r2"),
    ('set(A B)\nset(B value)\nset(OUT ${${A}})', "OUT", "value"),
    ("cmake_parse_arguments(P \"FAST\" \"NAME\" \"FILES\" extra FAST NAME x FILES a b)",
     "P_FILES", "a;b"),
    ("cmake_parse_arguments(P \"FAST\" \"NAME\" \"FILES\" extra FAST NAME x FILES a b)",
     "P_UNPARSED_ARGUMENTS", "extra"),
    ("cmake_parse_arguments(P \"FAST\" \"NAME\" \"FILES\" NAME x)", "P_FAST", "FALSE"),
    ("set(V 1 CACHE STRING \"doc\")\nset(V 2 CACHE STRING \"doc\")", "V", "1"),
    ("set(V 1 CACHE STRING \"doc\")\nset(V 2 CACHE STRING \"doc\" FORCE)", "V", "2"),
    ("option(FLAG \"doc\" ON)\nset(FLAG OFF)", "FLAG", "OFF"),
])
def test_commands_compute_values(program, name, value):
    assert run(program, env={"ROBOT": "r2"}).get(name) == value


def test_machine_dependent_values_stay_unknown():
    it = run('string(TIMESTAMP NOW)\nmath(EXPR BAD "__import__(\'os\')")\n'
             'file(READ /etc/hostname HOST)')
    assert it.get("NOW") is None and it.get("BAD") is None and it.get("HOST") is None


def test_function_scope_parent_scope_and_macro_arguments():
    it = run("""
        function(f out)
          set(inner 1)
          set(${out} "${ARGC}:${ARGV1}:${ARGN}" PARENT_SCOPE)
          unset(outer PARENT_SCOPE)
        endfunction()
        macro(m first)
          set(from_macro "${first}|${ARGN}|${ARGV0}")
        endmacro()
        set(outer yes)
        f(RESULT x y)
        m(a b c)
        """)
    assert it.get("RESULT") == "3:x:x;y"
    assert it.get("inner") is None and it.get("outer") is None
    assert it.get("from_macro") == "a|b;c|a"


@pytest.mark.parametrize(("condition", "expected"), [
    ("1 AND NOT 0", True),
    ("(ON OR OFF) AND NOT (YES AND NO)", True),
    ("KNOWN STREQUAL value", True),
    ('"${KNOWN}" MATCHES "^val"', True),
    ("10 LESS 9", False),
    ("2 EQUAL 2.0", True),
    ("1.10.2 VERSION_GREATER 1.9", True),
    ("1.2 VERSION_LESS_EQUAL 1.2.0", True),
    ("b IN_LIST LIST", True),
    ("z IN_LIST LIST", False),
    ("abc STRLESS abd", True),
    ("DEFINED KNOWN", True),
    ("DEFINED WAS_UNSET", False),
    ("DEFINED SOMETHING_ELSE", None),
    ("DEFINED ENV{HOME}", None),
    ("Foo_FOUND", None),
    ("Foo_FOUND OR 1", True),
    ("Foo_FOUND AND 0", False),
    ("NOT Foo_FOUND", None),
    ("Foo_VERSION VERSION_LESS 2", None),
    ("TARGET lib", True),
    ("COMMAND my_macro", True),
    ("IS_ABSOLUTE /x", True),
    ("EXISTS /pkg-outside/file", None),
])
def test_conditions_are_three_valued(condition, expected):
    it = run(f"""
        set(KNOWN value)
        set(LIST a b c)
        set(WAS_UNSET 1)
        unset(WAS_UNSET)
        macro(my_macro)
        endmacro()
        add_library(lib x.cpp)
        if({condition})
          set(RESULT yes)
        else()
          set(RESULT no)
        endif()
        """)
    outcome = {"yes": True, "no": False}
    if expected is None:
        # both branches ran, each under the condition
        assert it.get("RESULT") == "no"
        assert it.conditions == []
    else:
        assert outcome[it.get("RESULT") or ""] is expected


def test_exists_inside_the_package(tmp_path):
    (tmp_path / "extra.cmake").write_text("")
    it = run("if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/extra.cmake)\n set(R 1)\nendif()\n"
             "if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/none)\n set(S 1)\nendif()",
             folder=str(tmp_path))
    assert it.get("R") == "1" and it.get("S") is None


def test_unknown_condition_is_attached_to_targets_in_both_branches():
    it = run("""
        if(USE_GPU)
          add_executable(gpu a.cpp)
        elseif(ENABLE_CPU)
          add_executable(cpu a.cpp)
        else()
          add_executable(none a.cpp)
        endif()
        """)
    got = {n: [str(c) for c in t.conditions] for n, t in it.targets.items()}
    assert got == {"gpu": ["if (USE_GPU)"],
                   "cpu": ["else (USE_GPU)", "elseif (ENABLE_CPU)"],
                   "none": ["else (USE_GPU)", "else (ENABLE_CPU)"]}


def test_break_continue_and_zip_lists():
    it = run("""
        set(A a b c d)
        set(B 1 2)
        foreach(x y IN ZIP_LISTS A B)
          if(x STREQUAL "c")
            break()
          endif()
          list(APPEND OUT "${x}${y}")
        endforeach()
        foreach(n RANGE 3)
          if(n EQUAL 1)
            continue()
          endif()
          list(APPEND NUMS ${n})
        endforeach()
        """)
    assert it.get("OUT") == "a1;b2"
    assert it.get("NUMS") == "0;2;3"


def test_step_budget_is_reported_once(monkeypatch):
    monkeypatch.setattr(interp, "MAX_STEPS", 50)
    it = run("foreach(i RANGE 100)\n  set(x ${i})\nendforeach()\nadd_executable(late a.cpp)")
    assert [d.code for d in it.diagnostics] == ["CMAKE_LIMIT"]
    assert "late" not in it.targets


def test_user_macro_overrides_a_builtin_which_stays_reachable():
    it = run("""
        macro(add_executable name)
          _add_executable(${name}_wrapped ${ARGN})
        endmacro()
        add_executable(talker talker.cpp)
        """)
    assert list(it.targets) == ["talker_wrapped"]


ROS_VERSION_PROBE = """
    set(DISTROS humble iron)
    if(NOT DEFINED ROS_VERSION)
      foreach(distro IN LISTS DISTROS)
        if(EXISTS "/opt/ros/${distro}/setup.sh")
          set(ROS_VERSION 2)
          break()
        endif()
      endforeach()
    endif()
    if(NOT DEFINED ROS_VERSION AND DEFINED ENV{ROS_VERSION})
      set(ROS_VERSION $ENV{ROS_VERSION})
    endif()
    add_compile_options(-D__ROS_VERSION=${ROS_VERSION})
    if(ROS_VERSION EQUAL 0)
      add_compile_options(-DROSSIMU)
    endif()
    if(ROS_VERSION EQUAL 1)
      add_executable(ros1_node a.cpp)
    endif()
    if(ROS_VERSION EQUAL 2)
      add_executable(ros2_node a.cpp)
    endif()
    """


def test_a_variable_set_under_a_test_not_decided_holds_either_value():
    """sick_scan_xd's CMakeLists.txt sets ROS_VERSION 2 where /opt/ros/<distro>/setup.sh
    exists (outside the package: not decided), else from the environment: with ROS 1's
    environment, ROS_VERSION is 2 or 1, so both the ROS 1 and the ROS 2 target are built
    under their test, the -D flag's value is not known, and ``EQUAL 0`` is false on every
    path (its macro known absent)."""
    it = run(ROS_VERSION_PROBE, env={"ROS_VERSION": "1"})
    got = {n: [str(c) for c in t.conditions] for n, t in it.targets.items()}
    assert got == {"ros1_node": ["if (ROS_VERSION EQUAL 1)"],
                   "ros2_node": ["if (ROS_VERSION EQUAL 2)"]}
    assert set(it.either["ROS_VERSION"]) == {"1", "2"}
    [(definition)] = it.compile_options[-1]
    assert (definition.name, definition.known) == ("__ROS_VERSION", False)
    assert it.absent_definitions == {"ROSSIMU"}


def test_a_test_every_path_decides_alike_is_decided():
    """With ROS 2's environment every path gives ROS_VERSION 2 (the probe's, or the
    environment's where the probe found none): the ROS 2 target only, for certain."""
    it = run(ROS_VERSION_PROBE, env={"ROS_VERSION": "2"})
    assert {n: t.conditions for n, t in it.targets.items()} == {"ros2_node": ()}
    assert it.get("ROS_VERSION") == "2" and "ROS_VERSION" not in it.either
    [(definition)] = it.compile_options[-1]
    assert (definition.value, definition.known) == ("2", True)


def test_branches_not_decided_start_from_the_same_values():
    """An elseif's branch does not see what the if's branch set (they are exclusive), and
    a variable set in one branch only is, after the block, that value or the old one."""
    it = run("""
        set(MODE none)
        if(USE_GPU)
          set(MODE gpu)
          set(ONLY_GPU 1)
        elseif(MODE STREQUAL "gpu")
          add_executable(never a.cpp)
        else()
          set(MODE cpu)
        endif()
        if(MODE STREQUAL "none")
          add_executable(never_either a.cpp)
        endif()
        """)
    assert "never" not in it.targets and "never_either" not in it.targets
    assert set(it.either["MODE"]) == {"gpu", "cpu"}
    assert set(it.either["ONLY_GPU"]) == {"1", None}
    assert it.get("MODE") == "cpu"  # the value the reading goes on with: the last path's


def test_a_target_made_in_a_branch_and_in_its_else_is_made_for_certain():
    """sick_scan_xd makes sick_generic_caller in ``if(ROS_VERSION EQUAL 1)`` and again in
    its ``else()``: with ROS_VERSION either 1 or 2, it is made on both paths, under no
    condition (it was under the else's); one made in a branch and an unrelated test's
    keeps the later's."""
    it = run(ROS_VERSION_PROBE + """
        if(ROS_VERSION EQUAL 1)
          add_executable(caller one.cpp)
        else()
          add_executable(caller two.cpp)
        endif()
        if(USE_A)
          add_executable(other a.cpp)
        endif()
        if(USE_B)
          add_executable(other b.cpp)
        endif()
        """, env={"ROS_VERSION": "1"})
    assert it.targets["caller"].conditions == ()
    assert [str(c) for c in it.targets["other"].conditions] == ["if (USE_B)"]


DUAL = """
    find_package(catkin QUIET)
    if(catkin_FOUND)
      add_executable(ros1_node a.cpp)
    else()
      find_package(ament_cmake QUIET)
      if(ament_cmake_FOUND)
        add_executable(ros2_node a.cpp)
      endif()
    endif()
    """


@pytest.mark.parametrize(("env", "expected"), [
    ({"ROS_VERSION": "1"}, {"ros1_node": []}),
    ({"ROS_VERSION": "2"}, {"ros2_node": []}),
    ({}, {"ros1_node": ["if (catkin_FOUND)"],
          "ros2_node": ["else (catkin_FOUND)", "if (ament_cmake_FOUND)"]}),
])
def test_the_distribution_decides_which_build_tool_is_found(env, expected):
    """A package built for ROS 1 and ROS 2 that picks its code with ``find_package(catkin
    QUIET)`` and ``if(catkin_FOUND)``: a project's ``distro:`` (its ROS_VERSION) says
    which is found; with none known both branches stay, each under its test."""
    it = run(DUAL, env=env)
    assert {n: [str(c) for c in t.conditions] for n, t in it.targets.items()} == expected


def test_a_target_takes_the_sources_of_every_path():
    """Autoware's shape estimation adds its TensorRT source ``if(${CUDA_FOUND} AND ...)``
    and not in the ``else()``: the library's sources are those of both paths (after the
    else, the reading's own value left it out); a variable set to one list or another
    gives both lists."""
    it = run("""
        project(shape)
        set(${PROJECT_NAME}_SOURCES a.cpp)
        if(${CUDA_FOUND})
          list(APPEND ${PROJECT_NAME}_SOURCES gpu.cpp)
          set(EXTRA cuda.cpp)
        else()
          message("no CUDA")
          set(EXTRA cpu.cpp)
        endif()
        add_library(lib ${${PROJECT_NAME}_SOURCES})
        add_executable(node ${EXTRA})
        target_sources(node PRIVATE ${shape_SOURCES})
        """)
    assert [s.rsplit("/", 1)[1] for s in it.targets["lib"].sources] == ["a.cpp", "gpu.cpp"]
    assert [s.rsplit("/", 1)[1] for s in it.targets["node"].sources] == [
        "cpu.cpp", "cuda.cpp", "a.cpp", "gpu.cpp"]


CLIENT_LIBRARIES = """
    find_package(roscpp QUIET)
    if(roscpp_FOUND)
      add_definitions(-DROS_FOUND)
    endif()
    find_package(rclcpp QUIET)
    if(rclcpp_FOUND)
      add_definitions(-DROS2_FOUND)
    endif()
    add_executable(driver a.cpp)
    """


@pytest.mark.parametrize(("env", "expected"), [
    ({"ROS_VERSION": "1"}, {"ROS_FOUND": []}),
    ({"ROS_VERSION": "2"}, {"ROS2_FOUND": []}),
    ({}, {"ROS_FOUND": ["if (roscpp_FOUND)"], "ROS2_FOUND": ["if (rclcpp_FOUND)"]}),
])
def test_the_distribution_decides_which_client_library_is_found(env, expected):
    """Hesai's driver (HesaiLidar_ROS_2.0 e7e112f0) defines ROS2_FOUND under
    ``find_package(rclcpp QUIET)`` and ``if(rclcpp_FOUND)``, and picks its ROS 2 code
    with ``#elif ROS2_FOUND``: a project's ``distro:`` says which ROS's C++ client
    library is found (roscpp is in no ROS 2 distribution, rclcpp in no ROS 1 one); with
    none known both definitions stay under their tests."""
    it = run(CLIENT_LIBRARIES, env=env)
    defined = it.targets["driver"].directory_definitions
    assert {d.name: [str(c) for c in d.conditions] for d in defined} == expected
