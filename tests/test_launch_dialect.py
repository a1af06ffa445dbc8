"""Which launch system a file is for: by content, then package, then name (dialect)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch.dialect import foreign_to_package, ros_version
from haros_arch.workspace import scan

NEUTRAL = '<launch><arg name="a" default="1"/><include file="x.xml"/></launch>'


def catkin_xml(name: str) -> str:
    return (f'<?xml version="1.0"?>\n<package format="2"><name>{name}</name>'
            "<version>0.1.0</version><description>d</description>"
            '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
            "<buildtool_depend>catkin</buildtool_depend></package>\n")


def test_content_decides_before_the_suffix(write_tree):
    root = write_tree({
        "a.launch.xml": '<launch><node pkg="p" type="t" name="n"/></launch>',
        "b.launch.xml": '<launch><arg name="m"/><param name="x" value="$(arg m)"/></launch>',
        "c.launch": '<launch><node pkg="p" exec="t" name="n"/></launch>',
        "d.launch.xml": '<launch><!-- <node pkg="p" type="t"/> --><let name="a" value="1"/>'
                        "</launch>",
    })
    assert ros_version(str(root / "a.launch.xml")) == 1
    assert ros_version(str(root / "b.launch.xml")) == 1
    assert ros_version(str(root / "c.launch")) == 2
    assert ros_version(str(root / "d.launch.xml")) == 2  # comments say nothing


def test_package_decides_a_file_that_could_be_either(write_tree):
    root = write_tree({
        "src/old/package.xml": catkin_xml("old"),
        "src/old/launch/x.launch.xml": NEUTRAL,
        "src/new/package.xml": package_xml("new", "ament_cmake"),
        "src/new/launch/x.launch": NEUTRAL,
        "src/first/package.xml": '<package><name>first</name></package>',
        "src/first/launch/x.launch.xml": NEUTRAL,
        "src/loose/x.launch.xml": NEUTRAL,
    })
    ws = scan([str(root / "src")], {})
    assert ros_version(str(root / "src/old/launch/x.launch.xml"), ws) == 1
    assert ros_version(str(root / "src/new/launch/x.launch"), ws) == 2
    assert ros_version(str(root / "src/first/launch/x.launch.xml"), ws) == 1  # format 1
    assert ros_version(str(root / "src/loose/x.launch.xml"), ws) == 2  # name, at last
    assert ros_version("missing.launch.xml", ws) == 2 and ros_version("m.launch", ws) == 1
    assert ros_version("x.launch.py") == 2 and ros_version("x.launch.yaml") == 2


def test_a_file_its_own_package_cannot_run(write_tree):
    """A roslaunch file left in a package ported to ament (twist_mux's twist_mux.launch:
    ``<node type=>`` and ``<rosparam>`` loading a ``ros__parameters`` YAML) is foreign to
    it; the same file in a catkin package, a ROS 2 file in an ament package, a file that
    could be either and a package that builds for both ROS versions are not."""
    ros1 = ('<launch><node pkg="p" type="t" name="n">'
            '<rosparam file="$(find p)/c.yaml" command="load"/></node></launch>')
    ros2 = '<launch><node pkg="p" exec="t" name="n"/></launch>'
    dual = catkin_xml("dual").replace(
        "<buildtool_depend>catkin</buildtool_depend>",
        '<buildtool_depend condition="$ROS_VERSION == 1">catkin</buildtool_depend>'
        '<buildtool_depend condition="$ROS_VERSION == 2">ament_cmake</buildtool_depend>')
    root = write_tree({
        "src/mux/package.xml": package_xml("mux", "ament_cmake"),
        "src/mux/launch/old.launch": ros1,
        "src/mux/launch/new.launch.xml": ros2,
        "src/mux/launch/either.launch": NEUTRAL,
        "src/old/package.xml": catkin_xml("old"),
        "src/old/launch/old.launch": ros1,
        "src/old/launch/new.launch.xml": ros2,
        "src/dual/package.xml": dual,
        "src/dual/launch/old.launch": ros1,
    })
    ws = scan([str(root / "src")])
    why = foreign_to_package(str(root / "src/mux/launch/old.launch"), ws)
    assert why == ("roslaunch (ROS 1) XML in mux, an ament (ROS 2) package: ros2 launch "
                   "cannot run it")
    assert foreign_to_package(str(root / "src/old/launch/new.launch.xml"), ws) == (
        "ROS 2 launch XML in old, a catkin (ROS 1) package: roslaunch cannot run it")
    for fine in ("mux/launch/new.launch.xml", "mux/launch/either.launch",
                 "old/launch/old.launch", "dual/launch/old.launch"):
        assert foreign_to_package(str(root / "src" / fine), ws) is None, fine


def test_a_word_of_an_attributes_value_is_no_mark(write_tree):
    """``namespace=`` and ``exec=`` mark ROS 2 XML as attributes only: naoqi_driver2's
    roslaunch file passes ``args="... --namespace=$(arg namespace)"`` to its node, which
    made it a file of both systems, decided by its ament package as ROS 2, and the run
    reported ros2 launch's errors on it instead of skipping it as a ROS 1 leftover."""
    root = write_tree({
        "src/drv/package.xml": package_xml("drv", "ament_cmake"),
        "src/drv/launch/drv.launch": (
            '<launch><arg name="namespace" default="drv"/>'
            '<node pkg="drv" type="drv_node" name="$(arg namespace)" '
            'args="--exec=x --namespace=$(arg namespace)"/></launch>'),
        "src/drv/launch/drv.launch.xml": (
            '<launch><node pkg="drv" exec="drv_node" namespace = \'ns\'/></launch>'),
    })
    ws = scan([str(root / "src")])
    assert ros_version(str(root / "src/drv/launch/drv.launch"), ws) == 1
    assert ros_version(str(root / "src/drv/launch/drv.launch.xml"), ws) == 2
    assert foreign_to_package(str(root / "src/drv/launch/drv.launch"), ws) == (
        "roslaunch (ROS 1) XML in drv, an ament (ROS 2) package: ros2 launch cannot run it")
