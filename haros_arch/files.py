"""Reading files of the analysed workspace safely: bounded size, UTF-8 with replacement."""

from __future__ import annotations

import os
import stat

from . import diagnostics as diag
from .diagnostics import Diagnostic
from .model.location import Location

MAX_FILE_BYTES = 8 * 1024 * 1024
_BOM = b"\xef\xbb\xbf"


def _refuse_special(path: str, location: Location) -> list[Diagnostic]:
    """A FIFO, socket or device would block or never end: only regular files are read."""
    mode = os.stat(path).st_mode
    if stat.S_ISREG(mode):
        return []
    return [diag.make("FILE_UNREADABLE", location, path=location.file or path,
                      detail="not a regular file")]


def read_text(
    path: str, location: Location, limit: int = MAX_FILE_BYTES
) -> tuple[str | None, list[Diagnostic]]:
    """Read ``path`` as text. Problems become diagnostics at ``location``; never raises.
    A UTF-8 byte-order mark at the start is an encoding mark, not text: CMake, Python,
    YAML and C++ compilers all skip it, so it is dropped here for every reader."""
    try:
        special = _refuse_special(path, location)
        if special:
            return None, special
        size = os.path.getsize(path)
        if size > limit:
            return None, [diag.make("FILE_TOO_LARGE", location, path=location.file or path,
                                    size=size, limit=limit)]
        with open(path, "rb") as handle:
            raw = handle.read(limit + 1)
    except OSError as err:
        return None, [diag.make("FILE_UNREADABLE", location, path=location.file or path,
                                detail=err.strerror or str(err))]
    if raw.startswith(_BOM):
        raw = raw[len(_BOM):]
    try:
        return raw.decode("utf-8"), []
    except UnicodeDecodeError as err:
        bad = raw[: err.start].count(b"\n") + 1
        where = Location(location.package, location.file, bad, 0)
        return raw.decode("utf-8", errors="replace"), [
            diag.make("FILE_ENCODING", where, path=location.file or path)]


def read_bytes(
    path: str, location: Location, limit: int = MAX_FILE_BYTES
) -> tuple[bytes | None, list[Diagnostic]]:
    """Read ``path`` as bytes (for XML parsers that honour the declared encoding)."""
    try:
        special = _refuse_special(path, location)
        if special:
            return None, special
        size = os.path.getsize(path)
        if size > limit:
            return None, [diag.make("FILE_TOO_LARGE", location, path=location.file or path,
                                    size=size, limit=limit)]
        with open(path, "rb") as handle:
            return handle.read(limit + 1), []
    except OSError as err:
        return None, [diag.make("FILE_UNREADABLE", location, path=location.file or path,
                                detail=err.strerror or str(err))]
