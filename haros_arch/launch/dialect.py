"""Which launch system a launch file is written for: roslaunch (ROS 1) or ROS 2 launch.

Python and YAML launch files are ROS 2. An XML file is decided by what it says, then by
the package that holds it, and by its name only when neither tells: ROS 1 robots name
included files ``*.launch.xml`` too (TurtleBot's ``mobile_base.launch.xml``, MoveIt's
``ompl_planning_pipeline.launch.xml``), so the suffix alone decides nothing.

- **Content**: tags, attributes and substitutions that exist in one system only
  (``<node type=>``, ``<rosparam>``, ``<machine>``, ``<test>``, ``$(find)``,
  ``$(arg)``, ``$(optenv)`` for roslaunch; ``exec=``, ``<let>``, ``$(var)``,
  ``$(find-pkg-share)``, ``namespace=`` ... for ROS 2). A file with marks of one side
  only is that side's.
- **Package**: a package that builds with catkin (``buildtool_depend``), a rosbuild
  package (``manifest.xml``) or a format 1 ``package.xml`` is ROS 1; one that builds
  with ament (``buildtool_depend`` or ``<build_type>``) is ROS 2.
- **Name**: ``*.launch.xml`` is ROS 2, anything else roslaunch.
"""

from __future__ import annotations

import re

from ..manifest import ros_version as manifest_ros_version
from ..model.source import Package
from ..workspace import Workspace

__all__ = ["package_ros_version", "ros_version"]

ROS2_MARKS = re.compile(
    rb"\bexec\s*=|<let\b|\$\(var\b|<push[-_]ros[-_]namespace\b|<node_container\b|"
    rb"<set_remap\b|<set_parameter\b|<set_env\b|\bnamespace\s*=[^=]|<executable\b|"
    rb"<composable_node\b|<load_composable_node\b|"
    rb"\$\((?:find-pkg-share|find-pkg-prefix|find-exec|exec-in-pkg)\b")
ROS1_MARKS = re.compile(
    rb"<node\b[^>]*?\stype\s*=|<test\b|<rosparam\b|<machine\b|<master\b|"
    rb"\$\((?:find|arg|optenv)\s")
HEAD = 256 * 1024


def package_ros_version(package: Package | None) -> int | None:
    """1 or 2 as the package's manifest says (``manifest.ros_version``), else None."""
    return None if package is None else manifest_ros_version(package)


def ros_version(path: str, workspace: Workspace | None = None,
                head: bytes | None = None) -> int:
    """1 (roslaunch) or 2 (ROS 2 launch) for the launch file at ``path``."""
    lower = path.lower()
    if lower.endswith((".py", ".yaml", ".yml")):
        return 2
    if head is None:
        try:
            with open(path, "rb") as handle:
                head = handle.read(HEAD)
        except OSError:
            head = b""
    head = re.sub(rb"<!--.*?-->", b"", head, flags=re.DOTALL)
    ros1, ros2 = ROS1_MARKS.search(head), ROS2_MARKS.search(head)
    if ros1 and not ros2:
        return 1
    if ros2 and not ros1:
        return 2
    if workspace is not None:
        by_package = package_ros_version(workspace.package_of(path))
        if by_package is not None:
            return by_package
    return 2 if lower.endswith(".launch.xml") else 1
