"""C++ extraction on a real workspace: how many calls are found and how many clang
errors are left against our stand-in headers, for every package (or those named).

    PYTHONPATH=CHECKOUT .venv/bin/python bench/cpp_real.py PROJECT [--package P ...]
        [--node SUBSTRING] [--errors] [--calls] [--json FILE] [--jobs N] [--profile N]
        [--distro D]

PROJECT is what ``haros-arch extract`` takes: a project file or a workspace folder.
Runs the source stage of the pipeline as ``extract --no-cache`` does (the workspace
scanned in the run's environment, build files, C++ extraction with the project's
compile_commands.json and distribution: ``pipeline.cpp_arguments``; no cache, so every
translation unit is parsed) on the packages the project names (default: all) and
prints the number of C++ nodes, calls and CPP_PARSE_ERROR / CPP_MESSAGE_FIELD
diagnostics. The haros_arch measured is the one Python imports (PYTHONPATH, else the
installed one), printed first: run each checkout with its own PYTHONPATH.

``--node`` lists the calls of the nodes whose name contains SUBSTRING; ``--errors``
lists the clang errors grouped by their message; ``--calls`` writes every call as one
``node kind name type`` line (for a diff of two runs); ``--json FILE`` writes every C++
node's whole result (each call with all its fields, conditions and location, its ROS
names, the diagnostics of its units) as JSON, to compare two checkouts exactly: run
each checkout with its own PYTHONPATH on the same tree and ``diff`` the files.
``--jobs N`` parses in N processes (default 1); ``--profile N`` runs under cProfile
(with one job) and prints the N costliest functions by own time and the CPU seconds in
libclang's parse against the rest. ``--distro D`` parses for that
ROS distribution's rclcpp (``extract.cpp.versions``), as a project file's ``distro:``
(default: the project's, else ROS_DISTRO, as the pipeline).
"""

from __future__ import annotations

import argparse
import collections
import cProfile
import dataclasses
import json
import os
import pstats
import sys
import time

import checkout  # bench/checkout.py: says which haros_arch is measured

from haros_arch import pipeline
from haros_arch.autoproject import open_project
from haros_arch.extract import extract_nodes
from haros_arch.model.source import Node
from haros_arch.project import Project, ProjectError
from haros_arch.workspace import Workspace, scan

ERRORS = ("CPP_PARSE_ERROR", "CPP_MESSAGE_FIELD")


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("project", help="a project file or a workspace folder")
    parser.add_argument("--package", action="append", default=[])
    parser.add_argument("--node", default=None)
    parser.add_argument("--errors", action="store_true")
    parser.add_argument("--calls", action="store_true")
    parser.add_argument("--json", default=None)
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--profile", type=int, default=0)
    parser.add_argument("--distro", default=None)
    args = parser.parse_args(argv)
    checkout.announce(sys.stdout)
    project, env, workspace, nodes = opened(args.project, args.distro, args.package,
                                            "cpp_real")
    spent = _time_stages() if args.jobs == 1 or args.profile else None
    profile = cProfile.Profile(time.process_time) if args.profile else None
    start = time.process_time()
    if profile is not None:
        profile.enable()
    found = extract_nodes(nodes, workspace, cache_dir=None,
                          jobs=1 if profile is not None else args.jobs,
                          **pipeline.cpp_arguments(project, env))
    if profile is not None:
        profile.disable()
    total = time.process_time() - start
    print(f"extraction CPU {total:.2f} s (this process)")
    if spent is not None:
        print(f"  libclang parse {spent['parse']:.2f} s, walk (CallFinder.run) "
              f"{spent['walk']:.2f} s, the rest {total - spent['parse'] - spent['walk']:.2f} s;"
              f" walk / parse {spent['walk'] / max(spent['parse'], 1e-9):.2f}")
    if profile is not None:
        _profile_report(profile, args.profile)
    nodes = [n for n in nodes if not n.deferred]  # plugin classes nothing loads
    if args.json is not None:
        _dump(args.json, nodes, found, workspace.root)
    errors = [d for d in found if d.code in ERRORS]
    calls = [(n.name, c) for n in nodes for c in n.calls]
    print(f"C++ nodes {len(nodes)}  calls {len(calls)}  clang errors {len(errors)} "
          f"({sum(d.code == 'CPP_PARSE_ERROR' for d in errors)} CPP_PARSE_ERROR)")
    if args.node is not None:
        for name, call in calls:
            if args.node in name:
                print(f"  {name:40} {call.kind:14} {call.name:40} {call.type} "
                      f"{call.location.file}:{call.location.line} "
                      f"{[c.statement for c in call.conditions]}")
    if args.errors:
        counts = collections.Counter(d.message for d in errors)
        for message, count in counts.most_common():
            print(f"  {count:3} {message}")
    if args.calls:
        for name, call in sorted(calls, key=lambda nc: (nc[0], nc[1].kind, nc[1].name)):
            print(f"CALL {name} {call.kind} {call.name} {call.type}")


def opened(path: str, distro: str | None, packages: list[str], script: str
           ) -> tuple[Project, dict[str, str], Workspace, list[Node]]:
    """The project ``path`` names (a project file or a workspace folder; exit with its
    error), parsed for ``distro`` and limited to ``packages`` when given, the run's
    environment for it, and ``source_nodes``."""
    try:
        project = open_project(path)
    except ProjectError as err:
        sys.exit(f"{script}: {err}")
    project.distro = distro or project.distro
    project.packages = packages or project.packages
    env = pipeline.distro_environment(project, os.environ)
    workspace, nodes = source_nodes(project, env)
    return project, env, workspace, nodes


def source_nodes(project: Project, env: dict[str, str]) -> tuple[Workspace, list[Node]]:
    """The workspace as the pipeline scans it for ``project`` in the run's environment
    ``env`` (``pipeline.distro_environment``) and the C++ nodes of the packages the
    project names (all when none), read from their build files as the pipeline reads
    them. The packages only a configuration's launch files name are not added."""
    workspace = scan(project.workspace, env)
    nodes = []
    for name in project.packages or sorted(workspace.packages):
        package = workspace.packages.get(name)
        if package is not None:
            pipeline.read_build_files(package, workspace)
            nodes += [n for n in package.nodes if n.language == "cpp"]
    return workspace, nodes


def _time_stages() -> dict[str, float]:
    """CPU seconds in libclang's parse and in the walk of the parsed units (the call
    finder's ``run``), measured by wrapping the two (one process: ``--jobs 1``)."""
    from clang.cindex import Index

    from haros_arch.extract.cpp import visitor

    spent = {"parse": 0.0, "walk": 0.0}

    def timed(owner: type, name: str, stage: str) -> None:
        inner = getattr(owner, name)

        def wrapper(*args: object, **kwargs: object) -> object:
            begin = time.process_time()
            try:
                return inner(*args, **kwargs)
            finally:
                spent[stage] += time.process_time() - begin

        setattr(owner, name, wrapper)

    timed(Index, "parse", "parse")
    timed(visitor.CallFinder, "run", "walk")
    return spent


def _dump(path: str, nodes: list, found: list, root: str) -> None:
    """Every C++ node's calls (all fields), names and the diagnostics of the run, sorted,
    paths relative to the workspace: the same extraction gives the same file."""
    def plain(value: object) -> object:
        if dataclasses.is_dataclass(value) and not isinstance(value, type):
            return {f.name: plain(getattr(value, f.name)) for f in dataclasses.fields(value)}
        if isinstance(value, (list, tuple)):
            return [plain(v) for v in value]
        if isinstance(value, dict):
            return {str(k): plain(v) for k, v in value.items()}
        if isinstance(value, str):
            return value.replace(root, "$WS")
        return value

    document = {
        "nodes": [{"package": n.package, "name": n.name,
                   "sources": sorted(str(s) for s in n.sources), "rosname": n.rosname,
                   "rosnames": plain(getattr(n, "rosnames", None)),
                   "calls": [plain(c) for c in n.calls]}
                  for n in sorted(nodes, key=lambda n: (n.package, n.name))],
        "diagnostics": sorted(json.dumps(plain(d), sort_keys=True) for d in found),
    }
    with open(path, "w", encoding="utf-8") as handle:
        json.dump(document, handle, indent=1, sort_keys=True, default=str)
    print(f"wrote {path}: {sum(len(n['calls']) for n in document['nodes'])} calls, "
          f"{len(document['diagnostics'])} diagnostics")


def _profile_report(profile: cProfile.Profile, count: int) -> None:
    """The N costliest functions by own time, and libclang's parse against the rest."""
    stats = pstats.Stats(profile)
    total = parse = 0.0
    for (filename, _, name), (_, _, own, cumulative, _) in stats.stats.items():  # type: ignore[attr-defined]
        total += own
        if name == "from_source" and filename.endswith("cindex.py"):
            parse += cumulative
    print(f"profile: {total:.1f} s in all, libclang parse (TranslationUnit.from_source) "
          f"{parse:.1f} s, the rest {total - parse:.1f} s ({(total - parse) / parse:.2f}x "
          f"the parse)" if parse else f"profile: {total:.1f} s, no parse seen")
    stats.sort_stats("tottime").print_stats(count)


if __name__ == "__main__":
    main()
