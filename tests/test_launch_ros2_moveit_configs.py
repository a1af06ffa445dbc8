"""moveit_configs_utils in ROS 2 Python launch files (every MoveIt 2 ``*_moveit_config``):
``MoveItConfigsBuilder`` reads the config package's files into move_group's parameters,
``generate_*_launch`` start the nodes launches.py starts. Both were calls not
interpreted: move_group's parameters missing, the demo's nodes unseen."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

CONFIG = "src/arm_moveit_config"

FILES = {
    f"{CONFIG}/package.xml": package_xml("arm_moveit_config", "ament_cmake"),
    f"{CONFIG}/.setup_assistant": """
        moveit_setup_assistant_config:
          urdf:
            package: arm_description
            relative_path: urdf/arm.urdf.xacro
            xacro_args: "prefix:=left_"
          srdf:
            relative_path: config/arm.srdf
        """,
    f"{CONFIG}/config/arm.srdf": """
        <robot name="arm">
          <group name="manipulator"><chain base_link="base" tip_link="tool"/></group>
          <virtual_joint name="fixed" type="fixed" parent_frame="world" child_link="base"/>
        </robot>
        """,
    f"{CONFIG}/config/kinematics.yaml": """
        manipulator:
          kinematics_solver: kdl_kinematics_plugin/KDLKinematicsPlugin
          kinematics_solver_timeout: 0.005
        """,
    f"{CONFIG}/config/joint_limits.yaml": """
        joint_limits:
          joint1: {has_velocity_limits: true, max_velocity: 2.0}
        """,
    f"{CONFIG}/config/moveit_controllers.yaml": """
        moveit_controller_manager: moveit_simple_controller_manager/MoveItSimpleControllerManager
        moveit_simple_controller_manager:
          controller_names: [arm_controller]
        """,
    f"{CONFIG}/config/ros2_controllers.yaml": "controller_manager: {}\n",
    f"{CONFIG}/config/ompl_planning.yaml": """
        planning_plugins: [ompl_interface/OMPLPlanner]
        planner_configs:
          RRTConnect: {type: geometric::RRTConnect}
        """,
    f"{CONFIG}/config/pilz_industrial_motion_planner_planning.yaml": """
        planning_plugins: [pilz_industrial_motion_planner/CommandPlanner]
        """,
    f"{CONFIG}/config/pilz_cartesian_limits.yaml": """
        cartesian_limits:
          max_trans_vel: 1.0
        """,
    "src/arm_description/package.xml": package_xml("arm_description", "ament_cmake"),
    "src/arm_description/urdf/arm.urdf.xacro": "<robot name='arm'/>\n",
}

MOVE_GROUP = """
from moveit_configs_utils import MoveItConfigsBuilder
from moveit_configs_utils.launches import generate_move_group_launch

def generate_launch_description():
    moveit_config = MoveItConfigsBuilder("arm").to_moveit_configs()
    return generate_move_group_launch(moveit_config)
"""


def run(write_tree, launch: str, files: dict[str, str] | None = None,
        env: dict[str, str] | None = None):
    tree = {**FILES, f"{CONFIG}/launch/main.launch.py": launch, **(files or {})}
    root = write_tree(tree)
    ws = scan([str(root / "src")], env or {})
    return load(str(root / CONFIG / "launch/main.launch.py"), ws, {}, env or {}), root


def params_of(model, executable: str) -> dict:
    """The parameters the launch gives the one node of that executable (their names
    below the node's)."""
    [index] = [i for i, n in enumerate(model.nodes) if n.executable == executable]
    prefix = model.nodes[index].name + "/"
    return {p.name[len(prefix):]: p.value for p in model.params if p.owner == index}


def test_move_group_gets_the_config_package_s_parameters(write_tree) -> None:
    model, _ = run(write_tree, MOVE_GROUP)
    # launches.py's node (its twin in gdb is for debug:=true, false by default)
    assert [(n.package, n.executable) for n in model.nodes] == [
        ("moveit_ros_move_group", "move_group")]
    params = params_of(model, "move_group")
    assert params["robot_description_kinematics.manipulator.kinematics_solver"] == \
        "kdl_kinematics_plugin/KDLKinematicsPlugin"
    assert params["robot_description_planning.joint_limits.joint1.max_velocity"] == 2.0
    # the Pilz pipeline is there: its cartesian limits join robot_description_planning
    assert params["robot_description_planning.cartesian_limits.max_trans_vel"] == 1.0
    assert params["moveit_controller_manager"] == \
        "moveit_simple_controller_manager/MoveItSimpleControllerManager"
    assert params["moveit_simple_controller_manager.controller_names"] == ["arm_controller"]
    assert params["moveit_manage_controllers"] is True
    assert params["ompl.planning_plugins"] == ["ompl_interface/OMPLPlanner"]
    assert params["default_planning_pipeline"] == "ompl"
    assert params["publish_robot_description_semantic"] is True
    assert params["capabilities"] == ""
    # moveit_configs_utils is not in the workspace: the default pipelines it adds are not
    # known, so the list is not known and a parameter '?' says there may be others
    assert params["planning_pipelines"] is None
    assert "?" in params
    # the descriptions: the xacro command lines on the files .setup_assistant names
    # (never run here), said where their values are made
    commands = sorted(d.message for d in model.diagnostics if d.code == "LAUNCH_UNKNOWN_VALUE"
                      and "xacro" in d.message)
    assert 'xacro arm_description/urdf/arm.urdf.xacro prefix:=left_"' in commands[0]
    assert 'xacro arm_moveit_config/config/arm.srdf"' in commands[1]
    assert {"robot_description", "robot_description_semantic"} <= set(params)


def test_chained_methods_override_the_files_read(write_tree) -> None:
    model, _ = run(write_tree, """
from launch import LaunchDescription
from launch_ros.actions import Node
from moveit_configs_utils import MoveItConfigsBuilder

def generate_launch_description():
    moveit_config = (
        MoveItConfigsBuilder("arm", package_name="arm_moveit_config")
        .robot_description_kinematics(file_path="config/other_kinematics.yaml")
        .trajectory_execution(file_path="config/moveit_controllers.yaml",
                              moveit_manage_controllers=False)
        .planning_scene_monitor(publish_robot_description=True)
        .planning_pipelines(pipelines=["ompl"])
        .to_moveit_configs()
    )
    moveit_config.moveit_cpp.update({"use_sim_time": True})
    return LaunchDescription([
        Node(package="moveit_ros_move_group", executable="move_group",
             parameters=[moveit_config.to_dict()]),
        Node(package="robot_state_publisher", executable="robot_state_publisher",
             parameters=[moveit_config.robot_description]),
    ])
""", {f"{CONFIG}/config/other_kinematics.yaml": "manipulator:\n  kinematics_solver: trac\n"})
    params = params_of(model, "move_group")
    assert params["robot_description_kinematics.manipulator.kinematics_solver"] == "trac"
    assert params["moveit_manage_controllers"] is False
    assert params["publish_robot_description"] is True
    assert params["publish_planning_scene"] is True
    assert params["planning_pipelines"] == ["ompl"]
    assert params["use_sim_time"] is True
    assert "?" not in params  # every file was read
    assert not any(name.startswith("pilz") or ".cartesian_limits" in name for name in params)
    assert set(params_of(model, "robot_state_publisher")) == {"robot_description"}


def test_what_cannot_be_read_stays_unknown_and_is_said(write_tree) -> None:
    model, _ = run(write_tree, """
from moveit_configs_utils import MoveItConfigsBuilder
from moveit_configs_utils.launches import generate_move_group_launch

def generate_launch_description():
    moveit_config = (MoveItConfigsBuilder("arm")
                     .joint_limits(file_path="config/missing_limits.yaml")
                     .to_moveit_configs())
    return generate_move_group_launch(moveit_config)
""")
    params = params_of(model, "move_group")
    assert "robot_description_planning.?" in params  # not absent: not known
    said = [d for d in model.diagnostics if d.code == "LAUNCH_PY_FILE_UNKNOWN"
            and "missing_limits.yaml" in d.message]
    assert said and said[0].location.line == 5  # the statement that asks for it
    model, _ = run(write_tree, """
from moveit_configs_utils import MoveItConfigsBuilder
from moveit_configs_utils.launches import generate_move_group_launch

def generate_launch_description():
    moveit_config = MoveItConfigsBuilder("other").to_moveit_configs()
    return generate_move_group_launch(moveit_config)
""")
    assert "?" in params_of(model, "move_group")
    assert any("other_moveit_config" in d.message for d in model.diagnostics
               if d.code == "LAUNCH_PY_UNSUPPORTED")


def test_a_description_file_that_is_not_there_is_left_out_as_moveit_does(
        write_tree) -> None:
    """No ``.setup_assistant`` and no ``config/<robot>.urdf``: moveit_configs_utils'
    ``robot_description()`` catches load_xacro's file-not-found error, warns and leaves
    the description out (MoveIt reads /robot_description); open_manipulator's
    ``MoveItConfigsBuilder(robot_name='omx_f', ...)`` configs were said unknown."""
    bare = "src/bare_moveit_config"
    files = {f"{bare}/package.xml": package_xml("bare_moveit_config", "ament_cmake"),
             f"{bare}/config/kinematics.yaml": "manipulator: {kinematics_solver: kdl}\n"}
    model, _ = run(write_tree, """
from launch import LaunchDescription
from launch_ros.actions import Node
from moveit_configs_utils import MoveItConfigsBuilder

def generate_launch_description():
    moveit_config = MoveItConfigsBuilder("bare").to_moveit_configs()
    return LaunchDescription([
        Node(package="moveit_ros_move_group", executable="move_group",
             parameters=[moveit_config.to_dict()]),
        Node(package="robot_state_publisher", executable="robot_state_publisher",
             parameters=[moveit_config.robot_description]),
    ])
""", files)
    params = params_of(model, "move_group")
    assert params["robot_description_kinematics.manipulator.kinematics_solver"] == "kdl"
    assert "robot_description" not in params
    assert params_of(model, "robot_state_publisher") == {}
    said = [d for d in model.diagnostics if d.code == "LAUNCH_MOVEIT_DESCRIPTION_TOPIC"]
    assert len(said) == 1 and "bare.urdf" in said[0].message
    assert said[0].severity == "info" and said[0].location.line == 6
    assert not any("bare.urdf" in d.message for d in model.diagnostics
                   if d.code == "LAUNCH_PY_UNSUPPORTED")
    # xacro arguments with a substitution: an Xacro substitution, which fails when
    # launch runs it; not known here, as before
    model, _ = run(write_tree, """
from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from moveit_configs_utils import MoveItConfigsBuilder

def generate_launch_description():
    moveit_config = (MoveItConfigsBuilder("bare")
                     .robot_description(mappings={"x": LaunchConfiguration("x")})
                     .to_moveit_configs())
    return LaunchDescription([
        Node(package="robot_state_publisher", executable="robot_state_publisher",
             parameters=[moveit_config.robot_description]),
    ])
""", files)
    assert "robot_description" in params_of(model, "robot_state_publisher")
    assert not any(d.code == "LAUNCH_MOVEIT_DESCRIPTION_TOPIC" for d in model.diagnostics)


def test_the_demo_starts_the_config_package_s_launch_files(write_tree) -> None:
    helpers = {
        f"{CONFIG}/launch/{name}.launch.py": f"""
from moveit_configs_utils import MoveItConfigsBuilder
from moveit_configs_utils.launches import generate_{name}_launch

def generate_launch_description():
    return generate_{name}_launch(MoveItConfigsBuilder("arm").to_moveit_configs())
""" for name in ("rsp", "move_group", "moveit_rviz", "spawn_controllers",
                 "static_virtual_joint_tfs", "warehouse_db")}
    demo = """
from moveit_configs_utils import MoveItConfigsBuilder
from moveit_configs_utils.launches import generate_demo_launch

def generate_launch_description():
    return generate_demo_launch(MoveItConfigsBuilder("arm").to_moveit_configs())
"""
    model, _ = run(write_tree, demo, helpers)
    # use_rviz true, db false by default: no warehouse
    assert sorted(n.executable for n in model.nodes) == [
        "move_group", "robot_state_publisher", "ros2_control_node", "rviz2", "spawner",
        "spawner", "static_transform_publisher"]
    assert sorted(n.args for n in model.nodes if n.executable == "spawner") == [
        "arm_controller", "joint_state_broadcaster"]
    [tf] = [n for n in model.nodes if n.executable == "static_transform_publisher"]
    assert (tf.name, tf.args) == ("/static_transform_publisher0",
                                  "--frame-id world --child-frame-id base")
    assert "LAUNCH_PY_UNSUPPORTED" not in [d.code for d in model.diagnostics]
    # ros2_control_node: from moveit_configs_utils 2.9.0 on (jazzy) it reads the
    # description rsp publishes; before (humble) it is given it
    [control] = [n for n in model.nodes if n.executable == "ros2_control_node"]
    assert control.remaps == [("/controller_manager/robot_description", "/robot_description")]
    assert "robot_description" not in params_of(model, "ros2_control_node")
    assert any("version is not known" in d.message for d in model.diagnostics)
    model, _ = run(write_tree, demo, helpers, {"ROS_DISTRO": "humble"})
    [control] = [n for n in model.nodes if n.executable == "ros2_control_node"]
    assert control.remaps == []
    assert "robot_description" in params_of(model, "ros2_control_node")
    model, _ = run(write_tree, demo, {**helpers, "src/moveit_configs_utils/package.xml":
                                      package_xml("moveit_configs_utils").replace(
                                          "0.1.0", "2.12.4")}, {"ROS_DISTRO": "humble"})
    [control] = [n for n in model.nodes if n.executable == "ros2_control_node"]
    assert control.remaps  # the workspace's moveit_configs_utils decides


def test_a_field_of_the_configs_set_by_the_launch_file(write_tree) -> None:
    # crane_plus' run_move_group.launch.py: the description from a launch argument
    model, _ = run(write_tree, """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from moveit_configs_utils import MoveItConfigsBuilder
from moveit_configs_utils.launches import generate_rsp_launch

def generate_launch_description():
    moveit_config = MoveItConfigsBuilder("arm").to_moveit_configs()
    moveit_config.robot_description = {"robot_description": LaunchConfiguration("urdf")}
    return LaunchDescription([DeclareLaunchArgument("urdf", default_value="<robot/>"),
                              generate_rsp_launch(moveit_config)])
""")
    assert params_of(model, "robot_state_publisher") == {
        "robot_description": "<robot/>", "publish_frequency": 15.0}
    assert "LAUNCH_PY_UNSUPPORTED" not in [d.code for d in model.diagnostics]


def test_moveit_configs_utils_default_pipelines_when_it_is_in_the_workspace(write_tree) -> None:
    utils = "src/moveit2/moveit_configs_utils"
    model, _ = run(write_tree, MOVE_GROUP, {
        f"{utils}/package.xml": package_xml("moveit_configs_utils", "ament_python"),
        f"{utils}/default_configs/ompl_planning.yaml": "planning_plugins: [default_ompl]\n",
        f"{utils}/default_configs/chomp_planning.yaml": "planning_plugins: [chomp]\n",
        f"{utils}/default_configs/ompl_defaults.yaml": "planner_configs: {PRM: {}}\n",
    })
    params = params_of(model, "move_group")
    # the config package's pipelines first, then the defaults it does not have
    assert params["planning_pipelines"] == ["ompl", "pilz_industrial_motion_planner", "chomp"]
    assert params["ompl.planning_plugins"] == ["ompl_interface/OMPLPlanner"]  # the package's
    assert params["chomp.planning_plugins"] == ["chomp"]
    assert "ompl.planner_configs.PRM" not in params  # the package's ompl has its own
    assert "?" not in params
    # its own share folder is its code's look-up, not one of the launch file's package
    assert "moveit_configs_utils" not in [use.package for use in model.package_uses]
    assert "arm_description" in [use.package for use in model.package_uses]


def test_launch_param_builder_reads_the_package_s_files(write_tree) -> None:
    # MoveIt 2's servo launch files: ParameterBuilder("pkg").yaml(...).to_dict()
    model, _ = run(write_tree, """
from launch import LaunchDescription
from launch_ros.actions import Node
from launch_param_builder import ParameterBuilder, load_yaml

def generate_launch_description():
    servo = (ParameterBuilder("arm_moveit_config")
             .yaml("config/servo.yaml", parameter_namespace="moveit_servo")
             .parameter("moveit_servo.use_gazebo", False)
             .to_dict())
    templated = ParameterBuilder("arm_moveit_config").yaml("config/templated.yaml").to_dict()
    return LaunchDescription([
        Node(package="moveit_servo", executable="servo_node", parameters=[servo]),
        Node(package="other", executable="templated", parameters=[templated]),
    ])
""", {f"{CONFIG}/config/servo.yaml": "publish_period: 0.034\nmove_group_name: arm\n",
      f"{CONFIG}/config/templated.yaml": "angle: {{ radians(90) }}\n"})
    # a Jinja2 template, rendered by load_yaml before it is read: not known, said; and
    # ParameterBuilder's parameters are a class attribute: both builders fill one dict,
    # which both nodes get (launch_ros reads it when the nodes run)
    assert params_of(model, "servo_node") == params_of(model, "templated") == {
        "moveit_servo.publish_period": 0.034, "moveit_servo.move_group_name": "arm",
        "moveit_servo.use_gazebo": False, "?": None}
    assert any("templated.yaml is a Jinja2 template" in d.message for d in model.diagnostics)


def test_the_default_pipeline_of_files_listed_in_no_known_order(write_tree) -> None:
    second = "src/second_moveit_config"
    model, _ = run(write_tree, """
from launch import LaunchDescription
from launch_ros.actions import Node
from moveit_configs_utils import MoveItConfigsBuilder

def generate_launch_description():
    listed = (MoveItConfigsBuilder("arm", package_name="second_moveit_config")
              .planning_pipelines(load_all=False).to_moveit_configs())
    given = (MoveItConfigsBuilder("arm", package_name="second_moveit_config")
             .planning_pipelines(pipelines=["stomp", "chomp"]).to_moveit_configs())
    return LaunchDescription([
        Node(package="a", executable="listed", parameters=[listed.planning_pipelines]),
        Node(package="a", executable="given", parameters=[given.planning_pipelines])])
""", {f"{second}/package.xml": package_xml("second_moveit_config", "ament_cmake"),
      f"{second}/config/chomp_planning.yaml": "planning_plugins: [chomp]\n",
      f"{second}/config/stomp_planning.yaml": "planning_plugins: [stomp]\n"})
    # the first file Path.iterdir gives: not known
    listed = params_of(model, "listed")
    assert listed["default_planning_pipeline"] is None
    assert sorted(listed["planning_pipelines"]) == ["chomp", "stomp"]
    assert any("first *_planning.yaml" in d.message for d in model.diagnostics)
    assert params_of(model, "given")["default_planning_pipeline"] == "stomp"


def test_bad_config_files_are_said_not_raised(write_tree) -> None:
    model, _ = run(write_tree, MOVE_GROUP, {
        f"{CONFIG}/.setup_assistant": "moveit_setup_assistant_config: {urdf: {package: 5, "
                                      "relative_path: [1]}, srdf: 7}\n",
        f"{CONFIG}/config/kinematics.yaml": "manipulator: [unclosed\n",
        f"{CONFIG}/config/joint_limits.yaml": "",
    })
    params = params_of(model, "move_group")
    assert "robot_description_kinematics.?" in params
    said = [d for d in model.diagnostics if "kinematics.yaml cannot be read as YAML" in d.message]
    assert said and said[0].location.file.endswith("main.launch.py")
    assert params["robot_description_planning"] is None  # an empty file: None, as yaml's


def test_the_default_pipelines_of_the_distribution_when_not_in_the_workspace(
        write_tree) -> None:
    # moveit_configs_utils adds its default_configs' pipelines: by ROS_DISTRO, their names
    # are known (jazzy's: chomp, ompl, pilz, stomp), their files not
    model, _ = run(write_tree, MOVE_GROUP, env={"ROS_DISTRO": "jazzy"})
    params = params_of(model, "move_group")
    assert params["planning_pipelines"] == [
        "ompl", "pilz_industrial_motion_planner", "chomp", "stomp"]
    assert params["default_planning_pipeline"] == "ompl"
    assert "chomp.?" in params and "stomp.?" in params and "?" not in params
    assert params["ompl.planning_plugins"] == ["ompl_interface/OMPLPlanner"]  # the package's
    model, _ = run(write_tree, MOVE_GROUP, env={"ROS_DISTRO": "humble"})
    params = params_of(model, "move_group")
    assert params["planning_pipelines"] == ["ompl", "pilz_industrial_motion_planner", "chomp"]


def test_a_builder_not_known_statically_is_said_once_not_at_each_chained_call(
        write_tree) -> None:
    """abb_ros2's abb_moveit.launch.py: ``MoveItConfigsBuilder(.., package_name=
    arg.perform(context))`` of an argument without a value, then eight chained calls
    and ``.to_dict()`` given to two nodes: every second call of the chain and each
    node's parameters were said again (6 warnings more)."""
    model, _ = run(write_tree, """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from moveit_configs_utils import MoveItConfigsBuilder

def setup(context):
    package = LaunchConfiguration("moveit_config_package")
    config = (MoveItConfigsBuilder("arm", package_name=package.perform(context))
              .robot_description(file_path="urdf/arm.urdf.xacro")
              .robot_description_semantic(file_path="config/arm.srdf")
              .planning_pipelines()
              .robot_description_kinematics(file_path="config/kinematics.yaml")
              .planning_scene_monitor(publish_planning_scene=True)
              .to_moveit_configs())
    return [
        Node(package="moveit_ros_move_group", executable="move_group",
             parameters=[config.to_dict()]),
        Node(package="rviz2", executable="rviz2", parameters=[config.to_dict()]),
    ]

def generate_launch_description():
    return LaunchDescription([DeclareLaunchArgument("moveit_config_package"),
                              OpaqueFunction(function=setup)])
""")
    said = [(d.location.line, d.message) for d in model.diagnostics
            if d.code == "LAUNCH_PY_UNSUPPORTED"]
    assert len(said) == 1 and said[0][0] == 9
    assert "MoveItConfigsBuilder" in said[0][1]
    # not known, not empty: each node's parameters are unknown, from that call
    for executable in ("move_group", "rviz2"):
        assert "?" in params_of(model, executable)
