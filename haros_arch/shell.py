"""How a shell and a terminal emulator run a command line: its words as a shell splits
them, and the commands it runs, through ``gnome-terminal -- bash -c '...'`` and the like.

A Python node's subprocess call (``extract.python.visitor``: does it start ROS nodes?)
and a ROS 2 launch file's process (``launch.ros2.entities``: is it ``ros2 run``?) read
their commands so.
"""

from __future__ import annotations

import itertools
import re
import shlex

# a command's words read at most; the terminal emulators that run the command after
# ``--``, ``-e``, ``-x`` (or ``--command=`` / ``--execute``), and the shells that run
# the text after ``-c``, with what may come before a command in a shell line
MAX_WORDS = 64
TERMINALS = frozenset({"gnome-terminal", "xterm", "konsole", "terminator", "tilix",
                       "xfce4-terminal", "mate-terminal", "lxterminal", "kitty",
                       "alacritty", "urxvt", "x-terminal-emulator"})
_TERMINAL_RUNS = frozenset({"--", "-e", "-x", "--command", "--execute"})
SHELLS = frozenset({"bash", "sh", "zsh", "dash"})
_PREFIX_WORDS = frozenset({"exec", "nohup", "sudo", "setsid"})
_SEPARATORS = frozenset({";", "&&", "||", "|", "&"})


def split_words(text: str) -> list[str]:
    """A command line's words, as a shell splits them (quotes kept together, ``;``,
    ``&&``, ``|`` words of their own); split on spaces when its quoting is broken."""
    try:
        lexer = shlex.shlex(text, posix=True, punctuation_chars=";&|")
        lexer.whitespace_split = True
        return list(itertools.islice(lexer, MAX_WORDS))
    except ValueError:
        return text.split()[:MAX_WORDS]


def commands(words: list[str], depth: int = 0) -> list[list[str]]:
    """The commands a command line runs: itself, or what the terminal emulator or the
    shell it starts runs (``gnome-terminal --tab -- bash -c 'cd ~/PX4 && make; exec
    bash'``: ``cd ~/PX4``, ``make``, ``exec bash``), each without a leading ``exec``,
    ``nohup``, ``sudo`` or variable assignment."""
    found: list[list[str]] = []
    current: list[str] = []
    for word in [*words, ";"]:
        if word not in _SEPARATORS:
            current.append(word)
            continue
        while current and (current[0] in _PREFIX_WORDS or re.fullmatch(r"\w+=\S*", current[0])):
            current = current[1:]
        first = current[0].rsplit("/", 1)[-1] if current else ""
        inner: list[str] | None = None
        if first in TERMINALS:
            at = next((i for i, w in enumerate(current) if w in _TERMINAL_RUNS
                       or w.startswith("--command=")), None)
            if at is not None:
                given = current[at]
                inner = ([given.split("=", 1)[1]] if given.startswith("--command=")
                         else current[at + 1:])
                if len(inner) == 1:
                    inner = split_words(inner[0])
        elif first in SHELLS and len(current) > 2 and current[1] == "-c":
            inner = split_words(current[2])
        if inner is not None and depth < 3:
            found += commands(inner, depth + 1)
        elif current:
            found.append(current)
        current = []
    return found
