"""What real ROS 2 launch files needed (survey Z48).

space-ros/demos' curiosity_gazebo.launch.py and canadarm.launch.py hand ros_gz_sim's
``create`` the arguments ``["-name", "curiosity_mars_rover", "-topic",
robot_description, ...]`` where ``robot_description`` is the parameter dict
``{"robot_description": doc.toxml()}``: launch's ``normalize_to_list_of_substitutions``
iterates what it is given, and a dict iterates over its keys, so the word is
``robot_description`` (the spawner reads the topic robot_state_publisher publishes).
Before, the dict was "not supported" (a warning) and the word ``?``."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan


def _load(write_tree, text: str):
    root = write_tree({
        "src/sim/package.xml": package_xml("sim", "ament_cmake"),
        "src/sim/launch/sim.launch.py": text,
    })
    return load(str(root / "src/sim/launch/sim.launch.py"), scan([str(root / "src")], {}),
                {}, {})


def test_a_dict_as_a_node_argument_is_its_keys(write_tree):
    model = _load(write_tree, """
from launch import LaunchDescription
from launch_ros.actions import Node

def generate_launch_description():
    robot_description = {'robot_description': '<robot name="r"/>'}
    return LaunchDescription([
        Node(package='ros_gz_sim', executable='create',
             arguments=['-name', 'rover', '-topic', robot_description, '-z', '1.0'])])
""")
    assert [n.args for n in model.nodes] == ["-name rover -topic robot_description -z 1.0"]
    assert not [d for d in model.diagnostics if d.code.startswith("LAUNCH_")], \
        [d.message for d in model.diagnostics]


def test_a_dict_key_that_is_no_text_stops_launch(write_tree):
    # normalize raises a TypeError on an item that is neither str nor a substitution
    model = _load(write_tree, """
from launch import LaunchDescription
from launch_ros.actions import Node

def generate_launch_description():
    return LaunchDescription([
        Node(package='p', executable='e', arguments=['-n', {3: 'x'}])])
""")
    assert [d.code for d in model.diagnostics if d.code.startswith("LAUNCH_")] == [
        "LAUNCH_BAD_VALUE"], [d.message for d in model.diagnostics]


def test_a_method_of_a_library_table_on_a_value_said_unknown_is_not_said_again(write_tree):
    # nvblox_examples_bringup's launch files build isaac_ros_launch_utils'
    # ``ArgumentContainer`` (isaac_ros_common, not in the workspace), then call its
    # ``add_arg`` ten times: each was said again, as robotnik_common's ``add_arg`` of the
    # table, on a value already said not interpreted where it was made
    model = _load(write_tree, """
import missing_launch_utils as lu
from launch import LaunchDescription

def generate_launch_description():
    args = lu.ArgumentContainer()
    args.add_arg('rosbag', 'None', cli=True)
    args.add_arg('log_level', 'info', cli=True)
    args.process_arg()
    poses = lu.poses()
    poses.value()
    return LaunchDescription([])
""")
    said = [d.message for d in model.diagnostics if d.code == "LAUNCH_PY_UNSUPPORTED"]
    assert len(said) == 2, said
    assert all("is not interpreted (never run)" in m for m in said), said
