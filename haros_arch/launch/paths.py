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
import re
from collections.abc import Callable

from ..model.values import UNKNOWN_MARK
from ..share import generated_at
from ..workspace import Workspace

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


# options after which a path names a file the program writes (missing_argument_paths)
_OUTPUT_OPTION = re.compile(r"-[oOfw]$|--?\w*(out|save|log|write|record|dump|prefix)\w*$",
                            re.IGNORECASE)
_OUTPUT_KEY = re.compile(r"out|save|log|write|record|dump|prefix", re.IGNORECASE)


def missing_argument_paths(words: list[str], workspace: Workspace,
                           installed: Callable[[str], str | None] | None = None
                           ) -> list[str]:
    """The absolute paths among a node's command-line words (a word, or what follows
    the ``=`` of ``--world=PATH`` or the ``:=`` of ``name:=PATH``) that lie in a
    workspace folder and are not there: ROS 1's ``$(find pkg)/...`` gives the
    package's own folder, so such a file is missing where the node runs as well
    (gazebo_ros' range_world.launch handed gzserver ``$(find gazebo_plugins)/test/
    test_worlds/gazebo_ros_range.W()orld``), unless the package's build makes it
    into its share folder: roslaunch's ``$(find pkg)/path`` looks for ``path`` in the
    devel and install spaces' share folders before the package's own (vrx_gazebo's
    ``xacro_add_files(worlds/ocean.world.xacro INSTALL DESTINATION worlds)`` makes
    the ``worlds/ocean.world`` its launch files give gzserver). ROS 2's share folder
    holds what the package's build installs: ``installed`` gives the source file a
    path of it stands for (``share.share_source``), or None for a file the build
    makes, which is not judged (mycobot_ros2's detect_marker.launch.py gave rviz2
    ``-d`` its package's ``config/mypal_260.rviz``, not there). A word with an
    unknown part, or in a git submodule not checked out here, is not judged; nor is
    one the program may write, given to an option of output (map_saver's ``-f
    $(find pkg)/maps/new``, rosbag's ``-O``, ``--log_file=...``, ``_save_path:=...``)."""
    missing: list[str] = []
    for candidate in _path_words(words, output=False):
        for path in _path_list(candidate.strip("'\"")):
            if not path.startswith(os.sep) or UNKNOWN_MARK in path:
                continue
            source: str | None = os.path.normpath(path)
            if installed is not None:
                source = installed(source)  # type: ignore[arg-type]
            elif generated_at(workspace, source) is not None:  # type: ignore[arg-type]
                continue
            if source is None or not workspace.holds(source):
                continue
            if not os.path.exists(source) and workspace.submodule_of(source) is None \
                    and source not in missing:
                missing.append(source)
    return missing


def written_argument_paths(words: list[str]) -> list[str]:
    """The absolute paths among a node's command-line words that name a file the program
    writes (after an option of output, ``xacro -o PATH``, or as the value of an output
    key, ``--out=PATH``): another node of the launch may be handed that file to read
    (mbzirc2020's challenge launch files run xacro with ``-o $(find challenge_worlds)/
    worlds/challenge2.world`` and give that world to Gazebo)."""
    return [os.path.normpath(path) for word in _path_words(words, output=True)
            for path in _path_list(word.strip("'\""))
            if path.startswith(os.sep) and UNKNOWN_MARK not in path]


def _path_words(words: list[str], output: bool) -> list[str]:
    """The words (or values of ``key=value`` / ``key:=value`` words) that may be paths a
    program reads (``output`` False) or writes (True)."""
    found: list[str] = []
    for at, word in enumerate(words):
        reads, writes = [word], []
        for sep in (":=", "="):
            if sep in word:
                key, value = word.split(sep, 1)
                if _OUTPUT_KEY.search(key.lstrip("-_")):
                    reads, writes = [], [value]
                else:
                    reads.append(value)
                break
        if at and _OUTPUT_OPTION.match(words[at - 1]):
            reads, writes = [], [word]
        found += writes if output else reads
    return found


def _path_list(text: str) -> list[str]:
    """A list of absolute paths joined by ``:``, a search path (``GAZEBO_MODEL_PATH``'s
    form, ``-add_model_path=$(find a)/models:$(find b)/urdf``): its paths; else the text."""
    parts = text.split(":")
    if len(parts) > 1 and all(part.startswith(os.sep) for part in parts):
        return parts
    return [text]
