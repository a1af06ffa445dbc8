"""An install(PROGRAMS) file absent from the sources: missing in a package that builds
nothing by custom commands; maybe made at build time in one that does (webots_ros2_driver
installs webots/webots-controller, which its add_custom_target's make builds)."""

from __future__ import annotations

from test_cmake import workspace_with

from haros_arch.cmake import parse_package


def test_without_custom_commands_it_is_missing(write_tree):
    ws, pkg = workspace_with(write_tree, """
        project(pkg)
        install(PROGRAMS tools/run_me DESTINATION lib/${PROJECT_NAME})
        """)
    _, found = parse_package(pkg, ws)
    assert [(d.code, d.severity) for d in found] == [("CMAKE_SOURCE_MISSING", "warning")]


def test_a_custom_target_may_build_it(write_tree):
    ws, pkg = workspace_with(write_tree, """
        project(pkg)
        add_custom_target(build-tools ALL
          COMMAND make release WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/tools/src)
        install(PROGRAMS tools/run_me DESTINATION lib/${PROJECT_NAME})
        """)
    _, found = parse_package(pkg, ws)
    assert [(d.code, d.severity, d.location.line) for d in found] == [
        ("CMAKE_PROGRAM_NOT_IN_SOURCES", "info", 4)]
    assert "add_custom_target" in found[0].message and "CMakeLists.txt:2" in found[0].message


def test_install_type_is_a_destination_and_a_build_folder_file_is_made_by_the_build(
        write_tree):
    # tucan_ros2's simulation/qgroundcontrol/CMakeLists.txt:9-19: file(DOWNLOAD) into the
    # build folder, then install(PROGRAMS ${CMAKE_BINARY_DIR}/... TYPE BIN): TYPE and
    # BIN were two programs "missing", the downloaded file a third
    ws, pkg = workspace_with(write_tree, """
        project(pkg)
        file(DOWNLOAD https://example.org/Tool.AppImage Tool.AppImage)
        install(PROGRAMS ${CMAKE_BINARY_DIR}/Tool.AppImage TYPE BIN)
        install(PROGRAMS tools/run_me TYPE BIN)
        """)
    _, found = parse_package(pkg, ws)
    assert [(d.code, d.severity, d.location.line) for d in found] == [
        ("CMAKE_PROGRAM_FROM_BUILD", "info", 3), ("CMAKE_SOURCE_MISSING", "warning", 4)]
    assert "${CMAKE_BINARY_DIR}/Tool.AppImage" in found[0].message
    assert "tools/run_me" in found[1].message
