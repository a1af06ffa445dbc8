"""Flattened launch files against their originals: ROS 1 read by the real roslaunch,
ROS 2 read by our loader and, when given, by the real ROS 2 launch.

    .venv/bin/python bench/launch_flatten.py FOLDER [FOLDER ...] [-v]
    .venv/bin/python bench/launch_flatten.py --ros2 FOLDER [FOLDER ...] [-v]
        [--real-python PY --src SRC]

ROS 1 (the default):

Every ROS 1 launch file under each FOLDER (as ``launch_agreement.py`` finds them, with
every FOLDER on ``ROS_PACKAGE_PATH``) is loaded by ``haros_arch.launch.load`` and
written flat (``launch.ros1.flatten``); Debian's roslaunch loads the original and the
flattened file. Prints how many originals roslaunch accepts, how many flattened files it
reads as the original (same nodes, all fields, and the same parameters, leaving out
what the flattener says it leaves out), how many flattened files it refuses, and how
many nodes and parameters were left out (``-v``: each difference).

``--ros2``: every ROS 2 launch file under each FOLDER (found by name as
``launch_ros2_compare.py`` finds them; FOLDERs are one workspace) is loaded with its
default arguments and written flat in each format (XML, YAML, Python,
``launch.ros2.flatten``); our loader reads each flat file, and its nodes and parameters
(``flatten.facts``) are compared with the original's less what the flattener says it
leaves out. Prints files, files flattened, round trips equal per format, what was left
out by cause, and differences by cause (the field that differs). With ``--real-python``
(the scratch venv of ``launch_ros2_compare.py``) and ``--src`` (its SRC: launch,
launch_ros and the FOLDERs under it), the real launch also runs each original and its
flat files in the install-like tree that script builds, and they are compared as that
script compares ours with the real one.
"""

from __future__ import annotations

import json
import re
import sys
import tempfile
from pathlib import Path
from typing import Any

from launch_agreement import environment, flat, launch_files, roslaunch

from haros_arch.launch import load
from haros_arch.launch.ros1.flatten import flatten
from haros_arch.workspace import scan


def leaves(params: dict[str, Any]) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for key, value in params.items():
        flat(key, value, out)
    return {k: v for k, v in out.items() if v != {}}


ANON = re.compile(r"_[A-Za-z0-9_]*_\d+_\d+(?=/|$)")  # roslaunch's anon: _host_pid_random


def unanon(data: dict[str, Any]) -> dict[str, Any]:
    """Random anonymous names made one (each roslaunch run draws new ones)."""
    if "error" in data:
        return data
    nodes = [{**n, "name": ANON.sub("_ANON", n["name"] or "")} for n in data["nodes"]]
    return {**data, "nodes": nodes,
            "params": {ANON.sub("_ANON", k): v for k, v in data["params"].items()},
            "clear_params": [ANON.sub("_ANON", k) for k in data["clear_params"]]}


def typed(params: dict[str, Any]) -> dict[str, str]:
    """Values as JSON: an int parameter (1) is not a double one (1.0)."""
    return {k: json.dumps(v, sort_keys=True) for k, v in params.items()}


def main(argv: list[str]) -> int:
    if "--ros2" in argv:
        from launch_flatten_ros2 import main as main_ros2

        return main_ros2([a for a in argv if a != "--ros2"])
    verbose = "-v" in argv
    folders = [Path(a).resolve() for a in argv if a != "-v"]
    files = [f for folder in folders for f in launch_files(folder)]
    counts = dict.fromkeys(("files", "accepted", "agree", "differ", "flat refused",
                            "nodes", "nodes left out", "params", "params left out"), 0)
    with tempfile.TemporaryDirectory() as home:
        env = environment(":".join(map(str, folders)), home, {})
        workspace = scan([str(f) for f in folders], env)
        flats: list[Path] = []
        notes: list[list[str]] = []
        for index, path in enumerate(files):
            text, said = flatten(load(str(path), workspace, {}, env))
            out = Path(home) / f"flat{index}.launch"
            out.write_text(text)
            flats.append(out)
            notes.append(said)
        originals = [unanon(d) for d in roslaunch(files, env)]
        flattened = [unanon(d) for d in roslaunch(flats, env)]
    for path, original, mine, said in zip(files, originals, flattened, notes, strict=True):
        counts["files"] += 1
        if "error" in original:
            continue
        counts["accepted"] += 1
        if "error" in mine:
            counts["flat refused"] += 1
            if verbose:
                print(f"flat refused: {path}: {mine['error'][-200:]}")
            continue
        gone = [re.compile(".+".join(map(re.escape, n.split()[1].split("?"))) + "$")
                for n in said]

        def kept(name: str, gone: list[re.Pattern[str]] = gone) -> bool:
            return not any(p.match(name or "") for p in gone)

        theirs = {k: v for k, v in leaves(original["params"]).items() if kept(k)}
        nodes = sorted((n for n in original["nodes"] if kept(n["name"])),
                       key=lambda n: str(n["name"]))
        counts["nodes"] += len(original["nodes"])
        counts["nodes left out"] += len(original["nodes"]) - len(nodes)
        counts["params"] += len(leaves(original["params"]))
        counts["params left out"] += len(leaves(original["params"])) - len(theirs)
        cleared = sorted(original["clear_params"]) == sorted(mine["clear_params"]) or any(
            n.startswith("namespace ") for n in said)
        same = cleared and typed(leaves(mine["params"])) == typed(theirs) and sorted(
            mine["nodes"], key=lambda n: str(n["name"])) == nodes
        counts["agree" if same else "differ"] += 1
        if not same and verbose:
            ours, want = typed(leaves(mine["params"])), typed(theirs)
            diff = {k: (ours.get(k), v) for k, v in want.items() if ours.get(k) != v}
            extra = sorted(set(ours) - set(theirs))
            print(f"differ: {path}: params {dict(list(diff.items())[:3])} extra {extra[:3]}")
    for key, value in counts.items():
        print(f"{key:>16}: {value}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
