"""The workspace's include folders as one clang header map (issue #24).

A parse names every include folder of the workspace (hundreds on Autoware); for each
``#include`` the preprocessor tries the folders one by one, a failed ``stat`` each, and
every ``<vector>`` of every header goes through all of them before the standard library
stand-ins. A header map is a file that clang reads in place of a folder on the include
path: a hash table from the name written in ``#include`` to the file it opens. One map
built from the folders in their order (the first folder that holds a name wins, as in
the search it replaces) answers a name in one look-up and a name none holds in one
miss, so the parse reads the same files.

The format (clang's ``HeaderMapTypes.h``): a header (magic ``hmap``, version 1, the
offset of the string pool, the number of entries and of buckets, a power of two, and the
length of the longest path), the buckets (three offsets into the pool: the key, and the
path's prefix and suffix, joined), then the pool, whose first byte is unused (offset 0
is an empty bucket). A bucket is the sum of 13 times each lower-cased byte of the key;
collisions probe the next bucket. Keys are compared ignoring case, so names that differ
only in case cannot both be in a map: they are left out, and the folders that hold them
are searched after the map, in their order, as before.

Where the map and the folders could differ, and why it does not matter here: a name
written with ``.`` or ``..`` parts (``"../src/publishers/basic.hpp"``) is no file's name
below a folder, so the map has it only when the scan before the parse resolved it
through a folder (``dotted``: naoqi_driver2 includes it so, through its ``include``
folder); a name written in another case than the file's is found where Linux
would not find it, and ``#include_next`` in a header found through the map goes on after
the map, not after its folder. Code that builds on Linux writes neither of these two.
"""

from __future__ import annotations

import os
import struct
from collections.abc import Mapping, Sequence

MAGIC = 0x686D6170  # 'hmap'
VERSION = 1
MAX_FILES = 200_000  # a folder larger than a workspace's headers: search it as a folder
MAX_DEPTH = 32
_HEADER = struct.Struct("<IHHIIII")
_BUCKET = struct.Struct("<III")


def search_path(path: str, folders: Sequence[str],
                dotted: Mapping[str, str] | None = None) -> list[str] | None:
    """Write the header map of ``folders`` at ``path``; the include folders to use in
    their place (the map, then the folders holding names that differ only in case), or
    None when the folders are too large or the file cannot be written (search them).
    ``dotted``: names written with ``.`` or ``..`` parts -> the folder of ``folders``
    that resolves them (the first, as the search would), mapped as written."""
    found = _names(folders)
    if found is None:
        return None
    names, clashing = found
    lowered = {name.lower() for name in names}
    for header, folder in (dotted or {}).items():
        key = os.fsencode(header)
        if folder in folders and folder not in clashing and key.lower() not in lowered:
            names[key] = os.fsencode(folder) + b"/"
            lowered.add(key.lower())
    try:
        with open(path, "wb") as handle:
            handle.write(_encode(names))
    except OSError:
        return None
    return [path, *(f for f in folders if f in clashing)]


def _names(folders: Sequence[str]) -> tuple[dict[bytes, bytes], set[str]] | None:
    """Each name an ``#include`` can give (a file's path below a folder) -> the folder
    the search finds it in first (with its separator); and the folders of names that
    differ from another only in case (left out)."""
    first: dict[bytes, bytes] = {}
    where: dict[bytes, set[str]] = {}
    count = 0
    for folder in folders:
        prefix = os.fsencode(folder) + b"/"
        for name in _files(folder):
            count += 1
            if count > MAX_FILES:
                return None
            first.setdefault(name, prefix)
            where.setdefault(name.lower(), set()).add(folder)
    cases: dict[bytes, list[bytes]] = {}
    for name in first:
        cases.setdefault(name.lower(), []).append(name)
    clashing: set[str] = set()
    for lowered, spellings in cases.items():
        if len(spellings) > 1:
            for name in spellings:
                del first[name]
            clashing |= where[lowered]
    return first, clashing


def _files(folder: str) -> list[bytes]:
    """The paths of the files below ``folder`` relative to it, as an ``#include`` writes
    them; through symbolic links as the search goes, each real folder once."""
    found: list[bytes] = []
    seen: set[str] = set()
    for top, subfolders, files in os.walk(folder, followlinks=True):
        real = os.path.realpath(top)
        relative = os.path.relpath(top, folder)
        if real in seen or relative.count(os.sep) >= MAX_DEPTH:
            subfolders[:] = []
            continue
        seen.add(real)
        subfolders.sort()
        stem = b"" if relative == os.curdir else os.fsencode(relative) + b"/"
        found.extend(stem + os.fsencode(name) for name in sorted(files))
    return found


def _bucket(key: bytes) -> int:
    total = 0
    for byte in key.lower():
        total += byte * 13
    return total & 0xFFFFFFFF


def _encode(names: dict[bytes, bytes]) -> bytes:
    """The header map file of ``names`` (key -> folder prefix)."""
    count = 1
    while count < 2 * len(names) + 2:  # at least one empty bucket ends every probe
        count *= 2
    pool = bytearray(b"\0")
    offsets: dict[bytes, int] = {}

    def string(text: bytes) -> int:
        offset = offsets.get(text)
        if offset is None:
            offset = offsets[text] = len(pool)
            pool.extend(text + b"\0")
        return offset

    buckets = [(0, 0, 0)] * count
    longest = 0
    for key, prefix in names.items():
        longest = max(longest, len(prefix) + len(key))
        index = _bucket(key) & (count - 1)
        while buckets[index][0]:
            index = (index + 1) & (count - 1)
        buckets[index] = (string(key), string(prefix), string(key))
    start = _HEADER.size + _BUCKET.size * count
    out = bytearray(_HEADER.pack(MAGIC, VERSION, 0, start, len(names), count, longest))
    for bucket in buckets:
        out += _BUCKET.pack(*bucket)
    out += pool
    return bytes(out)
