from __future__ import annotations

import os

import pytest
from conftest import package_xml

from haros_arch.cmake import parse_package, targets_of
from haros_arch.cmake.lexer import CMakeSyntaxError, tokenize
from haros_arch.workspace import scan


def test_lexer_argument_forms():
    commands = tokenize(r'''
# a comment
#[[ a bracket
comment ]]
set(A "quoted \"x\" ${B}" unquoted\ space [==[bracket ]] ${raw}]==])
message(STATUS "line \
continued")
if((A AND B) OR C)
''')
    names = [c.name for c in commands]
    assert names == ["set", "message", "if"]
    args = commands[0].args
    assert [a.kind for a in args] == ["unquoted", "quoted", "unquoted", "bracket"]
    assert args[1].text == 'quoted "x" ${B}'
    assert args[2].text == "unquoted space"
    assert args[3].text == "bracket ]] ${raw}"
    assert commands[1].args[1].text == "line continued"
    assert [a.text for a in commands[2].args] == ["(", "A", "AND", "B", ")", "OR", "C"]
    assert (commands[0].line, commands[0].column) == (5, 1)


@pytest.mark.parametrize(("text", "line"), [
    ('set(A "unterminated\n', 1),
    ("set(A B\n", 1),
    ("not a command\n", 1),
    ("set(A [[open\n", 1),
])
def test_lexer_errors_carry_line(text, line):
    with pytest.raises(CMakeSyntaxError) as caught:
        tokenize(text)
    assert caught.value.line == line


def workspace_with(write_tree, cmake: str, sources=("src/a.cpp", "src/b.cpp", "src/c.cpp")):
    files = {"src/pkg/package.xml": package_xml("pkg"), "src/pkg/CMakeLists.txt": cmake}
    files.update({f"src/pkg/{s}": "int main() {}\n" for s in sources})
    root = write_tree(files)
    ws = scan([str(root / "src")], {})
    return ws, ws.packages["pkg"]


def test_executables_through_variables_and_foreach(write_tree):
    ws, pkg = workspace_with(write_tree, """
        project(pkg)
        set(NODES a b)
        list(APPEND NODES c)
        foreach(n ${NODES})
          add_executable(${PROJECT_NAME}_${n} src/${n}.cpp)
        endforeach()
        add_library(helpers src/a.cpp)
        """)
    nodes, found = parse_package(pkg, ws)
    assert [n.executable for n in nodes] == ["pkg_a", "pkg_b", "pkg_c"]
    assert nodes[0].sources == ["pkg/src/a.cpp"]
    assert nodes[0].location.file == "pkg/CMakeLists.txt"
    assert nodes[0].location.line == 5
    assert found == []


def test_output_name_target_sources_and_missing_source(write_tree):
    ws, pkg = workspace_with(write_tree, """
        project(pkg)
        add_executable(node_impl src/a.cpp)
        target_sources(node_impl PRIVATE src/b.cpp)
        set_target_properties(node_impl PROPERTIES OUTPUT_NAME node)
        add_executable(ghost src/ghost.cpp)
        """)
    nodes, found = parse_package(pkg, ws)
    assert [(n.executable, n.sources) for n in nodes] == [
        ("node", ["pkg/src/a.cpp", "pkg/src/b.cpp"]), ("ghost", [])]
    assert [(d.code, d.location.line) for d in found] == [("CMAKE_SOURCE_MISSING", 5)]


def test_source_named_without_extension(write_tree):
    ws, pkg = workspace_with(write_tree, """
        project(pkg)
        add_executable(demo src/demo)
        add_executable(lost src/lost)
        add_executable(header src/a.cpp include/pkg/util.h)
        """, sources=("src/a.cpp", "src/demo.cc", "include/pkg/util.h"))
    nodes, found = parse_package(pkg, ws)
    assert [(n.executable, n.sources) for n in nodes] == [
        ("demo", ["pkg/src/demo.cc"]), ("lost", []), ("header", ["pkg/src/a.cpp"])]
    assert [(d.code, d.location.line) for d in found] == [("CMAKE_SOURCE_MISSING", 3)]


def test_unknown_condition_makes_targets_conditional(write_tree):
    ws, pkg = workspace_with(write_tree, """
        project(pkg)
        option(WITH_B "build b" OFF)
        if(FALSE)
          add_executable(never src/a.cpp)
        elseif(NOT DEFINED PROJECT_NAME)
          add_executable(never2 src/a.cpp)
        endif()
        if(SOME_FOUND)
          add_executable(maybe src/b.cpp)
        else()
          add_executable(otherwise src/c.cpp)
        endif()
        """)
    targets, _ = targets_of(pkg, ws)
    by_name = {t.name: t for t in targets}
    assert sorted(by_name) == ["maybe", "otherwise"]
    assert [(c.statement, c.text) for c in by_name["maybe"].conditions] == [
        ("if", "SOME_FOUND")]
    assert [(c.statement, c.text) for c in by_name["otherwise"].conditions] == [
        ("else", "SOME_FOUND")]


def test_syntax_error_keeps_commands_before_it(write_tree):
    ws, pkg = workspace_with(write_tree, """
        project(pkg)
        add_executable(first src/a.cpp)
        set(BROKEN "never closed)
        add_executable(second src/b.cpp)
        """)
    nodes, found = parse_package(pkg, ws)
    assert [n.executable for n in nodes] == ["first"]
    assert [(d.code, d.location.file, d.location.line) for d in found] == [
        ("CMAKE_SYNTAX", "pkg/CMakeLists.txt", 3)]


def test_byte_order_mark_before_the_first_command(write_tree):
    """cmake-language(7): a source file may begin with a UTF-8 byte-order mark."""
    ws, pkg = workspace_with(write_tree, """
        project(pkg)
        add_executable(first src/a.cpp)
        """)
    path = ws.packages["pkg"].root + "/CMakeLists.txt"
    with open(path, "rb") as handle:
        text = handle.read()
    with open(path, "wb") as handle:
        handle.write(b"\xef\xbb\xbf" + text)
    nodes, found = parse_package(pkg, ws)
    assert [n.executable for n in nodes] == ["first"]
    assert found == []


def test_rosbuild_package_executables(write_tree):
    root = write_tree({
        "src/old/manifest.xml": '<package><depend package="roscpp"/></package>',
        "src/old/CMakeLists.txt": """
            include($ENV{ROS_ROOT}/core/rosbuild/rosbuild.cmake)
            rosbuild_init()
            rosbuild_add_library(old_helpers src/helpers.cpp)
            rosbuild_add_executable(old_node src/node.cpp)
            target_link_libraries(old_node old_helpers)
            """,
        "src/old/src/node.cpp": "int helper();\nint main() { return helper(); }\n",
        "src/old/src/helpers.cpp": "int helper() { return 1; }\n",
    })
    ws = scan([str(root / "src")], {})
    nodes, _found = parse_package(ws.packages["old"], ws)
    assert [(n.executable, sorted(n.sources)) for n in nodes] == [
        ("old_node", ["old/src/helpers.cpp", "old/src/node.cpp"])]


def test_ament_auto_targets_link_the_package_s_auto_libraries(write_tree):
    """ament_cmake_auto: ``ament_auto_add_executable`` links every library made before it
    with ``ament_auto_add_library`` (``${PROJECT_NAME}_LIBRARIES``), unless
    ``NO_TARGET_LINK_LIBRARIES``: image_pipeline's image_publisher_node runs the
    library's ImagePublisher, which its own source only constructs. An executable runs
    the linked sources its code needs, those that define what it names."""
    root = write_tree({
        "src/pub/package.xml": package_xml("pub", build_type="ament_cmake"),
        "src/pub/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.5)
            project(pub)
            find_package(ament_cmake_auto REQUIRED)
            ament_auto_find_build_dependencies()
            ament_auto_add_library(pub SHARED src/pub.cpp)
            ament_auto_add_library(monitor SHARED src/monitor.cpp)
            ament_auto_add_executable(pub_node src/pub_node.cpp)
            ament_auto_add_executable(alone src/alone.cpp NO_TARGET_LINK_LIBRARIES)
            ament_auto_add_executable(reader src/reader.cpp)
            ament_auto_add_executable(host src/host.cpp)
            ament_auto_package()
            """,
        "src/pub/src/pub.cpp": "#include \"pub.hpp\"\nvoid Pub::start() {}\n",
        "src/pub/src/monitor.cpp": "#include \"monitor.hpp\"\nvoid Monitor::check() {}\n",
        "src/pub/src/pub_node.cpp": "#include \"pub.hpp\"\n"
                                    "int main() { Pub pub; pub.start(); return 0; }\n",
        "src/pub/src/alone.cpp": "int main() { return 0; }\n",
        # links both libraries (all of the package's) and runs neither class: its code
        # names none (Autoware's hdd_reader, a daemon beside the monitor nodes)
        "src/pub/src/reader.cpp": "int main() { return 0; }\n",
        # loads plugins by name: their base classes' code is the plugins' to name
        "src/pub/src/host.cpp": "int main() { auto p = loader.createSharedInstance(\"x\"); }\n",
    })
    ws = scan([str(root / "src")], {})
    nodes, _found = parse_package(ws.packages["pub"], ws)
    assert sorted((n.executable, sorted(n.sources)) for n in nodes) == [
        ("alone", ["pub/src/alone.cpp"]),
        ("host", ["pub/src/host.cpp", "pub/src/monitor.cpp", "pub/src/pub.cpp"]),
        ("pub_node", ["pub/src/pub.cpp", "pub/src/pub_node.cpp"]),
        ("reader", ["pub/src/reader.cpp"])]


def test_an_executable_made_by_a_function_defined_outside_the_workspace(write_tree):
    """cartographer_ros builds every node with ``google_binary(NAME SRCS main.cc)``, a
    function of the cartographer package (``include(${CARTOGRAPHER_CMAKE_DIR}/
    functions.cmake)``, not in the workspace): the launch files' cartographer_node was
    "not in the workspace". A command nobody defines that names a new target and sources
    of the package, one of which defines main(), is that executable, linking the
    package's libraries (of which it runs what its code names). Without main() (a
    library), a test wrapper, or a known or workspace-defined command: nothing guessed."""
    root = write_tree({
        "src/carto/package.xml": package_xml("carto"),
        "src/carto/CMakeLists.txt": """
            project(carto)
            find_package(cartographer REQUIRED)
            include("${CARTOGRAPHER_CMAKE_DIR}/functions.cmake")
            add_library(${PROJECT_NAME} STATIC src/node.cc src/other.cc)
            google_binary(carto_node SRCS src/node_main.cc)
            google_library(helpers SRCS src/helpers.cc)
            google_test(node_test SRCS src/node_test.cc)
            ament_add_gmock(node_gmock src/node_test.cc)
            ament_add_google_benchmark(bench src/node_test.cc)
            google_binary(in_test_folder SRCS test/main.cc)
            macro(local_thing name)
            endmacro()
            local_thing(local src/local_main.cc)
            install(TARGETS carto_node RUNTIME DESTINATION bin)
            """,
        "src/carto/src/node.cc": "#include \"node.h\"\nvoid Node::Start() {}\n",
        "src/carto/src/other.cc": "#include \"other.h\"\nvoid Other::Run() {}\n",
        "src/carto/src/node_main.cc": "#include \"node.h\"\n"
                                      "int main(int argc, char** argv) { Node n; n.Start(); }\n",
        "src/carto/src/helpers.cc": "int helper() { return 1; }\n",
        "src/carto/src/node_test.cc": "int main() { return 0; }\n",
        "src/carto/src/local_main.cc": "int main() { return 0; }\n",
        "src/carto/test/main.cc": "int main() { return 0; }\n",
    })
    ws = scan([str(root / "src")], {})
    nodes, found = parse_package(ws.packages["carto"], ws)
    assert [(n.executable, sorted(n.sources)) for n in nodes] == [
        ("carto_node", ["carto/src/node.cc", "carto/src/node_main.cc"])]
    guessed = [d for d in found if d.code == "CMAKE_GUESSED_EXECUTABLE"]
    assert [(d.severity, d.location.line) for d in guessed] == [("info", 5)]
    assert "google_binary() is defined outside the workspace" in guessed[0].message


def test_an_outside_function_of_keyword_arguments_names_its_target_after_the_keyword(
        write_tree):
    """MOLA builds mola-cli with ``mola_add_executable(TARGET mola-cli SOURCES
    mola-cli.cpp ...)``, a function of its mola_common package (not in the workspace):
    the executable was taken to be named ``TARGET``, so the demos' launch files that
    run mola_launcher/mola-cli had it "not in the workspace" (an error). The name is the
    word after the keyword. Its ``mola_add_library(TARGET mola_launcher ...)``, whose
    sources define no main(), is a library: mola-cli links it (it runs its code)."""
    root = write_tree({
        "src/launcher/package.xml": package_xml("launcher"),
        "src/launcher/CMakeLists.txt": """
            project(launcher)
            find_package(mola_common REQUIRED)
            mola_add_library(TARGET ${PROJECT_NAME} SOURCES src/app.cpp)
            add_subdirectory(apps)
            install(TARGETS mola-cli RUNTIME DESTINATION lib/${PROJECT_NAME})
            """,
        "src/launcher/apps/CMakeLists.txt": """
            mola_add_executable(
              TARGET  mola-cli
              SOURCES mola-cli.cpp
              LINK_LIBRARIES mola::mola_launcher)
            """,
        "src/launcher/src/app.cpp": "#include \"launcher/app.h\"\nvoid App::run() {}\n",
        "src/launcher/include/launcher/app.h": "class App { public: void run(); };\n",
        "src/launcher/apps/mola-cli.cpp": "#include <launcher/app.h>\n"
                                          "int main(int argc, char** argv) { App().run(); }\n",
    })
    ws = scan([str(root / "src")], {})
    nodes, found = parse_package(ws.packages["launcher"], ws)
    # the library (no main(), a command named for libraries) is linked: its code runs
    assert [(n.executable, sorted(n.sources)) for n in nodes] == [
        ("mola-cli", ["launcher/apps/mola-cli.cpp", "launcher/src/app.cpp"])]
    guessed = [d.message for d in found if d.code.startswith("CMAKE_GUESSED_")]
    assert guessed == [
        "mola_add_library() is defined outside the workspace; launcher is taken as a "
        "library built from app.cpp",
        "mola_add_executable() is defined outside the workspace; mola-cli is taken as an "
        "executable built from mola-cli.cpp, one of which defines main()"]


def test_a_library_a_later_folder_adds_is_linked(write_tree):
    """CMake resolves the names target_link_libraries gives once every file is read:
    autorally_core adds src/gps, whose executable links SerialSensorInterface, before
    src/SerialSensorInterface, which adds that library. Its GPS node read none of the
    serial port's parameters."""
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg"),
        "src/pkg/CMakeLists.txt": """
            project(pkg)
            add_subdirectory(src/gps)
            add_subdirectory(src/serial)
            """,
        "src/pkg/src/gps/CMakeLists.txt": """
            add_executable(gps gps.cpp)
            target_link_libraries(gps ${catkin_LIBRARIES} Serial pthread)
            """,
        "src/pkg/src/serial/CMakeLists.txt": "add_library(Serial serial.cpp)\n",
        "src/pkg/src/gps/gps.cpp": "void open_port();\nint main() { open_port(); }\n",
        "src/pkg/src/serial/serial.cpp": "void open_port() {}\n",
    })
    ws = scan([str(root / "src")], {})
    nodes, _found = parse_package(ws.packages["pkg"], ws)
    assert [(n.executable, sorted(n.sources)) for n in nodes] == [
        ("gps", ["pkg/src/gps/gps.cpp", "pkg/src/serial/serial.cpp"])]


def test_a_class_the_executable_defines_itself_names_no_library_file(write_tree):
    """cartographer_ros' occupancy_grid_node_main.cc defines its own ``class Node`` and
    links the package library, whose node.cc defines the SLAM ``Node``'s members: the
    word ``Node`` gave the occupancy grid node the SLAM node's publishers (6 false
    multiple-publishers). A class the executable's own source defines is its own; a
    library class it only uses still brings its file."""
    root = write_tree({
        "src/carto/package.xml": package_xml("carto"),
        "src/carto/CMakeLists.txt": """
            project(carto)
            add_library(carto STATIC src/node.cc src/submap.cc)
            add_executable(grid src/grid_main.cc)
            target_link_libraries(grid carto)
            add_executable(slam src/slam_main.cc)
            target_link_libraries(slam carto)
            """,
        "src/carto/src/node.cc": "#include \"node.h\"\nNode::Node() { Publish(); }\n",
        "src/carto/src/submap.cc": "#include \"submap.h\"\nvoid Submap::Fetch() {}\n",
        "src/carto/src/grid_main.cc": """
            #include "submap.h"
            namespace {
            class Node {
             public:
              Node();
            };
            Node::Node() { Submap s; s.Fetch(); }
            }
            int main() { Node node; }
            """,
        "src/carto/src/slam_main.cc": "#include \"node.h\"\nint main() { Node node; }\n",
    })
    ws = scan([str(root / "src")], {})
    nodes, _found = parse_package(ws.packages["carto"], ws)
    assert sorted((n.executable, sorted(n.sources)) for n in nodes) == [
        ("grid", ["carto/src/grid_main.cc", "carto/src/submap.cc"]),
        ("slam", ["carto/src/node.cc", "carto/src/slam_main.cc"])]


def test_a_member_initialiser_from_the_first_column_defines_no_member(write_tree):
    """slam_toolbox's merge_maps_kinematic links toolbox_common and uses only its
    laser_utils; slam_toolbox_common.cpp writes its constructor's initialiser from the
    first column, ``: rclcpp_lifecycle::LifecycleNode("slam_toolbox", "", options),``,
    which was read as a definition of a member of ``rclcpp_lifecycle``, a word the
    executable names: the whole SLAM node's interface, and its node name (a false
    duplicate-node-names), went to the merge node. A ``::ns::T C::f(`` line still
    defines ``C::f``."""
    root = write_tree({
        "src/slam/package.xml": package_xml("slam", build_type="ament_cmake"),
        "src/slam/CMakeLists.txt": """
            project(slam)
            add_library(common src/toolbox.cpp src/laser.cpp src/global.cpp)
            add_executable(merge src/merge.cpp)
            target_link_libraries(merge common)
            add_executable(stamp src/stamp.cpp)
            target_link_libraries(stamp common)
            """,
        "src/slam/src/toolbox.cpp": "#include \"toolbox.hpp\"\n"
                                    "Toolbox::Toolbox(rclcpp::NodeOptions options)\n"
                                    ": rclcpp_lifecycle::LifecycleNode(\"slam\", \"\", options),\n"
                                    "  scans_(0)\n{}\n",
        "src/slam/src/laser.cpp": "#include \"laser.hpp\"\nLaser::Laser() {}\n",
        "src/slam/src/global.cpp": "::std::string Clock::stamp() { return \"\"; }\n",
        "src/slam/src/merge.cpp": "#include \"laser.hpp\"\n"
                                  "#include <rclcpp_lifecycle/lifecycle_node.hpp>\n"
                                  "void on(const rclcpp_lifecycle::State &) {}\n"
                                  "int main() { Laser laser; }\n",
        "src/slam/src/stamp.cpp": "int main() { Clock c; c.stamp(); }\n",
    })
    ws = scan([str(root / "src")], {})
    nodes, _found = parse_package(ws.packages["slam"], ws)
    assert sorted((n.executable, sorted(n.sources)) for n in nodes) == [
        ("merge", ["slam/src/laser.cpp", "slam/src/merge.cpp"]),
        ("stamp", ["slam/src/global.cpp", "slam/src/stamp.cpp"])]


@pytest.mark.parametrize(("install", "scripts"), [
    ("ament_python_install_package(pkg SCRIPTS_DESTINATION lib/pkg)", ["spawner"]),
    ("ament_python_install_package(pkg)", []),  # the module only, no executable
])
def test_setup_cfg_entry_points_that_ament_python_install_package_installs(
        write_tree, install, scripts):
    # ros2_control's controller_manager (CMakeLists.txt:323-325, setup.cfg): `ros2 run
    # controller_manager spawner` runs controller_manager/spawner.py's main
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg", "ament_cmake"),
        "src/pkg/CMakeLists.txt": f"""
            project(pkg)
            find_package(ament_cmake_python REQUIRED)
            add_executable(node src/a.cpp)
            {install}
            """,
        "src/pkg/src/a.cpp": "int main() {}\n",
        "src/pkg/setup.cfg": "[options.entry_points]\nconsole_scripts =\n"
                             "    spawner = pkg.spawner:main\n",
        "src/pkg/pkg/__init__.py": "",
        "src/pkg/pkg/spawner.py": "def main():\n    pass\n",
    })
    ws = scan([str(root / "src")], {})
    nodes, found = parse_package(ws.packages["pkg"], ws)
    assert [(n.executable, n.kind) for n in nodes] == [
        ("node", "executable"), *((s, "script") for s in scripts)]
    assert [n.sources for n in nodes if n.kind == "script"] == [
        ["pkg/pkg/spawner.py"] for _ in scripts]
    assert found == []


def test_an_external_project_that_builds_executables_is_said(write_tree):
    """micro-ROS-demos' rclc package builds each demo with ExternalProject_Add(SOURCE_DIR
    <demo folder>) from a function and installs what they built: the package had no
    node and no diagnostic, as if it built nothing. An external project of the package
    whose CMakeLists.txt builds an executable is CMAKE_EXTERNAL_PROJECT (warning); one
    that builds only a library, or a folder outside the package, is not."""
    root = write_tree({
        "src/demos/package.xml": package_xml("demos", "ament_cmake"),
        "src/demos/CMakeLists.txt": """\
            cmake_minimum_required(VERSION 3.5)
            project(demos)
            include(ExternalProject)
            function(export_demo leaf)
                ExternalProject_Add(${leaf}
                    PREFIX ${PROJECT_BINARY_DIR}/${leaf}
                    SOURCE_DIR ${PROJECT_SOURCE_DIR}/${leaf}
                    BUILD_ALWAYS 1)
            endfunction()
            export_demo(talker)
            export_demo(vendored)
            ExternalProject_Add(outside SOURCE_DIR ${PROJECT_SOURCE_DIR}/../elsewhere)
            ament_package()
            """,
        "src/demos/talker/CMakeLists.txt": "project(talker C)\n"
                                          "add_executable(${PROJECT_NAME} main.c)\n",
        "src/demos/talker/main.c": "int main() { return 0; }\n",
        "src/demos/vendored/CMakeLists.txt": "add_library(v STATIC v.c)\n",
        "src/elsewhere/CMakeLists.txt": "add_executable(e main.c)\n",
    })
    ws = scan([str(root / "src")], {})
    nodes, found = parse_package(ws.packages["demos"], ws)
    assert nodes == []
    said = [d for d in found if d.code == "CMAKE_EXTERNAL_PROJECT"]
    assert [(d.severity, d.location.line, d.message) for d in said] == [
        ("warning", 5, "ExternalProject_Add(talker) builds talker as a project of its own, "
         "whose executables are not read; the nodes it builds are unknown")]


def test_an_included_file_named_without_a_folder(write_tree):
    # include(<name>) with no folder and no .cmake suffix: a module of CMAKE_MODULE_PATH
    # when there is one, else the file of that name in the current source folder
    ws, pkg = workspace_with(write_tree, """
        project(pkg)
        set(CMAKE_MODULE_PATH ${CMAKE_CURRENT_SOURCE_DIR}/cmake)
        include(Helpers)
        include(CMakeLists_catkin.txt)
        return()
        add_executable(pkg_after_return src/c.cpp)
        """)
    root = pkg.root
    with open(f"{root}/CMakeLists_catkin.txt", "w", encoding="utf-8") as handle:
        handle.write("add_executable(pkg_node ${NODE_SOURCE})\n")
    os.makedirs(f"{root}/cmake")
    with open(f"{root}/cmake/Helpers.cmake", "w", encoding="utf-8") as handle:
        handle.write("set(NODE_SOURCE src/a.cpp)\n")
    nodes, _ = parse_package(pkg, ws)
    assert [(n.executable, n.sources) for n in nodes] == [("pkg_node", ["pkg/src/a.cpp"])]


def test_an_else_that_returns_after_a_test_not_decided(write_tree):
    """rotors_hil_interface builds its node only when Mavlink is found: ``if
    (Mavlink_DIR) message(...) else () catkin_package() return() endif ()``. The else's
    return() ended the reading, so the launch file's rotors_hil_interface_node was 'not
    in the workspace' (a launch-missing-reference error): it is built when the test
    holds."""
    ws, pkg = workspace_with(write_tree, """
        project(pkg)
        find_package(Mavlink QUIET)
        if (Mavlink_DIR)
          message(STATUS "building")
        else ()
          return()
        endif ()
        add_executable(pkg_node src/a.cpp)
        if (NOT Mavlink_DIR)
          return()
        elseif (WITH_B)
          add_executable(pkg_b src/b.cpp)
        else ()
          return()
        endif ()
        add_executable(pkg_c src/c.cpp)
        """)
    nodes, _ = parse_package(pkg, ws)
    assert [(n.executable, [(c.statement, c.text) for c in n.conditions])
            for n in nodes] == [
        ("pkg_node", [("if", "Mavlink_DIR")]),
        ("pkg_b", [("if", "Mavlink_DIR"), ("else", "NOT Mavlink_DIR"), ("elseif", "WITH_B")]),
        ("pkg_c", [("if", "Mavlink_DIR"), ("if", "NOT (NOT Mavlink_DIR)"),
                   ("if", "(NOT Mavlink_DIR) OR (WITH_B)")])]


def test_a_superbuild_of_the_package_itself_reads_its_second_configuration(write_tree):
    """panther_ros' panther_diagnostics: an option chooses a superbuild, which builds a
    dependency and then the package's own folder as an external project with
    -DUSE_SUPERBUILD=OFF, and returns; the first reading stopped there and the package
    had no executable (its launch file's node 'not in the workspace'). The targets are
    those of the configuration the external project gives; a cache entry it does not
    give keeps its option's default, and an external project of the package's folder
    with no cache entry is read no second time."""
    root = write_tree({
        "src/diag/package.xml": package_xml("diag", "ament_cmake"),
        "src/diag/CMakeLists.txt": """\
            cmake_minimum_required(VERSION 3.8)
            option(USE_SUPERBUILD "superbuild" ON)
            option(WITH_EXTRA "extra" OFF)
            if(USE_SUPERBUILD)
              project(SUPERBUILD NONE)
              include(cmake/SuperBuild.cmake)
              return()
            else()
              project(diag)
            endif()
            add_executable(monitor src/main.cpp)
            if(WITH_EXTRA)
              add_executable(extra src/main.cpp)
            endif()
            install(TARGETS monitor DESTINATION lib/${PROJECT_NAME})
            """,
        "src/diag/cmake/SuperBuild.cmake": """\
            include(ExternalProject)
            ExternalProject_Add(ep_dep GIT_REPOSITORY https://example.org/dep.git)
            ExternalProject_Add(ep_diag
              DEPENDS ep_dep
              SOURCE_DIR ${PROJECT_SOURCE_DIR}
              CMAKE_ARGS -DUSE_SUPERBUILD:BOOL=OFF
              INSTALL_COMMAND "")
            """,
        "src/diag/src/main.cpp": "int main() { return 0; }\n",
        "src/plain/package.xml": package_xml("plain", "ament_cmake"),
        "src/plain/CMakeLists.txt": """\
            project(plain)
            include(ExternalProject)
            ExternalProject_Add(again SOURCE_DIR ${PROJECT_SOURCE_DIR})
            return()
            add_executable(never main.cpp)
            """,
        "src/plain/main.cpp": "int main() { return 0; }\n",
    })
    ws = scan([str(root / "src")], {})
    nodes, found = parse_package(ws.packages["diag"], ws)
    assert [(n.executable, n.kind) for n in nodes] == [("monitor", "executable")]
    said = [d for d in found if d.code == "CMAKE_SUPERBUILD"]
    assert [(d.severity, d.location.file, d.location.line, d.message) for d in said] == [
        ("info", "diag/cmake/SuperBuild.cmake", 3,
         "ExternalProject_Add(ep_diag) configures the package's own folder again with "
         "-DUSE_SUPERBUILD=OFF; its targets are read from that configuration")]
    nodes, found = parse_package(ws.packages["plain"], ws)
    assert nodes == []
    assert [d.code for d in found if d.code.startswith("CMAKE_")] == ["CMAKE_EXTERNAL_PROJECT"]


def test_words_in_comments_and_strings_name_no_library_file(write_tree):
    """laser_filters' scan_to_cloud_filter_chain links the package's filter library and
    runs none of its filters, but a comment of its source says ``@b ScanShadowsFilter is
    a simple node...``: that word gave it every filter's calls (69). A word of a comment
    or of a string literal names nothing the code uses; one of code still does."""
    root = write_tree({
        "src/lf/package.xml": package_xml("lf", build_type="ament_cmake"),
        "src/lf/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.5)
            project(lf)
            find_package(ament_cmake_auto REQUIRED)
            ament_auto_find_build_dependencies()
            ament_auto_add_library(filters SHARED src/filters.cpp src/monitor.cpp
                                   src/projector.cpp)
            ament_auto_add_executable(chain src/chain.cpp)
            ament_auto_package()
            """,
        "src/lf/src/filters.cpp": """
            #include "filters.hpp"
            bool ShadowsFilter::update() { return true; }
            bool RangeFilter::update() { return true; }
            PLUGINLIB_EXPORT_CLASS(lf::ShadowsFilter, filters::FilterBase)
            PLUGINLIB_EXPORT_CLASS(lf::RangeFilter, filters::FilterBase)
            """,
        "src/lf/src/monitor.cpp": "#include \"monitor.hpp\"\nvoid Monitor::check() {}\n",
        "src/lf/src/projector.cpp": "#include \"projector.hpp\"\nvoid Projector::run() {}\n",
        "src/lf/src/chain.cpp": """
            #include "projector.hpp"
            /** @b ShadowsFilter is a simple node that filters shadow points
             * (a Monitor watches it) */
            int main() {
              // RangeFilter next
              const char * said = "RangeFilter and Monitor";
              Projector p;  // not a Monitor
              p.run();
            }
            """,
    })
    ws = scan([str(root / "src")], {})
    nodes, _found = parse_package(ws.packages["lf"], ws)
    assert [(n.executable, sorted(n.sources)) for n in nodes
            if n.kind == "executable"] == [("chain", ["lf/src/chain.cpp",
                                                      "lf/src/projector.cpp"])]


def test_a_component_registered_in_a_branch_and_in_its_else_is_made_for_certain(
        write_tree):
    """Autoware's traffic light classifier registers its component under
    ``if(TRT_AVAIL AND CUDA_AVAIL AND CUDNN_AVAIL)`` (one library) and again in the
    ``else()`` (another): the node is made on both paths, under no condition (the first
    registration's condition stayed)."""
    ws, pkg = workspace_with(write_tree, """
        project(pkg)
        find_package(rclcpp_components REQUIRED)
        if(GPU_FOUND)
          set(GPU ON)
        else()
          set(GPU OFF)
        endif()
        if(GPU)
          add_library(gpu_lib SHARED src/b.cpp)
          rclcpp_components_register_node(gpu_lib PLUGIN "pkg::Classifier"
            EXECUTABLE classifier_node)
        else()
          add_library(cpu_lib SHARED src/c.cpp)
          rclcpp_components_register_node(cpu_lib PLUGIN "pkg::Classifier"
            EXECUTABLE classifier_node)
        endif()
        """)
    nodes, _ = parse_package(pkg, ws)
    assert {n.executable: [str(c) for c in n.conditions] for n in nodes} == {
        "classifier_node": [], "pkg::Classifier": []}


def test_a_quoted_list_of_sources_is_each_of_its_files(write_tree):
    # PX4-Avoidance: add_library(avoidance "${AVOIDANCE_CPP_FILES}"), a list variable in
    # quotes, one argument that CMake's SOURCES property reads as its items
    ws, pkg = workspace_with(write_tree, """
        project(pkg)
        set(LIB_FILES "src/b.cpp" "src/c.cpp")
        add_library(lib "${LIB_FILES}")
        add_executable(node src/a.cpp)
        target_sources(node PRIVATE "src/d.cpp;src/e.cpp")
        """, sources=("src/a.cpp", "src/b.cpp", "src/c.cpp", "src/d.cpp", "src/e.cpp"))
    targets, _ = targets_of(pkg, ws)
    assert {t.name: [os.path.basename(s) for s in t.sources] for t in targets} == {
        "lib": ["b.cpp", "c.cpp"], "node": ["a.cpp", "d.cpp", "e.cpp"]}
    nodes, found = parse_package(pkg, ws)
    assert [(n.executable, n.sources) for n in nodes] == [
        ("node", ["pkg/src/a.cpp", "pkg/src/d.cpp", "pkg/src/e.cpp"])]
    assert found == []


def test_a_library_file_with_another_program_s_main_is_not_run_by_its_main(write_tree):
    """PX4-Avoidance's safe_landing_planner library holds waypoint_generator_node.cpp,
    the waypoint generator's class and its program's ``main``; safe_landing_planner_node
    links the library and runs only its own class. The word ``main`` of its own file
    named that file: the node had the waypoint generator's 9 topics and parameters."""
    root = write_tree({
        "src/slp/package.xml": package_xml("slp"),
        "src/slp/CMakeLists.txt": """
            project(slp)
            add_library(slp src/planner.cpp src/generator_node.cpp)
            add_executable(planner_node src/planner_main.cpp)
            target_link_libraries(planner_node slp)
            add_executable(generator_node src/generator_node.cpp)
            target_link_libraries(generator_node slp)
            """,
        "src/slp/src/planner.cpp": "#include \"planner.h\"\nPlanner::Planner() {}\n",
        "src/slp/src/generator_node.cpp": """
            #include "generator.h"
            Generator::Generator() {}
            int main(int argc, char ** argv) { Generator g; }
            """,
        "src/slp/src/planner_main.cpp": """
            #include "planner.h"
            int main(int argc, char ** argv) { Planner p; }
            """,
    })
    ws = scan([str(root / "src")], {})
    nodes, _found = parse_package(ws.packages["slp"], ws)
    assert sorted((n.executable, sorted(n.sources)) for n in nodes) == [
        ("generator_node", ["slp/src/generator_node.cpp"]),
        ("planner_node", ["slp/src/planner.cpp", "slp/src/planner_main.cpp"])]
