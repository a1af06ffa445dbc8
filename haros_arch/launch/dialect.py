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

__all__ = ["foreign_to_package", "package_ros_version", "ros_version"]

# ``exec=`` and ``namespace=`` as attributes only: a word of an attribute's value is none
# (naoqi_driver2's roslaunch file passes ``args="... --namespace=$(arg namespace)"``)
ROS2_MARKS = re.compile(
    rb"\sexec\s*=\s*[\"']|<let\b|\$\(var\b|<push[-_]ros[-_]namespace\b|"
    rb"<node_container\b|<set_remap\b|<set_parameter\b|<set_env\b|"
    rb"\snamespace\s*=\s*[\"']|<executable\b|"
    rb"<composable_node\b|<load_composable_node\b|"
    rb"\$\((?:find-pkg-share|find-pkg-prefix|find-exec|exec-in-pkg)\b")
ROS1_MARKS = re.compile(
    rb"<node\b[^>]*?\stype\s*=|<test\b|<rosparam\b|<machine\b|<master\b|"
    rb"\$\((?:find|arg|optenv)\s")
HEAD = 256 * 1024


def package_ros_version(package: Package | None) -> int | None:
    """1 or 2 as the package's manifest says (``manifest.ros_version``), else None."""
    return None if package is None else manifest_ros_version(package)


def _by_content(path: str, head: bytes | None) -> int | None:
    """1 or 2 when the XML file has marks of one launch system only, else None."""
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
    return None


def ros_version(path: str, workspace: Workspace | None = None,
                head: bytes | None = None) -> int:
    """1 (roslaunch) or 2 (ROS 2 launch) for the launch file at ``path``."""
    lower = path.lower()
    if lower.endswith((".py", ".yaml", ".yml")):
        return 2
    by_content = _by_content(path, head)
    if by_content is not None:
        return by_content
    if workspace is not None:
        by_package = package_ros_version(workspace.package_of(path))
        if by_package is not None:
            return by_package
    return 2 if lower.endswith(".launch.xml") else 1


def foreign_to_package(path: str, workspace: Workspace) -> str | None:
    """Why the XML launch file at ``path`` cannot be run by its own package's ROS, or None.

    A file whose content is roslaunch XML (``<node type=>``, ``<rosparam>``, ``$(find)``)
    in a package that builds with ament only is a ROS 1 leftover of a port that
    ``ros2 launch`` rejects (twist_mux's ``twist_mux.launch``, mavros_extras'
    ``px4flow.launch``); a ROS 2 XML file in a catkin-only package is the reverse. A
    package that builds for both (a ``$ROS_VERSION`` condition on a dependency) keeps
    both kinds of file."""
    if path.lower().endswith((".py", ".yaml", ".yml")):
        return None
    package = workspace.package_of(path)
    if package is None or any(dep.condition and "ROS_VERSION" in dep.condition
                              for dep in package.dependencies):
        return None
    by_package = package_ros_version(package)
    by_content = _by_content(path, None)
    if by_package is None or by_content is None or by_package == by_content:
        return None
    build = "an ament" if by_package == 2 else "a catkin"
    runner = "ros2 launch" if by_package == 2 else "roslaunch"
    return (f"{'roslaunch (ROS 1)' if by_content == 1 else 'ROS 2 launch'} XML in "
            f"{package.name}, {build} (ROS {by_package}) package: {runner} cannot run it")
