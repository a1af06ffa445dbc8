"""Seconds per C++ translation unit: our extraction (stand-in headers, precompiled once)
against libclang parsing the same file with the real installed ROS headers (HAROS's
way, ``system_headers=True``), both followed by the same call finder; then a no-change
re-run of all the files through the cache. Prints the ratios measured in this one run.

    .venv/bin/python bench/cpp_extract.py [WORKSPACE [SOURCE.cpp ...]]

Without arguments it runs on the repository's C++ fixtures (ROS 1 sources only for the
real-header side, since Debian ships ROS 1 headers, not ROS 2).
"""

from __future__ import annotations

import os
import sys
import tempfile
import time

import checkout  # bench/checkout.py: says which haros_arch is measured

HERE = os.path.dirname(os.path.abspath(__file__))

from haros_arch.extract.cpp import extract_cpp  # noqa: E402
from haros_arch.workspace import scan  # noqa: E402

FIXTURES = os.path.join(os.path.dirname(HERE), "fixtures")
DEFAULT = [
    (os.path.join(FIXTURES, "paper_minimal"), ["src/example/src/active.cpp",
                                               "src/example/src/reactive.cpp"]),
    (os.path.join(FIXTURES, "cpp", "features"), ["src/demo/src/names.cpp",
                                                 "src/demo/src/conditions.cpp",
                                                 "src/demo/src/libraries.cpp"]),
]


def timed(sources: list[str], workspace: object, **options: object) -> tuple[float, object]:
    start = time.perf_counter()
    result = extract_cpp(sources, workspace, **options)  # type: ignore[arg-type]
    return time.perf_counter() - start, result


def main(argv: list[str]) -> int:
    cases = DEFAULT if not argv else [(argv[0], argv[1:])]
    ours_total = real_total = 0.0
    ours_calls = real_calls = 0
    every: list[tuple[object, str]] = []
    print(f"{'file':50} {'ours s':>8} {'real s':>8} {'ratio':>7} {'calls':>11}")
    for root, files in cases:
        workspace = scan([root])
        for rel in files:
            path = os.path.join(root, rel)
            every.append((workspace, path))
            extract_cpp([path], workspace, cache_dir=None)  # the once-per-process PCH
            ours, mine = timed([path], workspace, cache_dir=None, jobs=1)
            real, theirs = timed([path], workspace, cache_dir=None, jobs=1,
                                 system_headers=True)
            ours_total += ours
            real_total += real
            ours_calls += len(mine.calls)  # type: ignore[attr-defined]
            real_calls += len(theirs.calls)  # type: ignore[attr-defined]
            print(f"{rel[-50:]:50} {ours:8.3f} {real:8.3f} {real / ours:7.1f} "
                  f"{len(mine.calls):5d}/{len(theirs.calls):<5d}")  # type: ignore[attr-defined]
    count = len(every)
    print(f"per translation unit: ours {ours_total / count:.4f} s, real headers "
          f"{real_total / count:.3f} s, ratio {real_total / ours_total:.1f}x; "
          f"calls ours {ours_calls}, real headers {real_calls}")
    with tempfile.TemporaryDirectory() as store:
        for workspace, path in every:
            extract_cpp([path], workspace, cache_dir=store)  # type: ignore[arg-type]
        start = time.perf_counter()
        for workspace, path in every:
            extract_cpp([path], workspace, cache_dir=store)  # type: ignore[arg-type]
        warm = time.perf_counter() - start
    print(f"no-change re-run of {count} files from the cache: {warm:.3f} s")
    return 0


if __name__ == "__main__":
    checkout.announce()
    sys.exit(main(sys.argv[1:]))
