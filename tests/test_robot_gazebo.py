"""Gazebo plugins of robot descriptions end to end on fixtures/robot (ROS 1 and ROS 2)."""

from __future__ import annotations

import os
import shutil

import pytest
from conftest import FIXTURES, package_xml
from lxml import etree

from haros_arch import pipeline
from haros_arch.model.load import from_data
from haros_arch.model.location import NOWHERE
from haros_arch.model.model import Model
from haros_arch.model.runtime import Configuration
from haros_arch.model.serialise import model_to_data
from haros_arch.project import ConfigurationSpec, Project
from haros_arch.robot import xacro
from haros_arch.robot.attach import xacro_command
from haros_arch.robot.bridge import _from_arguments
from haros_arch.workspace import Workspace

ROS1 = str(FIXTURES / "robot" / "ros1")
ROS2 = str(FIXTURES / "robot" / "ros2")


def analyse(root: str, launch: str, env: dict[str, str] | None = None,
            **args: str) -> Model:
    project = Project("robot", os.path.join(root, "project.yaml"), workspace=[root],
                      configurations=[ConfigurationSpec("c", [launch], dict(args))])
    return pipeline.analyse(project, env or {}, pipeline.Options(cache_dir=None, jobs=1))


def configuration(root: str, launch: str, env: dict[str, str] | None = None,
                  **args: str) -> Configuration:
    return analyse(root, launch, env, **args).configurations[0]


def made(config: Configuration) -> list[tuple[str, str, str, str | None]]:
    return sorted((link.node.name, link.kind, link.resource.name, link.type)
                  for link in config.links if link.origin == "description")


def test_ros1_plugins_are_calls_of_the_gazebo_node_with_their_names_and_types():
    config = configuration(ROS1, "bot_gazebo/launch/sim.launch", {"BOT_CAMERA": "0"})
    assert made(config) == [
        ("/gazebo", "publish", "/front/scan", "sensor_msgs/LaserScan"),
        ("/gazebo", "publish", "/imu/data", "sensor_msgs/Imu"),
        ("/gazebo", "publish", "/joint_states", "sensor_msgs/JointState"),
        ("/gazebo", "publish", "/odom", "nav_msgs/Odometry"),
        ("/gazebo", "publish", "/tf", "tf2_msgs/TFMessage"),
        ("/gazebo", "server", "/default_imu", "std_srvs/Empty"),  # imu's default service
        ("/gazebo", "subscribe", "/cmd_vel", "geometry_msgs/Twist"),
    ]
    # the sensor topics meet the node that uses them
    scan = config.topic("/front/scan")
    assert [link.node.name for link in scan.subscribers] == ["/scan_reader"]
    assert [link.node.name for link in config.topic("/cmd_vel").publishers] == ["/scan_reader"]
    # no launch file starts Gazebo: a /gazebo instance stands for it, with the plugin's
    # unknown library said at its line
    codes = {(d.code, d.location.file, d.location.line) for d in config.diagnostics
             if d.code.startswith(("GAZEBO", "ROBOT"))}
    assert codes == {("GAZEBO_NOT_STARTED", "bot_gazebo/launch/sim.launch", 5),
                     ("GAZEBO_PLUGIN_UNKNOWN", "bot_description/urdf/bot.urdf.xacro", 43)}
    assert config.node("/gazebo").completeness == "unknown"
    (description,) = config.robot_descriptions
    assert (description.name, description.file) == ("/robot_description",
                                                     "bot_description/urdf/bot.urdf.xacro")
    assert description.files == ["bot_description/urdf/bot.urdf.xacro",
                                 "bot_description/urdf/parts.xacro"]
    assert description.links == ["base_link", "left_wheel", "right_wheel", "laser"]
    assert [(p.name, p.location.file, p.location.line, p.node)
            for p in description.plugins] == [
        ("laser_controller", "bot_description/urdf/parts.xacro", 19, "/gazebo"),
        ("diff_drive", "bot_description/urdf/bot.urdf.xacro", 33, "/gazebo"),
        ("imu", "bot_description/urdf/bot.urdf.xacro", 40, "/gazebo"),
        ("lights", "bot_description/urdf/bot.urdf.xacro", 43, None)]
    assert description.completeness == "partial"


def test_launch_arguments_reach_the_xacro_command():
    config = configuration(ROS1, "bot_gazebo/launch/sim.launch", {"BOT_CAMERA": "1"},
                           laser="false")
    names = [name for _, _, name, _ in made(config)]
    assert "/front/scan" not in names
    assert "/front_camera/image_raw" in names and "/front_camera/camera_info" in names


def test_a_description_condition_not_known_makes_the_plugin_calls_conditional():
    config = configuration(ROS1, "bot_gazebo/launch/sim.launch")  # BOT_CAMERA unset
    (image,) = [link for link in config.links if link.resource.name == "/front_camera/image_raw"]
    assert [(c.statement, c.text) for c in image.conditions] == [
        ("xacro:if", "if $(arg camera_enabled) (bot_description/urdf/bot.urdf.xacro:21)")]
    (scan,) = [link for link in config.links if link.resource.name == "/front/scan"
               and link.origin == "description"]
    assert scan.conditions == ()
    assert any("BOT_CAMERA" in r for r in config.robot_descriptions[0].completeness_reasons)


def test_ros2_plugins_are_nodes_of_their_own_with_namespace_and_remappings():
    config = configuration(ROS2, "bot2_description/launch/sim.launch.py")
    assert made(config) == [
        ("/bot2/drive", "publish", "/bot2/odom", "nav_msgs/msg/Odometry"),
        ("/bot2/drive", "subscribe", "/bot2/cmd_vel", "geometry_msgs/msg/Twist"),
        ("/bot2/lidar_driver", "publish", "/bot2/scan", "sensor_msgs/msg/LaserScan"),
        # a depth camera: its sensor's name, and the depth topics
        ("/camera_driver", "publish", "/cam/camera_info", "sensor_msgs/msg/CameraInfo"),
        ("/camera_driver", "publish", "/cam/depth/camera_info", "sensor_msgs/msg/CameraInfo"),
        ("/camera_driver", "publish", "/cam/depth/image_raw", "sensor_msgs/msg/Image"),
        ("/camera_driver", "publish", "/cam/image_raw", "sensor_msgs/msg/Image"),
        ("/camera_driver", "publish", "/cam/points", "sensor_msgs/msg/PointCloud2"),
    ]
    drive = config.node("/bot2/drive")
    assert drive.origin == "description" and drive.node.name == \
        "gazebo_plugins/gazebo_ros_diff_drive"
    # the description came from robot_state_publisher's Command(['xacro ', ...]) with the
    # launch argument (prefix:=front_)
    (description,) = config.robot_descriptions
    assert description.name == "/robot_description"
    assert description.links == ["front_base_link"]
    (control,) = description.ros2_control
    assert (control.name, control.hardware, control.joints, control.location.line) == (
        "GazeboSystem", "gazebo_ros2_control/GazeboSystem", ["front_wheel_joint"], 33)


def test_a_xacro_command_through_find_executable_without_xacro_installed():
    """``Command([PathJoinSubstitution([FindExecutable(name="xacro")]), " ", file])``:
    the analysis reads the xacro file itself, so xacro need not be on the PATH (it was
    a value not known, and the description was lost: survey C, rosbot's simulation)."""
    config = configuration(ROS2, "bot2_description/launch/sim_find.launch.py")
    (description,) = config.robot_descriptions
    assert description.links == ["front_base_link"]
    assert ("/bot2/drive", "subscribe", "/bot2/cmd_vel", "geometry_msgs/msg/Twist") in made(
        config)


def test_a_xacro_command_kept_in_a_launch_configuration():
    """``<let name="d" value="$(command '$(find-exec xacro) ...')"/>`` then ``<param
    name="robot_description" value="$(var d)"/>`` (gz_ros2_control's XML demos): the
    description is that command's output, as when the Command is given directly; it was
    not known (ROBOT_DESCRIPTION_UNKNOWN), so the simulated robot's plugins and its
    controller manager were missing from the XML configurations."""
    config = configuration(ROS2, "bot2_description/launch/sim_let.launch.xml")
    (description,) = config.robot_descriptions
    assert description.links == ["front_base_link"]
    assert ("/bot2/drive", "subscribe", "/bot2/cmd_vel", "geometry_msgs/msg/Twist") in made(
        config)
    assert "ROBOT_DESCRIPTION_UNKNOWN" not in {d.code for d in config.diagnostics}


def test_ros2_spawner_file_is_read_as_it_is():
    config = configuration(ROS2, "bot2_description/launch/model.launch.py")
    assert made(config) == [
        ("/imu_driver", "publish", "/imu", "sensor_msgs/msg/Imu"),
        ("/states", "publish", "/joint_states", "sensor_msgs/msg/JointState"),
    ]
    assert (config.robot_descriptions[0].name, config.robot_descriptions[0].file) == (
        "bot2_description/models/bot2.sdf", "bot2_description/models/bot2.sdf")


@pytest.mark.parametrize("launch", ["spawn.launch.py", "cat.launch.py"])
def test_a_description_read_as_it_is_keeps_a_prefix_no_xmlns_declares(write_tree, launch):
    """IOES-Lab/dave's DVL models: ``<sensor type="custom" gz:type="dvl">`` with no
    ``xmlns:gz``, spawned with ``ros_gz_sim create -file``. sdformat (tinyxml2) reads it,
    and so does urdfdom the output of ``cat``; lxml's namespace error had made the
    whole file unread (ROBOT_DESCRIPTION_FILE) and its plugins lost."""
    sdf = ('<?xml version="1.0"?>\n<sdf version="1.9">\n  <model name="dvl">\n'
           '    <link name="base">\n'
           '      <sensor name="dvl" type="custom" gz:type="dvl">\n'
           "        <topic>/dvl/velocity</topic>\n      </sensor>\n"
           '      <sensor name="imu" type="imu">\n'
           '        <plugin name="imu_driver" filename="libgazebo_ros_imu_sensor.so">\n'
           "          <ros><remapping>~/out:=imu</remapping></ros>\n"
           "        </plugin>\n      </sensor>\n    </link>\n  </model>\n</sdf>\n")
    head = ("import os\nfrom ament_index_python.packages import get_package_share_directory\n"
            "from launch import LaunchDescription\nfrom launch.substitutions import Command\n"
            "from launch_ros.actions import Node\n\n\ndef generate_launch_description():\n"
            "    sdf = os.path.join(get_package_share_directory('dvl'), 'models', "
            "'dvl.sdf')\n    return LaunchDescription([\n")
    root = write_tree({
        "dvl/package.xml": package_xml("dvl", "ament_cmake"),
        "dvl/CMakeLists.txt": "project(dvl)\n",
        "dvl/models/dvl.sdf": sdf,
        "dvl/launch/spawn.launch.py": head + (
            "        Node(package='gazebo_ros', executable='spawn_entity.py',\n"
            "             arguments=['-entity', 'dvl', '-file', sdf])])\n"),
        "dvl/launch/cat.launch.py": head + (
            "        Node(package='robot_state_publisher', executable='robot_state_publisher',"
            "\n             parameters=[{'robot_description': Command(['cat ', sdf])}]),\n"
            "        Node(package='gazebo_ros', executable='spawn_entity.py',\n"
            "             arguments=['-entity', 'dvl', '-topic', 'robot_description'])])\n"),
    })
    config = configuration(str(root), f"dvl/launch/{launch}")
    assert made(config) == [("/imu_driver", "publish", "/imu", "sensor_msgs/msg/Imu")]
    assert "ROBOT_DESCRIPTION_FILE" not in {d.code for d in config.diagnostics}


def test_an_earlier_parse_error_does_not_count_for_a_file_read_as_it_is(tmp_path):
    """lxml's exception carries the errors of earlier parses in the same thread too: a
    broken file read before made the namespace-only errors look fatal (the test above
    failed after the ROS 1 launch tests)."""
    with pytest.raises(etree.XMLSyntaxError):
        etree.fromstring(b"<a><b></a>")
    sdf = tmp_path / "dvl.sdf"
    sdf.write_text('<sdf version="1.9"><model name="dvl"><link name="base">'
                   '<sensor name="dvl" type="custom" gz:type="dvl"/></link></model></sdf>')
    description = xacro.expand(str(sdf), {}, Workspace(root=str(tmp_path)), {},
                               by_xacro=False)
    assert description.root is not None and not description.diagnostics


def test_xacro_still_rejects_a_prefix_no_xmlns_declares(write_tree):
    """xacro reads its files with minidom, namespace-aware: ``xacro:property`` without
    ``xmlns:xacro`` fails there, and so it does here."""
    root = write_tree({
        "bot/package.xml": package_xml("bot", "ament_cmake"),
        "bot/CMakeLists.txt": "project(bot)\n",
        "bot/urdf/bot.urdf.xacro": (
            '<?xml version="1.0"?>\n<robot name="bot">\n'
            '  <xacro:property name="r" value="1"/>\n  <link name="base"/>\n</robot>\n'),
        "bot/launch/rsp.launch.py": (
            "import os\nfrom ament_index_python.packages import get_package_share_directory\n"
            "from launch import LaunchDescription\nfrom launch.substitutions import Command\n"
            "from launch_ros.actions import Node\n\n\ndef generate_launch_description():\n"
            "    urdf = os.path.join(get_package_share_directory('bot'), 'urdf', "
            "'bot.urdf.xacro')\n    return LaunchDescription([\n"
            "        Node(package='robot_state_publisher', executable='robot_state_publisher',"
            "\n             parameters=[{'robot_description': Command(['xacro ', urdf])}]),\n"
            "        Node(package='gazebo_ros', executable='spawn_entity.py',\n"
            "             arguments=['-entity', 'bot', '-topic', 'robot_description'])])\n"),
    })
    config = configuration(str(root), "bot/launch/rsp.launch.py")
    # (launch runs the Command: xacro fails, and the launch stops)
    assert [(d.code, d.severity, d.location.file, d.location.line)
            for d in config.diagnostics if d.code.startswith("ROBOT_DESCRIPTION")] == [
        ("ROBOT_DESCRIPTION_COMMAND_FAILS", "error", "bot/urdf/bot.urdf.xacro", 3)]


def test_robot_descriptions_survive_the_json_model():
    model = analyse(ROS1, "bot_gazebo/launch/sim.launch", {"BOT_CAMERA": "0"})
    again = from_data(model_to_data(model))
    assert again.configurations[0].robot_descriptions == \
        model.configurations[0].robot_descriptions
    assert again.configurations[0].robot_descriptions[0].plugins[0].name == "laser_controller"


@pytest.mark.parametrize(("command", "expected"), [
    ("/opt/ros/noetic/bin/xacro --inorder '/ws/a b.urdf.xacro' ns:=/r x:=1",
     ("/ws/a b.urdf.xacro", {"ns": "/r", "x": "1"}, "xacro")),
    ("?/xacro /ws/r.xacro", ("/ws/r.xacro", {}, "xacro")),
    ("cat /ws/r.urdf", ("/ws/r.urdf", {}, "cat")),
    ("python3 make_urdf.py", None),
])
def test_xacro_command_lines(command: str, expected: object):
    assert xacro_command(command) == expected


def test_gz_systems_make_no_ros_calls_and_bridges_make_their_topics_ros_topics():
    config = configuration(ROS2, "bot2_description/launch/gz.launch.py")
    # the bridges' jazzy interface models name the nodes (ros_gz_bridge, ros_gz_image)
    # and know their parameters; the topics come from their arguments and config file
    assert made(config) == [
        ("/ros_gz_bridge", "publish", "/clock", "rosgraph_msgs/msg/Clock"),
        ("/ros_gz_bridge", "publish", "/joint_states", "sensor_msgs/msg/JointState"),
        ("/ros_gz_bridge", "publish", "/scan", "sensor_msgs/msg/LaserScan"),
        ("/ros_gz_bridge", "subscribe", "/cmd_vel", "geometry_msgs/msg/Twist"),
        ("/ros_gz_bridge", "subscribe", "/joint_states", "sensor_msgs/msg/JointState"),
        ("/ros_gz_image", "publish", "/camera/image_raw", "sensor_msgs/msg/Image"),
    ]
    (description,) = config.robot_descriptions
    assert [(p.filename, p.node) for p in description.plugins] == [
        ("gz-sim-diff-drive-system", None), ("libgazebo_ros_imu_sensor.so", None)]
    # a gazebo_ros plugin does not load in gz sim: not a gz system, said at its line
    assert [(d.code, d.location.line) for d in config.diagnostics
            if d.code == "GAZEBO_PLUGIN_UNKNOWN"] == [("GAZEBO_PLUGIN_UNKNOWN", 8)]


def test_image_bridge_publishes_through_image_transport():
    # image_bridge.cpp's image_transport::create_publisher: the transports' topics too
    config = configuration(ROS2, "bot2_description/launch/gz.launch.py")
    published = sorted(link.resource.name for link in config.links
                       if link.node.name == "/ros_gz_image" and link.kind == "publish")
    assert "/camera/image_raw/compressed" in published
    assert "/camera/image_raw/theora" in published


@pytest.mark.parametrize(("argument", "expected"), [
    ("/chatter@std_msgs/msg/String@gz.msgs.StringMsg",
     [("publish", "std_msgs/msg/String"), ("subscribe", "std_msgs/msg/String")]),
    ("/chatter@std_msgs/msg/String[gz.msgs.StringMsg", [("publish", "std_msgs/msg/String")]),
    ("/chatter@std_msgs/msg/String]gz.msgs.StringMsg", [("subscribe", "std_msgs/msg/String")]),
    ("/world/default/control@ros_gz_interfaces/srv/ControlWorld",  # gz types inferred
     [("server", "ros_gz_interfaces/srv/ControlWorld")]),
    ("/chatter@std_msgs/msg/String", []),  # a topic needs its gz type: refused
    ("/world/default/control@ros_gz_interfaces/srv/ControlWorld@gz.msgs.WorldControl"
     "@gz.msgs.Boolean", [("server", "ros_gz_interfaces/srv/ControlWorld")]),
    ("not-a-bridge", []),
])
def test_parameter_bridge_arguments(argument: str, expected: list[tuple[str, str]]):
    calls = list(_from_arguments([argument], NOWHERE))
    assert [(c.kind, c.type) for c in calls] == expected


def test_ros1_textfile_description_in_a_namespace():
    # spawn_model adds its namespace as robotNamespace to plugins that have none
    config = configuration(ROS1, "bot_gazebo/launch/textfile.launch")
    assert made(config) == [
        ("/gazebo", "publish", "/plain/ground_truth/odom", "nav_msgs/Odometry"),
        ("/gazebo", "publish", "/plain/joint_states", "sensor_msgs/JointState"),
    ]
    assert config.robot_descriptions[0].name == "/plain/robot_description"


def test_ros2_xml_command_substitution_gives_the_description():
    config = configuration(ROS2, "bot2_description/launch/sim.launch.xml")
    (description,) = config.robot_descriptions
    assert (description.name, description.links) == ("/xml/robot_description",
                                                     ["x_base_link"])
    assert ("/bot2/lidar_driver", "publish", "/bot2/scan", "sensor_msgs/msg/LaserScan") \
        in made(config)


def test_ros2_python_xacro_process_file_gives_the_description():
    config = configuration(ROS2, "bot2_description/launch/process_file.launch.py")
    (description,) = config.robot_descriptions
    assert (description.name, description.links) == ("/pf/robot_description",
                                                     ["pf_base_link"])
    assert ("/bot2/drive", "publish", "/bot2/odom", "nav_msgs/msg/Odometry") in made(config)


PARSE_DOC = """import os

import xacro
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def get_xacro_to_doc(xacro_file_path, mappings):
    doc = xacro.parse(open(xacro_file_path))
    xacro.process_doc(doc, mappings=mappings)
    return doc


def generate_launch_description():
    path = os.path.join(get_package_share_directory("bot2_description"), "urdf",
                        "bot2.urdf.xacro")
    doc = get_xacro_to_doc(path, {"prefix": "pd_"})
    raw = xacro.parse(open(path))
    return LaunchDescription([
        Node(package="robot_state_publisher", executable="robot_state_publisher",
             namespace="pd", parameters=[{"robot_description": doc.toxml()}]),
        Node(package="gazebo_ros", executable="spawn_entity.py", namespace="pd",
             arguments=["-topic", "robot_description", "-entity", "bot2"]),
        Node(package="robot_state_publisher", executable="robot_state_publisher",
             namespace="raw", parameters=[{"robot_description": raw.toxml()}]),
        Node(package="gazebo_ros", executable="spawn_entity.py", namespace="raw",
             arguments=["-topic", "robot_description", "-entity", "raw"]),
    ])
"""


def test_ros2_python_xacro_parse_and_process_doc_give_the_description(tmp_path):
    """bcr_bot's rviz.launch.py: ``doc = xacro.parse(open(path))``, then
    ``xacro.process_doc(doc, mappings=...)`` in place and ``doc.toxml()``; both calls
    were not interpreted (LAUNCH_PY_UNSUPPORTED) and the description not known. A
    document only parsed is the file as it is."""
    root = tmp_path / "ws"
    shutil.copytree(ROS2, root)
    (root / "bot2_description" / "launch" / "parse_doc.launch.py").write_text(PARSE_DOC)
    config = configuration(str(root), "bot2_description/launch/parse_doc.launch.py")
    assert sorted((d.name, d.file, tuple(d.links)) for d in config.robot_descriptions
                  if d.name.startswith("/pd/")) == [
        ("/pd/robot_description", "bot2_description/urdf/bot2.urdf.xacro", ("pd_base_link",))]
    # only parsed: the file as it is, a cat command's output
    assert "command \"cat bot2_description/urdf/bot2.urdf.xacro\" is not run" in {
        d.message.split(";")[0] for d in config.diagnostics}
    assert not [d for d in config.diagnostics if d.code.startswith("LAUNCH_PY")]


def test_gazebo_ros2_control_starts_a_controller_manager_that_hosts_the_spawned_controllers():
    # the plugin's <parameters> file gives the controller's class; its package is not
    # in the workspace here, so the controller takes ros2_controllers' jazzy model
    config = configuration(ROS2, "bot2_description/launch/sim.launch.py")
    manager = config.node("/controller_manager")
    assert manager is not None and manager.origin == "description"
    assert not [d for d in config.diagnostics if d.code == "PLUGIN_NOT_FOUND"]
    base = config.node("/base")
    assert base is not None and base.origin == "plugin" and base.node is not None
    assert base.node.model is not None and "diff_drive_controller" in base.node.model
    # ``~/cmd_vel_out`` is published under ``params_.publish_limited_velocity``, a
    # parameter no file sets here: its default, false, decides it
    assert {(link.kind, link.resource.name) for link in config.links
            if link.node.name == "/base" and link.kind in ("publish", "subscribe")} == {
        ("subscribe", "/base/cmd_vel"), ("publish", "/base/odom"), ("publish", "/tf")}
    (separation,) = [p for p in config.parameters if p.name == "/base/wheel_separation"]
    assert separation.value == 0.3 and separation.set_by_launch
    # at its key's line in the plugin's <parameters> file (was the file's first line)
    place = separation.launch_location
    with open(os.path.join(ROS2, place.file)) as lines:
        assert "wheel_separation:" in lines.read().splitlines()[place.line - 1]
    assert [r.node.name for r in separation.readers] == ["/base"]  # declared by the model
    assert config.node("/gazebo_ros2_control").completeness == "partial"


def test_a_bridge_without_a_model_gets_a_node_of_its_own():
    model = analyse(ROS2, "bot2_description/launch/gz.launch.py")
    config = model.configurations[0]
    assert config.node("/ros_gz_bridge").node.model is not None  # the shipped model
    without = pipeline.analyse(
        Project("robot", os.path.join(ROS2, "project.yaml"), workspace=[ROS2],
                configurations=[ConfigurationSpec(
                    "c", ["bot2_description/launch/gz.launch.py"], {})]),
        {}, pipeline.Options(cache_dir=None, jobs=1, models=False)).configurations[0]
    bridge = [n for n in without.nodes if n.node is not None
              and n.node.executable == "parameter_bridge"]
    # five topics, and its own parameters not known (test_robot_bridge_unknown_parameters)
    assert [(n.completeness, len([c for c in n.node.calls if c.kind != "read"]),
             [c.name for c in n.node.calls if c.kind == "read"]) for n in bridge] == [
        ("complete", 5, ["~?"])]


def test_ros1_spawned_controllers_are_loaded_by_the_gazebo_ros_control_of_the_description():
    # the spawner's controller goes to the controller manager gazebo_ros_control starts
    # in the Gazebo node (its load_controller service), not to a node of its own
    config = configuration(ROS1, "bot_control/launch/control.launch")
    assert config.node("/joint_state_controller") is None
    gazebo = {(link.kind, link.resource.name) for link in config.links
              if link.node.name == "/gazebo"}
    assert {("server", "/controller_manager/load_controller"),
            ("publish", "/joint_states"),  # joint_state_controller's, by the model
            ("read", "/joint_state_controller/publish_rate"),
            ("read", "/joint_state_controller/type")} <= gazebo
    assert not [d for d in config.diagnostics if d.code.startswith("PLUGIN")]


def test_a_ros1_spawner_given_a_yaml_file_loads_it_and_spawns_its_controllers(tmp_path):
    # controller_manager's ROS 1 spawner takes a file's path among its controllers: it
    # loads the file into its namespace and spawns each of its top-level keys (AutoRally's
    # simulation). The path was taken for a controller's name: PLUGIN_CLASS_UNKNOWN, and
    # joint_state_controller, its publisher and its parameters were not in the graph
    root = tmp_path / "ros1"
    shutil.copytree(ROS1, root)
    (root / "bot_control" / "launch" / "control_file.launch").write_text(
        '<launch>\n'
        '  <param name="robot_description"'
        ' command="xacro \'$(find bot_control)/urdf/arm.urdf.xacro\'"/>\n'
        '  <node name="spawn_arm" pkg="gazebo_ros" type="spawn_model"\n'
        '        args="-urdf -param robot_description -model arm"/>\n'
        '  <node name="controller_spawner" pkg="controller_manager" type="spawner"\n'
        '        args="--shutdown-timeout 3 $(find bot_control)/config/controllers.yaml"/>\n'
        '</launch>\n')
    config = configuration(str(root), "bot_control/launch/control_file.launch")
    gazebo = {(link.kind, link.resource.name) for link in config.links
              if link.node.name == "/gazebo"}
    assert {("publish", "/joint_states"),
            ("read", "/joint_state_controller/publish_rate"),
            ("read", "/joint_state_controller/type")} <= gazebo
    assert not [d for d in config.diagnostics if d.code.startswith("PLUGIN")]
    rate = config.parameter("/joint_state_controller/publish_rate")
    assert rate is not None and rate.value == 50 and rate.set_by_launch
    assert rate.launch_location.file.endswith("config/controllers.yaml")
    assert rate.launch_location.line == 3


def test_ros1_sensor_and_gripper_controllers_take_ros_controllers_models(tmp_path):
    # ros_controllers' force_torque_sensor_controller, imu_sensor_controller and
    # gripper_action_controller (UR's and Kinova's arms): not modelled, each was
    # PLUGIN_NOT_FOUND and its host partial
    root = tmp_path / "ros1"
    shutil.copytree(ROS1, root)
    (root / "bot_control" / "config" / "sensors.yaml").write_text(
        "ft_controller:\n  type: force_torque_sensor_controller/ForceTorqueSensorController\n"
        "  publish_rate: 100\n"
        "imu_controller:\n  type: imu_sensor_controller/ImuSensorController\n"
        "  publish_rate: 50\n"
        "gripper_controller:\n  type: position_controllers/GripperActionController\n"
        "  joint: finger\n")
    (root / "bot_control" / "launch" / "sensors.launch").write_text(
        '<launch>\n'
        '  <param name="robot_description"'
        ' command="xacro \'$(find bot_control)/urdf/arm.urdf.xacro\'"/>\n'
        '  <node name="spawn_arm" pkg="gazebo_ros" type="spawn_model"\n'
        '        args="-urdf -param robot_description -model arm"/>\n'
        '  <rosparam file="$(find bot_control)/config/sensors.yaml" command="load"/>\n'
        '  <node name="controller_spawner" pkg="controller_manager" type="spawner"\n'
        '        args="ft_controller imu_controller gripper_controller"/>\n'
        '</launch>\n')
    config = configuration(str(root), "bot_control/launch/sensors.launch")
    assert not [d for d in config.diagnostics if d.code.startswith("PLUGIN")]
    gazebo = {(link.kind, link.resource.name) for link in config.links
              if link.node.name == "/gazebo"}
    assert {("read", "/ft_controller/publish_rate"), ("read", "/imu_controller/publish_rate"),
            ("read", "/gripper_controller/joint"),
            ("action-server", "/gripper_controller/gripper_cmd")} <= gazebo
    for name in ("/ft_controller/publish_rate", "/gripper_controller/joint"):
        parameter = config.parameter(name)
        assert parameter is not None and [r.node.name for r in parameter.readers] == [
            "/gazebo"]


def test_a_gazebo_camera_publishes_the_topics_of_the_image_transport_plugins():
    config = configuration(ROS1, "bot_gazebo/launch/sim.launch", {"BOT_CAMERA": "1"})
    transports = sorted((link.node.name, link.resource.name, link.type,
                         [c.text for c in link.conditions]) for link in config.links
                        if link.resource.name.startswith("/front_camera/image_raw/")
                        and link.kind == "publish"
                        and not link.type.startswith("dynamic_reconfigure/"))
    assert transports == [
        ("/gazebo", "/front_camera/image_raw/compressed", "sensor_msgs/CompressedImage",
         ["compressed_image_transport is installed"]),
        ("/gazebo", "/front_camera/image_raw/compressedDepth", "sensor_msgs/CompressedImage",
         ["compressed_depth_image_transport is installed"]),
        ("/gazebo", "/front_camera/image_raw/theora", "theora_image_transport/Packet",
         ["theora_image_transport is installed"])]


def test_names_the_tool_derives_keep_the_form_the_code_wrote():
    # survey B (TurtleBot3 autorace camera, Husky control.launch): the camera plugin
    # names its image relative (<cameraName>front_camera</cameraName>), and the
    # controller manager reads <controller>/type on its root handle: the names made
    # from them are relative too, so global-names does not call them global; the
    # resolved names stay those of the tests above
    config = configuration(ROS1, "bot_gazebo/launch/sim.launch", {"BOT_CAMERA": "1"})
    derived = {(link.resource.name, link.rosname.given) for link in config.links
               if link.resource.name.startswith("/front_camera/image_raw/")}
    assert ("/front_camera/image_raw/compressed", "front_camera/image_raw/compressed") in derived
    assert ("/front_camera/image_raw/compressed/format",
            "front_camera/image_raw/compressed/format") in derived
    assert ("/front_camera/image_raw/disable_pub_plugins",
            "front_camera/image_raw/disable_pub_plugins") in derived
    assert not [given for _, given in derived if given.startswith("/")]
    config = configuration(ROS1, "bot_control/launch/control.launch")
    (typed,) = [link for link in config.links if link.node.name == "/gazebo"
                and link.resource.name == "/joint_state_controller/type"]
    assert typed.rosname.given == "joint_state_controller/type"


@pytest.mark.parametrize(("ns", "expected"), [
    ("/", [("/gazebo", "publish", "/bot/joint_states"), ("/gazebo", "publish", "/imu/data"),
           ("/gazebo", "publish", "/odom"), ("/gazebo", "publish", "/tf"),
           ("/gazebo", "server", "/default_imu"),
           ("/gazebo", "subscribe", "/bot/cmd_vel")]),
    # in a namespace: the diff drive's robotNamespace / keeps its topics out of it (and
    # of the remaps, which name /sim/joint_states); the imu's are in it
    ("sim", [("/sim/gazebo", "publish", "/joint_states"), ("/sim/gazebo", "publish", "/odom"),
             ("/sim/gazebo", "publish", "/sim/imu/data"), ("/sim/gazebo", "publish", "/tf"),
             ("/sim/gazebo", "server", "/default_imu"),
             ("/sim/gazebo", "subscribe", "/cmd_vel")]),
])
def test_gazebo_from_a_modelled_gazebo_ros_launch_file_takes_the_remaps_around_it(
        ns: str, expected: list[tuple[str, str, str]]):
    """mir_gazebo (noetic): ``<remap from="joint_states" to="mir/joint_states"/>`` around
    ``<include file="$(find gazebo_ros)/launch/empty_world.launch">``, gazebo_ros not
    found. The gazebo node that file starts takes those remaps and the include's
    namespace (a stand-in /gazebo took neither, so it published /joint_states beside
    joint_state_publisher, a false multiple-publishers): the file is read from gazebo_ros'
    launch model, its gazebo node gzserver of the node model."""
    config = configuration(ROS1, "bot_gazebo/launch/world.launch", {"BOT_CAMERA": "0"},
                           ns=ns)
    gazebo = expected[0][0]
    (started,) = [n for n in config.nodes if n.node is not None
                  and n.node.name == "gazebo_ros/gzserver"]
    assert (started.name, started.origin) == (gazebo, "launch")
    assert started.location.file.endswith("/gazebo_ros/launch/empty_world.launch")
    assert [(n, kind, name) for n, kind, name, _ in made(config)] == expected
    assert "GAZEBO_NOT_STARTED" not in {d.code for d in config.diagnostics}


def test_ros1_video_plugin_subscribes_to_the_images_it_shows(write_tree):
    # sawyer_description's head screen: <visual><plugin filename="libgazebo_ros_video.so">
    # with <topicName>/robot/head_display</topicName> (gazebo_plugins' video plugin)
    root = write_tree({
        "bot/package.xml": '<package format="2"><name>bot</name><version>0.1.0</version>'
                           "<description>d</description>"
                           '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
                           "<buildtool_depend>catkin</buildtool_depend></package>\n",
        "bot/CMakeLists.txt": "project(bot)\n",
        "bot/urdf/bot.urdf": (
            '<robot name="bot">\n  <link name="screen"/>\n  <gazebo reference="screen">\n'
            '    <visual>\n      <plugin name="video" filename="libgazebo_ros_video.so">\n'
            "        <topicName>/robot/head_display</topicName>\n"
            "        <robotNamespace>/robot</robotNamespace>\n"
            "      </plugin>\n    </visual>\n  </gazebo>\n  <gazebo reference=\"screen\">\n"
            '    <visual>\n      <plugin name="tv" filename="libgazebo_ros_video.so"/>\n'
            "    </visual>\n  </gazebo>\n</robot>\n"),
        "bot/launch/sim.launch": (
            '<launch>\n  <param name="robot_description" textfile="$(find bot)/urdf/bot.urdf"/>'
            '\n  <node pkg="gazebo_ros" type="spawn_model" name="spawn"'
            ' args="-param robot_description -urdf -model bot"/>\n</launch>\n'),
    })
    config = configuration(str(root), "bot/launch/sim.launch")
    assert made(config) == [
        ("/gazebo", "subscribe", "/image_raw", "sensor_msgs/Image"),  # the defaults
        ("/gazebo", "subscribe", "/robot/head_display", "sensor_msgs/Image"),
    ]
    assert not [d for d in config.diagnostics if d.code == "GAZEBO_PLUGIN_UNKNOWN"]
