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
    ``nohup``, ``sudo`` or variable assignment (``run_order``, without the waits)."""
    return [command for command, _ in run_order(words, depth)]


# what a command waits for before it starts: the shell's operator before it (``;``: the
# commands before have ended; ``&&``: they succeeded; ``||``: they failed) and those
# commands' line
Wait = tuple[str, str]
# commands that end at once and as a rule succeed (a shell's set-up before the program
# it runs: ``source setup.bash && ros2 run ...``, ``sleep 5; ros2 launch ...``): waiting
# for them is no condition of what follows
SETUP = frozenset({"source", ".", "cd", "export", "sleep", "echo", "printf", "set",
                   "unset", "true", ":", "pushd", "popd", "clear", "alias", "umask",
                   "ulimit", "shopt", "trap", "mkdir", "sync"})
_WAIT_TEXT = 60  # characters of the line waited for, in a wait's text


def run_order(words: list[str], depth: int = 0) -> list[tuple[list[str], tuple[Wait, ...]]]:
    """``commands`` with what each waits for before it starts, as a shell runs a line:
    lists split by ``;`` and ``&`` (after ``;`` the next list starts once the one before
    has ended, after ``&`` at once), each list of pipelines joined by ``&&`` / ``||``
    (one runs once those before it succeeded / failed), a pipeline's commands (``|``)
    together. A wait for set-up commands only (``SETUP``) is none; what a wrapper
    (a terminal emulator, ``bash -c``) runs waits for what the wrapper waits for. A
    command after ``exec CMD;`` never runs (the shell became CMD)."""
    found: list[tuple[list[str], tuple[Wait, ...]]] = []
    base: tuple[Wait, ...] = ()  # what the current list waits for
    waits = base  # what the current pipeline waits for
    done: list[list[str]] = []  # the commands of the current list before this pipeline
    line: list[str] = []  # their words, with the operators between them
    pipeline: list[list[str]] = []
    current: list[str] = []
    for word in [*words, ";"]:
        if word not in _SEPARATORS:
            current.append(word)
            continue
        written = current
        replaced = False
        while current and (current[0] in _PREFIX_WORDS or re.fullmatch(r"\w+=\S*", current[0])):
            replaced = replaced or current[0] == "exec"
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
            found += [(command, waits + more) for command, more in run_order(inner, depth + 1)]
        elif current:
            found.append((current, waits))
        if current:
            pipeline.append(current)
        line += [*written, word] if written else []
        current = []
        if word == "|":
            continue
        done += pipeline
        pipeline = []
        if replaced and word != "&":
            break  # ``exec CMD; ...``: the shell is CMD now, what follows never runs
        if word in ("&&", "||"):
            waits = base + _wait(word, done, line[:-1])
            continue
        if word == ";":
            base = base + _wait(word, done, line[:-1])
        waits, done, line = base, [], []
    return found


def _wait(operator: str, done: list[list[str]], line: list[str]) -> tuple[Wait, ...]:
    """What a command after ``operator`` waits for: the line of ``done`` (none when those
    are set-up commands only, ``SETUP``)."""
    if not done or all(command[0] in SETUP for command in done):
        return ()
    text = " ".join(line)
    return ((operator, text if len(text) <= _WAIT_TEXT else text[:_WAIT_TEXT - 3] + "..."),)
