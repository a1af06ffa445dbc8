"""The cyclic garbage collector held back while a stage makes many objects that live on.

CPython's collector runs each time allocations outnumber deallocations by its youngest
threshold (700), and each run walks the objects made since. A stage that builds a
large structure (a translation unit's syntax nodes, a model read or written) would have
it walk them again and again, though none of them is garbage yet. ``held_back`` raises
the threshold for such a block and restores it after; what the block leaves as cyclic
garbage is collected by the runs that follow.
"""

from __future__ import annotations

import contextlib
import gc
from collections.abc import Iterator

__all__ = ["held_back"]


@contextlib.contextmanager
def held_back(young: int = 0) -> Iterator[None]:
    """The youngest generation's threshold is ``young`` in the block (0: no automatic
    collection at all), then what it was."""
    before = gc.get_threshold()
    gc.set_threshold(young, *before[1:])
    try:
        yield
    finally:
        gc.set_threshold(*before)
