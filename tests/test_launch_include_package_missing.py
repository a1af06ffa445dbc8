"""An include of a launch file whose package is neither in the workspace nor installed
here (ros_gz_sim's ``gz_sim.launch.py`` on a machine without Gazebo) is said once, where
the package is looked for (``LAUNCH_UNKNOWN_VALUE``, info: installed on the robot,
perhaps), not again as a construct not read; the include stays in the launch tree as one
not read, so what it would start is unseen. An include whose path is not known for
another reason (an argument with no value) is still a warning."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

PY = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
def generate_launch_description():
    gz = get_package_share_directory('ros_gz_sim')
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            os.path.join(gz, 'launch', 'gz_sim.launch.py'))),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            [LaunchConfiguration('world_launch')])),
    ])
"""

FILES = {
    "src/pkg/package.xml": package_xml("pkg", "ament_python"),
    "src/pkg/launch/sim.launch.py": PY,
    "src/pkg/launch/sim.launch.xml":
        '<launch><include file="$(find-pkg-share ros_gz_sim)/launch/gz_sim.launch.py"/>'
        '</launch>',
    "src/pkg/launch/sim.launch":
        '<launch><arg name="world"/>'
        '<include file="$(find gazebo_ros)/launch/empty_world.launch"/>'
        '<include file="$(arg world)"/></launch>',
}


def _items(items):
    for item in items:
        yield item
        yield from _items(item.children)


def said(model):
    return sorted((d.code, d.severity) for d in model.diagnostics
                  if d.code in ("LAUNCH_UNKNOWN_VALUE", "LAUNCH_UNSUPPORTED", "LAUNCH_ARG_UNSET"))


def test_an_include_of_a_package_not_here_is_said_once_where_it_is_looked_for(write_tree):
    root = write_tree(FILES)
    ws = scan([str(root / "src")], {})
    python = load(str(root / "src/pkg/launch/sim.launch.py"), ws, {}, {})
    # the package, then the argument (undecided: the include not read may declare it),
    # then the include the argument names, whose path is not known: a warning
    assert said(python) == [("LAUNCH_UNKNOWN_VALUE", "info"), ("LAUNCH_UNKNOWN_VALUE", "info"),
                            ("LAUNCH_UNSUPPORTED", "warning")]
    assert [d.message for d in python.diagnostics if d.code == "LAUNCH_UNSUPPORTED"] == [
        "included file ? is not known statically"]
    xml = load(str(root / "src/pkg/launch/sim.launch.xml"), ws, {}, {})
    assert said(xml) == [("LAUNCH_UNKNOWN_VALUE", "info")]
    assert [i.kind for i in _items(xml.tree)].count("include") == 1
    ros1 = load(str(root / "src/pkg/launch/sim.launch"), ws, {}, {})
    assert ("LAUNCH_UNSUPPORTED", "warning") in said(ros1)  # $(arg world) has no value
    assert [d.message for d in ros1.diagnostics if d.code == "LAUNCH_UNSUPPORTED"] == [
        m for m in [d.message for d in ros1.diagnostics if d.code == "LAUNCH_UNSUPPORTED"]
        if "gazebo_ros" not in m]
    assert len(ros1.unread_includes) == 2


UNSET_PASSED = (
    '<launch><arg name="iamge_input" default="camera/color/image_raw"/>'
    '<include file="$(find raw2compressed)/launch/image.launch">'
    '<arg name="image_input" value="$(arg image_input)"/>'
    '<arg name="unused" value="$(arg never)" if="false"/>'
    '<env name="CAMERA" value="$(arg iamge_input)"/>'
    '</include></launch>')


def test_an_include_not_read_still_substitutes_the_values_it_passes(write_tree):
    """roslaunch substitutes an include's <arg> values before it reads the file, so a
    value naming an argument nothing declares fails the launch even where the included
    package is installed (turtlebot3 625cf703e: ``iamge_input`` declared, ``$(arg
    image_input)`` passed to raw2compressed's launch, not in the workspace). The arg a
    false condition leaves out is not substituted; the file is still not read."""
    root = write_tree({"src/pkg/package.xml": package_xml("pkg"),
                       "src/pkg/launch/cam.launch": UNSET_PASSED})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/pkg/launch/cam.launch"), ws, {}, {})
    unset = [d.message for d in model.diagnostics if d.code == "LAUNCH_ARG_UNSET"]
    assert len(unset) == 1 and "image_input" in unset[0]
    assert not any("never" in d.message for d in model.diagnostics)
    assert len(model.unread_includes) == 1


EVAL_FIND = (
    '<launch><arg name="arm_type" default="A-2085-06"/><arg name="gripper" default="none"/>'
    '<arg name="moveit_arm_type" value="$(eval arm_type.lower() + '
    "('-parallel-gripper' if gripper == 'parallel' else ''))\"/>"
    "<include file=\"$(eval find('hebi_' + moveit_arm_type + '_moveit_config') + "
    "'/launch/move_group.launch')\"/>"
    '<arg name="world"/>'
    "<include file=\"$(eval find('sim_' + world) + '/launch/world.launch')\"/>"
    '</launch>')


def test_an_eval_find_of_a_package_not_here_is_said_once(write_tree):
    """hebi_cpp_api_examples' arm_moveit_node.launch includes ``$(eval find('hebi_' +
    moveit_arm_type + '_moveit_config') + '/launch/move_group.launch')``, the MoveIt
    config of another repository: said once, where the package is looked for, as a
    ``$(find)`` outside an eval is, not also as an include the tool cannot read. An eval
    over an argument with no value is still a warning."""
    root = write_tree({"src/pkg/package.xml": package_xml("pkg"),
                       "src/pkg/launch/arm.launch": EVAL_FIND})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/pkg/launch/arm.launch"), ws, {}, {})
    assert [(d.code, d.message) for d in model.diagnostics
            if d.code in ("LAUNCH_UNKNOWN_VALUE", "LAUNCH_UNSUPPORTED")] == [
        ("LAUNCH_UNKNOWN_VALUE", "package hebi_a-2085-06_moveit_config is not in the "
         "workspace nor installed here; what depends on it keeps '?'"),
        ("LAUNCH_UNKNOWN_VALUE", "$(eval find('sim_' + world) + '/launch/world.launch') "
         "depends on unknown values; what depends on it keeps '?'"),
        ("LAUNCH_UNSUPPORTED", "include file \"$(eval find('sim_' + world) + "
         "'/launch/world.launch')\" is not known statically")]
    assert len(model.unread_includes) == 2
