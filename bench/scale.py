"""How the cost of a whole run grows with the workspace (issue #24): per project file, a
cold run (empty cache), a no-change re-run, and two re-runs after one C++ source changed
(a comment appended: the same model; a line added before its code: another), each in a
fresh process that does with one analysis what `check`, `report` and `extract -o` do
(the process's seconds are the three commands' but for two start-ups), with the seconds
of every stage, per translation unit and per package, and a check that the first three
runs give the same document (`extract -o`'s: the model and its findings).

    .venv/bin/python bench/scale.py [--jobs N] [--touch FILE.cpp] PROJECT.yaml [...]

Wall and CPU seconds of each whole process are printed (on a busy machine the wall time
waits for a processor: compare CPU). Stages (seconds of wall time): cache (the run
cache's snapshot and entry; the entry is written by a forked copy of the process, as
every command does, whose CPU is counted with the process's), scan (folders and package
manifests), launch, build files (CMake / setup.py), C++ (libclang's parse apart from the
rest, the walk of the syntax trees and the cache; the split is measured with ``--jobs
1`` only: workers parse out of sight), Python (the other nodes, read while the C++
workers parse: their seconds are within C++'s), models, graph, queries (the catalogue),
report (the HTML file) and document (`extract`'s JSON document, written, and its
summary). The changed file is ``--touch`` or the first C++ source of
the model; a comment is appended to it (touched: what the unit gives is the same, the
kept run answers) and, in a fourth run, a comment line is put before its first line
instead (edited: every call of the file moves: the kept run's model and findings
renumbered when no call changed otherwise, ``relocate``; else the run is made again,
from the unit cache and the other nodes' kept results); the file is restored afterwards
(use a copy of a fetched tree: this writes into it).
Each run uses its own cache folder (a temporary one, empty for the cold run), never the
user's.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from typing import Any

import checkout  # bench/checkout.py: says which haros_arch is measured

HERE = os.path.dirname(os.path.abspath(__file__))
STAGES = ("cache", "scan", "launch", "build files", "C++", "C++ parse", "Python", "models",
          "graph", "queries", "report", "document")


def child(project_path: str, cache: str, jobs: int, model_out: str) -> dict[str, Any]:
    """One run in this process: seconds per stage, counts, and the digest of `extract`'s
    document."""
    start = time.perf_counter()
    from haros_arch import pipeline  # noqa: F401 (its import is timed; ``_child`` runs it)
    from haros_arch.project import load
    imported = time.perf_counter() - start

    parse = [0.0, 0]
    if jobs == 1:  # libclang's own parse, timed apart from our walk of its trees
        import clang.cindex as ci

        original = ci.Index.parse

        def timed(self: Any, *args: Any, **kwargs: Any) -> Any:
            began = time.perf_counter()
            try:
                return original(self, *args, **kwargs)
            finally:
                parse[0] += time.perf_counter() - began
                parse[1] += 1

        ci.Index.parse = timed  # type: ignore[method-assign]

    timings: dict[str, float] = {}
    project = load(project_path)
    from haros_arch import runcache
    with runcache.background():  # as every command: the model kept by a forked copy
        return _child(project, cache, jobs, model_out, timings, parse, start, imported)


def _child(project: Any, cache: str, jobs: int, model_out: str, timings: dict[str, float],
           parse: list[Any], start: float, imported: float) -> dict[str, Any]:
    from haros_arch.pipeline import Options, analyse
    model = analyse(project, options=Options(cache_dir=cache, jobs=jobs, timings=timings))
    if jobs == 1:
        timings["C++ parse"] = parse[0]
    began = time.perf_counter()
    from haros_arch.query.command import check
    checked = check(model, project)
    timings["queries"] = time.perf_counter() - began
    began = time.perf_counter()
    from haros_arch.viz.command import project_findings, report_page, workspace_root
    from haros_arch.viz.html import write_page
    with tempfile.TemporaryDirectory() as folder:  # as `haros-arch report` does
        write_page(report_page(model, project_findings(model, project),
                               workspace_root(project, None), project),
                   os.path.join(folder, "report.html"))
    timings["report"] = time.perf_counter() - began
    began = time.perf_counter()  # as `haros-arch extract -o FILE` does: its document
    from haros_arch import runcache
    from haros_arch.report.json import document_text
    from haros_arch.report.text import summary_lines
    text = document_text(model, project)
    with open(model_out, "w", encoding="utf-8") as handle:
        handle.write(text)
    summary = runcache.summary(model, False, lambda: summary_lines(model, False))
    timings["document"] = time.perf_counter() - began
    total = time.perf_counter() - start
    found = {"timings": timings, "imports": imported, "parses": parse[1], "total": total,
             "findings": len(checked.findings),
             "slowest_query": max(checked.seconds.items(), key=lambda kv: kv[1],
                                  default=("", 0.0)),
             "digest": hashlib.sha256(text.encode()).hexdigest()[:16],
             "summary": len(summary)}
    if isinstance(model, runcache.KeptModel):
        return found  # the counts would decode a kept model, which no command above did
    nodes = [n for p in model.packages for n in p.nodes]
    return {**found, "packages": len(model.packages), "nodes": len(nodes),
            "cpp_units": len({s for n in nodes if n.language == "cpp" for s in n.sources}),
            "instances": sum(len(c.nodes) for c in model.configurations),
            "links": sum(len(c.links) for c in model.configurations),
            "first_cpp": next((s for n in nodes if n.language == "cpp" for s in n.sources),
                              None)}


def run(project: str, cache: str, jobs: int, model_out: str) -> dict[str, Any]:
    began = time.perf_counter()
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    done = subprocess.run(
        [sys.executable, __file__, "--child", project, "--cache", cache, "--jobs", str(jobs),
         "--model-out", model_out], capture_output=True, text=True, check=False)
    wall = time.perf_counter() - began
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        sys.exit(f"run failed ({done.returncode}):\n{done.stderr[-3000:]}")
    result: dict[str, Any] = json.loads(done.stdout.strip().splitlines()[-1])
    result["wall"] = wall
    result["cpu"] = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return result


def show(label: str, result: dict[str, Any], cold: dict[str, Any] | None) -> None:
    t = result["timings"]
    ratio = (f" ({result['wall'] / cold['wall']:.3f} of cold, CPU "
             f"{result['cpu'] / cold['cpu']:.3f})" if cold else "")
    print(f"  {label:<10} process {result['wall']:7.2f} s wall, {result['cpu']:7.2f} s CPU "
          f"(with its workers){ratio}; imports "
          f"{result['imports']:.2f} s; document {result['digest']}")
    print("    " + ", ".join(f"{s} {t[s]:.2f}" for s in STAGES if s in t))
    if label == "cold":
        units, packages = max(1, result["cpp_units"]), max(1, result["packages"])
        cpp = t.get("C++", 0.0)
        print(f"    {result['packages']} packages, {result['nodes']} nodes, "
              f"{result['cpp_units']} C++ units ({result['parses']} libclang parses), "
              f"{result['instances']} instances, {result['links']} links, "
              f"{result['findings']} findings; slowest query "
              f"{result['slowest_query'][0]} {result['slowest_query'][1]:.2f} s")
        print(f"    per C++ unit {1000 * cpp / units:.1f} ms (libclang "
              f"{1000 * t.get('C++ parse', 0.0) / units:.1f} ms); per package "
              f"{1000 * result['wall'] / packages:.1f} ms of the whole run")


def touched_file(project: str, result: dict[str, Any], given: str | None) -> str | None:
    if given:
        return given
    first = result.get("first_cpp")
    if not first:
        return None
    from haros_arch.project import load
    for root in load(project).workspace:
        path = os.path.join(root, first)  # relative to the workspace, or absolute
        if os.path.isfile(path):
            return path
    return None


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("projects", nargs="+")
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--touch")
    parser.add_argument("--keep", help="keep the cache and the models in this folder "
                        "(emptied first) instead of a temporary one")
    parser.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("--cache", help=argparse.SUPPRESS)
    parser.add_argument("--model-out", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        print(json.dumps(child(args.projects[0], args.cache, args.jobs, args.model_out)))
        return
    for project in args.projects:
        print(f"{project} (--jobs {args.jobs})")
        with tempfile.TemporaryDirectory() as temporary:
            folder = temporary
            if args.keep:
                folder = os.path.join(args.keep, os.path.basename(os.path.dirname(
                    os.path.abspath(project))))
                shutil.rmtree(folder, ignore_errors=True)
                os.makedirs(folder)
            cache = os.path.join(folder, "cache")
            models = [os.path.join(folder, f"model{i}.json") for i in range(4)]
            cold = run(project, cache, args.jobs, models[0])
            show("cold", cold, None)
            warm = run(project, cache, args.jobs, models[1])
            show("no change", warm, cold)
            path = touched_file(project, cold, args.touch)
            if path is None:
                print("  (no C++ source to touch)")
                continue
            with open(path, "rb") as handle:
                original = handle.read()
            try:
                with open(path, "ab") as handle:
                    handle.write(b"\n// touched by bench/scale.py\n")
                touched = run(project, cache, args.jobs, models[2])
                # an edit that changes what the unit gives: a line before the code moves
                # every call of the file, so the run is made again from the caches
                with open(path, "wb") as handle:
                    handle.write(b"// edited by bench/scale.py\n" + original)
                edited = run(project, cache, args.jobs, models[3])
            finally:
                with open(path, "wb") as handle:
                    handle.write(original)
            show("touched", touched, cold)
            show("edited", edited, cold)
            print(f"    touched / edited {path}")
            same = cold["digest"] == warm["digest"]
            print(f"  same document cold / no change: {same}; cold / touched: "
                  f"{cold['digest'] == touched['digest']} (a touched file's lines move "
                  "nothing: the comment is appended)")


if __name__ == "__main__":
    checkout.announce()
    main()
