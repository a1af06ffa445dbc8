"""A package.xml that names both catkin and ament_cmake as build tools, with no
condition (a port's leftover), is built by colcon with its REP 149 build type:
quadruped_ros2_control's magicdog_description (``<buildtool_depend>catkin``, then
``ament_cmake``, ``<build_type>ament_cmake</build_type>``) is a ROS 2 package, so the
roslaunch file left in it is one ``ros2 launch`` cannot run, not a configuration of its
own; was read as ROS 1, by the first build tool. With no build type given REP 149's
default, catkin, decides; a package whose build tools are conditioned on
``$ROS_VERSION`` keeps building for both."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch.dialect import foreign_to_package
from haros_arch.manifest import ros_version
from haros_arch.workspace import scan

ROS1 = ('<launch><node pkg="joint_state_publisher_gui" type="joint_state_publisher_gui" '
        'name="jsp"><param name="use_gui" value="TRUE"/></node></launch>')


def _both(name: str, build_type: str | None, first: str, second: str) -> str:
    return package_xml(name, build_type).replace(
        "<license>MIT</license>",
        f"<license>MIT</license><buildtool_depend>{first}</buildtool_depend>"
        f"<buildtool_depend>{second}</buildtool_depend><depend>rclcpp</depend>")


def test_the_build_type_decides_between_both_build_tools(write_tree) -> None:
    root = write_tree({
        "src/dog/package.xml": _both("dog", "ament_cmake", "catkin", "ament_cmake"),
        "src/dog/launch/dog_vis.launch": ROS1,
        "src/old/package.xml": _both("old", None, "ament_cmake", "catkin"),
        "src/old/launch/old.launch": ROS1,
    })
    ws = scan([str(root / "src")])
    assert ros_version(ws.packages["dog"]) == 2
    assert ros_version(ws.packages["old"]) == 1
    assert foreign_to_package(str(root / "src/dog/launch/dog_vis.launch"), ws) == (
        "roslaunch (ROS 1) XML in dog, an ament (ROS 2) package: ros2 launch cannot run it")
    assert foreign_to_package(str(root / "src/old/launch/old.launch"), ws) is None
