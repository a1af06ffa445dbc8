"""A launch file's ``$(find nav_bringupp)`` or ``FindPackageShare('nav_bringupp')`` of a
package that is neither in the workspace nor installed, a letter or two from one that is
(``nav_bringup``), is most likely a typo: roslaunch / ros2 launch fail there. It is said
at that line as ``PACKAGE_NOT_FOUND`` (so ``launch-missing-reference``), naming the
package it most likely misspells; a package whose name is near none stays an info
(``LAUNCH_UNKNOWN_VALUE``: installed where the robot runs, perhaps)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

ROS1 = """<launch>
  <include file="$(find unknown_pkg)/launch/x.launch"/>
  <include file="$(find nav_bringupp)/launch/x.launch"/>
  <include file="$(find nav)/launch/x.launch"/>
</launch>
"""

PY = """from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare

def generate_launch_description():
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            PathJoinSubstitution([FindPackageShare('unknown_pkg'), 'launch', 'x.py']))),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            PathJoinSubstitution([FindPackageShare('nav_bringupp'), 'launch', 'x.py']))),
    ])
"""

FILES = {
    "src/nav_bringup/package.xml": package_xml("nav_bringup"),
    "src/nav_bringup/launch/x.launch": "<launch/>",
    "src/other/package.xml": package_xml("other"),
    "src/other/launch/main.launch": ROS1,
    "src/other/launch/main.launch.py": PY,
}


def said(model):
    return [(d.code, d.location.line, d.message) for d in model.diagnostics
            if d.code in ("PACKAGE_NOT_FOUND", "LAUNCH_UNKNOWN_VALUE", "LAUNCH_UNSUPPORTED")]


def test_a_misspelt_package_is_a_missing_reference_with_the_name_it_misspells(write_tree):
    root = write_tree(FILES)
    ws = scan([str(root / "src")], {})
    ros1 = load(str(root / "src/other/launch/main.launch"), ws, {}, {})
    assert said(ros1) == [
        ("LAUNCH_UNKNOWN_VALUE", 2, "package unknown_pkg is not in the workspace nor "
         "installed here; what depends on it keeps '?'"),
        ("PACKAGE_NOT_FOUND", 3, "package nav_bringupp is not in the workspace nor "
         "installed here (did you mean nav_bringup?)"),
        # three letters: too short to tell a typo from another package
        ("LAUNCH_UNKNOWN_VALUE", 4, "package nav is not in the workspace nor installed "
         "here; what depends on it keeps '?'")]
    python = load(str(root / "src/other/launch/main.launch.py"), ws, {}, {})
    assert [(code, line) for code, line, _m in said(python)] == [
        ("LAUNCH_UNKNOWN_VALUE", 9), ("PACKAGE_NOT_FOUND", 11)]
    assert said(python)[1][2].endswith("(did you mean nav_bringup?)")


def test_the_nearest_packages_are_the_installed_ones_too(write_tree, tmp_path):
    """Installed packages count (an ament index, ROS_PACKAGE_PATH); only the nearest
    are offered, and a name as far from each as it is long is none's misspelling."""
    root = write_tree({**FILES, "opt/share/ament_index/resource_index/packages/nav2_msgs": "",
                       "opt/share/ament_index/resource_index/packages/nav2_msgx": "",
                       "ros1/nav_msgs/package.xml": package_xml("nav_msgs")})
    ws = scan([str(root / "src")], {"AMENT_PREFIX_PATH": str(root / "opt"),
                                   "ROS_PACKAGE_PATH": str(root / "ros1")})
    assert ws.misspelt("nav2_msgz") == ["nav2_msgs", "nav2_msgx"]
    assert ws.misspelt("nav_msg") == ["nav_msgs"]
    assert ws.misspelt("nav_bringup") == []  # found: no misspelling
    assert ws.misspelt("rclcpp_lifecycle") == []
