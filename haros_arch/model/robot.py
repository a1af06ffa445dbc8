"""Robot descriptions a configuration loads into a simulator, as read (``robot``).

One ``RobotDescription`` per description a spawner hands to Gazebo: where it comes from
(the parameter or file the spawner names, and the launch line that set it), the files
the xacro expansion read, the links and joints of the expanded document, and each
``<plugin>`` with the node instance that makes its calls. ``completeness`` says whether
every part was known (``partial``: an argument nobody set, a file not found, a plugin
library not in the table; the reasons say which, with file:line).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from .launch_tree import _location
from .location import NOWHERE, Location

OPTIONAL: dict[str, Any] = {"optional": True}


@dataclass
class DescribedPlugin:
    name: str  # the plugin's ``name`` attribute
    filename: str  # its library
    location: Location = NOWHERE  # the <plugin> element in its (xacro) file
    node: str | None = None  # the node instance making its calls; None: not in the table
    conditions: list[str] = field(default_factory=list, metadata=OPTIONAL)  # xacro ifs


@dataclass
class DescribedControl:
    """A ``<ros2_control>`` system of the description: its hardware plugin and joints."""

    name: str
    hardware: str | None = None  # ``<hardware><plugin>``: gazebo_ros2_control/GazeboSystem
    joints: list[str] = field(default_factory=list)
    location: Location = NOWHERE


@dataclass
class RobotDescription:
    # the parameter (``/robot_description``), the file the spawner names, or the command
    # line whose output its ``-string`` is
    name: str
    file: str | None = None  # the top file read (workspace-relative), None if unknown
    location: Location = NOWHERE  # where the launch file gives it (param, spawner)
    files: list[str] = field(default_factory=list)
    links: list[str] = field(default_factory=list)
    joints: list[str] = field(default_factory=list)
    plugins: list[DescribedPlugin] = field(default_factory=list)
    ros2_control: list[DescribedControl] = field(default_factory=list, metadata=OPTIONAL)
    completeness: str = "complete"  # complete | partial
    completeness_reasons: list[str] = field(default_factory=list, metadata=OPTIONAL)


def description_from_data(data: Any) -> RobotDescription | None:
    """The inverse of ``serialise.to_data`` for one description; None if it is not one."""
    if not isinstance(data, dict):
        return None
    plugins = [DescribedPlugin(str(p.get("name", "")), str(p.get("filename", "")),
                               _location(p.get("location")), p.get("node"),
                               [str(c) for c in p.get("conditions") or ()])
               for p in data.get("plugins") or () if isinstance(p, dict)]
    controls = [DescribedControl(str(c.get("name", "")), c.get("hardware"),
                                 [str(j) for j in c.get("joints") or ()],
                                 _location(c.get("location")))
                for c in data.get("ros2_control") or () if isinstance(c, dict)]
    return RobotDescription(
        str(data.get("name", "")), data.get("file"), _location(data.get("location")),
        [str(f) for f in data.get("files") or ()], [str(x) for x in data.get("links") or ()],
        [str(x) for x in data.get("joints") or ()], plugins, controls,
        str(data.get("completeness", "complete")),
        [str(r) for r in data.get("completeness_reasons") or ()])
