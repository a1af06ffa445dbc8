"""The xacro reader on every robot description of real workspaces.

    .venv/bin/python bench/xacro_real.py WORKSPACE [WORKSPACE ...] [--list] [--dump FILE]

Every ``*.urdf.xacro`` / ``*.xacro`` / ``*.urdf`` file that is a document of its own (its
root is ``<robot>``) is expanded with no arguments (defaults only) and the environment
empty: how many expand completely, how many keep unknown parts (and the commonest
reasons), how many stop (with the diagnostics by code), the links and Gazebo plugins
found, and the slowest file. ``--list`` prints one line per file. Macro-only files
(included by others) are expanded too: their macros are defined and unused. ``--dump FILE``
writes every expansion (the document, the unknown reasons, the diagnostics), each file
twice: with its defaults, and with every ``xacro:arg`` it declares known only in part
(``x_?``): two trees' files compare byte for byte (``cmp``).
"""

from __future__ import annotations

import argparse
import collections
import os
import re
import time
from typing import Any

import checkout  # bench/checkout.py: says which haros_arch is measured

HERE = os.path.dirname(os.path.abspath(__file__))

from lxml import etree  # noqa: E402

from haros_arch.robot import xacro  # noqa: E402
from haros_arch.workspace import scan  # noqa: E402

SUFFIXES = (".urdf.xacro", ".xacro", ".urdf")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("workspace", nargs="+")
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--dump", metavar="FILE")
    args = parser.parse_args()
    roots = [os.path.abspath(w) for w in args.workspace]
    workspace = scan(roots, {})
    files = sorted(os.path.join(folder, name) for root in roots
                   for folder, _, names in os.walk(root) for name in names
                   if name.endswith(SUFFIXES))
    counts: collections.Counter[str] = collections.Counter()
    codes: collections.Counter[str] = collections.Counter()
    reasons: collections.Counter[str] = collections.Counter()
    links = plugins = 0
    slowest = (0.0, "")
    for path in files:
        start = time.perf_counter()
        description = xacro.expand(path, {}, workspace, {})
        took = time.perf_counter() - start
        slowest = max(slowest, (took, workspace.relpath(path)))
        codes.update(d.code for d in description.diagnostics)
        if description.root is None:
            state = "stopped"
        elif description.unknown:
            state = "partial"
            reasons.update(r.split(" (")[0].split(": ")[0][:70] for r in description.unknown)
        else:
            state = "complete"
        counts[state] += 1
        if description.root is not None:
            links += len(description.root.findall("link"))
            plugins += sum(1 for p in description.root.iter("plugin") if p.get("filename"))
        if args.list:
            print(f"{state:8} {took * 1000:7.1f} ms {workspace.relpath(path)}")
    if args.dump:
        dump(files, workspace, args.dump)
    print(f"{len(files)} files: {counts['complete']} complete, {counts['partial']} partial, "
          f"{counts['stopped']} stopped; {links} links, {plugins} Gazebo plugins; slowest "
          f"{slowest[0] * 1000:.0f} ms ({slowest[1]})")
    print("diagnostics:", ", ".join(f"{c} {n}" for c, n in codes.most_common()) or "none")
    for reason, number in reasons.most_common(8):
        print(f"  {number:4} {reason}")


def dump(files: list[str], workspace: Any, out: str) -> None:
    with open(out, "w", encoding="utf-8", errors="surrogateescape") as stream:
        for path in files:
            with open(path, encoding="utf-8", errors="replace") as source:
                declared = sorted(set(re.findall(r'<xacro:arg\s+name="([^"]+)"',
                                                 source.read())))
            unknown = {name: xacro.partial_text("x_?", f"xacro argument {name} is not known")
                       for name in declared}
            for given in ({}, unknown):
                description = xacro.expand(path, given, workspace, {})
                root = description.root
                stream.write(f"=== {workspace.relpath(path)} {sorted(given)}\n"
                             + (etree.tostring(root).decode() if root is not None else "-")
                             + "\n--- unknown\n" + "\n".join(description.unknown)
                             + "\n--- diagnostics\n" + "\n".join(
                                 f"{d.code} {d.location} {d.message}"
                                 for d in description.diagnostics) + "\n")


if __name__ == "__main__":
    checkout.announce()
    main()
