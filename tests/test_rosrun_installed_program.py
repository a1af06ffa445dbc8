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
