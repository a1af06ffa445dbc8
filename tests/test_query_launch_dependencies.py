"""launch-undeclared-dependency on real launch files: the packages a launch file names
(nodes, $(find), FindPackageShare, get_package_share_directory) against its package.xml."""

from __future__ import annotations

import json

from haros_arch.model.load import from_data
from haros_arch.model.serialise import model_to_data
from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query.catalogue import UNDECIDED, load_catalogue, run_catalogue, run_rule

(RULE,) = [r for r in load_catalogue() if r.id == "launch-undeclared-dependency"]


def manifest(name: str, *deps: tuple[str, str], build_type: str = "") -> str:
    export = f"<export><build_type>{build_type}</build_type></export>" if build_type else ""
    tool = "ament_cmake" if build_type else "catkin"
    lines = "".join(f"<{kind}>{dep}</{kind}>" for kind, dep in deps)
    return (f'<?xml version="1.0"?>\n<package format="2"><name>{name}</name>'
            f"<version>0.1.0</version><description>d</description>"
            f'<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
            f"<buildtool_depend>{tool}</buildtool_depend>{lines}{export}</package>\n")


ROBOT_LAUNCH = """<launch>
  <arg name="model" default="$(find desc)/urdf/robot.xacro"/>
  <arg name="extra"/>
  <param name="robot_description" command="$(find xacro)/xacro $(arg model)"/>
  <node pkg="driver" type="driver_node" name="driver">
    <rosparam file="$(find other_robot)/param/diagnostics.yaml" command="load"/>
  </node>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
  <node pkg="$(arg extra)" type="tool" name="tool"/>
  <node pkg="bringup" type="watchdog.py" name="watchdog"/>
  <include file="$(find driver)/launch/view.launch"/>
  <include file="$(find bringup)/launch/description.launch"/>
</launch>
"""


def findings(model):
    return sorted((f.location.file, f.location.line, f.message.split(" uses ")[1]
                   .split(" ")[0]) for f in run_rule(RULE, model)
                  if not f.rule.endswith(UNDECIDED))


def test_ros1_nodes_finds_and_includes_against_run_dependencies(write_tree):
    root = write_tree({
        # xacro is only a build dependency; meta is the workspace's metapackage of desc
        "src/bringup/package.xml": manifest("bringup", ("exec_depend", "driver"),
                                            ("build_depend", "xacro"),
                                            ("exec_depend", "meta_unused"),
                                            ("test_depend", "robot_state_publisher")),
        "src/bringup/CMakeLists.txt": "project(bringup)\n",
        "src/bringup/launch/robot.launch": ROBOT_LAUNCH,
        "src/bringup/launch/description.launch": '<launch>\n  <param name="d" command="'
                                                 '$(find xacro)/xacro $(find desc)/a.xacro"/>'
                                                 "\n</launch>\n",
        "src/driver/package.xml": manifest("driver", ("depend", "meta")),
        "src/driver/CMakeLists.txt": "project(driver)\n",
        "src/driver/launch/view.launch": '<launch>\n  <node pkg="rviz" type="rviz" '
                                         'name="rviz"/>\n  <node pkg="desc" type="x" '
                                         'name="x"/>\n</launch>\n',
        "src/meta/package.xml": manifest("meta", ("exec_depend", "desc")),
        "src/meta/CMakeLists.txt": "project(meta)\n",
        "src/desc/package.xml": manifest("desc"),
        "src/desc/CMakeLists.txt": "project(desc)\n",
        "project.yaml": "project: p\nconfigurations:\n  c: [bringup/launch/robot.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    launch = "bringup/launch/robot.launch"
    # desc (line 2) is installed with bringup: through driver, which depends on the
    # workspace's metapackage meta; driver and bringup itself are declared
    expected = [
        ("bringup/launch/description.launch", 2, "xacro"),
        (launch, 4, "xacro"),  # a build dependency is not installed with it
        (launch, 6, "other_robot"),  # not in the workspace, not declared: still a fact
        (launch, 8, "robot_state_publisher"),  # a test dependency, in a roslaunch file
        ("driver/launch/view.launch", 2, "rviz"),  # the included file's own package
    ]
    assert findings(model) == expected
    # one missing line of a package.xml is one finding, whatever uses it
    merged = [f for f in run_catalogue(model, None, [RULE]) if "xacro" in f.message]
    assert [(f.location.file, f.location.line, [(a.file, a.line) for a in f.also])
            for f in merged] == [("bringup/launch/description.launch", 2, [(launch, 4)])]
    reloaded = from_data(json.loads(json.dumps(model_to_data(model))))
    assert findings(reloaded) == expected
    # $(arg extra) has no value: which package it starts is not known
    (info,) = [f for f in run_rule(RULE, model) if f.rule.endswith(UNDECIDED)]
    assert "1 possible finding" in info.message and info.location.line == 9


def test_ros1_test_files_may_use_test_dependencies(write_tree):
    root = write_tree({
        "src/bringup/package.xml": manifest("bringup", ("test_depend", "rostest"),
                                            ("test_depend", "checker")),
        "src/bringup/CMakeLists.txt": "project(bringup)\n",
        "src/bringup/test/robot.test": '<launch>\n  <node pkg="checker" type="c" name="c"/>'
                                       '\n  <test test-name="t" pkg="rostest" type="hz"/>\n'
                                       "</launch>\n",
        "project.yaml": "project: p\nconfigurations:\n  c: [bringup/test/robot.test]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    assert run_rule(RULE, model) == []
    assert {(u.package, u.test) for u in model.configurations[0].package_uses} == {
        ("checker", True), ("rostest", True)}


ROS2_LAUNCH = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    desc = get_package_share_directory('desc2')
    return LaunchDescription([
        Node(package='driver2', executable='driver_node', name='driver',
             parameters=[os.path.join(desc, 'params.yaml')]),
        Node(package='rviz2', executable='rviz2', name='rviz2', arguments=[
            '-d', PathJoinSubstitution([FindPackageShare('views2'), 'a.rviz'])]),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(PathJoinSubstitution([
            FindPackageShare('teleop2'), 'launch', 'teleop.launch.py']))),
        # no package name at all: no use
        Node(package='driver2', executable='helper', name='helper', arguments=[
            PathJoinSubstitution([FindPackageShare(''), 'a.yaml'])]),
    ])
"""


def test_ros2_nodes_and_package_shares(write_tree):
    root = write_tree({
        "src/bringup2/package.xml": manifest("bringup2", ("exec_depend", "driver2"),
                                             ("build_depend", "desc2"),
                                             build_type="ament_cmake"),
        "src/bringup2/CMakeLists.txt": "project(bringup2)\n",
        "src/bringup2/launch/robot.launch.py": ROS2_LAUNCH,
        "src/desc2/package.xml": manifest("desc2", build_type="ament_cmake"),
        "src/desc2/CMakeLists.txt": "project(desc2)\n",
        "project.yaml": "project: p\nconfigurations:\n  c: [bringup2/launch/robot.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    launch = "bringup2/launch/robot.launch.py"
    # desc2's share folder is asked for now (get_package_share_directory), the others'
    # when the actions run; driver2 is declared
    assert findings(model) == [(launch, 12, "desc2"), (launch, 16, "rviz2"),
                               (launch, 16, "views2"),
                               (launch, 18, "teleop2")]



OPAQUE_LAUNCH = """import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch_ros.actions import Node


def setup(context, *args, **kwargs):
    model = os.path.join(get_package_share_directory('boat_desc'), 'urdf', 'boat.xacro')
    return [Node(package='driver3', executable='driver_node', name='driver',
                 arguments=[model])]


def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=setup)])
"""


def test_ros2_a_package_an_opaque_function_asks_for_when_it_runs(write_tree):
    """vrx 747cb183: competition.launch.py spawns the boat in an OpaqueFunction, whose
    helper asks for wamv_gazebo's share folder when launch runs the function, after the
    module was read; vrx_gz's package.xml did not declare wamv_gazebo."""
    root = write_tree({
        "src/bringup3/package.xml": manifest("bringup3", ("exec_depend", "driver3"),
                                             build_type="ament_cmake"),
        "src/bringup3/CMakeLists.txt": "project(bringup3)\n",
        "src/bringup3/launch/boat.launch.py": OPAQUE_LAUNCH,
        "src/boat_desc/package.xml": manifest("boat_desc", build_type="ament_cmake"),
        "src/boat_desc/CMakeLists.txt": "project(boat_desc)\n",
        "project.yaml": "project: p\nconfigurations:\n  c: [bringup3/launch/boat.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    assert findings(model) == [("bringup3/launch/boat.launch.py", 10, "boat_desc")]


GUARDED_LAUNCH = """import os

from ament_index_python.packages import get_package_share_directory, get_packages_with_prefixes
from ament_index_python.resources import has_resource
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    nodes = []
    if 'nav2_bringup' in get_packages_with_prefixes():
        nodes.append(IncludeLaunchDescription(PythonLaunchDescriptionSource(os.path.join(
            get_package_share_directory('nav2_bringup'), 'launch', 'bringup_launch.py'))))
        nodes.append(Node(package='nav2_bringup', executable='tool', name='tool'))
    if has_resource('packages', 'image_view'):
        nodes.append(Node(package='image_view', executable='image_view', name='view',
                          arguments=[PathJoinSubstitution([FindPackageShare('image_view'),
                                                           'a.yaml'])]))
    if 'moveit' in get_packages_with_prefixes():
        nodes.append(Node(package='moveit_ros_move_group', executable='move_group'))
    nodes.append(Node(package='rviz2', executable='rviz2', name='rviz2'))
    return LaunchDescription(nodes)
"""


def test_ros2_a_package_used_where_the_file_found_it_installed_is_optional(write_tree):
    """webots_ros2's launch files use nav2_bringup, turtlebot3_navigation2 and
    turtlebot3_cartographer only under ``if 'nav2_bringup' in get_packages_with_prefixes():``
    (turtlebot3_bringup: ``has_resource('packages', 'image_view')``): they run without
    them, so these are no undeclared dependency (6 warnings). A package used under the
    check of another (moveit_ros_move_group under 'moveit') is undecided."""
    root = write_tree({
        "src/sim/package.xml": manifest("sim", build_type="ament_cmake"),
        "src/sim/CMakeLists.txt": "project(sim)\n",
        "src/sim/launch/robot.launch.py": GUARDED_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [sim/launch/robot.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    assert findings(model) == [("sim/launch/robot.launch.py", 25, "rviz2")]
    undecided = [f.message for f in run_rule(RULE, model) if f.rule.endswith(UNDECIDED)]
    assert len(undecided) == 1 and "moveit_ros_move_group" in undecided[0]
    reloaded = from_data(json.loads(json.dumps(model_to_data(model))))
    assert findings(reloaded) == findings(model)


def test_ros1_a_nodelet_uses_the_package_its_class_is_found_in(write_tree):
    root = write_tree({
        "src/cam/package.xml": manifest("cam", ("exec_depend", "nodelet")),
        "src/cam/CMakeLists.txt": "project(cam)\n",
        # image_proc's rectify is known from its interface model; the other lookup name
        # names no package found: which package has it is not known, so no use
        "src/cam/launch/cam.launch": '<launch>\n  <node pkg="nodelet" type="nodelet" '
                                     'name="manager" args="manager"/>\n  <node pkg="nodelet"'
                                     ' type="nodelet" name="rectify" args="load image_proc/'
                                     'rectify manager"/>\n  <node pkg="nodelet" type="nodelet"'
                                     ' name="other" args="load vendor_plugins/Thing manager"/>'
                                     "\n</launch>\n",
        "project.yaml": "project: p\nconfigurations:\n  c: [cam/launch/cam.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    assert findings(model) == [("cam/launch/cam.launch", 3, "image_proc")]


def test_an_installed_metapackage_brings_its_members(tmp_path):
    # linorobot2_gazebo exec_depends on gazebo_ros_pkgs (ROS 2) and uses gazebo_ros; a
    # ROS 1 package depending on navigation gets amcl. The table is the shipped one
    from haros_arch.manifest import installed_with, parse_manifest
    from haros_arch.model.location import Location

    def package(name, *deps, build_type=""):
        path = tmp_path / name / "package.xml"
        path.parent.mkdir()
        path.write_text(manifest(name, *deps, build_type=build_type))
        found, problems = parse_manifest(str(path), Location(file=str(path)), name, {})
        assert found is not None and not problems
        return found

    gazebo = package("gz_robot", ("exec_depend", "gazebo_ros_pkgs"), build_type="ament_cmake")
    assert {"gazebo_ros", "gazebo_plugins"} <= installed_with(gazebo, [gazebo])
    nav = package("nav_robot", ("exec_depend", "navigation"))
    assert {"amcl", "move_base", "map_server"} <= installed_with(nav, [nav])
    # ros2_control's metapackage folder also holds doc/ and rosdoc2.yaml
    arm = package("arm_bringup", ("exec_depend", "ros2_control"), build_type="ament_cmake")
    assert "controller_manager" in installed_with(arm, [arm])
    # moveit2's moveit (its folder also holds maintainer scripts) brings move_group
    # through moveit_ros (moveit2_tutorials' launch files start it)
    tutorial = package("tutorial", ("exec_depend", "moveit"), build_type="ament_cmake")
    assert "moveit_ros_move_group" in installed_with(tutorial, [tutorial])
    # rtabmap_ros is RTAB-Map's metapackage (stretch_rtabmap depends on it and launches
    # rtabmap_slam's rtabmap and rtabmap_odom's rgbd_odometry)
    mapping = package("mapping", ("depend", "rtabmap_ros"), build_type="ament_cmake")
    assert {"rtabmap_slam", "rtabmap_odom"} <= installed_with(mapping, [mapping])
    plain = package("plain_robot", ("exec_depend", "rviz"))
    assert installed_with(plain, [plain]) == {"rviz"}


def test_models_metapackages_reads_the_pinned_trees(tmp_path, capsys):
    import yaml

    from haros_arch.cli import main
    from haros_arch.models.generate import folder_of

    commit = "b" * 40
    tree = tmp_path / "sources" / folder_of("github:someone/stack", commit)
    ros1 = tree / "stack"  # ROS 1: the export says so
    ros1.mkdir(parents=True)
    (ros1 / "package.xml").write_text(manifest("stack", ("run_depend", "one"), (
        "run_depend", "two")).replace("</package>", "<export><metapackage/></export></package>"))
    ros2 = tree / "stack2"  # ROS 2: nothing but its manifest, build file and papers
    ros2.mkdir()
    (ros2 / "package.xml").write_text(manifest("stack2", ("exec_depend", "three"),
                                               build_type="ament_cmake"))
    (ros2 / "CMakeLists.txt").write_text("project(stack2)\n")
    (ros2 / "README.md").write_text("a stack\n")
    # ROS 2, with its documentation (ros2_control's metapackage: doc/, rosdoc2.yaml)
    documented = tree / "stack3"
    (documented / "doc").mkdir(parents=True)
    (documented / "doc" / "index.rst").write_text("Stack 3\n")
    (documented / "package.xml").write_text(manifest("stack3", ("exec_depend", "four"),
                                                     build_type="ament_cmake"))
    (documented / "CMakeLists.txt").write_text("project(stack3)\n")
    (documented / "rosdoc2.yaml").write_text("type: 'rosdoc2 config'\n")
    (documented / "stack3.repos").write_text("repositories: {}\n")
    # a package that builds nothing but installs launch files (jazzy's velodyne): its
    # install brings its run dependencies as a metapackage's does
    launcher = tree / "stack4"
    (launcher / "launch").mkdir(parents=True)
    (launcher / "launch" / "all.launch.py").write_text("# starts the stack\n")
    (launcher / "package.xml").write_text(manifest("stack4", ("exec_depend", "six"),
                                                   build_type="ament_cmake"))
    (launcher / "CMakeLists.txt").write_text("project(stack4)\n")
    # one whose CMakeLists.txt builds and installs nothing (moveit2's moveit): what else
    # its folder holds (maintainer scripts) is not installed
    tools = tree / "stack5"
    (tools / "scripts").mkdir(parents=True)
    (tools / "scripts" / "make_table.py").write_text("print('maintainers')\n")
    (tools / "package.xml").write_text(manifest("stack5", ("exec_depend", "seven"),
                                                build_type="ament_cmake"))
    (tools / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.22)\nproject(stack5)\n"
        "find_package(ament_cmake REQUIRED)\n\nament_package()\n")
    installs = tree / "stack6"  # ... but one that installs its scripts is a package
    (installs / "scripts").mkdir(parents=True)
    (installs / "scripts" / "node.py").write_text("print('a node')\n")
    (installs / "package.xml").write_text(manifest("stack6", ("exec_depend", "eight"),
                                                   build_type="ament_cmake"))
    (installs / "CMakeLists.txt").write_text(
        "project(stack6)\nfind_package(ament_cmake REQUIRED)\n"
        "install(PROGRAMS scripts/node.py DESTINATION lib/${PROJECT_NAME})\n"
        "ament_package()\n")
    code = tree / "one"  # a package with code is no metapackage
    (code / "src").mkdir(parents=True)
    (code / "package.xml").write_text(manifest("one", ("exec_depend", "two")))
    configs = tree / "configs"  # nor one with files of its own (a config folder, a YAML)
    (configs / "config").mkdir(parents=True)
    (configs / "package.xml").write_text(manifest("configs", ("exec_depend", "five"),
                                                  build_type="ament_cmake"))
    (configs / "params.yaml").write_text("a: 1\n")
    listing = tmp_path / "list.yaml"
    listing.write_text(yaml.safe_dump([{"repository": "github:someone/stack",
                                        "commit": commit, "distro": "noetic",
                                        "packages": ["stack"]}]))
    out = tmp_path / "meta.json"
    assert main(["models", "metapackages", str(listing), "--sources",
                 str(tmp_path / "sources"), "-o", str(out)]) == 0
    table = json.loads(out.read_text())
    assert table["metapackages"] == {"noetic": {"stack": ["one", "two"],
                                                "stack2": ["three"], "stack3": ["four"],
                                                "stack4": ["six"], "stack5": ["seven"]}}
    assert table["sources"] == [{"repository": "github:someone/stack", "commit": commit,
                                 "distro": "noetic"}]
    assert "noetic: 5 metapackages" in capsys.readouterr().out


def test_the_shipped_metapackage_table_comes_from_the_pinned_lists():
    import yaml

    from haros_arch.models import metapackages

    pinned = set()
    for path in metapackages.LISTS:
        with open(path, encoding="utf-8") as handle:
            for entry in yaml.safe_load(handle):
                pinned.add((entry["repository"], entry["commit"], entry["distro"]))
                pinned.update((w["repository"], w["commit"], entry["distro"])
                              for w in entry.get("with") or ())
    with open(metapackages.TABLE, encoding="utf-8") as handle:
        table = json.load(handle)
    assert table["sources"] and all(
        (s["repository"], s["commit"], s["distro"]) in pinned for s in table["sources"])
    assert "gazebo_ros" in table["metapackages"]["noetic"]["gazebo_ros_pkgs"]


def test_ros1_an_include_a_condition_leaves_out_uses_no_package(write_tree):
    # roslaunch-deps skips a tag whose if/unless does not hold; a skipped <node> was
    # never a use, a skipped <include>'s $(find pkg) was (dingo_bringup's charger)
    root = write_tree({
        "src/bringup/package.xml": manifest("bringup", ("exec_depend", "camera")),
        "src/bringup/CMakeLists.txt": "project(bringup)\n",
        "src/bringup/launch/robot.launch": (
            '<launch>\n  <group if="$(optenv CHARGER 0)">\n'
            '    <include file="$(find charger)/launch/charger.launch"/>\n  </group>\n'
            '  <include unless="true" file="$(find dock)/launch/dock.launch"/>\n'
            '  <include file="$(find camera)/launch/camera.launch"/>\n'
            '  <include if="$(optenv LIDAR 1)" file="$(find lidar)/launch/lidar.launch"/>\n'
            "</launch>\n"),
        "project.yaml": "project: p\nconfigurations:\n  c: [bringup/launch/robot.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    # camera is declared; lidar's include is reached (the condition holds) and is not
    assert findings(model) == [("bringup/launch/robot.launch", 7, "lidar")]
    assert sorted(u.package for u in model.configurations[0].package_uses) == [
        "camera", "lidar"]


HELPER_MODULE = """import os
from ament_index_python.packages import get_package_share_directory


def plugins_of(package_name, kind=None):
    return os.path.join(get_package_share_directory(package_name), 'plugins.xml')


def viewer_config():
    return os.path.join(get_package_share_directory('viewer'), 'a.rviz')
"""

HELPER_LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node
from core.plugin_utils import plugins_of, viewer_config


def generate_launch_description():
    own = plugins_of('est')
    other = plugins_of(package_name='planner')
    return LaunchDescription([
        Node(package='est', executable='est_node', name='est',
             parameters=[{'a': own, 'b': other, 'c': viewer_config()}]),
    ])
"""


def test_ros2_a_package_named_by_the_caller_of_another_packages_helper_is_the_callers(
        write_tree):
    """aerostack2: each package's launch file calls as2_core's
    ``get_available_plugins('<its own package>')``, whose
    ``get_package_share_directory(package_name)`` in as2_core's module was the use:
    as2_core was said to use six packages it never names. A package name the helper
    is given is used where it was written, by the caller; one the helper writes itself
    stays the helper's package's."""
    root = write_tree({
        "src/core/package.xml": manifest("core", build_type="ament_cmake"),
        "src/core/CMakeLists.txt": "project(core)\nament_python_install_package(core)\n",
        "src/core/core/__init__.py": "",
        "src/core/core/plugin_utils.py": HELPER_MODULE,
        "src/est/package.xml": manifest("est", ("exec_depend", "core"),
                                        build_type="ament_cmake"),
        "src/est/CMakeLists.txt": "project(est)\n",
        "src/est/launch/est.launch.py": HELPER_LAUNCH,
        "src/planner/package.xml": manifest("planner", build_type="ament_cmake"),
        "src/planner/CMakeLists.txt": "project(planner)\n",
        "src/viewer/package.xml": manifest("viewer", build_type="ament_cmake"),
        "src/viewer/CMakeLists.txt": "project(viewer)\n",
        "project.yaml": "project: p\nconfigurations:\n  c: [est/launch/est.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    assert findings(model) == [("core/core/plugin_utils.py", 10, "viewer"),
                               ("est/launch/est.launch.py", 8, "planner")]


BAG_LAUNCH = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration, PythonExpression


def generate_launch_description():
    bag = LaunchConfiguration('bagfile', default='')
    return LaunchDescription([
        ExecuteProcess(cmd=['ros2', 'bag', 'play', bag],
                       condition=IfCondition(PythonExpression(["'", bag, "' != ''"]))),
        ExecuteProcess(cmd=['ros2', 'service', 'call', '/reset', 'std_srvs/srv/Empty']),
        ExecuteProcess(cmd=['ros2', 'frobnicate']),
    ])
"""


def test_ros2_a_ros2cli_verb_uses_the_package_that_gives_it(write_tree):
    # kiss-icp's odometry.launch.py plays a bag with ``ros2 bag play`` and declares only
    # ros2launch: ros2bag is what gives ros2 its ``bag`` verb; a verb not known names
    # no package; a process a condition leaves out uses none
    root = write_tree({
        "src/odom/package.xml": manifest("odom", ("exec_depend", "ros2launch"),
                                         ("exec_depend", "ros2service"),
                                         build_type="ament_cmake"),
        "src/odom/CMakeLists.txt": "project(odom)\n",
        "src/odom/launch/odometry.launch.py": BAG_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  bag:\n"
                        "    launch: [odom/launch/odometry.launch.py]\n"
                        "    args: {bagfile: /data/run.bag}\n"
                        "  live: [odom/launch/odometry.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    bag, live = model.configurations
    assert sorted(u.package for u in bag.package_uses) == ["ros2bag", "ros2service"]
    assert sorted(u.package for u in live.package_uses) == ["ros2service"]
    assert findings(model) == [("odom/launch/odometry.launch.py", 10, "ros2bag")]


CHOSEN_LOADER = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription, OpaqueFunction
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
from launch_ros.substitutions import FindPackageShare


def launch_setup(context, *args, **kwargs):
    share = FindPackageShare([LaunchConfiguration('vehicle_model'), '_description']
                             ).perform(context)
    sensors = FindPackageShare([LaunchConfiguration('sensor_model'), '_description']
                               ).perform(context)
    return [IncludeLaunchDescription(PythonLaunchDescriptionSource(
        [FindPackageShare('info'), '/launch/info.launch.py']),
        launch_arguments={'file': [share, '/config/a.yaml'],
                          'other': [sensors, '/b.yaml']}.items())]


def generate_launch_description():
    return LaunchDescription([DeclareLaunchArgument('sensor_model', default_value='kit'),
                              OpaqueFunction(function=launch_setup)])
"""


def test_ros2_a_package_named_by_the_includers_configuration_is_undecided(write_tree):
    """autoware_global_parameter_loader's global_params.launch.py asks for
    ``FindPackageShare([LaunchConfiguration('vehicle_model'), '_description'])`` and
    declares no vehicle_model: the file that includes it (test_default_adapi.launch.xml,
    ``<arg name="vehicle_model" default="sample_vehicle"/>``) chooses the package, so
    the loader's package.xml cannot name it: undecided, not a warning on the loader. A
    configuration the file declares itself (sensor_model) or sets (``<let>``) is its own
    choice: a finding, as before."""
    root = write_tree({
        "src/loader/package.xml": manifest("loader", ("exec_depend", "info"),
                                           build_type="ament_cmake"),
        "src/loader/CMakeLists.txt": "project(loader)\n",
        "src/loader/launch/params.launch.py": CHOSEN_LOADER,
        "src/loader/launch/own.launch.xml": (
            '<launch>\n  <let name="vehicle_model" value="mine"/>\n'
            '  <include file="$(find-pkg-share $(var vehicle_model)_description)/x.py"/>\n'
            '</launch>\n'),
        "src/info/package.xml": manifest("info", build_type="ament_cmake"),
        "src/info/CMakeLists.txt": "project(info)\n",
        "src/info/launch/info.launch.py": "from launch import LaunchDescription\n\n\n"
                                          "def generate_launch_description():\n"
                                          "    return LaunchDescription([])\n",
        "src/api/package.xml": manifest("api", ("exec_depend", "loader"),
                                        build_type="ament_cmake"),
        "src/api/CMakeLists.txt": "project(api)\n",
        "src/api/launch/test_api.launch.xml": (
            '<launch>\n  <arg name="vehicle_model" default="sample_vehicle"/>\n'
            '  <include file="$(find-pkg-share loader)/launch/params.launch.py"/>\n'
            '  <include file="$(find-pkg-share loader)/launch/own.launch.xml"/>\n'
            '</launch>\n'),
        "project.yaml": "project: p\nconfigurations:\n  c: [api/launch/test_api.launch.xml]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    assert findings(model) == [("loader/launch/own.launch.xml", 3, "mine_description"),
                               ("loader/launch/params.launch.py", 21, "kit_description")]
    undecided = [f.message for f in run_rule(RULE, model) if f.rule.endswith(UNDECIDED)]
    assert len(undecided) == 1 and "sample_vehicle_description" in undecided[0]
    reloaded = from_data(json.loads(json.dumps(model_to_data(model))))
    assert findings(reloaded) == findings(model)
    assert [u.chosen_by for c in reloaded.configurations for u in c.package_uses
            if u.package == "sample_vehicle_description"] == ["vehicle_model"]


TRIED_LAUNCH = """import os

from ament_index_python.packages import PackageNotFoundError, get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    try:
        extra = os.path.join(get_package_share_directory('extras'), 'lib')
    except Exception:
        extra = ''
    try:
        more = get_package_share_directory('more_extras')
    except PackageNotFoundError:
        more = ''
    try:
        needed = get_package_share_directory('needed')
    except ValueError:
        needed = ''
    model = get_package_share_directory('desc')
    return LaunchDescription([Node(package='rviz2', executable='rviz2', name='rviz2',
                                   arguments=[extra, more, needed, model])])
"""


def test_ros2_a_package_asked_for_in_a_try_that_catches_its_absence_is_optional(write_tree):
    """usv_workspace's domain_bridge.launch.py asks for common_interfaces' share folder
    in a ``try`` whose ``except Exception`` goes on without it (an optional library
    path): the launch file runs without the package, which is no undeclared dependency.
    A handler of another error (ValueError) does not catch PackageNotFoundError."""
    root = write_tree({
        "src/sim/package.xml": manifest("sim", ("exec_depend", "rviz2"),
                                        build_type="ament_cmake"),
        "src/sim/CMakeLists.txt": "project(sim)\n",
        "src/sim/launch/robot.launch.py": TRIED_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [sim/launch/robot.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    assert [package for _, _, package in findings(model)] == ["needed", "desc"]


NODE_HELPER_MODULE = """from launch_ros.actions import Node
from launch_ros.descriptions import ComposableNode
from launch_ros.actions import LoadComposableNodes


def node_or_component(package, executable, plugin=None, container='', parameters=()):
    if container:
        return [LoadComposableNodes(target_container=container, composable_node_descriptions=[
            ComposableNode(package=package, plugin=plugin, name=executable)])]
    return [Node(package=package, executable=executable, name=executable,
                 parameters=list(parameters))]


def watchdog():
    return [Node(package='watchdog4', executable='watchdog', name='watchdog')]
"""

NODE_HELPER_LAUNCH = """from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import ComposableNodeContainer
from launch_ros.substitutions import FindPackageShare
from helpers4.launch import node_or_component, watchdog


def generate_launch_description():
    config = PathJoinSubstitution([FindPackageShare('config4'), 'tracker.yaml'])
    return LaunchDescription([
        ComposableNodeContainer(package='rclcpp_components', executable='component_container',
                                name='box', namespace=''),
        *node_or_component('tracker4', 'tracker', parameters=[{'config': config}]),
        *node_or_component(package='camera4', executable='camera', plugin='camera4::Camera',
                           container='/box'),
        *watchdog(),
    ])
"""


def test_ros2_a_helper_of_another_package_starts_the_node_its_caller_names(write_tree):
    """kalman_robot: kalman_utils' ``launch_node_or_load_component(package, ...)`` builds
    the Node (or ComposableNode) of the package its caller names; the launch file that
    names it (kalman_aruco's, aruco_opencv) is the one that uses the package, not the
    helper's package; so is a FindPackageShare the caller writes among the parameters it
    hands the helper (kalman_arm2's panel layout file), which launch performs at the
    helper's Node. A package the helper names itself is the helper's use."""
    root = write_tree({
        "src/app4/package.xml": manifest("app4", ("exec_depend", "tracker4"),
                                         ("exec_depend", "helpers4"),
                                         ("exec_depend", "rclcpp_components"),
                                         build_type="ament_cmake"),
        "src/app4/CMakeLists.txt": "project(app4)\n",
        "src/app4/launch/app.launch.py": NODE_HELPER_LAUNCH,
        "src/helpers4/package.xml": manifest("helpers4", build_type="ament_python"),
        "src/helpers4/setup.py": ("from setuptools import setup\n"
                                  "setup(name='helpers4', packages=['helpers4'])\n"),
        "src/helpers4/helpers4/__init__.py": "",
        "src/helpers4/helpers4/launch.py": NODE_HELPER_MODULE,
        "project.yaml": "project: p\nconfigurations:\n  c: [app4/launch/app.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    assert findings(model) == [("app4/launch/app.launch.py", 9, "config4"),
                               ("app4/launch/app.launch.py", 14, "camera4"),
                               ("helpers4/helpers4/launch.py", 15, "watchdog4")]
