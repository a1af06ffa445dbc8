"""The launch, setup.py and Python node readers of two checkouts on real workspaces, compared.

    .venv/bin/python bench/readers_differential.py OLD_CHECKOUT NEW_CHECKOUT ROOT [ROOT ...]

For every launch file under each ROOT (``*.launch``, ``*.launch.xml``, ``*launch.py``) and
every package with a setup.py: the nodes (name, package, executable, namespace, remaps),
the parameters with their values, the diagnostics, the whole model (`launch --format json`)
and its tree (`launch --tree`), the
``console_scripts`` entry points and the share map; the calls the Python node reader finds
in every ``.py`` file that uses rospy or rclpy. Each checkout runs in its own process
(its own ``haros_arch`` first on the path); the script prints how many records each made
and every record that differs, field by field. Made to check that a refactoring of the
readers (the one safe evaluator, #20) changes nothing on real code.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile

DUMP = r'''
import glob, json, os, sys
from haros_arch.workspace import scan
from haros_arch.launch import load
from haros_arch import pysetup
from haros_arch.share import share_map
from haros_arch.extract.python import extract_python
from haros_arch.launch.ros1.dump import as_data
from haros_arch.launch.tree_view import as_rich
from rich.console import Console

out = open(sys.argv[1], "w")
for root in sys.argv[2:]:
    ws = scan([root], {})
    for name, pkg in sorted(ws.packages.items()):
        if pkg.root.startswith(root) and os.path.isfile(os.path.join(pkg.root, "setup.py")):
            nodes, found = pysetup.parse_package(pkg, ws)
            out.write(json.dumps({"pkg": name,
                                  "nodes": sorted(f"{n.executable}:{n.sources}" for n in nodes),
                                  "diags": sorted(f"{d.code}:{d.location.line}"
                                                  for d in found)}) + "\n")
            out.write(json.dumps({"share": name,
                                  "map": sorted(share_map(pkg, ws).items())}) + "\n")
    files = sorted({f for pattern in ("*.launch", "*.launch.xml", "*launch.py")
                    for f in glob.glob(f"{root}/**/{pattern}", recursive=True)})
    for path in files:
        try:
            m = load(path, ws, {}, {})
            record = {"file": path,
                      "nodes": [f"{n.name}|{n.package}|{n.executable}|{n.namespace}|{n.remaps}"
                                for n in m.nodes],
                      "params": [f"{p.name}={p.value!r}" for p in m.params],
                      "diags": [f"{d.code}:{d.location.line}:{d.message}"
                                for d in m.diagnostics],
                      "model": json.dumps(as_data(m), sort_keys=True, default=str)}
            console = Console(width=1000, record=True, file=open(os.devnull, "w"))
            console.print(as_rich(m.tree), highlight=False, crop=False)
            record["tree"] = console.export_text()
        except Exception as err:  # a bug of one side: shown as a difference
            record = {"file": path, "error": f"{type(err).__name__}: {err}"}
        out.write(json.dumps(record, default=str) + "\n")
    for path in sorted(glob.glob(f"{root}/**/*.py", recursive=True)):
        try:
            with open(path, errors="replace") as handle:
                text = handle.read(300_000)
        except OSError:
            continue
        if "rospy" not in text and "rclpy" not in text:
            continue
        package = ws.package_of(path)
        try:
            found = extract_python([path], ws, package=package.name if package else "x")
            record = {"node": path, "calls": [f"{c.kind}|{c.name}|{c.type}" for c in found.calls]}
        except Exception as err:
            record = {"node": path, "error": f"{type(err).__name__}: {err}"}
        out.write(json.dumps(record, default=str) + "\n")
'''


def dump(checkout: str, roots: list[str], into: str) -> list[dict[str, object]]:
    env = {**os.environ, "PYTHONPATH": os.path.abspath(checkout)}
    subprocess.run([sys.executable, "-c", DUMP, into, *roots], env=env, check=True,
                   cwd=tempfile.gettempdir())
    with open(into) as handle:
        return [json.loads(line) for line in handle]


def main() -> int:
    if len(sys.argv) < 4:
        print(__doc__)
        return 2
    old_checkout, new_checkout, *roots = sys.argv[1:]
    roots = [os.path.abspath(r) for r in roots]
    with tempfile.TemporaryDirectory() as folder:
        old = dump(old_checkout, roots, os.path.join(folder, "old.jsonl"))
        new = dump(new_checkout, roots, os.path.join(folder, "new.jsonl"))
    kinds: dict[str, int] = {}
    differ = 0
    for before, after in zip(old, new, strict=False):
        kind = next(iter(before))
        kinds[kind] = kinds.get(kind, 0) + 1
        if before == after:
            continue
        differ += 1
        print(f"differs: {before.get(kind)}")
        for key, value in before.items():
            if value != after.get(key):
                print(f"  {key}: old {str(value)[:300]}\n  {key}: new {str(after.get(key))[:300]}")
    print(f"records: old {len(old)}, new {len(new)} (launch files {kinds.get('file', 0)}, "
          f"setup.py packages {kinds.get('pkg', 0)}, Python nodes {kinds.get('node', 0)}); "
          f"differing: {differ}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
