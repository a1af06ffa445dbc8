"""The C++ extractor for ROS 1 (roscpp): the primitive calls in one node's sources.

``extract_cpp(sources, workspace)`` parses each translation unit once with libclang,
against built-in stand-in ROS headers and message headers synthesised from the
workspace's ``.msg`` / ``.srv`` files (``headers``), so no ROS installation is needed,
and walks the functions defined in the workspace for calls listed in ``api.ROSCPP``
(``visitor``). Problems become diagnostics; nothing here raises for bad input.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass, field

from clang.cindex import Cursor, TranslationUnit, TranslationUnitLoadError
from clang.cindex import Diagnostic as ClangDiagnostic

from ... import diagnostics as diag
from ...diagnostics import Diagnostic
from ...files import MAX_FILE_BYTES, read_text
from ...model.location import Location
from ...model.source import PrimitiveCall
from ...workspace import Workspace
from . import toolchain
from .headers import STANDIN, IncludeSetup
from .visitor import CallFinder

__all__ = ["CppResult", "extract_cpp"]

# CXTranslationUnit_DetailedPreprocessingRecord (for #define constants) | KeepGoing
PARSE_OPTIONS = 0x01 | 0x200
MAX_ERRORS_PER_FILE = 50


@dataclass
class CppResult:
    """What one node's C++ sources give: calls, the name passed to ``ros::init``."""

    calls: list[PrimitiveCall] = field(default_factory=list)
    rosname: str | None = None
    diagnostics: list[Diagnostic] = field(default_factory=list)


def extract_cpp(sources: list[str], workspace: Workspace, *,
                include_dirs: Sequence[str] = (), system_headers: bool = False) -> CppResult:
    """The roscpp calls in the translation units ``sources`` (absolute paths) of a node.

    With ``system_headers`` the installed ROS headers are used instead of the stand-ins.
    """
    result = CppResult()
    setup = IncludeSetup(workspace, include_dirs, system_headers)
    try:
        texts: dict[str, str] = {}
        for path in sources:
            path = os.path.abspath(path)
            text, found = read_text(path, workspace.location(path))
            result.diagnostics.extend(found)
            if text is not None:
                texts[path] = text
                setup.scan(path, text)
        found_calls: list[PrimitiveCall] = []
        for path, text in texts.items():
            _translation_unit(path, text, setup, workspace, result, found_calls)
    finally:
        setup.close()
    result.diagnostics[:0] = setup.diagnostics
    seen: set[tuple[object, ...]] = set()
    for call in found_calls:
        key = (call.kind, call.name, call.location)
        if key not in seen:
            seen.add(key)
            result.calls.append(call)
    return result


def _translation_unit(path: str, text: str, setup: IncludeSetup, workspace: Workspace,
                      result: CppResult, calls: list[PrimitiveCall]) -> None:
    """Parse one source file and add what it gives to ``result`` and ``calls``."""
    data = text.encode("utf-8")
    source = SourceCache(workspace.root, {path: data})

    def owned(name: str) -> bool:
        name = os.path.abspath(name)
        if name == path:
            return True
        return name.startswith(workspace.root + os.sep) and not name.startswith(
            (setup.generated + os.sep, STANDIN + os.sep))

    def where(cursor: Cursor) -> Location:
        loc = cursor.location
        if loc.file is None:
            return workspace.location(path)
        return workspace.location(os.path.abspath(loc.file.name), loc.line, loc.column)

    tu = _parse(path, text, setup, workspace, result)
    if tu is None:
        return
    errors = [d for d in tu.diagnostics if d.severity >= ClangDiagnostic.Error
              and d.location.file is not None and owned(d.location.file.name)]
    for error in errors[:MAX_ERRORS_PER_FILE]:
        loc = error.location
        result.diagnostics.append(diag.make(
            "CPP_PARSE_ERROR", workspace.location(os.path.abspath(loc.file.name),
                                                  loc.line, loc.column),
            detail=error.spelling))
    finder = CallFinder(tu, source, owned, where, ros2=setup.ros2)
    finder.run()
    calls.extend(sorted(finder.calls, key=lambda c: (
        c.location.file or "", c.location.line, c.location.column)))
    result.diagnostics.extend(finder.diagnostics)
    if finder.rosname is not None and result.rosname is None:
        result.rosname = finder.rosname


def _parse(path: str, text: str, setup: IncludeSetup, workspace: Workspace,
           result: CppResult) -> TranslationUnit | None:
    """Parse ``path``; headers clang still misses are stood in for and parsed again."""
    unsaved = [(path, text)]
    for _attempt in range(2):
        try:
            tu = toolchain.index().parse(path, args=setup.arguments(), unsaved_files=unsaved,
                                         options=PARSE_OPTIONS)
        except TranslationUnitLoadError as err:
            result.diagnostics.append(diag.make(
                "CPP_PARSE_FAILED", workspace.location(path), detail=str(err) or "libclang"))
            return None
        missing = [
            (d.spelling, workspace.location(os.path.abspath(d.location.file.name),
                                            d.location.line, d.location.column))
            for d in tu.diagnostics
            if d.severity >= ClangDiagnostic.Error and d.location.file is not None
            and "file not found" in d.spelling]
        if not missing or not setup.repair(missing):
            return tu
    return tu


class SourceCache(dict[str, bytes]):
    """The bytes of the workspace files clang positions point into, read on demand."""

    def __init__(self, root: str, initial: dict[str, bytes]) -> None:
        super().__init__(initial)
        self.root = root

    def get(self, name: str, default: bytes | None = None) -> bytes | None:  # type: ignore[override]
        name = os.path.abspath(name)
        if name in self:
            return self[name]
        if not name.startswith(self.root + os.sep):
            return default
        try:
            with open(name, "rb") as handle:
                data = handle.read(MAX_FILE_BYTES)
        except OSError:
            return default
        self[name] = data
        return data
