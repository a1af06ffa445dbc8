"""How ``rosrun`` and roslaunch find a ROS 1 node that no build file installs.

roslaunch looks for ``type`` as an executable file anywhere in the package's source
folder (after catkin's libexec folders), so a script under ``test/`` or at the top of a
package still starts. We do the same for the launch declarations that no ``Node`` of
the build-file stage matches, and only for Python programs (a compiled binary would
need its build target, which the build-file stage already knows).
"""

from __future__ import annotations

import os
import stat

from .cmake.nodes import is_python
from .model.source import Node, Package
from .workspace import Workspace

MAX_DEPTH = 8
SKIP = {"build", "devel", "install", "node_modules", "__pycache__"}


def find_executable(root: str, name: str, executable: bool = True) -> str | None:
    """The first executable file called ``name`` under ``root`` (breadth first); with
    ``executable=False``, the first plain file of that name, executable or not."""
    level = [root]
    for _ in range(MAX_DEPTH):
        following: list[str] = []
        for folder in level:
            try:
                entries = sorted(os.scandir(folder), key=lambda e: e.name)
            except OSError:
                continue
            for entry in entries:
                if entry.name.startswith(".") or entry.name in SKIP:
                    continue
                if entry.is_dir(follow_symlinks=False):
                    following.append(entry.path)
                elif entry.name == name and (
                        _is_executable(entry.path) if executable else _is_file(entry.path)):
                    return entry.path
        level = following
    return None


def _is_file(path: str) -> bool:
    try:
        return stat.S_ISREG(os.stat(path).st_mode)
    except OSError:
        return False


def _is_executable(path: str) -> bool:
    try:
        mode = os.stat(path).st_mode
    except OSError:
        return False
    return stat.S_ISREG(mode) and bool(mode & stat.S_IXUSR)


def script_node(package: Package, name: str, workspace: Workspace) -> Node | None:
    """A Python script that rosrun would start as ``package/name``, if there is one."""
    if package.build_type != "catkin":
        return None
    path = find_executable(package.root, name)
    if path is None or not is_python(path):
        return None
    source = os.path.realpath(path)
    return Node(package.name, name, "script", "python", [workspace.relpath(source)],
                location=workspace.location(path, 1, 1), entry="")
