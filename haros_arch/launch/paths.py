"""Absolute paths a launch file's author wrote for a file to include.

An include of ``/home/me/ws/install/pkg/share/pkg/launch/x.launch.py`` works on the
machine that wrote it only: another checkout, a container or the robot has other folders,
and the include fails there. The file itself stays unknown here (it lies outside the
workspace and the installed packages, ``LAUNCH_UNKNOWN_VALUE``), but the path is the
launch file's own text, so that much is said, ``LAUNCH_INCLUDE_ABSOLUTE``: the same
mistake ``absolute-paths-in-launch`` reports in parameter values and node arguments.
"""

from __future__ import annotations

import os

# the folders of one machine: a user's home (Linux, macOS), an administrator's, mounts.
# /opt and /usr hold installed software, which a ROS install shares across machines of
# one distribution; /tmp holds files an earlier step of the launch may write.
MACHINE_PREFIXES = ("/home/", "/Users/", "/root/", "/mnt/", "/media/")


def written_absolute(path: str, includer: str | None) -> bool:
    """Whether ``path`` is an absolute path into one machine's folders
    (``MACHINE_PREFIXES``) that the including launch file ``includer`` writes out in
    full: a value the file made from the environment (``$(env HOME)``), a package look-up
    or a launch argument given on the command line is not its text."""
    if not os.path.isabs(path) or not path.startswith(MACHINE_PREFIXES) or not includer:
        return False
    try:
        with open(includer, encoding="utf-8", errors="replace") as handle:
            text = handle.read(1_000_000)
    except OSError:
        return False
    return path in text
