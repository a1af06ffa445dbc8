"""A ``<node>`` whose program runs roslaunch: the launch file it starts, read as an include.

timed_roslaunch (``timed_roslaunch.sh DELAY PKG FILE.launch [name:=value ...]``, and the
copies robots carry, kinova-movo's ``si_utils/timed_roslaunch``) is a shell script that
sleeps, drops its first word (``shift``) and runs ``roslaunch $@``. roslaunch starts the
node's process with ``ROS_NAMESPACE`` set to the node's namespace (``core.setup_env``)
and its command line the node's ``args``, then a ``from:=to`` word per remap and
``__name:=NAME`` (``node_args.create_local_process_args``); the roslaunch it runs puts
its top-level file in that namespace (``get_ros_namespace``: ``__ns:=`` first, else
``ROS_NAMESPACE``) and takes every ``name:=value`` word as an argument
(``load_sysargs_into_context``). The delay is not modelled.

A script is read when it can be found (in its package, as roslaunch finds ``type``):
it runs roslaunch this way when a line is ``roslaunch $@`` (or ``"$@"``, ``$*``, after
``exec``), the words it drops those of the ``shift`` lines before it. Not found, the
timed_roslaunch package's script is taken as it is published; any other is not read.
"""

from __future__ import annotations

import os
import re

from ...files import read_text
from ...model.location import Location
from ...rosrun import find_executable
from ...workspace import Workspace

# the published package: its script sleeps $1 seconds, shifts once, runs roslaunch $@
KNOWN = {("timed_roslaunch", "timed_roslaunch.sh"): 1}
_RUN = re.compile(r'^\s*(?:exec\s+)?roslaunch\s+"?\$[@*]"?\s*(?:[;&|#].*)?$')
_SHIFT = re.compile(r"^\s*shift(?:\s+(\d+))?\s*(?:[;#].*)?$")
_SHELLS = ("sh", "bash", "dash", "zsh")
# roslaunch's options that take the next word (roslaunch/__init__.py, _get_optparse)
VALUE_OPTIONS = {"-p", "--port", "-u", "--server_uri", "--run_id", "--pid",
                 "--master-logger-level", "-w", "--numworkers", "-t", "--timeout",
                 "--sigint-timeout", "--sigterm-timeout", "--log-dir"}
# options with which roslaunch prints and starts nothing
PRINT_OPTIONS = {"--files", "--args", "--nodes", "-n", "--find-node", "--ros-args",
                 "--dump-params", "--dump-deps", "--version", "-h", "--help"}
LAUNCH_SUFFIXES = (".launch", ".xml", ".test")


def dropped_words(package: str, executable: str, workspace: Workspace) -> int | None:
    """How many leading words of its command line a node's program drops before it runs
    ``roslaunch`` with the rest; None when it is not such a program (or not known)."""
    root = workspace.find(package) if package else None
    script = None
    if root is not None:
        script = (find_executable(root, executable)
                  or find_executable(root, executable, executable=False))
    if script is None:
        return KNOWN.get((package, executable))
    text, _ = read_text(script, Location(file=script))
    if text is None:
        return KNOWN.get((package, executable))
    lines = text.splitlines()
    if not lines or not lines[0].startswith("#!") or os.path.basename(
            lines[0][2:].split()[-1] if lines[0][2:].split() else "") not in _SHELLS:
        return None
    shifted = 0
    for line in lines[1:]:
        if _RUN.match(line):
            return shifted
        match = _SHIFT.match(line)
        if match:
            shifted += int(match.group(1) or 1)
    return None


def launched_file(words: list[str]) -> tuple[list[str], list[str]] | None:
    """roslaunch's command line split into the launch file's words (``PKG FILE`` or a
    path) and its ``name:=value`` words; None when it starts nothing (an option that
    prints) or names no file."""
    positional: list[str] = []
    mappings: list[str] = []
    skip = False
    for word in words:
        if skip:
            skip = False
            continue
        if word in PRINT_OPTIONS:
            return None
        if word.startswith("-"):
            skip = word in VALUE_OPTIONS
            continue
        (mappings if ":=" in word else positional).append(word)
    if not positional:
        return None
    if positional[0].endswith(LAUNCH_SUFFIXES):
        return positional[:1], mappings  # a path: the first file (more are rare)
    return positional[:2], mappings
