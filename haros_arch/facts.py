"""What the build-file stage read off files in an earlier run, taken again where those
files are unchanged.

The build-file stage asks many facts of the workspace's C++ files (a plugin's export
macro, the classes a source defines, the words of a ``main()``, the class loaders of a
package's code: ``plugins.classes.remembered``), each once per run. A run whose files
but C++ ones are an earlier run's (the run cache's outer key) reads the packages whose
C++ files changed again, and with them every fact they ask, of every file of the
libraries they link: 2 s of a re-run of navigation2 after an edit of one source. Those
facts, kept with the earlier run (``KeptFacts.to_data``), are taken again for this run
(``restore``) when every C++ file their computation read has the content it had; the
other files they read are the earlier run's by that key. A fact whose value is not
plain data (a number, a string, a list, tuple, set or mapping of those) is not kept,
nor one that holds file texts (reading the file again is as cheap).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from typing import Any, TypeVar

from .files import CPP_FILES, content_digest, kept_in

T = TypeVar("T")

# kinds of facts not kept: file texts (``classes._text``, ``_with_headers``)
UNKEPT = ("text", "with headers ")


class KeptFacts:
    """The facts of an earlier run (``before``, as ``to_data`` wrote them) and this
    run's (made or taken again), for the next."""

    def __init__(self, before: Any = None) -> None:
        self.paths: list[str] = []
        self._index: dict[str, int] = {}
        self.now: dict[str, list[Any]] = {}
        self._digests: dict[str, str | None] = {}
        self._before_paths: list[str] = []
        self._before: dict[str, Any] = {}
        if isinstance(before, dict) and isinstance(before.get("paths"), list) \
                and isinstance(before.get("facts"), dict) \
                and all(isinstance(p, str) for p in before["paths"]):
            self._before_paths = before["paths"]
            self._before = before["facts"]

    def restore(self, kind: str, source: str) -> tuple[Any, frozenset[str]] | None:
        """The earlier run's fact and the files its computation read, when its C++
        files are unchanged; else None."""
        entry = self._before.get(_key(kind, source))
        try:
            encoded, read, digests = entry  # type: ignore[misc]
            paths = self._before_paths
            if any(self._digest(paths[int(i)]) != d for i, d in digests.items()):
                return None
            value = decode(encoded)
            files = frozenset(paths[i] for i in read)
        except (TypeError, ValueError, KeyError, IndexError, AttributeError):
            return None
        self.now[_key(kind, source)] = [encoded, [self._number(p) for p in files],
                                        {str(self._number(paths[int(i)])): d
                                         for i, d in digests.items()}]
        return value, files

    def note(self, kind: str, source: str, value: Any, read: Iterable[str]) -> None:
        """Keep a fact this run made (``value``, from the files ``read``), when it is
        plain data that reads back as it is."""
        key = _key(kind, source)
        if key in self.now or kind.startswith(UNKEPT):
            return
        try:
            encoded = encode(value)
        except TypeError:
            return
        if not same(decode(encoded), value):
            return
        read = sorted(set(read))
        digests = {}
        for path in read:
            if path.endswith(CPP_FILES):
                digest = self._digest(path)
                if digest is None:
                    return
                digests[str(self._number(path))] = digest
        self.now[key] = [encoded, [self._number(p) for p in read], digests]

    def to_data(self) -> dict[str, Any]:
        return {"paths": self.paths, "facts": self.now}

    def _number(self, path: str) -> int:
        number = self._index.get(path)
        if number is None:
            number = self._index[path] = len(self.paths)
            self.paths.append(path)
        return number

    def _digest(self, path: str) -> str | None:
        if path not in self._digests:
            self._digests[path] = content_digest(path)
        return self._digests[path]


def remember(workspace: Any, kind: str, source: str, compute: Callable[[], T]) -> T:
    """``compute()``, a fact of kind ``kind`` about ``source``, asked once per run where
    ``workspace`` keeps such facts (its ``file_facts``, ``files.kept_in``), and taken
    from an earlier run's where it keeps those (its ``kept_facts``) and the C++ files
    it was read from are unchanged; else made, and kept for the next run."""
    memo: dict[tuple[str, str], Any] | None = getattr(workspace, "file_facts", None)
    if memo is None:
        return compute()
    key = (kind, source)
    kept: KeptFacts | None = getattr(workspace, "kept_facts", None)
    if kept is None or key in memo:
        return kept_in(memo, key, compute)
    restored = kept.restore(kind, source)
    if restored is not None:
        memo[key] = restored
    value = kept_in(memo, key, compute)
    if restored is None:
        kept.note(kind, source, *memo[key])
    return value


def _key(kind: str, source: str) -> str:
    return f"{kind}\0{source}"


def encode(value: Any) -> Any:
    """``value`` as JSON data that tells its types apart (``decode``); TypeError for a
    value that is not plain data."""
    if value is None or isinstance(value, (bool, str)):
        return value
    if isinstance(value, int):
        return value
    if isinstance(value, float):
        if not math.isfinite(value):
            raise TypeError("not a finite number")
        return {"n": value}
    if isinstance(value, list):
        return [encode(item) for item in value]
    if isinstance(value, tuple) and type(value) is tuple:
        return {"t": [encode(item) for item in value]}
    if isinstance(value, (set, frozenset)):
        return {"f" if isinstance(value, frozenset) else "s": [encode(i) for i in value]}
    if isinstance(value, dict) and type(value) is dict:
        return {"d": [[encode(k), encode(v)] for k, v in value.items()]}
    raise TypeError(f"not plain data: {type(value).__name__}")


def decode(data: Any) -> Any:
    if data is None or isinstance(data, (bool, str, int)):
        return data
    if isinstance(data, list):
        return [decode(item) for item in data]
    if isinstance(data, dict) and len(data) == 1:
        (tag, items), = data.items()
        if tag == "n" and isinstance(items, (int, float)):
            return float(items)
        if tag == "t":
            return tuple(decode(item) for item in items)
        if tag == "s":
            return {decode(item) for item in items}
        if tag == "f":
            return frozenset(decode(item) for item in items)
        if tag == "d":
            return {decode(k): decode(v) for k, v in items}
    raise ValueError("not encoded data")


def same(one: Any, other: Any) -> bool:
    """Equal, and of the same types throughout (``1 == True`` is not the same)."""
    if type(one) is not type(other):
        return False
    if isinstance(one, (list, tuple)):
        return len(one) == len(other) and all(same(a, b) for a, b in zip(one, other,
                                                                            strict=True))
    if isinstance(one, dict):
        return one.keys() == other.keys() and all(same(v, other[k]) for k, v in one.items())
    return bool(one == other)
