"""Reading files of the analysed workspace safely: bounded size, UTF-8 with replacement."""

from __future__ import annotations

import contextlib
import hashlib
import os
import stat
import tempfile
from collections.abc import Callable, Iterator, MutableMapping
from contextlib import contextmanager
from typing import Any, TypeVar

from . import diagnostics as diag
from .diagnostics import Diagnostic
from .model.location import Location

MAX_FILE_BYTES = 8 * 1024 * 1024
_BOM = b"\xef\xbb\xbf"
K = TypeVar("K")
V = TypeVar("V")
_RECORDING: list[set[str]] = []  # the blocks recording the files read (``recording``)


@contextmanager
def recording() -> Iterator[set[str]]:
    """The paths of the files read within the block (``read_text``, ``read_bytes``,
    ``note_read``): what a stage's result depends on, beside what it was given."""
    found: set[str] = set()
    _RECORDING.append(found)
    try:
        yield found
    finally:
        _RECORDING.pop()  # blocks nest: this one is the last (two equal sets would be
        # one to ``remove``)


def note_read(path: str) -> None:
    """``path`` is read (by a reader that opens it itself), for ``recording``."""
    for found in _RECORDING:
        found.add(path)


# C++ sources and headers: the files the run cache's outer key names without their
# content (``runcache``), whose facts ``facts.KeptFacts`` compares by content
CPP_FILES = (".c", ".cc", ".cpp", ".cxx", ".c++", ".h", ".hh", ".hpp", ".hxx", ".h++",
             ".ipp", ".inl", ".tcc")


def kept_in(memo: MutableMapping[K, Any], key: K, compute: Callable[[], V]) -> V:
    """``compute()``, kept in ``memo`` under ``key`` with the files it read: asked again,
    it reads them again for ``recording`` (what a package's build files give depends on
    the sources another package's made the workspace read first)."""
    kept = memo.get(key)
    if kept is None:
        with recording() as read:
            value = compute()
        memo[key] = (value, frozenset(read))
        return value
    value, read = kept
    for path in read if _RECORDING else ():
        note_read(path)
    return value


def package_files(root: str) -> Iterator[str]:
    """The files under a package's folder, in a stable order, not in hidden, build or
    install folders (a caller that needs only the first few stops the walk there)."""
    for folder, dirs, names in os.walk(root):
        dirs[:] = sorted(d for d in dirs if not d.startswith((".", "build", "install")))
        for name in sorted(names):
            yield os.path.join(folder, name)


def write_whole(path: str, text: str | bytes) -> None:
    """Write ``text`` (UTF-8, or bytes as they are) to ``path`` whole or not at all: a
    temporary file beside it, moved into place (a reader in another process never sees
    it half written). Raises ``OSError``; the temporary file is removed then."""
    folder = os.path.dirname(path)
    os.makedirs(folder, exist_ok=True)
    fd, temporary = tempfile.mkstemp(dir=folder, prefix=".haros-", suffix=".tmp")
    try:
        if isinstance(text, bytes):
            with os.fdopen(fd, "wb") as binary:
                binary.write(text)
        else:
            with os.fdopen(fd, "w", encoding="utf-8", newline="") as handle:
                handle.write(text)
        os.replace(temporary, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.remove(temporary)
        raise


def content_digest(path: str) -> str | None:
    """The SHA-256 of a file's content, None when it cannot be read (what the caches
    compare a file by: the run cache's snapshot, the unit cache's headers, the build
    files' C++ reads)."""
    try:
        with open(path, "rb") as handle:
            return hashlib.sha256(handle.read()).hexdigest()
    except OSError:
        return None


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
    if _RECORDING:
        note_read(path)
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
    if _RECORDING:
        note_read(path)
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


AUTO_CACHE = "auto"  # a ``cache_dir`` option's value: the default folder (``cache_folder``)


def cache_folder(workspace_root: str, cache_dir: str = AUTO_CACHE) -> str:
    """The cache folder a ``cache_dir`` option names: itself, or for ``AUTO_CACHE``
    ``$XDG_CACHE_HOME/haros-arch`` (``~/.cache/haros-arch``), ``.haros-arch-cache`` in
    the workspace when there is no home folder. Entries name files by absolute path, so
    one folder serves every workspace. (Here, not with the C++ cache, so that a re-run
    the run cache answers imports no C++ extractor.)"""
    if cache_dir != AUTO_CACHE:
        return cache_dir
    xdg = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    if xdg.startswith("~"):
        return os.path.join(workspace_root, ".haros-arch-cache")
    return os.path.join(xdg, "haros-arch")
