"""No project file: a workspace folder or a launch file is analysed as a user would."""

from __future__ import annotations

import json
import os
import textwrap
from pathlib import Path

import pytest

from haros_arch.autoproject import choose, is_launch_file, workspace_of
from haros_arch.cli import main
from haros_arch.project import ProjectError, load

ROS1_PKG = """<package format="2"><name>{name}</name><version>0.1.0</version>
<description>d</description><maintainer email="a@b.c">a</maintainer><license>BSD</license>
<buildtool_depend>catkin</buildtool_depend></package>"""
ROS2_PKG = """<package format="3"><name>{name}</name><version>0.1.0</version>
<description>d</description><maintainer email="a@b.c">a</maintainer><license>BSD</license>
<buildtool_depend>ament_cmake</buildtool_depend>
<export><build_type>ament_cmake</build_type></export></package>"""


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(textwrap.dedent(text))
    return path


@pytest.fixture()
def ws(tmp_path: Path) -> Path:
    src = tmp_path / "robot_ws" / "src"
    bringup = src / "bringup"
    write(bringup / "package.xml", ROS1_PKG.format(name="bringup"))
    write(bringup / "CMakeLists.txt", "project(bringup)\n")
    write(bringup / "launch" / "robot.launch", """\
        <launch>
          <arg name="model" default="small"/>
          <include file="$(find bringup)/launch/base.launch"/>
          <include file="$(find drivers)/launch/laser.launch.xml"/>
        </launch>""")
    write(bringup / "launch" / "base.launch", """\
        <launch><node pkg="bringup" type="base_node" name="base"/></launch>""")
    write(bringup / "launch" / "sim.launch", """\
        <launch><node pkg="bringup" type="sim_node" name="sim"/></launch>""")
    drivers = src / "drivers"
    write(drivers / "package.xml", ROS1_PKG.format(name="drivers"))
    write(drivers / "CMakeLists.txt", "project(drivers)\n")
    # a ROS 1 file with the .launch.xml suffix, reached only through an include
    write(drivers / "launch" / "laser.launch.xml", """\
        <launch><node pkg="drivers" type="laser" name="laser"/></launch>""")
    rover = src / "rover"
    write(rover / "package.xml", ROS2_PKG.format(name="rover"))
    write(rover / "CMakeLists.txt", "project(rover)\n"
          "install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})\n")
    write(rover / "launch" / "rover.launch.py", """\
        import os
        from ament_index_python.packages import get_package_share_directory
        from launch import LaunchDescription
        from launch.actions import IncludeLaunchDescription
        from launch.launch_description_sources import PythonLaunchDescriptionSource

        def generate_launch_description():
            share = get_package_share_directory('rover')
            return LaunchDescription([IncludeLaunchDescription(PythonLaunchDescriptionSource(
                os.path.join(share, 'launch', 'drive_launch.py')))])
        """)
    write(rover / "launch" / "drive_launch.py", """\
        from launch import LaunchDescription
        from launch_ros.actions import Node

        def generate_launch_description():
            return LaunchDescription([Node(package='rover', executable='drive', name='drive')])
        """)
    write(rover / "launch" / "notes.py", "print('not a launch file')\n")
    return tmp_path / "robot_ws"


def test_workspace_gives_one_configuration_per_top_launch_file(ws: Path) -> None:
    choice = choose(str(ws), environment={})
    configs = {c.name: c.launch for c in choice.project.configurations}
    assert configs == {"bringup/robot": ["bringup/launch/robot.launch"],
                       "bringup/sim": ["bringup/launch/sim.launch"],
                       "rover/rover": ["rover/launch/rover.launch.py"]}
    assert choice.project.name == "robot_ws"
    assert choice.project.workspace == [str(ws / "src")]
    assert "3 included by others, 3 configurations" in choice.notes[0]


def test_a_fragment_an_include_reaches_with_another_argument_is_no_configuration(
        tmp_path: Path) -> None:
    """MoveIt's shape: ``planning_pipeline.launch.xml`` includes
    ``$(arg pipeline)_planning_pipeline.launch.xml`` (default ompl). The chomp file
    sets parameters for move_group and starts no node: a fragment of that include, not
    a configuration (alone, each of its parameters was "set but never read"), and so is
    ``sensor_manager.launch.xml``, which an include leaves out unless
    ``allow_active_sensing``. A file of the same pattern that starts a node stays one,
    and so does a file of parameters no include can reach."""
    moveit = tmp_path / "ws" / "src" / "arm_moveit_config"
    write(moveit / "package.xml", ROS1_PKG.format(name="arm_moveit_config"))
    write(moveit / "CMakeLists.txt", "project(arm_moveit_config)\n")
    launch = moveit / "launch"
    write(launch / "move_group.launch", """\
        <launch>
          <arg name="pipeline" default="ompl"/>
          <arg name="allow_active_sensing" default="false"/>
          <node pkg="moveit_ros_move_group" type="move_group" name="move_group"/>
          <include ns="move_group"
                   file="$(find arm_moveit_config)/launch/planning_pipeline.launch.xml">
            <arg name="pipeline" value="$(arg pipeline)"/>
          </include>
          <include ns="move_group" if="$(arg allow_active_sensing)"
                   file="$(find arm_moveit_config)/launch/sensor_manager.launch.xml"/>
        </launch>""")
    write(launch / "sensor_manager.launch.xml", """\
        <launch><param name="octomap_resolution" value="0.02"/></launch>""")
    write(launch / "planning_pipeline.launch.xml", """\
        <launch>
          <arg name="pipeline" default="ompl"/>
          <include
            file="$(find arm_moveit_config)/launch/$(arg pipeline)_planning_pipeline.launch.xml"/>
        </launch>""")
    for name in ("ompl", "chomp"):
        write(launch / f"{name}_planning_pipeline.launch.xml", f"""\
            <launch><param name="planning_plugin" value="{name}/Planner"/></launch>""")
    write(launch / "demo_planning_pipeline.launch.xml", """\
        <launch><node pkg="arm_moveit_config" type="demo" name="demo"/></launch>""")
    write(launch / "tools.launch", """\
        <launch><param name="tool" value="gripper"/></launch>""")
    configs = {c.name for c in choose(str(tmp_path / "ws"), environment={}).project.configurations}
    assert configs == {"arm_moveit_config/move_group",
                       "arm_moveit_config/demo_planning_pipeline",
                       "arm_moveit_config/tools"}


def test_a_ros2_file_included_only_under_a_false_condition_is_no_configuration(
        tmp_path: Path) -> None:
    """A ROS 2 launch file that another includes only ``if`` an argument false by
    default holds (Python ``IncludeLaunchDescription(condition=IfCondition(..))``, XML
    ``<include if="$(var sim)">``) was a configuration of its own: alone, its argument
    of no default had no value (LAUNCH_ARG_UNSET, names with '?'), and a file of
    parameters alone set them for nobody. Such a file with an argument of no default,
    or that starts no node, is part of the launch that includes it, as in ROS 1 (also
    in a group left out); one that starts nodes with every argument set stays one."""
    pkg = tmp_path / "ws" / "src" / "arm"
    write(pkg / "package.xml", ROS2_PKG.format(name="arm"))
    write(pkg / "CMakeLists.txt", "project(arm)\n")
    launch = pkg / "launch"
    write(launch / "bringup.launch.py", """\
        import os
        from ament_index_python.packages import get_package_share_directory
        from launch import LaunchDescription
        from launch.actions import DeclareLaunchArgument, GroupAction
        from launch.actions import IncludeLaunchDescription
        from launch.conditions import IfCondition, UnlessCondition
        from launch.launch_description_sources import PythonLaunchDescriptionSource
        from launch.substitutions import LaunchConfiguration

        def generate_launch_description():
            share = get_package_share_directory('arm')
            real = IncludeLaunchDescription(
                PythonLaunchDescriptionSource(os.path.join(share, 'launch', 'driver.launch.py')),
                condition=IfCondition(LaunchConfiguration('real')),
                launch_arguments={'robot_ip': '10.0.0.2'}.items())
            viewer = GroupAction([IncludeLaunchDescription(PythonLaunchDescriptionSource(
                os.path.join(share, 'launch', 'viewer.launch.py')))],
                condition=UnlessCondition('true'))
            return LaunchDescription([
                DeclareLaunchArgument('real', default_value='false'), real, viewer])
        """)
    write(launch / "driver.launch.py", """\
        from launch import LaunchDescription
        from launch.actions import DeclareLaunchArgument
        from launch.substitutions import LaunchConfiguration
        from launch_ros.actions import Node

        def generate_launch_description():
            return LaunchDescription([
                DeclareLaunchArgument('robot_ip'),
                Node(package='arm', executable='driver', name='driver',
                     parameters=[{'ip': LaunchConfiguration('robot_ip')}])])
        """)
    write(launch / "viewer.launch.py", """\
        from launch import LaunchDescription
        from launch.actions import DeclareLaunchArgument
        from launch_ros.actions import Node

        def generate_launch_description():
            return LaunchDescription([DeclareLaunchArgument('layout'),
                                      Node(package='arm', executable='viewer')])
        """)
    write(launch / "sim.launch.xml", """\
        <launch>
          <arg name="sim" default="false"/>
          <include file="$(find-pkg-share arm)/launch/gazebo.launch.xml" if="$(var sim)">
            <arg name="world" value="empty"/>
          </include>
          <include file="$(find-pkg-share arm)/launch/params.launch.xml" if="$(var sim)"/>
          <include file="$(find-pkg-share arm)/launch/rviz.launch.xml" if="$(var sim)"/>
          <include file="$(find-pkg-share arm)/launch/camera.launch.xml" if="$(var sim)"/>
        </launch>""")
    write(launch / "rviz.launch.xml", """\
        <launch><node pkg="arm" exec="rviz" name="rviz"/></launch>""")
    write(launch / "gazebo.launch.xml", """\
        <launch>
          <arg name="world"/>
          <node pkg="arm" exec="gazebo" name="gazebo" args="$(var world)"/>
        </launch>""")
    write(launch / "params.launch.xml", """\
        <launch><set_parameter name="use_sim_time" value="true"/></launch>""")
    # a file that starts no node seen, but includes one not read (a package not here):
    # it may start nodes, so it is no fragment and stays a configuration
    write(launch / "camera.launch.xml", """\
        <launch><include file="$(find-pkg-share vendor_camera)/launch/cam.launch.xml"/>
        </launch>""")
    configs = {c.name for c in choose(str(tmp_path / "ws"), environment={}).project.configurations}
    assert configs == {"arm/bringup", "arm/sim", "arm/rviz", "arm/camera"}


def test_launch_file_is_the_configuration_and_finds_its_workspace(ws: Path) -> None:
    launch = ws / "src" / "rover" / "launch" / "drive_launch.py"
    assert workspace_of(str(launch)) == str(ws / "src")
    choice = choose(str(launch), args={"x": "1"}, environment={})
    [config] = choice.project.configurations
    assert config.launch == ["rover/launch/drive_launch.py"] and config.args == {"x": "1"}


def test_launch_file_detection(ws: Path) -> None:
    folder = ws / "src" / "rover" / "launch"
    assert is_launch_file(str(folder / "drive_launch.py"))
    assert not is_launch_file(str(folder / "notes.py"))


def test_a_python_module_of_a_launch_folder_is_a_launch_file_only_if_it_defines_one(
        tmp_path: Path) -> None:
    # clearpath_generator_common/launch/writer.py writes launch files: it names
    # generate_launch_description in a string, it defines none
    folder = tmp_path / "launch"
    folder.mkdir()
    write(folder / "writer.py", """\
        class LaunchWriter:
            def close(self):
                self.add('def generate_launch_description():', 0)
        """)
    write(folder / "bringup.py", """\
        from launch import LaunchDescription

        def generate_launch_description():
            return LaunchDescription([])
        """)
    write(folder / "typed.py", """\
        def  generate_launch_description() -> LaunchDescription:
            return LaunchDescription([])
        """)
    assert not is_launch_file(str(folder / "writer.py"))
    assert is_launch_file(str(folder / "bringup.py"))
    assert is_launch_file(str(folder / "typed.py"))


def test_not_a_workspace(tmp_path: Path) -> None:
    with pytest.raises(ProjectError, match="no ROS package") as raised:
        choose(str(tmp_path), environment={})
    assert "manifest" not in str(raised.value)


def test_packages_an_ignore_marker_leaves_out_are_said(tmp_path: Path) -> None:
    """interbotix_ros_manipulators 0bb2b0e (its ROS 1 main branch): ten package.xml files,
    every robot family's folder with a CATKIN_IGNORE: "no ROS package (package.xml)"
    said nothing of them. Now the markers are named with the packages they leave out."""
    for family, names in (("arms_a", ["a_control", "a_gazebo"]), ("arms_b", ["b_control"])):
        (tmp_path / family).mkdir()
        (tmp_path / family / "CATKIN_IGNORE").write_text("")
        for name in names:
            (tmp_path / family / name).mkdir()
            (tmp_path / family / name / "package.xml").write_text(ROS1_PKG.format(name=name))
    with pytest.raises(ProjectError, match="no ROS package") as raised:
        choose(str(tmp_path), environment={})
    said = str(raised.value)
    assert "3 package(s)" in said
    assert "arms_a/CATKIN_IGNORE (2: a_control, a_gazebo)" in said
    assert "arms_b/CATKIN_IGNORE (1: b_control)" in said


def test_a_package_whose_build_chooses_its_manifest_is_said(tmp_path: Path) -> None:
    """livox_ros_driver2 13eb05e: package_ROS1.xml and package_ROS2.xml at the top, which
    its build.sh copies to package.xml, and sources in src/: no package is read, and the
    error names the two manifests and what to do."""
    for name in ("package_ROS1.xml", "package_ROS2.xml"):
        (tmp_path / name).write_text('<?xml version="1.0"?>\n<package format="2"/>\n')
    (tmp_path / "src").mkdir()
    (tmp_path / "src" / "driver_node.cpp").write_text("int main() { return 0; }\n")
    with pytest.raises(ProjectError, match="no ROS package") as raised:
        choose(str(tmp_path), environment={})
    said = str(raised.value)
    assert str(tmp_path / "package_ROS1.xml") in said
    assert str(tmp_path / "package_ROS2.xml") in said
    assert "copies to package.xml" in said


def test_check_and_extract_take_a_folder(ws: Path, tmp_path: Path, capsys) -> None:
    out = tmp_path / "model.json"
    assert main(["extract", str(ws), "-o", str(out), "--no-cache", "-q"]) == 0
    data = json.loads(out.read_text())
    names = {c["name"]: sorted(n["name"] for n in c["nodes"]) for c in data["configurations"]}
    assert names == {"bringup/robot": ["/base", "/laser"], "bringup/sim": ["/sim"],
                     "rover/rover": ["/drive"]}
    assert main(["check", str(ws), "--fail-on", "never", "--no-cache",
                 "--launch", str(ws / "src" / "bringup" / "launch" / "sim.launch")]) == 0
    said = capsys.readouterr()
    assert "configuration bringup/sim" in said.err


def test_init_writes_a_project_file_that_loads(ws: Path, tmp_path: Path) -> None:
    target = tmp_path / "project.yaml"
    assert main(["init", str(ws), "-o", str(target), "--arg", "model:=big"]) == 0
    project = load(str(target))
    assert project.workspace == [str(ws / "src")]
    assert [c.name for c in project.configurations] == ["bringup/robot", "bringup/sim",
                                                         "rover/rover"]
    assert all(c.args == {"model": "big"} for c in project.configurations)


def test_explain_takes_rule_ids(capsys) -> None:
    assert main(["explain", "parameter-set-not-read"]) == 0
    assert "Parameter set but never read" in capsys.readouterr().out
    assert main(["explain", "no-such-thing"]) == 2
    assert main(["explain"]) == 0
    listing = capsys.readouterr().out
    assert "LAUNCH_UNKNOWN_TAG" in listing and "topic-type-mismatch" in listing


def test_a_package_folder_with_its_sources_in_src(tmp_path: Path) -> None:
    """A repository of one package (pointcloud_to_laserscan, teleop_twist_joy): its
    package.xml at the top and its C++ sources in src/. It is the package, not a
    workspace whose packages are under src/ (that was "no ROS package under src")."""
    package = tmp_path / "pointcloud_to_laserscan"
    write(package / "package.xml", ROS2_PKG.format(name="pointcloud_to_laserscan"))
    write(package / "CMakeLists.txt", "project(pointcloud_to_laserscan)\n"
          "add_executable(p2l src/p2l.cpp)\n"
          "install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})\n")
    write(package / "src" / "p2l.cpp", "int main() { return 0; }\n")
    write(package / "launch" / "p2l.launch.py", """\
        from launch import LaunchDescription
        from launch_ros.actions import Node

        def generate_launch_description():
            return LaunchDescription([Node(package='pointcloud_to_laserscan', executable='p2l')])
        """)
    choice = choose(str(package), environment={})
    assert [c.name for c in choice.project.configurations] == ["pointcloud_to_laserscan/p2l"]
    assert choice.project.workspace == [str(package)]


def test_a_launch_file_its_package_cannot_run_is_no_configuration(tmp_path: Path) -> None:
    """twist_mux (ament) still holds its ROS 1 ``twist_mux.launch``: chosen as a
    configuration, the ROS 2 ``ros__parameters`` YAML it loads with ``<rosparam>`` gave
    29 "set but never read" parameters. It is left out, with a note; --launch still
    analyses it."""
    pkg = tmp_path / "ws" / "src" / "mux"
    write(pkg / "package.xml", ROS2_PKG.format(name="mux"))
    write(pkg / "CMakeLists.txt", "project(mux)\nadd_executable(mux src/mux.cpp)\n")
    write(pkg / "launch" / "mux.launch", """\
        <launch><node pkg="mux" type="mux" name="mux">
          <rosparam file="$(find mux)/config/topics.yaml" command="load"/>
        </node></launch>""")
    write(pkg / "launch" / "mux_launch.py", """\
        from launch import LaunchDescription
        from launch_ros.actions import Node
        def generate_launch_description():
            return LaunchDescription([Node(package='mux', executable='mux', name='mux')])
        """)
    choice = choose(str(tmp_path / "ws"))
    assert [spec.launch for spec in choice.project.configurations] == [
        ["mux/launch/mux_launch.py"]]
    assert any(note.startswith("mux/launch/mux.launch skipped: roslaunch (ROS 1) XML in "
                               "mux, an ament (ROS 2) package") for note in choice.notes)
    named = choose(str(tmp_path / "ws"), launch=[str(pkg / "launch" / "mux.launch")])
    assert [spec.launch for spec in named.project.configurations] == [["mux/launch/mux.launch"]]


def test_a_module_named_like_a_launch_file_is_no_configuration(ws: Path) -> None:
    """interbotix_xs_modules' ``xs_launch/xs_launch.py`` is a module of helpers the launch
    files import; it names no ``generate_launch_description``, so ``ros2 launch`` cannot
    run it: no configuration of its own."""
    rover = ws / "src" / "rover"
    write(rover / "rover_modules" / "__init__.py", "")
    write(rover / "rover_modules" / "rover_launch.py", """\
        def declare_rover_arguments():
            return []
        """)
    choice = choose(str(ws), environment={})
    configs = {c.name: c.launch for c in choice.project.configurations}
    assert configs == {"bringup/robot": ["bringup/launch/robot.launch"],
                       "bringup/sim": ["bringup/launch/sim.launch"],
                       "rover/rover": ["rover/launch/rover.launch.py"]}


def test_a_src_folder_of_code_beside_the_packages(tmp_path: Path) -> None:
    """pyrobot 03af552: its Python library in src/ (no package.xml), its ROS packages in
    robots/ and pyrobot_bridge/. The folder's src/ was taken for a workspace's package
    folder: "no ROS package (package.xml) under .../src", nothing analysed. Now a src/
    without packages leaves the folder given to be read."""
    write(tmp_path / "src" / "robotlib" / "__init__.py", "VERSION = 1\n")
    write(tmp_path / "robots" / "arm_control" / "package.xml",
          ROS1_PKG.format(name="arm_control"))
    write(tmp_path / "robots" / "arm_control" / "launch" / "arm.launch", """\
        <launch><node pkg="arm_control" type="arm_node" name="arm"/></launch>""")
    choice = choose(str(tmp_path), environment={})
    assert choice.project.workspace == [str(tmp_path)]
    assert [c.launch for c in choice.project.configurations] == [
        ["arm_control/launch/arm.launch"]]


def test_a_yaml_file_named_like_a_launch_file_that_is_none_is_no_configuration(
        ws: Path) -> None:
    """perseus-v2's ``config/realsense_launch.yaml`` holds the arguments its launch file
    gives realsense2_camera's: a YAML launch file is one mapping with the key ``launch``,
    so ``ros2 launch`` cannot run it; it was a configuration whose only result was a
    LAUNCH_YAML_SYNTAX error. A YAML launch file with that key stays one."""
    rover = ws / "src" / "rover"
    write(rover / "config" / "camera_launch.yaml", """\
        # the camera's launch arguments
        camera_name: camera
        enable_color: true
        """)
    write(rover / "launch" / "lidar.launch.yaml", """\
        %YAML 1.2
        ---
        launch:
        - node: {pkg: rover, exec: lidar, name: lidar}
        """)
    choice = choose(str(ws), environment={})
    configs = {c.name: c.launch for c in choice.project.configurations}
    assert "rover/camera" not in configs
    assert configs["rover/lidar"] == ["rover/launch/lidar.launch.yaml"]


@pytest.fixture()
def loads(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """One item per call of ``root_launch_files`` (which loads every launch file)."""
    from haros_arch import autoproject

    counted: list[int] = []
    real = autoproject.root_launch_files

    def counting(*args, **kwargs):
        counted.append(1)
        return real(*args, **kwargs)

    monkeypatch.setattr(autoproject, "root_launch_files", counting)
    return counted


def test_the_chosen_roots_are_kept_while_no_file_they_read_changes(
        ws: Path, tmp_path: Path, loads: list[int]) -> None:
    # choosing loads every launch file of the workspace: a re-run with nothing changed
    # takes the roots from the cache folder (issue 24), a changed file chooses again
    cache = str(tmp_path / "cache")

    def configs() -> dict[str, list[str]]:
        choice = choose(str(ws), environment={}, cache_dir=cache)
        return {c.name: c.launch for c in choice.project.configurations}

    first = configs()
    assert first == {"bringup/robot": ["bringup/launch/robot.launch"],
                     "bringup/sim": ["bringup/launch/sim.launch"],
                     "rover/rover": ["rover/launch/rover.launch.py"]}
    assert configs() == first and len(loads) == 1  # read back, nothing loaded
    # robot.launch now also includes sim.launch: sim is a root no more
    robot = ws / "src" / "bringup" / "launch" / "robot.launch"
    robot.write_text(robot.read_text().replace(
        "</launch>", '<include file="$(find bringup)/launch/sim.launch"/></launch>'))
    assert configs() == {"bringup/robot": ["bringup/launch/robot.launch"],
                         "rover/rover": ["rover/launch/rover.launch.py"]}
    assert len(loads) == 2
    # the environment is an input too (a launch file may read it)
    choose(str(ws), environment={"ROBOT": "b"}, cache_dir=cache)
    assert len(loads) == 3
    assert configs() == {"bringup/robot": ["bringup/launch/robot.launch"],
                         "rover/rover": ["rover/launch/rover.launch.py"]}
    assert len(loads) == 3


@pytest.mark.parametrize("command", ["check", "report"])
def test_a_command_on_a_folder_again_takes_the_kept_choice(
        ws: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, loads: list[int],
        command: str) -> None:
    # every command that analyses a folder chooses its configurations through the cache
    # folder (report asked for the project first without it, loading every launch file)
    from haros_arch import autoproject

    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    extra = ["--fail-on", "never"] if command == "check" else ["-o", str(tmp_path / "r.html")]
    for _ in range(2):
        autoproject._chosen.clear()  # a new process
        assert main([command, str(ws), *extra]) == 0
    assert len(loads) == 1


def test_a_folder_analysed_walks_its_files_once(ws: Path, tmp_path: Path,
                                                monkeypatch: pytest.MonkeyPatch) -> None:
    # (issue 24) the kept choice of configurations and the run's key are both keyed by a
    # snapshot of the workspace's files: one command takes it once; a change between two
    # commands is still seen (each takes its own)
    from haros_arch import autoproject, runcache
    from haros_arch.api import analyse_path
    from haros_arch.pipeline import Options

    walked: list[str] = []
    real = runcache.Snapshot.tree

    def counting(self, top, skip=frozenset()):
        if os.path.abspath(top).startswith(str(ws)):
            walked.append(top)
        return real(self, top, skip)

    monkeypatch.setattr(runcache.Snapshot, "tree", counting)
    options = Options(cache_dir=str(tmp_path / "cache"), jobs=1)
    first = analyse_path(str(ws), options)
    assert first.model is not None and len(walked) == 1
    autoproject._chosen.clear()  # a new process
    robot = ws / "src" / "bringup" / "launch" / "robot.launch"
    robot.write_text(robot.read_text().replace(
        "</launch>", '<include file="$(find bringup)/launch/sim.launch"/></launch>'))
    again = analyse_path(str(ws), options)
    assert len(walked) == 2 and again.model is not None
    assert [c.name for c in again.model.configurations] == ["bringup/robot", "rover/rover"]
