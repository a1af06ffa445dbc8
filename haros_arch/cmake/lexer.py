"""A lexer for the CMake language: command invocations with their arguments.

Handles quoted arguments (escapes, line continuations), unquoted arguments (with
nested parentheses), bracket arguments ``[==[ ... ]==]``, line comments and bracket
comments ``#[[ ... ]]``. Errors raise ``CMakeSyntaxError`` with line and column; the
caller keeps the commands read before it.
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


class CMakeSyntaxError(Exception):
    def __init__(self, message: str, line: int, column: int) -> None:
        super().__init__(message)
        self.message, self.line, self.column = message, line, column


_IDENT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_BRACKET_OPEN = re.compile(r"\[(=*)\[")
_ESCAPES = {"t": "\t", "n": "\n", "r": "\r", ";": "\\;"}


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

    def advance(self, count: int) -> str:
        chunk = self.text[self.pos:self.pos + count]
        for offset, char in enumerate(chunk):
            if char == "\n":
                self.line += 1
                self.line_start = self.pos + offset + 1
        self.pos += count
        return chunk

    def peek(self, offset: int = 0) -> str:
        index = self.pos + offset
        return self.text[index] if index < len(self.text) else ""

    def skip_space_and_comments(self, newlines: bool = True) -> None:
        while self.pos < len(self.text):
            char = self.peek()
            if char in " \t\r" or (newlines and char == "\n"):
                self.advance(1)
            elif char == "#":
                self.skip_comment()
            else:
                return

    def skip_comment(self) -> None:
        bracket = _BRACKET_OPEN.match(self.text, self.pos + 1)
        if bracket:
            self.read_bracket(start=self.pos + 1, equals=bracket.group(1))
            return
        end = self.text.find("\n", self.pos)
        self.advance((end if end >= 0 else len(self.text)) - self.pos)

    def read_bracket(self, start: int, equals: str) -> str:
        line, column = self.line, self.column
        self.advance(start - self.pos + len(equals) + 2)
        close = "]" + equals + "]"
        end = self.text.find(close, self.pos)
        if end < 0:
            raise CMakeSyntaxError("unterminated bracket argument or comment", line, column)
        body = self.text[self.pos:end]
        self.advance(end - self.pos + len(close))
        return body[1:] if body.startswith("\n") else body


def tokenize(text: str) -> list[Invocation]:
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
        scanner.advance(len(match.group()))
        scanner.skip_space_and_comments(newlines=False)
        if scanner.peek() != "(":
            raise scanner.error(f"expected '(' after {match.group()}")
        scanner.advance(1)
        commands.append(Invocation(match.group().lower(), tuple(_arguments(scanner)),
                                   line, column))


def _arguments(scanner: _Scanner) -> list[Argument]:
    args: list[Argument] = []
    depth = 0
    line, column = scanner.line, scanner.column
    while True:
        scanner.skip_space_and_comments()
        char = scanner.peek()
        if not char:
            raise CMakeSyntaxError("unterminated command: missing ')'", line, column)
        if char == ")":
            scanner.advance(1)
            if depth == 0:
                return args
            depth -= 1
            args.append(Argument(")"))
        elif char == "(":
            scanner.advance(1)
            depth += 1
            args.append(Argument("("))
        elif char == '"':
            args.append(Argument(_quoted(scanner), "quoted"))
        elif char == "[" and (bracket := _BRACKET_OPEN.match(scanner.text, scanner.pos)):
            args.append(Argument(scanner.read_bracket(scanner.pos, bracket.group(1)),
                                 "bracket"))
        else:
            args.append(Argument(_unquoted(scanner)))


def _quoted(scanner: _Scanner) -> str:
    line, column = scanner.line, scanner.column
    scanner.advance(1)
    out: list[str] = []
    while True:
        char = scanner.peek()
        if not char:
            raise CMakeSyntaxError("unterminated quoted argument", line, column)
        if char == '"':
            scanner.advance(1)
            return "".join(out)
        if char == "\\":
            following = scanner.peek(1)
            if following == "\n":  # line continuation
                scanner.advance(2)
                continue
            scanner.advance(2)
            out.append(_ESCAPES.get(following, following))
            continue
        out.append(scanner.advance(1))


def _unquoted(scanner: _Scanner) -> str:
    out: list[str] = []
    while True:
        char = scanner.peek()
        if not char or char in " \t\r\n()#":
            return "".join(out)
        if char == '"' and out:  # legacy: quotes inside an unquoted argument
            out.append(scanner.advance(1))
            continue
        if char == "\\":
            following = scanner.peek(1)
            scanner.advance(2)
            out.append(_ESCAPES.get(following, following))
            continue
        out.append(scanner.advance(1))
