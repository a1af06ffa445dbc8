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
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field

from clang.cindex import Cursor, TranslationUnit, TranslationUnitLoadError
from clang.cindex import Diagnostic as ClangDiagnostic

from ... import diagnostics as diag
from ...diagnostics import Diagnostic
from ...files import MAX_FILE_BYTES, read_text
from ...model.location import Location
from ...model.source import PrimitiveCall
from ...workspace import Workspace
from . import cache, toolchain
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
                include_dirs: Sequence[str] = (), system_headers: bool = False,
                cache_dir: str | None = cache.AUTO, jobs: int | None = None) -> CppResult:
    """The ROS calls in the translation units ``sources`` (absolute paths) of a node.

    With ``system_headers`` the installed ROS headers are used instead of the stand-ins.
    ``cache_dir`` is where results are kept between runs (``"auto"``: see
    ``cache.default_folder``; None: no cache). ``jobs`` translation units are parsed at a
    time in worker processes (default: the number of cores, at most the sources).
    """
    result = CppResult()
    setup = IncludeSetup(workspace, include_dirs, system_headers)
    store = None
    if cache_dir is not None:
        folder = cache.default_folder(workspace.root) if cache_dir == cache.AUTO else cache_dir
        store = cache.Cache(folder, setup.generated)
    try:
        texts: dict[str, str] = {}
        for path in sources:
            path = os.path.abspath(path)
            text, found = read_text(path, workspace.location(path))
            result.diagnostics.extend(found)
            if text is not None:
                texts[path] = text
                setup.scan(path, text)
        units = _units(texts, setup, store, jobs)
    finally:
        setup.close()
    result.diagnostics[:0] = setup.diagnostics
    seen: set[tuple[object, ...]] = set()
    for unit in units:
        result.diagnostics.extend(d for d in unit.diagnostics if d not in result.diagnostics)
        if unit.rosname is not None and result.rosname is None:
            result.rosname = unit.rosname
        for call in unit.calls:
            key = (call.kind, call.name, call.location)
            if key not in seen:
                seen.add(key)
                result.calls.append(call)
    return result


def _units(texts: dict[str, str], setup: IncludeSetup, store: cache.Cache | None,
           jobs: int | None) -> list[CppResult]:
    """Each translation unit's result, from the cache or parsed (in parallel)."""
    args = setup.arguments()
    keys = {path: cache.key(setup.workspace.relpath(path), text, args, setup.generated)
            for path, text in texts.items()}
    done: dict[str, CppResult] = {}
    if store is not None:
        for path, entry in keys.items():
            data = store.load(entry)
            if data is not None:
                try:
                    calls, rosname, found = cache.from_data(data)
                except (ValueError, TypeError, KeyError):
                    continue
                done[path] = CppResult(calls, rosname, found)
    todo = [path for path in texts if path not in done]
    workers = min(len(todo), jobs or os.cpu_count() or 1)
    parsed: list[tuple[CppResult, list[str]]]
    if workers > 1:
        with ProcessPoolExecutor(max_workers=workers) as pool:
            parsed = list(pool.map(_translation_unit, todo, [texts[p] for p in todo],
                                   [setup] * len(todo)))
    else:
        parsed = [_translation_unit(path, texts[path], setup) for path in todo]
    for path, (unit, headers) in zip(todo, parsed, strict=True):
        done[path] = unit
        if store is not None and headers:
            store.store(keys[path], headers, cache.to_data(
                unit.calls, unit.rosname, unit.diagnostics))
    return [done[path] for path in texts]


def _translation_unit(path: str, text: str,
                      setup: IncludeSetup) -> tuple[CppResult, list[str]]:
    """What one source file gives, and the workspace / synthesised headers it read
    (empty when the result must not be cached)."""
    workspace = setup.workspace
    result = CppResult()
    before = len(setup.diagnostics)
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
        return result, []
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
    result.calls = sorted(finder.calls, key=lambda c: (
        c.location.file or "", c.location.line, c.location.column))
    result.diagnostics.extend(finder.diagnostics)
    result.diagnostics[:0] = setup.diagnostics[before:]
    result.rosname = finder.rosname
    headers = [path]
    for include in tu.get_includes():
        name = os.path.abspath(include.include.name)
        if name.startswith((workspace.root + os.sep, setup.generated + os.sep)) or (
            setup.system_headers and not name.startswith(STANDIN + os.sep)
        ):
            headers.append(name)
    return result, sorted(set(headers))


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
