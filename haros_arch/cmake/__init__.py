"""CMake front end: which runnable nodes a CMake-built package has, and their sources.

Entry point: ``parse_package(package, workspace)``.
"""

from __future__ import annotations

import os

from .. import diagnostics as diag
from ..diagnostics import Diagnostic
from ..files import read_text
from ..model.source import Node, Package
from ..workspace import Workspace
from .interpreter import Interpreter, Target
from .lexer import CMakeSyntaxError, Invocation, tokenize

__all__ = ["Target", "parse_package", "read_commands", "targets_of"]

CPP_SUFFIXES = (".cpp", ".cc", ".cxx", ".c++", ".C", ".c")


def read_commands(path: str, workspace: Workspace) -> tuple[list[Invocation], list[Diagnostic]]:
    """Tokenise a CMake file; a syntax error keeps the commands read before it."""
    text, found = read_text(path, workspace.location(path))
    if text is None:
        return [], found
    try:
        return tokenize(text), found
    except CMakeSyntaxError as err:
        # keep what precedes the error: tokenise the text up to the failing line
        head = "\n".join(text.splitlines()[: max(err.line - 1, 0)])
        try:
            commands = tokenize(head)
        except CMakeSyntaxError:
            commands = []
        where = workspace.location(path, err.line, err.column)
        return commands, [*found, diag.make("CMAKE_SYNTAX", where, detail=err.message)]


def targets_of(package: Package, workspace: Workspace) -> tuple[list[Target], list[Diagnostic]]:
    """The build targets of a package's top-level CMakeLists.txt."""
    path = os.path.join(package.root, "CMakeLists.txt")
    if not os.path.isfile(path):
        return [], []
    commands, found = read_commands(path, workspace)
    interpreter = Interpreter(package.root, workspace.environment, file=path,
                              location=workspace.location)
    interpreter.run(commands)
    return list(interpreter.targets.values()), found


def parse_package(package: Package, workspace: Workspace) -> tuple[list[Node], list[Diagnostic]]:
    """The runnable C++ nodes (executables) a package builds, with their sources."""
    targets, found = targets_of(package, workspace)
    nodes: list[Node] = []
    for target in targets:
        if target.kind != "executable":
            continue
        sources = []
        for source in target.sources:
            if not source.endswith(CPP_SUFFIXES):
                continue
            if not os.path.isfile(source):
                found.append(diag.make(
                    "CMAKE_SOURCE_MISSING",
                    workspace.location(target.file, target.line, target.column),
                    path=workspace.relpath(source), target=target.name))
                continue
            sources.append(workspace.relpath(source))
        nodes.append(Node(
            package=package.name,
            executable=target.output_name or target.name,
            kind="executable",
            language="cpp",
            sources=sources,
            conditions=target.conditions,
            location=workspace.location(target.file, target.line, target.column),
        ))
    return nodes, found
