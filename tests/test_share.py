"""A package's share folder as ROS 2 sees it in the install space (haros_arch.share).

fixtures/share_ros2 holds three packages whose installed layout differs from their
source: ``arm_bringup`` installs ``bringup/config``, ``bringup/launch``,
``description/launch`` and ``description/urdf`` side by side into ``share/arm_bringup``
(as ros2_control_demos does); ``gripper_driver`` installs only the ``*.yaml`` of
``params/`` (not ``experimental/``) as ``config/`` and renames its launch file;
``rover_teleop`` (ament_python) installs ``params/joystick.yaml`` as
``config/joystick.yaml`` through ``data_files``.
"""

from __future__ import annotations

import os
from pathlib import Path

from conftest import FIXTURES, package_xml

from haros_arch import launch
from haros_arch.share import share_map, share_source
from haros_arch.workspace import Workspace, scan

ROOT = FIXTURES / "share_ros2" / "src"


def mapped(workspace: Workspace, name: str) -> dict[str, str]:
    """The package's share map with workspace-relative sources."""
    package = workspace.packages[name]
    return {k: workspace.relpath(v) for k, v in share_map(package, workspace).items()}


def fixture() -> Workspace:
    return scan([str(ROOT)], {})


# -- the map --------------------------------------------------------------------------
def test_cmake_folders_installed_side_by_side() -> None:
    assert mapped(fixture(), "arm_bringup") == {
        "config/arm_controllers.yaml": "arm_bringup/bringup/config/arm_controllers.yaml",
        "launch/arm.launch.py": "arm_bringup/bringup/launch/arm.launch.py",
        "launch/arm_state.launch.xml": "arm_bringup/bringup/launch/arm_state.launch.xml",
        "launch/view_arm.launch.py": "arm_bringup/description/launch/view_arm.launch.py",
        "urdf/arm.urdf": "arm_bringup/description/urdf/arm.urdf",
        "package.xml": "arm_bringup/package.xml",
    }


def test_cmake_files_matching_exclude_and_rename() -> None:
    assert mapped(fixture(), "gripper_driver") == {
        "config/gripper.yaml": "gripper_driver/params/gripper.yaml",
        "launch/driver.launch.xml": "gripper_driver/launch/gripper.launch.xml",
        "package.xml": "gripper_driver/package.xml",
    }


def test_ament_python_data_files() -> None:
    assert mapped(fixture(), "rover_teleop") == {
        "config/joystick.yaml": "rover_teleop/params/joystick.yaml",
        "launch/teleop.launch.py": "rover_teleop/launch/teleop.launch.py",
        "maps/yard/yard.yaml": "rover_teleop/maps/yard/yard.yaml",
        "package.xml": "rover_teleop/package.xml",
    }


def test_map_is_cached_per_package() -> None:
    ws = fixture()
    package = ws.packages["arm_bringup"]
    assert share_map(package, ws) is share_map(package, ws)
    assert set(ws.share_maps) == {"arm_bringup"}


def test_share_source_maps_installed_paths_and_keeps_the_rest() -> None:
    ws = fixture()
    arm = ws.packages["arm_bringup"].root
    assert share_source(ws, os.path.join(arm, "config", "arm_controllers.yaml")) == \
        os.path.join(arm, "bringup", "config", "arm_controllers.yaml")
    # a source path, not installed under that name: as it is
    source = os.path.join(arm, "bringup", "config", "arm_controllers.yaml")
    assert share_source(ws, source) == source
    assert share_source(ws, os.path.join(arm, "config", "nothing.yaml")) == \
        os.path.join(arm, "config", "nothing.yaml")
    assert share_source(ws, "/elsewhere/config/a.yaml") == "/elsewhere/config/a.yaml"
    assert share_source(ws, arm) == arm


def cmake_package(write_tree, cmake: str, files: dict[str, str]) -> Workspace:
    root = write_tree({"src/pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "src/pkg/CMakeLists.txt": cmake,
                       **{f"src/pkg/{k}": v for k, v in files.items()}})
    return scan([str(Path(root) / "src")], {})


def test_cmake_install_forms(write_tree) -> None:
    ws = cmake_package(write_tree, """
        cmake_minimum_required(VERSION 3.8)
        project(pkg)
        set(SHARE_DIR share/${PROJECT_NAME})
        install(DIRECTORY maps/ DESTINATION ${SHARE_DIR}/maps/)   # contents
        install(DIRECTORY rviz DESTINATION share/${PROJECT_NAME}/ USE_SOURCE_PERMISSIONS)
        install(DIRECTORY cfg DESTINATION share/${PROJECT_NAME}
                FILES_MATCHING REGEX "\\\\.(yaml|json)$")
        install(FILES extra/a.yaml extra/b.yaml DESTINATION share/${PROJECT_NAME}/x RENAME c.yaml)
        install(PROGRAMS tools/run.sh DESTINATION share/${PROJECT_NAME}/tools)
        install(DIRECTORY launch DESTINATION share/other_pkg)     # not this package's share
        install(DIRECTORY include/ DESTINATION include)
        install(FILES ../outside.yaml DESTINATION share/${PROJECT_NAME})
        add_subdirectory(sub)
        ament_package()
        """, {
        "maps/yard.yaml": "a: 1\n", "maps/deep/lot.yaml": "a: 2\n",
        "rviz/view.rviz": "x\n",
        "cfg/one.yaml": "a: 1\n", "cfg/two.json": "{}\n", "cfg/notes.txt": "x\n",
        "extra/a.yaml": "a: 1\n", "extra/b.yaml": "b: 1\n",
        "tools/run.sh": "#!/bin/sh\n",
        "launch/x.launch.py": "", "include/pkg/h.hpp": "",
        "sub/CMakeLists.txt": "install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})\n",
        "sub/launch/sub.launch.xml": "<launch/>\n",
        "../outside.yaml": "a: 1\n",
    })
    assert mapped(ws, "pkg") == {
        "maps/yard.yaml": "pkg/maps/yard.yaml",
        "maps/deep/lot.yaml": "pkg/maps/deep/lot.yaml",
        "rviz/view.rviz": "pkg/rviz/view.rviz",
        "cfg/one.yaml": "pkg/cfg/one.yaml", "cfg/two.json": "pkg/cfg/two.json",
        "x/a.yaml": "pkg/extra/a.yaml", "x/b.yaml": "pkg/extra/b.yaml",  # RENAME: one file only
        "tools/run.sh": "pkg/tools/run.sh",
        "launch/sub.launch.xml": "pkg/sub/launch/sub.launch.xml",
        "package.xml": "pkg/package.xml",
    }


def test_cmake_rename_one_file_and_later_rules_win(write_tree) -> None:
    ws = cmake_package(write_tree, """
        project(pkg)
        install(FILES params/real.yaml DESTINATION share/pkg/config RENAME robot.yaml)
        install(DIRECTORY defaults/ DESTINATION share/pkg/config)
        """, {"params/real.yaml": "a: 1\n", "defaults/robot.yaml": "a: 0\n"})
    assert mapped(ws, "pkg")["config/robot.yaml"] == "pkg/defaults/robot.yaml"


def test_ament_auto_package_install_to_share(write_tree) -> None:
    ws = cmake_package(write_tree, """
        project(pkg)
        find_package(ament_cmake_auto REQUIRED)
        ament_auto_find_build_dependencies()
        ament_auto_package(INSTALL_TO_SHARE launch config)
        """, {"launch/pkg.launch.xml": "<launch/>\n", "config/pkg.param.yaml": "a: 1\n"})
    assert mapped(ws, "pkg") == {"launch/pkg.launch.xml": "pkg/launch/pkg.launch.xml",
                                 "config/pkg.param.yaml": "pkg/config/pkg.param.yaml",
                                 "package.xml": "pkg/package.xml"}


def python_package(write_tree, setup: str, files: dict[str, str]) -> Workspace:
    root = write_tree({"src/pkg/package.xml": package_xml("pkg", "ament_python"),
                       "src/pkg/setup.py": setup,
                       **{f"src/pkg/{k}": v for k, v in files.items()}})
    return scan([str(Path(root) / "src")], {})


def test_setup_py_forms(write_tree) -> None:
    ws = python_package(write_tree, """
        import os
        import glob as g
        from os import path
        from setuptools import setup

        package_name = 'pkg'
        files = []
        files.append(('share/{}'.format(package_name), ['package.xml']))
        files.extend([(f'share/{package_name}/launch', g.glob('launch/*.launch.xml'))])
        setup(
            name=package_name,
            data_files=files + [
                ('share/%s/config' % package_name, sorted(g.glob('params/*.yaml'))),
                (path.join('share', package_name, 'rviz'), ['rviz/view.rviz']),
                ('share/' + package_name, ['../escape.yaml']),
                ('share/' + package_name + '/more', g.glob('../*.yaml')),
                ('lib/' + package_name, ['scripts/tool']),
                ('share/' + package_name + '/unknown', some_helper('x')),
                (os.path.join('share', package_name, 'worlds'),
                 [f for f in g.glob('worlds/*') if os.path.isfile(f)]),
            ],
        )
        """, {"launch/a.launch.xml": "<launch/>\n", "launch/notes.txt": "",
              "params/one.yaml": "a: 1\n", "params/two.yaml": "b: 1\n",
              "rviz/view.rviz": "x\n", "scripts/tool": "", "worlds/w.sdf": "",
              "worlds/models/m.sdf": "", "../escape.yaml": "a: 1\n"})
    assert mapped(ws, "pkg") == {
        "package.xml": "pkg/package.xml",
        "launch/a.launch.xml": "pkg/launch/a.launch.xml",
        "config/one.yaml": "pkg/params/one.yaml", "config/two.yaml": "pkg/params/two.yaml",
        "rviz/view.rviz": "pkg/rviz/view.rviz",
        "worlds/w.sdf": "pkg/worlds/w.sdf",
    }


def test_setup_py_that_cannot_be_read_gives_an_empty_map(write_tree) -> None:
    ws = python_package(write_tree, "setup(data_files=[('share/pkg', \n",
                        {"launch/a.launch.py": ""})
    assert mapped(ws, "pkg") == {}
    path = os.path.join(ws.packages["pkg"].root, "launch", "a.launch.py")
    assert share_source(ws, path) == path


# -- ROS 2 launch files find what is installed -------------------------------------------
def test_launch_finds_installed_launch_and_parameter_files() -> None:
    ws = fixture()
    model = launch.load(str(ROOT / "arm_bringup/bringup/launch/arm.launch.py"), ws, {})
    assert model.files == [
        "arm_bringup/bringup/launch/arm.launch.py",
        "arm_bringup/bringup/config/arm_controllers.yaml",
        "arm_bringup/description/launch/view_arm.launch.py",
        # $(dirname) of view_arm.launch.py is share/arm_bringup/launch, as installed
        "arm_bringup/bringup/launch/arm_state.launch.xml",
        "gripper_driver/launch/gripper.launch.xml",
        "gripper_driver/params/gripper.yaml",
    ]
    params = {p.name: p.value for p in model.params}
    assert params["/controller_manager/update_rate"] == 100
    assert params["/controller_manager/forward_position_controller.type"] == \
        "forward_command_controller/ForwardCommandController"
    assert params["/gripper/max_force"] == 12.5  # not experimental/gripper.yaml's 99.0
    assert params["/joint_state_publisher/rate"] == 30
    assert '<robot name="arm">' in str(params["/?/robot_description"])
    assert sorted(n.executable for n in model.nodes) == [
        "gripper_node", "joint_state_publisher", "robot_state_publisher", "ros2_control_node",
        "spawner"]
    codes = {d.code for d in model.diagnostics}
    assert not codes & {"LAUNCH_FILE_MISSING", "LAUNCH_PARAM_FILE", "LAUNCH_UNSUPPORTED"}


def test_launch_by_installed_name_and_data_files_parameters() -> None:
    ws = fixture()
    share = ws.find("rover_teleop")
    assert share is not None
    model = launch.load(os.path.join(share, "launch", "teleop.launch.py"), ws, {})
    params = {p.name: p.value for p in model.params}
    assert params["/teleop/scale"] == 0.4
    assert params["/teleop/map"] == os.path.join(share, "maps", "yard", "yard.yaml")
    assert "rover_teleop/params/joystick.yaml" in model.files
    # a launch file named by where it is installed runs from its source
    gripper = ws.find("gripper_driver")
    assert gripper is not None
    model = launch.load(os.path.join(gripper, "launch", "driver.launch.xml"), ws, {})
    assert model.files[0] == "gripper_driver/launch/gripper.launch.xml"
    assert {p.name: p.value for p in model.params}["/gripper/port"] == "/dev/ttyUSB0"


def test_file_not_installed_is_read_from_the_source(write_tree) -> None:
    ws = cmake_package(write_tree, """
        project(pkg)
        install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
        """, {"launch/a.launch.xml": """
        <launch>
          <node pkg="pkg" exec="talker" name="talker">
            <param from="$(find-pkg-share pkg)/config/talker.yaml"/>
          </node>
        </launch>
        """, "config/talker.yaml": "talker:\n  ros__parameters:\n    rate: 5\n"})
    model = launch.load(os.path.join(ws.packages["pkg"].root, "launch", "a.launch.xml"), ws)
    assert {p.name: p.value for p in model.params} == {"/talker/rate": 5}


def test_ros1_find_is_the_source_folder(write_tree) -> None:
    """roslaunch's $(find) is the package's source (devel space): install rules don't apply."""
    root = write_tree({
        "src/robot/package.xml": package_xml("robot"),
        "src/robot/CMakeLists.txt": """
            project(robot)
            find_package(catkin REQUIRED)
            catkin_package()
            install(DIRECTORY bringup/launch DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})
            """,
        "src/robot/bringup/launch/inner.launch": "<launch><node pkg='robot' type='a' "
                                                 "name='a'/></launch>\n",
        "src/robot/launch/outer.launch": "<launch><include file='$(find robot)/launch/"
                                         "inner.launch'/></launch>\n",
    })
    ws = scan([str(Path(root) / "src")], {})
    assert mapped(ws, "robot")["launch/inner.launch"] == "robot/bringup/launch/inner.launch"
    model = launch.load(str(Path(root) / "src/robot/launch/outer.launch"), ws, {})
    assert not model.nodes
    assert "LAUNCH_FILE_MISSING" in {d.code for d in model.diagnostics}


def test_project_names_launch_files_where_they_are_installed(tmp_path: Path) -> None:
    from haros_arch.pipeline import Options, analyse
    from haros_arch.project import load

    model = analyse(load(str(ROOT.parent / "project.yaml")), {},
                    Options(cache_dir=str(tmp_path / "cache"), jobs=1))
    arm, teleop = model.configurations
    # robot_state_publisher (no source here, unnamed in the launch file) is named by its
    # jazzy interface model, as its code names it; the spawner by its arguments, as its
    # code does: "spawner_" + its first controller (spawner.py:401, models.commands); the
    # controller it loads (a ros2_controllers class, no source here) is a node of its own
    assert sorted(n.name for n in arm.nodes if "?" not in n.name) == [
        "/controller_manager", "/gripper", "/joint_state_broadcaster",
        "/joint_state_publisher", "/robot_state_publisher",
        "/spawner_joint_state_broadcaster"]
    assert [n.name for n in arm.nodes if n.node is not None
            and n.node.name == "controller_manager/spawner"] == [
        "/spawner_joint_state_broadcaster"]
    # its interface from ros2_controllers' jazzy model
    broadcaster = arm.node("/joint_state_broadcaster").node
    assert broadcaster is not None and "joint_state_broadcaster" in (broadcaster.model or "")
    gripper = arm.node("/gripper")
    assert gripper is not None and gripper.node is not None  # built from gripper_driver
    force = next(p for p in arm.parameters if p.name == "/gripper/max_force")
    assert force.value == 12.5 and force.readers  # set from params/gripper.yaml, read in C++
    assert [n.name for n in teleop.nodes] == ["/teleop"]
    codes = {d.code for c in model.configurations for d in c.diagnostics} | {
        d.code for d in model.diagnostics}
    assert "LAUNCH_FILE_MISSING" not in codes


def test_links_out_of_the_package_are_not_mapped(write_tree) -> None:
    ws = cmake_package(write_tree, """
        project(pkg)
        install(DIRECTORY config DESTINATION share/${PROJECT_NAME})
        """, {"config/own.yaml": "a: 1\n", "../secret.yaml": "b: 2\n"})
    root = ws.packages["pkg"].root
    os.symlink(os.path.join(root, "..", "secret.yaml"), os.path.join(root, "config", "s.yaml"))
    assert mapped(ws, "pkg") == {"config/own.yaml": "pkg/config/own.yaml",
                                 "package.xml": "pkg/package.xml"}


def test_setup_py_destination_not_known_is_skipped(write_tree) -> None:
    # found by scripts/fuzz: an unknown name in a destination left an unknown value there
    ws = python_package(write_tree, """
        from setuptools import setup
        setup(data_files=[(undefined_name + '/x', ['a.yaml']), ('share/pkg', ['b.yaml'])])
        """, {"a.yaml": "a: 1\n", "b.yaml": "b: 1\n"})
    assert mapped(ws, "pkg") == {"b.yaml": "pkg/b.yaml"}
