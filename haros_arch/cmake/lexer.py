"""A lexer for the CMake language: command invocations with their arguments.

Handles quoted arguments (escapes, line continuations), unquoted arguments (with
nested parentheses), bracket arguments ``[==[ ... ]==]``, line comments and bracket
comments ``#[[ ... ]]``. Errors raise ``CMakeSyntaxError`` with line and column; the
caller keeps the commands read before it. Scanning is regex-driven: a workspace has
hundreds of CMake files and this runs on all of them.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Literal

ArgKind = Literal["unquoted", "quoted", "bracket"]


@dataclass(frozen=True)
class Argument:
    text: str
    kind: ArgKind = "unquoted"


@dataclass(frozen=True)
class Invocation:
    name: str
    args: tuple[Argument, ...]
    line: int
    column: int
    file: str = ""


class CMakeSyntaxError(Exception):
    def __init__(self, message: str, line: int, column: int) -> None:
        super().__init__(message)
        self.message, self.line, self.column = message, line, column


_IDENT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_BRACKET_OPEN = re.compile(r"\[(=*)\[")
_SPACE = re.compile(r"[ \t\r\n]+")
_INLINE_SPACE = re.compile(r"[ \t\r]+")
_LINE_COMMENT = re.compile(r"#[^\n]*")
_QUOTED = re.compile(r'"((?:[^"\\]|\\.)*)"', re.S)
_UNQUOTED = re.compile(r'(?:[^\s()#"\\]|\\.)(?:[^\s()#\\]|\\.)*', re.S)
_ESCAPE = re.compile(r"\\(.)", re.S)
_ESCAPES = {"t": "\t", "n": "\n", "r": "\r", ";": "\\;", "\n": ""}


def _unescape(text: str) -> str:
    if "\\" not in text:
        return text
    return _ESCAPE.sub(lambda m: _ESCAPES.get(m.group(1), m.group(1)), text)


class _Scanner:
    def __init__(self, text: str) -> None:
        self.text = text
        self.pos = 0
        self.line = 1
        self.line_start = 0

    @property
    def column(self) -> int:
        return self.pos - self.line_start + 1

    def error(self, message: str) -> CMakeSyntaxError:
        return CMakeSyntaxError(message, self.line, self.column)

    def move_to(self, end: int) -> None:
        newlines = self.text.count("\n", self.pos, end)
        if newlines:
            self.line += newlines
            self.line_start = self.text.rindex("\n", self.pos, end) + 1
        self.pos = end

    def peek(self) -> str:
        return self.text[self.pos] if self.pos < len(self.text) else ""

    def skip_space_and_comments(self, newlines: bool = True) -> None:
        space = _SPACE if newlines else _INLINE_SPACE
        while True:
            match = space.match(self.text, self.pos)
            if match:
                self.move_to(match.end())
            if self.peek() != "#":
                return
            bracket = _BRACKET_OPEN.match(self.text, self.pos + 1)
            if bracket:
                self.read_bracket(self.pos + 1, bracket.group(1))
            else:
                self.move_to(_LINE_COMMENT.match(self.text, self.pos).end())  # type: ignore[union-attr]

    def read_bracket(self, start: int, equals: str) -> str:
        line, column = self.line, self.column
        self.move_to(start + len(equals) + 2)
        close = "]" + equals + "]"
        end = self.text.find(close, self.pos)
        if end < 0:
            raise CMakeSyntaxError("unterminated bracket argument or comment", line, column)
        body = self.text[self.pos:end]
        self.move_to(end + len(close))
        return body[1:] if body.startswith("\n") else body


def tokenize(text: str, file: str = "") -> list[Invocation]:
    """All command invocations of a CMake file, in order."""
    scanner = _Scanner(text)
    commands: list[Invocation] = []
    while True:
        scanner.skip_space_and_comments()
        if scanner.pos >= len(text):
            return commands
        line, column = scanner.line, scanner.column
        match = _IDENT.match(text, scanner.pos)
        if not match:
            raise scanner.error(f"expected a command name, found {scanner.peek()!r}")
        scanner.move_to(match.end())
        scanner.skip_space_and_comments(newlines=False)
        if scanner.peek() != "(":
            raise scanner.error(f"expected '(' after {match.group()}")
        scanner.move_to(scanner.pos + 1)
        commands.append(Invocation(match.group().lower(), tuple(_arguments(scanner)),
                                   line, column, file))


def _arguments(scanner: _Scanner) -> list[Argument]:
    args: list[Argument] = []
    depth = 0
    line, column = scanner.line, scanner.column
    text = scanner.text
    while True:
        scanner.skip_space_and_comments()
        char = scanner.peek()
        if not char:
            raise CMakeSyntaxError("unterminated command: missing ')'", line, column)
        if char == ")":
            scanner.move_to(scanner.pos + 1)
            if depth == 0:
                return args
            depth -= 1
            args.append(Argument(")"))
        elif char == "(":
            scanner.move_to(scanner.pos + 1)
            depth += 1
            args.append(Argument("("))
        elif char == '"':
            match = _QUOTED.match(text, scanner.pos)
            if not match:
                raise scanner.error("unterminated quoted argument")
            scanner.move_to(match.end())
            args.append(Argument(_unescape(match.group(1)), "quoted"))
        elif char == "[" and (bracket := _BRACKET_OPEN.match(text, scanner.pos)):
            args.append(Argument(scanner.read_bracket(scanner.pos, bracket.group(1)),
                                 "bracket"))
        else:
            match = _UNQUOTED.match(text, scanner.pos)
            if not match:
                raise scanner.error(f"unexpected {char!r}")
            scanner.move_to(match.end())
            args.append(Argument(_unescape(match.group())))
