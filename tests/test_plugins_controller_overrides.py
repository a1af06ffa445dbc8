"""A ros2_control controller is a node of the manager's process made with
``automatically_declare_parameters_from_overrides(true)``: the ``/**`` entries of the
process's parameter files are its parameters too, so the ``robot_description`` a launch
file gives ros2_control_node as a dictionary (launch_ros writes it under ``/**``)
reaches a controller that requires it (franka_ros2's state broadcaster aborts its
configuration without it)."""

from __future__ import annotations

import os

from conftest import FIXTURES

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue

PLUGINS = FIXTURES / "build" / "plugins"


def _tree(controller: str, launch: str, plugins_xml: str | None = None,
          bringup: tuple[str, ...] = (), extra: dict[str, str] | None = None
          ) -> dict[str, str]:
    """The two packages' files: ros2_ctrl with the controller's source and plugin
    description (the fixture's, or ``plugins_xml``), ros2_bringup with the launch file
    and the fixture's files named in ``bringup``; ``extra``: more files, by path; and
    the project file."""
    files = {f"src/ros2_ctrl/{name}": (PLUGINS / "ros2_ctrl" / name).read_text()
             for name in ("CMakeLists.txt", "package.xml",
                          *(("ros2_ctrl.xml",) if plugins_xml is None else ()))}
    if plugins_xml is not None:
        files["src/ros2_ctrl/ros2_ctrl.xml"] = plugins_xml
    files["src/ros2_ctrl/src/follower.cpp"] = controller
    files.update({f"src/ros2_bringup/{name}": (PLUGINS / "ros2_bringup" / name).read_text()
                  for name in ("CMakeLists.txt", "package.xml", *bringup)})
    files["src/ros2_bringup/launch/c.launch.py"] = launch
    files.update(extra or {})
    files["project.yaml"] = ("project: p\ndistro: jazzy\nconfigurations:\n"
                             "  c: [ros2_bringup/launch/c.launch.py]\n")
    return files

CONTROLLER = r"""
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <pluginlib/class_list_macros.hpp>

namespace ros2_ctrl
{
class Follower
{
public:
  bool on_init(rclcpp::Node::SharedPtr node)
  {
    std::string description, mode;
    if (!node->get_parameter("robot_description", description)) {
      RCLCPP_ERROR(node->get_logger(), "Failed to get robot_description parameter");
      return false;
    }
    if (!node->get_parameter("mode", mode)) {
      RCLCPP_ERROR(node->get_logger(), "Failed to get mode parameter");
      return false;
    }
    return true;
  }
};
}  // namespace ros2_ctrl

PLUGINLIB_EXPORT_CLASS(ros2_ctrl::Follower, controller_interface::ControllerInterface)
"""

LAUNCH = """
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    config = os.path.join(get_package_share_directory('ros2_bringup'), 'config',
                          'controllers.yaml')
    return LaunchDescription([
        Node(package='controller_manager', executable='ros2_control_node',
             namespace='robot', parameters=[{'robot_description': '<robot/>'}]),
        Node(package='controller_manager', executable='spawner', namespace='robot',
             arguments=['follower', '--param-file', config]),
    ])
"""


def test_a_controller_gets_the_managers_dictionary_parameters(write_tree):
    files = _tree(CONTROLLER, LAUNCH, bringup=("params/controllers.yaml",))
    root = write_tree(files)
    model = analyse(load(os.path.join(root, "project.yaml")), {},
                    Options(cache_dir=None, jobs=1))
    config = model.configuration("c")
    description = config.parameter("/robot/follower/robot_description")
    assert description is not None and description.set_by_launch
    # the required parameter nothing sets is reported, the one the manager's process
    # gives is not
    unset = sorted(f.message.split(" is read")[0] for f in run_catalogue(model)
                   if f.rule == "parameter-read-not-set")
    assert unset == ["/robot/follower/mode"]


LEADER = r"""
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <pluginlib/class_list_macros.hpp>

namespace ros2_ctrl
{
class Leader
{
public:
  bool on_init(rclcpp::Node::SharedPtr node)
  {
    bool gate = node->declare_parameter<bool>("gate", true);
    return gate;
  }
};
class Quiet
{
public:
  bool on_init(rclcpp::Node::SharedPtr node)
  {
    return node->declare_parameter<int>("period", 1) > 0;
  }
};
}  // namespace ros2_ctrl

PLUGINLIB_EXPORT_CLASS(ros2_ctrl::Leader, controller_interface::ControllerInterface)
PLUGINLIB_EXPORT_CLASS(ros2_ctrl::Quiet, controller_interface::ControllerInterface)
"""

PLUGINS_XML = """<library path="ros2_ctrl">
  <class name="ros2_ctrl/Leader" type="ros2_ctrl::Leader"
         base_class_type="controller_interface::ControllerInterface"/>
  <class name="ros2_ctrl/Quiet" type="ros2_ctrl::Quiet"
         base_class_type="controller_interface::ControllerInterface"/>
</library>
"""

SPAWNED = """/robot/leader:
  ros__parameters:
    type: ros2_ctrl/Leader
/robot/quiet:
  ros__parameters:
    type: ros2_ctrl/Quiet
"""

SHARED_LAUNCH = """
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    config = os.path.join(get_package_share_directory('ros2_bringup'), 'config',
                          'spawned.yaml')
    return LaunchDescription([
        Node(package='controller_manager', executable='ros2_control_node',
             namespace='robot',
             parameters=[{'robot_description': '<robot/>', 'gate': False, 'nobody': 1}]),
        Node(package='controller_manager', executable='spawner', namespace='robot',
             arguments=['leader', 'quiet', '--param-file', config]),
    ])
"""


def test_a_managers_dictionary_value_is_one_setting_for_its_controllers(write_tree):
    """Universal_Robots_ROS2_Driver's ur_control.launch.py:246 gives ros2_control_node
    ``{"verify_payload_on_set": ...}``, which launch_ros writes under ``/**``: every
    controller of the process gets it, and only the io_and_status_controller reads it.
    It was "set but never read" once per other controller (15 warnings); a value for the
    whole process is unread only when none of its nodes reads it."""
    files = _tree(LEADER, SHARED_LAUNCH, PLUGINS_XML,
                  extra={"src/ros2_bringup/params/spawned.yaml": SPAWNED})
    root = write_tree(files)
    model = analyse(load(os.path.join(root, "project.yaml")), {},
                    Options(cache_dir=None, jobs=1))
    config = model.configuration("c")
    gate = config.parameter("/robot/quiet/gate")
    assert gate is not None and gate.set_by_launch
    leader = config.parameter("/robot/leader/gate")
    assert leader is not None and [r.node.name for r in leader.readers] == ["/robot/leader"]
    findings = run_catalogue(model)
    unread = sorted(f.message.split(" is set")[0] for f in findings
                    if f.rule == "parameter-set-not-read")
    # ``gate`` is read by one node of the process; ``nobody`` by none it reaches: said
    # once, for the manager, whose own reads are partly unseen (undecided)
    assert unread == []
    undecided = [f.message for f in findings if f.rule == "parameter-set-not-read-undecided"]
    assert len(undecided) == 1 and "/robot/controller_manager/nobody" in undecided[0]
    assert "gate" not in undecided[0]


MANAGER_FILE = """controller_manager:
  ros__parameters:
    follower:
      type: ros2_ctrl/Follower

/**/follower:
  ros__parameters:
    mode: track
    stale_setting: true
"""

MANAGER_FILE_LAUNCH = """
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    config = os.path.join(get_package_share_directory('ros2_bringup'), 'config',
                          'manager.yaml')
    return LaunchDescription([
        Node(package='controller_manager', executable='ros2_control_node',
             parameters=[{'robot_description': '<robot/>'}, config]),
        Node(package='controller_manager', executable='spawner', arguments=['follower']),
    ])
"""


def test_a_controllers_setting_in_the_managers_file_is_placed_at_its_line(write_tree):
    # rosbot_ros 5b024d7 gives ros2_control_node one file with a section per controller
    # (``/**/imu_broadcaster:``); its settings the controller never reads were all said
    # at the launch file's line, not at theirs in the file
    files = _tree(CONTROLLER, MANAGER_FILE_LAUNCH,
                  extra={"src/ros2_bringup/config/manager.yaml": MANAGER_FILE})
    root = write_tree(files)
    model = analyse(load(os.path.join(root, "project.yaml")), {},
                    Options(cache_dir=None, jobs=1))
    config = model.configuration("c")
    stale = config.parameter("/follower/stale_setting")
    assert stale is not None and stale.set_by_launch
    assert (stale.launch_location.file, stale.launch_location.line) == (
        "ros2_bringup/config/manager.yaml", 9)
    unread = [(f.location.file, f.location.line) for f in run_catalogue(model)
              if f.rule == "parameter-set-not-read"]
    assert unread == [("ros2_bringup/config/manager.yaml", 9)]


SHARED_FILE = """/**:
  ros__parameters:
    gate: false
    speed: 2.0
    nobody: 1
/robot/leader:
  ros__parameters:
    type: ros2_ctrl/Leader
"""

MOVER = """
import rclpy
from rclpy.node import Node


class Mover(Node):
    def __init__(self):
        super().__init__('mover')
        self.speed = self.declare_parameter('speed', 1.0).value


def main():
    rclpy.init()
    rclpy.spin(Mover())
"""

MOVER_SETUP = """from setuptools import setup
setup(name='mover_pkg', packages=['mover_pkg'],
      entry_points={'console_scripts': ['mover = mover_pkg.mover:main']})
"""

FILE_TO_BOTH_LAUNCH = """
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    shared = os.path.join(get_package_share_directory('ros2_bringup'), 'config',
                          'shared.yaml')
    return LaunchDescription([
        Node(package='mover_pkg', executable='mover', namespace='robot',
             parameters=[shared]),
        Node(package='controller_manager', executable='ros2_control_node',
             namespace='robot', parameters=[{'robot_description': '<robot/>'}]),
        Node(package='controller_manager', executable='spawner', namespace='robot',
             arguments=['leader', '--param-file', shared]),
    ])
"""


def test_a_file_given_to_a_node_and_by_a_spawner_is_one_setting(write_tree):
    """elkapod_core's controllers.launch.py gives elkapod_motion_manager.yaml (its
    entries under ``/**``) to the motion manager's node and, by the spawner's
    ``--param-file``, to elkapod_gait_controller, which reads ``max_vel.tripod`` and
    others the manager does not: each was "set but never read" for the manager, the
    controller's copy a setting of its own. A ``/**`` entry of a file a spawner gives is
    the same setting as that file's entry given to a node: unread when none reads it."""
    files = _tree(LEADER, FILE_TO_BOTH_LAUNCH, PLUGINS_XML,
                  extra={"src/ros2_bringup/params/shared.yaml": SHARED_FILE})
    files["src/mover_pkg/package.xml"] = (
        '<package format="3"><name>mover_pkg</name><version>0.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>MIT</license><exec_depend>rclpy</exec_depend>'
        '<export><build_type>ament_python</build_type></export></package>')
    files["src/mover_pkg/setup.py"] = MOVER_SETUP
    files["src/mover_pkg/mover_pkg/__init__.py"] = ""
    files["src/mover_pkg/mover_pkg/mover.py"] = MOVER
    root = write_tree(files)
    model = analyse(load(os.path.join(root, "project.yaml")), {},
                    Options(cache_dir=None, jobs=1))
    config = model.configuration("c")
    gate = config.parameter("/robot/leader/gate")
    assert gate is not None and [r.node.name for r in gate.readers] == ["/robot/leader"]
    unread = sorted(f.message.split(" is set")[0] for f in run_catalogue(model)
                    if f.rule == "parameter-set-not-read")
    # gate: the controller reads its copy; speed: the mover reads its own; nobody: none
    assert unread == ["/robot/mover/nobody"]
