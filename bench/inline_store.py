"""`haros-arch` with each run's model kept in line, as before the store moved to a forked
copy of the command (``runcache.background``, #24): the yardstick of what that move is
worth. Same arguments as `haros-arch`; the same outputs.

    farm-bench -n 3 --vs "sh -c 'rm -rf C2; XDG_CACHE_HOME=C2 \\
                              python bench/inline_store.py check TREE'" \\
        -- sh -c 'rm -rf C1; XDG_CACHE_HOME=C1 haros-arch check TREE'

(an empty cache folder each run: a cold run, whose store is the whole model's).
"""

from __future__ import annotations

import contextlib
import sys

import checkout  # bench/checkout.py: says which haros_arch is measured

from haros_arch import runcache
from haros_arch.cli import main

if __name__ == "__main__":
    checkout.announce()
    runcache.background = contextlib.nullcontext  # type: ignore[assignment]
    sys.exit(main(sys.argv[1:]))
