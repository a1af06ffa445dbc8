"""A gz_ros2_control plugin's ``<parameters>`` file written as rcl reads it: node keys
nested under a namespace key (``/**:`` then ``controller_manager:``) and the same top key
written again for each controller (open_manipulator's
open_manipulator_bringup/config/omx_f/hardware_controller_manager.yaml, jazzy). The
plugin's reader took only top keys and kept the last ``/**:``, so the manager got none
of its parameters and each controller the gazebo launch files spawn had a class not
known (PLUGIN_CLASS_UNKNOWN)."""

from __future__ import annotations

from haros_arch import pipeline
from haros_arch.project import ConfigurationSpec, Project
from haros_arch.robot.attach import _node_names
from tests.conftest import package_xml
from tests.test_robot_gz_spawn_string import LAUNCH, URDF

CONTROLLERS = """/**:
  controller_manager:
    ros__parameters:
      update_rate: 100  # Hz

      joint_state_broadcaster:
        type: joint_state_broadcaster/JointStateBroadcaster

      arm_controller:
        type: joint_trajectory_controller/JointTrajectoryController

/**:
  arm_controller:
    ros__parameters:
      joints:
        - joint1
      command_interfaces:
        - position
"""

SPAWNERS = """
        Node(package="controller_manager", executable="spawner",
             arguments=["arm_controller"]),
    ])
"""


def test_nested_and_repeated_keys_of_the_plugin_s_parameter_file(write_tree) -> None:
    launch = (LAUNCH % '"-string", description').replace("\n    ])\n", SPAWNERS, 1)
    root = write_tree({
        "bot/package.xml": package_xml("bot", "ament_cmake"),
        "bot/CMakeLists.txt": "project(bot)\nament_package()\n",
        "bot/urdf/bot.urdf.xacro": URDF,
        "bot/config/controllers.yaml": CONTROLLERS,
        "bot/launch/sim.launch.py": launch,
    })
    project = Project("bot", str(root / "project.yaml"), workspace=[str(root)],
                      configurations=[ConfigurationSpec("c", ["bot/launch/sim.launch.py"], {})],
                      distro="jazzy")
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    assert not [d for d in config.diagnostics if d.code == "PLUGIN_CLASS_UNKNOWN"]
    for name in ("/joint_state_broadcaster", "/arm_controller"):
        controller = config.node(name)
        assert controller is not None and controller.origin == "plugin"
    update = config.parameter("/controller_manager/update_rate")
    assert update is not None and update.value == 100
    assert update.launch_location is not None and update.launch_location.line == 4
    joints = config.parameter("/arm_controller/joints")
    assert joints is not None and joints.value == ["joint1"]


def test_the_node_names_a_parameter_file_gives() -> None:
    document = {
        "controller_manager": {"ros__parameters": {}},  # in the plugin's namespace
        "/**/imu": {"ros__parameters": {}},
        "/**": {"ros__parameters": {}, "arm": {"ros__parameters": {}}},
        "/other": {"inner": {"ros__parameters": {}}},
        "odd": 3,  # no parameters: kept as before
    }
    assert _node_names(document, "/bot/") == [
        "/bot/controller_manager", "/bot/imu", "/bot/arm", "/other/inner", "/bot/odd"]
