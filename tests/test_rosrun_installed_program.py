"""A ROS 1 launch file runs a shell script whose source file has no execute bit, and
which its package's CMakeLists installs with ``install(PROGRAMS ... DESTINATION
${CATKIN_PACKAGE_BIN_DESTINATION})`` (osrf/subt 083c6a8's ``rostopic_stats_logger.sh``,
mode 644 in git, run by competition_init.launch in an install space): install gives the
copy its execute bit and roslaunch finds it in the package's lib folder, so the launch
runs it. It is a program this tool does not read (NODE_NOT_READ, a warning), not one
roslaunch refuses (NODE_NOT_EXECUTABLE, a launch-missing-reference error). A script the
build does not install stays refused."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue


def test_a_script_install_programs_installs_is_run_not_refused(write_tree) -> None:
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg"),
        "src/pkg/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.0.2)
            project(pkg)
            find_package(catkin REQUIRED)
            catkin_package()
            install(PROGRAMS scripts/logger.sh
              DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
            """,
        "src/pkg/scripts/logger.sh": "#!/bin/bash\nrostopic list\n",
        "src/pkg/scripts/notes.sh": "#!/bin/bash\n",
        "src/pkg/launch/s.launch": """
            <launch>
              <node name="logger" pkg="pkg" type="logger.sh" />
              <node name="notes" pkg="pkg" type="notes.sh" />
            </launch>
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [pkg/launch/s.launch]\n",
    })
    # (neither script has its execute bit)
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (config,) = model.configurations
    assert config.node("/logger").node is None
    assert [(d.code, d.location.line) for d in config.diagnostics] == [
        ("NODE_NOT_READ", 2), ("NODE_NOT_EXECUTABLE", 3)]
    findings = [(f.rule, f.location.line) for f in run_catalogue(model)
                if f.rule == "launch-missing-reference"]
    assert findings == [("launch-missing-reference", 3)]


def test_a_script_of_a_folder_installed_with_its_permissions_is_run(write_tree) -> None:
    """ateam_bringup (SSL-A-Team, Jazzy): ``install(DIRECTORY scripts/ DESTINATION
    lib/${PROJECT_NAME} USE_SOURCE_PERMISSIONS)`` installs its executable
    ``scream_if_wifi_enabled.sh``, which bringup_physical_core.launch.py starts as a
    Node; ros2 launch finds it in the lib folder. It was a launch-missing-reference
    error ("not in the workspace"); now NODE_NOT_READ. A file of the folder without its
    execute bit is no program there."""
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg", "ament_cmake"),
        "src/pkg/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.5)
            project(pkg)
            find_package(ament_cmake REQUIRED)
            install(DIRECTORY scripts/
              DESTINATION lib/${PROJECT_NAME}
              USE_SOURCE_PERMISSIONS)
            ament_package()
            """,
        "src/pkg/scripts/wifi_check.sh": "#!/bin/bash\nnmcli radio wifi\n",
        "src/pkg/scripts/notes.sh": "#!/bin/bash\n",
        "src/pkg/launch/s.launch.py": """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='pkg', executable='wifi_check.sh', name='wifi_checker'),
        Node(package='pkg', executable='notes.sh', name='notes'),
    ])
""",
        "project.yaml": "project: p\nconfigurations:\n  c: [pkg/launch/s.launch.py]\n",
    })
    (root / "src/pkg/scripts/wifi_check.sh").chmod(0o755)
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (config,) = model.configurations
    assert [(d.code, d.location.line) for d in config.diagnostics
            if d.code.startswith("NODE_")] == [("NODE_NOT_READ", 7), ("NODE_NOT_FOUND", 8)]
    findings = [(f.rule, f.location.line) for f in run_catalogue(model)
                if f.rule == "launch-missing-reference"]
    assert findings == [("launch-missing-reference", 8)]
