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
