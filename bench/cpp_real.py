"""C++ extraction on a real workspace: how many calls are found and how many clang
errors are left against our stand-in headers, for every package (or those named).

    .venv/bin/python bench/cpp_real.py WORKSPACE [--package P ...] [--node SUBSTRING]
        [--errors] [--calls]

Runs the source stage of the pipeline (workspace scan, build files, C++ extraction; no
cache, so every translation unit is parsed) and prints the number of C++ nodes, calls
and CPP_PARSE_ERROR / CPP_MESSAGE_FIELD diagnostics. ``--node`` lists the calls of the
nodes whose name contains SUBSTRING; ``--errors`` lists the clang errors grouped by their
message; ``--calls`` writes every call as one ``node kind name type`` line (for a diff of
two runs).
"""

from __future__ import annotations

import argparse
import collections
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))

from haros_arch import cmake  # noqa: E402
from haros_arch.extract import extract_nodes  # noqa: E402
from haros_arch.workspace import scan  # noqa: E402

ERRORS = ("CPP_PARSE_ERROR", "CPP_MESSAGE_FIELD")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("workspace")
    parser.add_argument("--package", action="append", default=[])
    parser.add_argument("--node", default=None)
    parser.add_argument("--errors", action="store_true")
    parser.add_argument("--calls", action="store_true")
    args = parser.parse_args()
    workspace = scan([os.path.abspath(args.workspace)], dict(os.environ))
    nodes = []
    for name in args.package or sorted(workspace.packages):
        package = workspace.packages[name]
        if package.build_type in ("catkin", "ament_cmake", "cmake"):
            package.nodes, _ = cmake.parse_package(package, workspace)
        nodes += [n for n in package.nodes if n.language == "cpp"]
    found = extract_nodes(nodes, workspace, cache_dir=None)
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


if __name__ == "__main__":
    main()
