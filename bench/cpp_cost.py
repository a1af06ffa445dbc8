"""Cold C++ extraction cost of one checkout, for a ratio against another checkout.

    PYTHONPATH=CHECKOUT .venv/bin/python bench/cpp_cost.py WORKSPACE [--jobs N] [--out FILE]

Extracts every ``.cpp`` / ``.cc`` / ``.cxx`` file of the workspace's packages (tests,
docs and examples left out) as its own node, with no cache, through
``extract_cpp_nodes`` (the entry point every checkout since round 1 has, so the same
script times an old checkout and a new one), and prints the units, the calls found and
this process's CPU seconds for the extraction (with ``--jobs 1`` every parse is in it).
``--out FILE`` appends that line to FILE. To compare two checkouts, run the two
commands in turn, A B A B ... (the ratio is taken pair by pair, so that a drift of the
machine's speed cancels)::

    PYTHONPATH=NEW python bench/cpp_cost.py WS --out /tmp/new.txt
    PYTHONPATH=OLD python bench/cpp_cost.py WS --out /tmp/old.txt

and read the per-run extraction CPU of each from the two files (their medians' ratio is
the cost per unit of the change; a whole process's figures, `/usr/bin/time -v`, add
start-up).
"""

from __future__ import annotations

import argparse
import os
import sys
import time

_SKIP = ("test", "tests", "doc", "docs", "example", "examples")
_SUFFIXES = (".cpp", ".cc", ".cxx")


def units_of(root: str) -> list[str]:
    """The C++ sources under ``root`` outside test, doc and example folders."""
    found: list[str] = []
    for folder, dirs, files in os.walk(root):
        dirs[:] = sorted(d for d in dirs if d not in _SKIP and not d.startswith("."))
        found += [os.path.join(folder, f) for f in sorted(files) if f.endswith(_SUFFIXES)]
    return found


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("workspace")
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--out")
    args = parser.parse_args()
    from haros_arch.extract.cpp import extract_cpp_nodes
    from haros_arch.workspace import scan

    root = os.path.abspath(args.workspace)
    workspace = scan([root], dict(os.environ))
    units = units_of(root)
    started = time.process_time()
    batch = extract_cpp_nodes([[u] for u in units], workspace, cache_dir=None,
                              jobs=args.jobs)
    cpu = time.process_time() - started
    calls = sum(len(r.calls) for r in batch.results)
    line = (f"{os.path.basename(root.rstrip(os.sep))}: {len(units)} units, {calls} calls, "
            f"{cpu:.2f} s CPU, {1000 * cpu / max(1, len(units)):.1f} ms per unit")
    print(line)
    if args.out:
        with open(args.out, "a", encoding="utf-8") as out:
            out.write(line + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
