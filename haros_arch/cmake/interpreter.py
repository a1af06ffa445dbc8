"""Evaluate CMake commands far enough to know a package's build targets.

Variables (with ``${}`` and ``$ENV{}`` references, nested), list splitting of unquoted
arguments, ``set``/``unset``/``list(APPEND)``, ``project``, ``if``/``elseif``/``else``
(known conditions decide, unknown ones make what they guard conditional), ``foreach``,
and the target commands. Commands it does not know are skipped quietly: they cannot
create runnable nodes.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

from ..model.conditions import Condition
from ..model.location import Location
from .conditions import Evaluator
from .lexer import Argument, Invocation

_VAR_REF = re.compile(r"\$(ENV)?\{([^${}]*)\}")
MAX_STEPS = 200_000


@dataclass
class Target:
    """A build target: ``add_executable`` or ``add_library``."""

    name: str
    kind: str  # "executable" | "library"
    sources: list[str] = field(default_factory=list)  # absolute paths
    output_name: str | None = None
    conditions: tuple[Condition, ...] = ()
    line: int = 0
    column: int = 0
    file: str = ""


@dataclass
class Interpreter:
    source_dir: str
    environment: Mapping[str, str]
    variables: dict[str, str] = field(default_factory=dict)
    targets: dict[str, Target] = field(default_factory=dict)
    conditions: list[Condition] = field(default_factory=list)
    location: Callable[[str, int, int], Location] | None = None
    file: str = ""
    steps: int = 0

    def __post_init__(self) -> None:
        for var in ("CMAKE_SOURCE_DIR", "CMAKE_CURRENT_SOURCE_DIR", "PROJECT_SOURCE_DIR",
                    "CMAKE_CURRENT_LIST_DIR"):
            self.variables[var] = self.source_dir

    # -- values ---------------------------------------------------------------
    def expand(self, text: str) -> str:
        for _ in range(100):
            match = _VAR_REF.search(text)
            if not match:
                return text
            if match.group(1):
                value = self.environment.get(match.group(2), "")
            else:
                value = self.variables.get(match.group(2), "")
            text = text[:match.start()] + value + text[match.end():]
        return text

    def arguments(self, args: tuple[Argument, ...]) -> list[str]:
        """Expand references; unquoted arguments split on ';' as CMake does."""
        values: list[str] = []
        for arg in args:
            if arg.kind == "bracket":
                values.append(arg.text)
            elif arg.kind == "quoted":
                values.append(self.expand(arg.text))
            else:
                expanded = self.expand(arg.text)
                values.extend(item.replace("\\;", ";")
                              for item in re.split(r"(?<!\\);", expanded) if item)
        return values

    # -- execution ------------------------------------------------------------
    def run(self, commands: list[Invocation]) -> None:
        index = 0
        while index < len(commands):
            index = self.step(commands, index)

    def step(self, commands: list[Invocation], index: int) -> int:
        self.steps += 1
        if self.steps > MAX_STEPS:
            return len(commands)
        command = commands[index]
        if command.name == "if":
            return self.run_if(commands, index)
        if command.name == "foreach":
            return self.run_foreach(commands, index)
        handler = getattr(self, "cmd_" + command.name, None)
        if handler is not None:
            handler(command, self.arguments(command.args))
        return index + 1

    def block_end(self, commands: list[Invocation], index: int, opener: str,
                  closer: str, middles: tuple[str, ...] = ()) -> list[int]:
        """Indexes of the middle keywords at depth 0 and of the closing command."""
        depth = 0
        marks: list[int] = []
        for position in range(index + 1, len(commands)):
            name = commands[position].name
            if name == opener:
                depth += 1
            elif name == closer:
                if depth == 0:
                    marks.append(position)
                    return marks
                depth -= 1
            elif depth == 0 and name in middles:
                marks.append(position)
        marks.append(len(commands))
        return marks

    def run_if(self, commands: list[Invocation], index: int) -> int:
        marks = self.block_end(commands, index, "if", "endif", ("elseif", "else"))
        branches = [index, *marks[:-1]]
        end = marks[-1]
        pushed = 0
        for number, start in enumerate(branches):
            stop = marks[number]
            head = commands[start]
            if head.name == "else":
                self.run(commands[start + 1:stop])
                break
            text = " ".join(a.text for a in head.args)
            evaluator = Evaluator(self.variables, self.targets, self.source_dir,
                                  lambda name: hasattr(self, "cmd_" + name.lower()))
            decided = evaluator.evaluate(self.arguments(head.args))
            if decided is None:
                self.conditions.append(Condition(text, "source", head.name, self._where(head)))
                pushed += 1
                self.run(commands[start + 1:stop])
                self.conditions[-1] = Condition(
                    text, "source", "else", self._where(head))
                continue
            if decided:
                self.run(commands[start + 1:stop])
                break
        del self.conditions[len(self.conditions) - pushed:]
        return end + 1

    def run_foreach(self, commands: list[Invocation], index: int) -> int:
        end = self.block_end(commands, index, "foreach", "endforeach")[-1]
        args = self.arguments(commands[index].args)
        if not args:
            return end + 1
        var, items = args[0], args[1:]
        if items[:1] == ["RANGE"]:
            numbers = [int(x) for x in items[1:] if x.lstrip("-").isdigit()]
            start, stop, step = (0, numbers[0], 1) if len(numbers) == 1 else (
                *numbers[:2], numbers[2] if len(numbers) > 2 else 1)
            items = [str(n) for n in range(start, stop + 1, step or 1)]
        elif items[:1] == ["IN"]:
            values: list[str] = []
            mode = "ITEMS"
            for item in items[1:]:
                if item in ("LISTS", "ITEMS"):
                    mode = item
                elif mode == "LISTS":
                    values.extend(x for x in self.variables.get(item, "").split(";") if x)
                else:
                    values.append(item)
            items = values
        for item in items:
            self.variables[var] = item
            self.run(commands[index + 1:end])
        return end + 1

    def _where(self, command: Invocation) -> Location:
        if self.location is not None:
            return self.location(self.file, command.line, command.column)
        return Location(file=self.file, line=command.line, column=command.column)

    # -- commands -------------------------------------------------------------
    def cmd_set(self, command: Invocation, args: list[str]) -> None:
        if not args:
            return
        values = args[1:]
        for keyword in ("PARENT_SCOPE", "CACHE"):
            if keyword in values:
                values = values[:values.index(keyword)]
        self.variables[args[0]] = ";".join(values)

    def cmd_option(self, command: Invocation, args: list[str]) -> None:
        if args and args[0] not in self.variables:
            self.variables[args[0]] = args[2] if len(args) > 2 else "OFF"

    def cmd_unset(self, command: Invocation, args: list[str]) -> None:
        if args:
            self.variables.pop(args[0], None)

    def cmd_list(self, command: Invocation, args: list[str]) -> None:
        if len(args) >= 2 and args[0] == "APPEND":
            current = [x for x in self.variables.get(args[1], "").split(";") if x]
            self.variables[args[1]] = ";".join(current + args[2:])

    def cmd_project(self, command: Invocation, args: list[str]) -> None:
        if args:
            self.variables["PROJECT_NAME"] = args[0]
            self.variables["CMAKE_PROJECT_NAME"] = args[0]
            self.variables[f"{args[0]}_SOURCE_DIR"] = self.source_dir

    def cmd_add_executable(self, command: Invocation, args: list[str]) -> None:
        self._add_target(command, args, "executable",
                         ("WIN32", "MACOSX_BUNDLE", "EXCLUDE_FROM_ALL"))

    def cmd_add_library(self, command: Invocation, args: list[str]) -> None:
        self._add_target(command, args, "library",
                         ("STATIC", "SHARED", "MODULE", "OBJECT", "EXCLUDE_FROM_ALL"))

    def _add_target(self, command: Invocation, args: list[str], kind: str,
                    flags: tuple[str, ...]) -> None:
        if not args or "IMPORTED" in args or "ALIAS" in args or "INTERFACE" in args[1:2]:
            return
        sources = [self._path(a) for a in args[1:] if a not in flags]
        self.targets[args[0]] = Target(args[0], kind, sources, None,
                                       tuple(self.conditions), command.line,
                                       command.column, self.file)

    def cmd_target_sources(self, command: Invocation, args: list[str]) -> None:
        if args and args[0] in self.targets:
            keywords = ("PRIVATE", "PUBLIC", "INTERFACE")
            self.targets[args[0]].sources.extend(
                self._path(a) for a in args[1:] if a not in keywords)

    def cmd_set_target_properties(self, command: Invocation, args: list[str]) -> None:
        if "PROPERTIES" not in args:
            return
        split = args.index("PROPERTIES")
        props = args[split + 1:]
        for key, value in zip(props[::2], props[1::2], strict=False):
            if key == "OUTPUT_NAME":
                for name in args[:split]:
                    if name in self.targets:
                        self.targets[name].output_name = value

    def _path(self, text: str) -> str:
        return os.path.normpath(os.path.join(self.source_dir, text))
