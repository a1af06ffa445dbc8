"""The launch tree against the launch model it was recorded with, on real folders.

    .venv/bin/python bench/launch_tree.py FOLDER [FOLDER ...] [-v]

Every launch file under each FOLDER (ROS 1 ``*.launch``/``*.test``/``*.xml``, ROS 2
``*.launch.py``/``*.launch.xml``/``*.launch.yaml``) is loaded with the folders as the
workspace. Prints the number of files, tree items, included files, groups, nodes,
conditions (decided true, false, unknown) and left-out parts, and how many trees
disagree with their model: the tree's started nodes must be the model's node
declarations (same names, same order) and its files the files the model read (``-v``
lists each disagreement).
"""

from __future__ import annotations

import sys
from collections import Counter
from pathlib import Path

from haros_arch.launch import load
from haros_arch.workspace import scan

SUFFIXES = (".launch", ".test", ".launch.py", ".launch.xml", ".launch.yaml")


def main(argv: list[str]) -> int:
    verbose = "-v" in argv
    folders = [Path(a) for a in argv if a != "-v"]
    workspace = scan([str(f) for f in folders], {})
    counts: Counter[str] = Counter()
    for folder in folders:
        for path in sorted(folder.rglob("*")):
            if not path.is_file() or not path.name.endswith(SUFFIXES):
                continue
            model = load(str(path), workspace, {}, {})
            counts["launch files loaded"] += 1
            items = [i for root in model.tree for i in root.walk()]
            counts["items"] += len(items)
            started = [i.name for i in items if i.kind == "node" and not i.skipped]
            files = [i.name for i in items if i.kind == "file"]
            read = [f for f in model.files if not f.endswith((".yaml", ".yml"))]
            for item in items:
                counts[f"{item.kind} items" + (" left out" if item.skipped else "")] += 1
                if item.condition is not None:
                    counts[f"conditions {item.condition.holds}"] += 1
            if started != [n.name for n in model.nodes]:
                counts["node mismatch"] += 1
                if verbose:
                    print(f"nodes differ: {path}")
            if not set(read) <= set(files):
                counts["file mismatch"] += 1
                if verbose:
                    print(f"files differ: {path}: {sorted(set(read) - set(files))}")
    for key, value in sorted(counts.items()):
        print(f"{key:>24}: {value}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
