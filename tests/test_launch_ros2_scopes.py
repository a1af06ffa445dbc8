"""launch_ros's scoped global actions: SetParametersFromFile, SetParameter, SetRemap,
PushROSNamespace, inside and outside a group; SetUseSimTime and SetROSLogDir (the launch
process's own node: nothing in the graph); ROSTimer. fixtures/launch_ros2/src/rover_fleet
has the same launch in XML and Python."""

from __future__ import annotations

from typing import Any

import pytest
from conftest import FIXTURES

from haros_arch.launch import load
from haros_arch.workspace import scan

ROOT = FIXTURES / "launch_ros2" / "src"


def run(name: str, args: dict[str, str] | None = None) -> Any:
    workspace = scan([str(ROOT)], {})
    return load(str(ROOT / "rover_fleet" / "launch" / name), workspace, args or {}, {})


def params_of(model: Any, node: str) -> dict[str, Any]:
    return {p.key: p.value for p in model.params if p.node == node}


@pytest.mark.parametrize("name", ["scopes.launch.xml", "scopes_launch.py"])
def test_group_scoped_parameter_file_parameter_and_remap(name: str) -> None:
    model = run(name, {"robot": "r7"})
    assert [n.name for n in model.nodes] == ["/r7/driver", "/r7/watch", "/driver", "/late"]
    driver, watch, outside, late = model.nodes
    # the file's /** and /**/driver entries, then the node's own rate wins
    assert params_of(model, "/r7/driver") == {
        "use_sim_time": True, "frame_prefix": "fleet", "rate": 50, "limits.speed": 1.5,
        "level": 3}
    assert {k: v for k, v in params_of(model, "/r7/watch").items()
            if k not in ("level_seen", "mode")} == {
        "use_sim_time": True, "frame_prefix": "fleet", "level": 3}
    assert driver.remaps == watch.remaps == [("cmd_vel", "/r7/cmd")]
    # outside the group: none of it
    assert params_of(model, "/driver") == {} and outside.remaps == []
    assert [c.statement for c in late.conditions] == ["timer"]
    assert "rover_fleet/config/common.yaml" in model.files
    assert model.diagnostics == []


def test_param_substitution_reads_set_parameter_in_scope() -> None:
    model = run("scopes.launch.xml")
    watch = params_of(model, "/r1/watch")
    assert (watch["level_seen"], watch["mode"]) == (3, "idle")


def test_parameter_file_with_unknown_path_is_reported(write_tree) -> None:
    from conftest import package_xml

    root = write_tree({
        "src/p/package.xml": package_xml("p", "ament_cmake"),
        "src/p/launch/a.launch.xml": """<launch>
  <arg name="params"/>
  <group>
    <set_parameters_from_file filename="$(var params)"/>
    <node pkg="p" exec="e" name="n"/>
  </group>
</launch>"""})
    workspace = scan([str(root / "src")], {})
    model = load(str(root / "src/p/launch/a.launch.xml"), workspace, {}, {})
    assert [n.name for n in model.nodes] == ["/n"]
    assert sorted({d.code for d in model.diagnostics}) == [
        "LAUNCH_ARG_UNSET", "LAUNCH_PARAM_FILE"]
    assert [d.location.line for d in model.diagnostics
            if d.code == "LAUNCH_PARAM_FILE"] == [4]


def test_with_not_interpreted_leaves_its_names_unknown_and_classes_are_skipped(
        write_tree) -> None:
    from conftest import package_xml

    root = write_tree({
        "src/p/package.xml": package_xml("p", "ament_python"),
        "src/p/launch/sim.launch.py": """
import os
from typing import TypedDict
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node

class RobotConfig(TypedDict):
    name: str

class Pipeline:
    def nodes(self):
        return []

def generate_launch_description():
    urdf = os.path.join(get_package_share_directory('missing_sim'), 'robot.urdf')
    with open(urdf, 'r') as infp:
        robot_description = infp.read()
        names = [n for n in ('a', 'b')]
    RobotConfig(name='a')
    return LaunchDescription([
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[{'robot_description': robot_description, 'rate': 5}]),
    ])
"""})
    workspace = scan([str(root / "src")], {})
    model = load(str(root / "src/p/launch/sim.launch.py"), workspace, {}, {})
    assert [n.executable for n in model.nodes] == ["robot_state_publisher"]
    assert {p.key: p.value for p in model.params} == {"robot_description": None, "rate": 5}
    found = [(d.code, d.location.line) for d in model.diagnostics]
    # the with, not run: its file is in a package launch finds only when it runs
    assert ("LAUNCH_PY_FILE_UNKNOWN", 16) in found
    assert not any("not defined" in d.message or "ClassDef" in d.message
                   for d in model.diagnostics)
    # a class of a base not interpreted (TypedDict) is not run: where it is used, that
    # use is reported, by name; a plain class (Pipeline) is read, and unused says nothing
    assert [d.location.line for d in model.diagnostics if "RobotConfig" in d.message] == [19]
    assert not [d for d in model.diagnostics if "Pipeline" in d.message]


def test_unset_environment_variable_is_an_unknown_value_not_an_unsupported_construct(
        write_tree) -> None:
    from conftest import package_xml

    root = write_tree({
        "src/p/package.xml": package_xml("p", "ament_python"),
        "src/p/launch/bot.launch.py": """
import os
from launch import LaunchDescription
from launch_ros.actions import Node

MODEL = os.environ['ROBOT_MODEL']

def generate_launch_description():
    return LaunchDescription([
        Node(package='p', executable='e', name='driver',
             parameters=[{'model': MODEL, 'home': os.getenv('FLEET_HOME', '/srv')}]),
    ])
"""})
    workspace = scan([str(root / "src")], {})
    model = load(str(root / "src/p/launch/bot.launch.py"), workspace, {}, {})
    assert {p.key: p.value for p in model.params} == {"model": None, "home": "/srv"}
    assert [(d.code, d.location.line) for d in model.diagnostics] == [
        ("LAUNCH_UNKNOWN_VALUE", 5)]


def test_rewritten_yaml_key_and_value_rewrites(write_tree) -> None:
    from conftest import package_xml

    root = write_tree({
        "src/p/package.xml": package_xml("p", "ament_python"),
        "src/p/config/nav.yaml": """costmap:
  ros__parameters:
    filters: [keepout, inflation]
    keepout:
      enabled: KEEPOUT_ZONE_ENABLED
controller_old:
  ros__parameters:
    rate: 10
""",
        "src/p/launch/nav.launch.py": """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.descriptions import ParameterFile
from nav2_common.launch import RewrittenYaml

def generate_launch_description():
    params = ParameterFile(RewrittenYaml(
        source_file=os.path.join(get_package_share_directory('p'), 'config', 'nav.yaml'),
        root_key='', param_rewrites={},
        key_rewrites={'controller_old': 'controller'},
        value_rewrites={'KEEPOUT_ZONE_ENABLED': LaunchConfiguration('keepout')},
        convert_types=True))
    return LaunchDescription([
        DeclareLaunchArgument('keepout', default_value='False'),
        Node(package='p', executable='c', name='costmap', parameters=[params]),
        Node(package='p', executable='c', name='controller', parameters=[params]),
    ])
"""})
    workspace = scan([str(root / "src")], {})
    model = load(str(root / "src/p/launch/nav.launch.py"), workspace, {}, {})
    assert {p.name: p.value for p in model.params} == {
        "/costmap/filters": ["keepout", "inflation"], "/costmap/keepout.enabled": False,
        "/controller/rate": 10}
    assert model.diagnostics == []


def test_rewritten_yaml_passed_to_an_include_keeps_its_rewrites(write_tree) -> None:
    """orca4's bringup rewrites nav2_params.yaml (``default_nav_to_pose_bt_xml`` set to
    its own tree) and gives the RewrittenYaml to nav2's navigation_launch.py as
    ``params_file``, which rewrites it again (use_sim_time, a root key): the included
    file read the source file, without the first rewrites (bt_navigator's tree was "bringup.py
    should replace me", BT_TREE_NOT_FOUND). Both apply, the outer's last."""
    from conftest import package_xml

    root = write_tree({
        "src/p/package.xml": package_xml("p", "ament_python"),
        "src/p/config/nav.yaml": """bt_navigator:
  ros__parameters:
    tree: "replace me"
    use_sim_time: true
    rate: 1
""",
        "src/p/launch/bringup.launch.py": """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from nav2_common.launch import RewrittenYaml

def generate_launch_description():
    share = get_package_share_directory('p')
    configured = RewrittenYaml(
        source_file=os.path.join(share, 'config', 'nav.yaml'),
        param_rewrites={'tree': '/trees/mine.xml', 'rate': '5'}, convert_types=True)
    return LaunchDescription([
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(os.path.join(share, 'launch', 'nav.launch.py')),
            launch_arguments={'params_file': configured, 'sim': 'False'}.items()),
    ])
""",
        "src/p/launch/nav.launch.py": """
from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from nav2_common.launch import RewrittenYaml

def generate_launch_description():
    params = RewrittenYaml(
        source_file=LaunchConfiguration('params_file'), root_key='',
        param_rewrites={'use_sim_time': LaunchConfiguration('sim'), 'rate': '7'},
        convert_types=True)
    return LaunchDescription([
        Node(package='p', executable='bt', name='bt_navigator', parameters=[params]),
    ])
"""})
    workspace = scan([str(root / "src")], {})
    model = load(str(root / "src/p/launch/bringup.launch.py"), workspace, {}, {})
    assert {p.name: p.value for p in model.params} == {
        "/bt_navigator/tree": "/trees/mine.xml", "/bt_navigator/use_sim_time": False,
        "/bt_navigator/rate": 7}
    assert model.diagnostics == []


RESET_XML = """<launch>
  <arg name="robot" default="r1"/>
  <arg name="rate" default="5"/>
  <group>
    <push_ros_namespace namespace="ns1"/>
    <set_parameter name="level" value="2"/>
    <set_remap from="a" to="b"/>
    <reset><keep name="robot" value="$(var robot)_kept"/></reset>
    <node pkg="p" exec="e" name="$(var robot)">
      <param name="rate" value="$(var rate 9)"/>
    </node>
  </group>
</launch>"""

RESET_PY = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, ResetLaunchConfigurations
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushROSNamespace, SetParameter, SetRemap

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='r1'),
        DeclareLaunchArgument('rate', default_value='5'),
        GroupAction([
            PushROSNamespace('ns1'), SetParameter(name='level', value=2),
            SetRemap(src='a', dst='b'),
            ResetLaunchConfigurations({'robot': [LaunchConfiguration('robot'), '_kept']}),
            Node(package='p', executable='e', name=LaunchConfiguration('robot'),
                 parameters=[{'rate': LaunchConfiguration('rate', default='9')}]),
        ]),
    ])
"""


@pytest.mark.parametrize(("name", "text"), [("r.launch.xml", RESET_XML),
                                            ("r.launch.py", RESET_PY)])
def test_reset_launch_configurations_clears_namespace_remaps_and_globals(
        write_tree, name: str, text: str) -> None:
    from conftest import package_xml

    root = write_tree({"src/p/package.xml": package_xml("p", "ament_python"),
                       f"src/p/launch/{name}": text})
    workspace = scan([str(root / "src")], {})
    model = load(str(root / "src/p/launch" / name), workspace, {}, {})
    [node] = model.nodes
    assert (node.name, node.remaps) == ("/r1_kept", [])
    assert {p.key: p.value for p in model.params} == {"rate": 9}
    assert model.diagnostics == []


def test_a_parameter_file_that_is_not_there_is_said_where_it_is_given(write_tree) -> None:
    """robotiq_control.launch.py:99-117 gives controller_manager
    config/robotiq_update_rate.yaml, which the package does not have: one warning at the
    Node (launch_ros skips the file with a warning and starts the node), not an error
    located at the missing file's own path, line 0; what it would set stays unknown."""
    from conftest import package_xml

    root = write_tree({
        "src/p/package.xml": package_xml("p", "ament_cmake"),
        "src/p/config/there.yaml": "/**:\n  ros__parameters:\n    rate: 5\n",
        "src/p/launch/a.launch.py": """from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    share = FindPackageShare('p')
    return LaunchDescription([
        Node(package='p', executable='e', name='n',
             parameters=[PathJoinSubstitution([share, 'config', 'missing.yaml']),
                         PathJoinSubstitution([share, 'config', 'there.yaml'])]),
    ])
"""})
    workspace = scan([str(root / "src")], {})
    model = load(str(root / "src/p/launch/a.launch.py"), workspace, {}, {})
    assert [(d.code, d.severity, d.location.file, d.location.line) for d in model.diagnostics] \
        == [("LAUNCH_PARAM_FILE", "warning", "p/launch/a.launch.py", 10)]
    assert "p/config/missing.yaml does not exist" in model.diagnostics[0].message
    assert params_of(model, "/n")["rate"] == 5


def test_a_parameter_file_launch_ros_opens_itself_must_be_there(write_tree) -> None:
    """autoware_core 6207f301d: preprocessor.launch.py gives its crop box filter
    component ``ParameterFile(config/crop_box_filter.param.yaml, allow_substs=True)``, a
    file the package has not (its file is crop_box_filter_node.param.yaml). launch_ros
    opens a composable node's parameter files to build the load request
    (to_parameters_list's open()) and a ParameterFile with allow_substs to substitute in
    it: a file not there raises FileNotFoundError and ros2 launch fails, an error where
    the launch file gives it. A plain Node's missing file stays the warning (launch_ros
    skips it and starts the node)."""
    from conftest import package_xml

    root = write_tree({
        "src/p/package.xml": package_xml("p", "ament_cmake"),
        "src/p/config/there.yaml": "/**:\n  ros__parameters:\n    rate: 5\n",
        "src/p/launch/a.launch.py": """from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import ComposableNodeContainer, Node
from launch_ros.descriptions import ComposableNode, ParameterFile
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    share = FindPackageShare('p')
    missing = PathJoinSubstitution([share, 'config', 'missing.yaml'])
    there = PathJoinSubstitution([share, 'config', 'there.yaml'])
    return LaunchDescription([
        ComposableNodeContainer(
            package='rclcpp_components', executable='component_container', name='box',
            namespace='', composable_node_descriptions=[
                ComposableNode(package='p', plugin='p::Filter', name='filter',
                               parameters=[missing, there])]),
        Node(package='p', executable='e', name='subst',
             parameters=[ParameterFile(missing, allow_substs=True)]),
        Node(package='p', executable='e', name='plain', parameters=[missing, there]),
    ])
"""})
    workspace = scan([str(root / "src")], {})
    model = load(str(root / "src/p/launch/a.launch.py"), workspace, {}, {})
    said = [(d.code, d.severity, d.location.line) for d in model.diagnostics
            if "missing.yaml" in d.message]
    assert said == [("LAUNCH_BAD_VALUE", "error", 16), ("LAUNCH_BAD_VALUE", "error", 19),
                    ("LAUNCH_PARAM_FILE", "warning", 20)]
    errors = [d.message for d in model.diagnostics if d.code == "LAUNCH_BAD_VALUE"]
    assert "to load the component" in errors[0] and "allow_substs" in errors[1]
    assert params_of(model, "/filter")["rate"] == 5
    assert params_of(model, "/plain")["rate"] == 5


def test_a_parameter_file_outside_the_workspace_is_not_read(write_tree) -> None:
    """A ROS 2 parameter file is read only inside the workspace and the installed
    packages, as a ROS 1 ``<rosparam file>`` and ``$(file-content)`` are: it was read
    from anywhere (clearpath_common's /etc/clearpath/platform/config/control.yaml was an
    error for not being there; any file that is there was read into the model)."""
    from conftest import package_xml

    root = write_tree({
        "src/p/package.xml": package_xml("p", "ament_cmake"),
        "outside.yaml": "/**:\n  ros__parameters:\n    secret: 42\n",
        "src/p/launch/a.launch.py": """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='p', executable='e', name='n', parameters=['PLACE/outside.yaml']),
    ])
"""})
    launch = root / "src/p/launch/a.launch.py"
    launch.write_text(launch.read_text().replace("PLACE", str(root)))
    workspace = scan([str(root / "src")], {})
    model = load(str(launch), workspace, {}, {})
    assert "secret" not in params_of(model, "/n")
    assert [(d.code, d.location.line) for d in model.diagnostics] == [
        ("LAUNCH_UNKNOWN_VALUE", 7)]
    assert "outside the workspace" in model.diagnostics[0].message


def test_an_included_launch_file_outside_the_workspace_is_not_read(write_tree) -> None:
    """An included launch file is read only inside the workspace and the installed
    packages, as parameter files are: Clearpath's robot_spawn.launch.py includes
    ``$HOME/clearpath/platform/launch/platform-service.launch.py``, which its generator
    writes on the robot; the analysing machine's HOME made it a missing file (an error,
    launch-missing-reference), and a file there would have been read into the model."""
    from conftest import package_xml

    root = write_tree({
        "src/p/package.xml": package_xml("p", "ament_cmake"),
        "home/gen/there.launch.py": """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package='p', executable='e', name='stray')])
""",
        "src/p/launch/a.launch.py": """from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import EnvironmentVariable, PathJoinSubstitution


def generate_launch_description():
    here = PathJoinSubstitution([EnvironmentVariable('HOME'), 'gen', 'there.launch.py'])
    gone = PathJoinSubstitution([EnvironmentVariable('HOME'), 'gen', 'gone.launch.py'])
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource([here])),
        IncludeLaunchDescription(PythonLaunchDescriptionSource([gone])),
    ])
"""})
    environment = {"HOME": str(root / "home")}
    workspace = scan([str(root / "src")], environment)
    model = load(str(root / "src/p/launch/a.launch.py"), workspace, {}, environment)
    assert [n.name for n in model.nodes] == []
    assert [(d.code, d.location.line) for d in model.diagnostics] == [
        ("LAUNCH_UNKNOWN_VALUE", 11), ("LAUNCH_UNKNOWN_VALUE", 12)]
    assert all("outside the workspace" in d.message for d in model.diagnostics)


def test_an_included_launch_file_the_build_makes_is_unread_not_missing(write_tree) -> None:
    """A launch file a package installs from its build folder (ros_gz_sim's
    gz_sim.launch.py: ``configure_file`` of gz_sim.launch.py.in, then
    ``install(FILES ${CMAKE_CURRENT_BINARY_DIR}/launch/gz_sim.launch.py ...)``) is there
    after colcon build but has no source file: an unread include (what it starts is
    unknown), not a missing file (an error, launch-missing-reference). A file no rule
    installs stays missing."""
    from conftest import package_xml

    root = write_tree({
        "src/q/package.xml": package_xml("q", "ament_cmake"),
        "src/q/CMakeLists.txt": """cmake_minimum_required(VERSION 3.5)
project(q)
configure_file(launch/sim.launch.py.in launch/sim.launch.py @ONLY)
install(FILES "${CMAKE_CURRENT_BINARY_DIR}/launch/sim.launch.py"
  DESTINATION share/${PROJECT_NAME}/launch)
install(DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}/made" DESTINATION share/${PROJECT_NAME})
""",
        "src/q/launch/sim.launch.py.in": "# @X@\n",
        "src/p/package.xml": package_xml("p", "ament_cmake"),
        "src/p/launch/a.launch.py": """import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource


def generate_launch_description():
    q = get_package_share_directory('q')
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            os.path.join(q, 'launch', 'sim.launch.py'))),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            os.path.join(q, 'made', 'deep', 'x.launch.py'))),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            os.path.join(q, 'launch', 'gone.launch.py'))),
    ])
"""})
    workspace = scan([str(root / "src")], {})
    model = load(str(root / "src/p/launch/a.launch.py"), workspace, {}, {})
    assert [(d.code, d.location.line) for d in model.diagnostics] == [
        ("LAUNCH_UNKNOWN_VALUE", 11), ("LAUNCH_UNKNOWN_VALUE", 13),
        ("LAUNCH_FILE_MISSING", 15)]
    assert "made by the build" in model.diagnostics[0].message
    assert "CMakeLists.txt:4" in model.diagnostics[0].message
    assert "CMakeLists.txt:6" in model.diagnostics[1].message
    (top,) = model.tree
    kinds = [(item.kind, item.name.rsplit("/", 1)[-1]) for item in top.children]
    assert kinds[:2] == [("include", "sim.launch.py"), ("include", "x.launch.py")]
