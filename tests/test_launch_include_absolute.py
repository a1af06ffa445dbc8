"""An include by an absolute path into one machine's folders, written out in the launch
file, is said as a warning, LAUNCH_INCLUDE_ABSOLUTE, where the include is: ros2_kortex
a588109's gen3_dual.launch.py included kortex_control.launch.py from
``/home/<developer>/.../install/kortex_bringup/share/...``, which no other machine has.
The file itself stays unknown (LAUNCH_UNKNOWN_VALUE), ROS 1 and ROS 2 alike; a path
the file takes from the environment (``$(env HOME)``) or from the command line is not
its text, and is not said."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

PY = """
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
def generate_launch_description():
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            '/home/dev/ws/install/pkg/share/pkg/launch/control.launch.py')),
    ])
"""

XML = """<launch>
  <arg name="other" default="/Users/dev/other.launch"/>
  <include file="/home/dev/catkin_ws/src/pkg/launch/control.launch"/>
  <include file="$(env HOME)/robot/control.launch"/>
  <include file="$(arg other)"/>
  <include file="$(arg given)"/>
</launch>
"""


def _said(model) -> list[tuple[str, int]]:
    return sorted((d.message.split()[2], d.location.line) for d in model.diagnostics
                  if d.code == "LAUNCH_INCLUDE_ABSOLUTE")


def test_ros2_include_by_a_home_path(write_tree) -> None:
    root = write_tree({"src/pkg/package.xml": package_xml("pkg", "ament_python"),
                       "src/pkg/launch/dual.launch.py": PY})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/pkg/launch/dual.launch.py"), ws, {}, {})
    assert _said(model) == [("/home/dev/ws/install/pkg/share/pkg/launch/control.launch.py",
                             6)]
    assert any(d.code == "LAUNCH_UNKNOWN_VALUE" for d in model.diagnostics)


def test_ros1_include_by_a_home_path(write_tree) -> None:
    root = write_tree({"src/pkg/package.xml": package_xml("pkg", "catkin"),
                       "src/pkg/launch/main.launch": XML})
    ws = scan([str(root / "src")], {"HOME": "/home/runner"})
    model = load(str(root / "src/pkg/launch/main.launch"), ws,
                 {"given": "/home/runner/x.launch"}, {"HOME": "/home/runner"})
    assert _said(model) == [("/Users/dev/other.launch", 5),
                            ("/home/dev/catkin_ws/src/pkg/launch/control.launch", 3)]
