"""A package a launch file uses that the workspace holds under an ignore marker
(COLCON_IGNORE, CATKIN_IGNORE, AMENT_IGNORE) stays out of the workspace, as colcon and
catkin leave it out, but the diagnostic says it is there and names the marker file
rather than calling it missing (rosbot_ros 5b024d7 with rosbot_controller/COLCON_IGNORE:
bringup.launch.py's get_package_share_directory("rosbot_controller"))."""

from __future__ import annotations

from pathlib import Path

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import scan

SCAN = Path(__file__).resolve().parent.parent / "fixtures" / "workspace_scan" / "src"


def test_scan_keeps_ignored_packages_out_and_remembers_their_marker() -> None:
    ws = scan([str(SCAN)], {"ROS_VERSION": "2"})
    assert "hidden_pkg" not in ws.packages and "colcon_skip" not in ws.packages
    assert ws.ignored["hidden_pkg"] == (str(SCAN / "ignored" / "CATKIN_IGNORE"),
                                        str(SCAN / "ignored" / "hidden_pkg"))
    assert ws.ignored["colcon_skip"][0] == str(SCAN / "colcon_skip" / "COLCON_IGNORE")
    assert "ignored/CATKIN_IGNORE" in ws.absence("hidden_pkg")
    assert ws.absence("elsewhere") == "is not in the workspace nor installed here"


def test_an_ignored_package_found_elsewhere_is_not_said_ignored(write_tree) -> None:
    root = write_tree({
        "src/old/COLCON_IGNORE": "",
        "src/old/motor/package.xml": package_xml("motor"),
        "src/new/motor/package.xml": package_xml("motor"),
    })
    ws = scan([str(root / "src")], {})
    assert "motor" in ws.packages and ws.ignored == {}


def _said(config_diagnostics, codes):
    return sorted((d.code, d.location.line, d.message) for d in config_diagnostics
                  if d.code in codes)


def test_ros1_node_and_find_of_an_ignored_package_name_the_marker(write_tree) -> None:
    root = write_tree({
        "src/bringup/package.xml": package_xml("bringup"),
        "src/bringup/launch/robot.launch": (
            "<launch>\n"
            "  <node name=\"drive\" pkg=\"haros_motor_drv\" type=\"driver\"/>\n"
            "  <rosparam command=\"load\" file=\"$(find haros_motor_drv)/config/a.yaml\"/>\n"
            "</launch>\n"),
        "src/drivers/CATKIN_IGNORE": "",
        "src/drivers/haros_motor_drv/package.xml": package_xml("haros_motor_drv"),
        "project.yaml": (
            "project: p\nworkspace: src\n"
            "configurations:\n  c: [bringup/launch/robot.launch]\n"),
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    said = _said(config.diagnostics + model.diagnostics,
                 ("NODE_PACKAGE_UNKNOWN", "LAUNCH_UNKNOWN_VALUE"))
    assert [(code, line) for code, line, _ in said] == [
        ("LAUNCH_UNKNOWN_VALUE", 3), ("NODE_PACKAGE_UNKNOWN", 2)]
    for _code, _line, message in said:
        assert "is in the workspace (drivers/haros_motor_drv) but ignored" in message
        assert "drivers/CATKIN_IGNORE" in message


def test_ros2_node_and_share_of_an_ignored_package_name_the_marker(write_tree) -> None:
    root = write_tree({
        "src/bringup/package.xml": package_xml("bringup"),
        "src/bringup/launch/robot.launch.py": (
            "from launch import LaunchDescription\n"
            "from launch_ros.actions import Node\n"
            "from launch_ros.substitutions import FindPackageShare\n"
            "def generate_launch_description():\n"
            "    config = FindPackageShare('haros_lidar_drv')\n"
            "    return LaunchDescription([\n"
            "        Node(package='haros_lidar_drv', executable='lidar',\n"
            "             parameters=[config]),\n"
            "    ])\n"),
        "src/haros_lidar_drv/COLCON_IGNORE": "",
        "src/haros_lidar_drv/package.xml": package_xml("haros_lidar_drv"),
        "project.yaml": (
            "project: p\nworkspace: src\npackages: [bringup, haros_lidar_drv]\n"
            "configurations:\n  c: [bringup/launch/robot.launch.py]\n"),
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    said = _said(config.diagnostics + model.diagnostics,
                 ("NODE_PACKAGE_UNKNOWN", "LAUNCH_UNKNOWN_VALUE", "PACKAGE_NOT_FOUND"))
    assert sorted(code for code, _, _ in said) == [
        "LAUNCH_UNKNOWN_VALUE", "NODE_PACKAGE_UNKNOWN", "PACKAGE_NOT_FOUND"]
    for _code, _line, message in said:
        assert "haros_lidar_drv/COLCON_IGNORE" in message, message
