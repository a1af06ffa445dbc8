"""Whether a header function gives the same in every unit that analyses it (#24): the
evidence a cache of header functions across units would need.

    PYTHONPATH=CHECKOUT .venv/bin/python bench/header_share.py PROJECT [--package P ...]
        [--examples N] [--distro D]

Runs the C++ extraction as ``cpp_real.py --jobs 1`` does (one process, no cache) and
records, for each function of a workspace header (not the unit's own file) in a unit's
function set, what three stages of ``CallFinder.run`` give for it as plain data:
``_gives`` (whether its walk may find something), its wrapper summary
(``Wrappers.summaries``, as ``repr``) and the calls its walk ``_function`` adds (each
``PrimitiveCall`` as ``repr``). A function is told by its place (file, line, column)
and spelling; then again by that place with the unit's parse arguments and the unsaved
files other than the unit's own source (the synthesised declarations): the key "file +
flags" a cache would take. For each stage and key it prints how many distinct
functions there are, how many analyses, and how many functions gave different results
in different units (with ``--examples`` the first N of those, with a unit of each).
A function with one result everywhere on one tree proves nothing for another; one with
two shows that the stage depends on the unit around it.
"""

from __future__ import annotations

import argparse
import collections
import hashlib
import os
import sys
from typing import Any

import checkout  # bench/checkout.py: says which haros_arch is measured
from cpp_real import opened

from haros_arch import pipeline
from haros_arch.extract import extract_nodes

Results = dict[tuple[Any, ...], dict[str, set[str]]]


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("project", help="a project file or a workspace folder")
    parser.add_argument("--package", action="append", default=[])
    parser.add_argument("--examples", type=int, default=0)
    parser.add_argument("--distro", default=None)
    args = parser.parse_args(argv)
    checkout.announce(sys.stdout)
    project, env, workspace, nodes = opened(args.project, args.distro, args.package,
                                            "header_share")
    stages: dict[str, Results] = {name: collections.defaultdict(
        lambda: collections.defaultdict(set)) for name in ("gives", "summary", "calls")}
    parsed = _record(stages)
    extract_nodes(nodes, workspace, cache_dir=None, jobs=1,
                  **pipeline.cpp_arguments(project, env))
    print(f"units {len(parsed)}, distinct parse arguments "
          f"{len({p[:-1] for p in parsed.values()})}, distinct other unsaved files "
          f"{len({p[-1] for p in parsed.values()})}, distinct both {len(set(parsed.values()))}")
    print("stage    key            functions  analyses  differing")
    for name, results in stages.items():
        for key_name, width in (("place", 4), ("place+flags", 5)):
            merged: Results = collections.defaultdict(lambda: collections.defaultdict(set))
            for key, found in results.items():
                for result, units in found.items():
                    merged[key[:width]][result] |= units
            analyses = sum(len(u) for found in merged.values() for u in found.values())
            differing = [key for key, found in merged.items() if len(found) > 1]
            print(f"{name:8} {key_name:12} {len(merged):11} {analyses:9} {len(differing):10}")
            if key_name == "place":
                for key in differing[:args.examples]:
                    print(f"  {key[0]}:{key[1]}:{key[2]} {key[3]}")
                    for result, units in list(merged[key].items())[:2]:
                        print(f"    in {len(units)} units ({os.path.basename(min(units))}):"
                              f" {result[:300]}")


def _record(stages: dict[str, Results]) -> dict[str, tuple[str, ...]]:
    """Wrap the three stages so that each records its result for each header function,
    by its place and the unit's parse; return each unit's parse (its arguments, and a
    digest of the unsaved files other than its source), filled as units are parsed."""
    from clang.cindex import Index

    from haros_arch.extract.cpp import visitor, wrappers

    parses: dict[int, tuple[str, ...]] = {}  # id of each parse made -> its parse
    parsed: dict[str, tuple[str, ...]] = {}  # each walked unit's source -> its parse
    parse = Index.parse

    def recorded_parse(self: Any, path: str, args: Any = None, unsaved_files: Any = None,
                       options: int = 0) -> Any:
        unit = parse(self, path, args=args, unsaved_files=unsaved_files, options=options)
        others = sorted((n, c) for n, c in unsaved_files or () if n != path)
        parses[id(unit)] = (*(str(a) for a in args or ()),
                            hashlib.sha1(repr(others).encode()).hexdigest())
        return unit

    def key(finder: Any, function: Any) -> tuple[Any, ...] | None:
        where = function.location.file
        if where is None or where.name == finder.tu.spelling:
            return None
        place = (where.name, function.location.line, function.location.column,
                 function.spelling)
        # (the parse walked: the synthesis may parse a unit again, ``extract.cpp``)
        walked = parsed[finder.tu.spelling] = parses.get(id(finder.tu), ())
        return (*place, walked, finder.tu.spelling)

    def note(stage: str, found: tuple[Any, ...] | None, result: str) -> None:
        if found is not None:
            stages[stage][found[:5]][result].add(found[5])

    gives, walk, build = (visitor.CallFinder._gives, visitor.CallFinder._function,
                          wrappers.Wrappers.build)

    def recorded_gives(self: Any, function: Any) -> bool:
        given = gives(self, function)
        note("gives", key(self, function), str(given))
        return given

    def recorded_walk(self: Any, function: Any) -> None:
        first = len(self.calls)
        walk(self, function)
        note("calls", key(self, function), repr(self.calls[first:]))

    def recorded_build(self: Any) -> None:
        build(self)
        for function in self.finder.functions:
            summary = self.summaries.get(wrappers._key(function.canonical))
            note("summary", key(self.finder, function), repr(summary))

    Index.parse = recorded_parse  # type: ignore[method-assign]
    visitor.CallFinder._gives = recorded_gives  # type: ignore[method-assign]
    visitor.CallFinder._function = recorded_walk  # type: ignore[method-assign]
    wrappers.Wrappers.build = recorded_build  # type: ignore[method-assign]
    return parsed


if __name__ == "__main__":
    main()
