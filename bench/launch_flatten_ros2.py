"""ROS 2 part of ``launch_flatten.py`` (``--ros2``): see that script's docstring."""

from __future__ import annotations

import argparse
import json
import os
import re
import shlex
import tempfile
import traceback
from collections import Counter
from typing import Any

from launch_ros2_compare import (
    compare,
    install_tree,
    ros2_launch_files,
    run_real,
    write_standins,
)

from haros_arch.launch import load
from haros_arch.launch.dialect import ros_version
from haros_arch.launch.ros2.flatten import FORMATS, Flat, collect, facts, flatten
from haros_arch.workspace import scan

SUFFIX = {"xml": ".launch.xml", "yaml": ".launch.yaml", "python": ".launch.py"}


def left_out_causes(flat: Flat) -> Counter[str]:
    causes: Counter[str] = Counter()
    for note in flat.notes:
        if note.startswith("parameter ") and "for nodes named" in note:
            causes["parameter file section for a node name, file not kept as a path"] += 1
        elif note.startswith("parameter ") and "cannot be written" in note:
            causes["parameter value the format cannot hold"] += 1
        elif note.startswith("parameter "):
            causes["parameter value not known"] += 1
        elif "runs only" in note:
            causes["node under an undecided condition"] += 1
        elif "no name" in note:
            causes["component with no name (launch_ros's XML / YAML need one)"] += 1
        elif "start at once" in note:
            causes["node started by an event handler (written to start at once)"] += 1
        else:
            causes["node with parts not known"] += 1
    return causes


def difference_causes(want: list[str], got: list[str]) -> Counter[str]:
    """Which field differs, node by node (paired by name, package and executable)."""
    def keyed(lines: list[str]) -> dict[str, dict[str, Any]]:
        out: dict[str, dict[str, Any]] = {}
        for line in lines:
            node = json.loads(line)
            key = f"{node['name']} {node['package']} {node['executable']}"
            while key in out:
                key += "+"
            out[key] = node
        return out

    a, b = keyed(want), keyed(got)
    causes: Counter[str] = Counter()
    for key in set(a) | set(b):
        if key not in b:
            causes["node missing from the flat file"] += 1
        elif key not in a:
            causes["node only in the flat file"] += 1
        else:
            for name in a[key]:
                if a[key][name] != b[key][name]:
                    causes[f"node {name} differ"] += 1
    return causes


def ours(files: list[str], workspace: Any, env: dict[str, str], out: str,
         verbose: bool) -> None:
    counts: Counter[str] = Counter()
    left: Counter[str] = Counter()
    differ: Counter[str] = Counter()
    for index, path in enumerate(files):
        counts["files"] += 1
        try:
            model = load(path, workspace, {}, env)
        except Exception:
            counts["loader or flattener raised"] += 1
            if verbose:
                print(f"raised: {path}\n{traceback.format_exc()[-600:]}")
            continue
        counts["nodes"] += len(model.nodes)
        counts["parameters"] += len(model.params)
        if model.nodes:
            counts["files with nodes"] += 1
        counts["flattened"] += 1
        for fmt in FORMATS:
            flat = collect(model, fmt)
            want = facts(model, flat)
            counts[f"nodes left out ({fmt})"] += len(flat.left_out)
            counts[f"parameters left out ({fmt})"] += len(flat.params_left_out)
            left.update(f"{fmt}: {c}" for c in left_out_causes(flat).elements())
            text, _ = flatten(model, fmt)
            target = os.path.join(out, f"flat{index}{SUFFIX[fmt]}")
            with open(target, "w") as handle:
                handle.write(text)
            again = load(target, workspace, {}, env)
            got = facts(again)
            errors = [d for d in again.diagnostics if d.severity == "error"]
            if errors:
                differ[f"{fmt}: the flat file has errors"] += 1
            if got == want and not errors:
                counts[f"round trip equal ({fmt})"] += 1
                continue
            causes = difference_causes(want, got)
            differ.update(f"{fmt}: {c}" for c in causes)
            if verbose:
                print(f"differ ({fmt}): {path}: {dict(causes)} {errors[:2]}")
    print("our loader, original against flat file")
    for key, value in counts.items():
        print(f"  {key}: {value}")
    print("left out, by cause (each said in a note and a comment)")
    for key, value in sorted(left.items()):
        print(f"  {key}: {value}")
    print("differences, by cause")
    for key, value in sorted(differ.items()) or [("none", 0)]:
        print(f"  {key}: {value}")


def real(files: list[str], src: str, python: str, verbose: bool) -> None:
    """The real launch on each original and on its flat files (install-like tree)."""
    sources = scan(files and sorted({_root(src, f) for f in files}), {})
    prefix = tempfile.mkdtemp(prefix="bench_flat_install_")
    installed = install_tree({n: p.root for n, p in sources.packages.items()}, prefix)
    empty = os.path.join(prefix, "empty")
    os.makedirs(empty)
    env = dict(os.environ, AMENT_PREFIX_PATH=prefix)
    workspace = scan([empty], env)
    packages = {name: os.path.join(prefix, "share", name) for name in sources.packages}
    packages.setdefault("launch", os.path.join(src, "launch", "launch", "share", "launch"))
    extra_path = [os.path.join(src, "navigation2", "nav2_common")]
    counts: Counter[str] = Counter()
    causes: Counter[str] = Counter()
    flats = os.path.join(prefix, "flat")
    os.makedirs(flats)
    with tempfile.TemporaryDirectory() as standins:
        write_standins(standins)
        for index, source in enumerate(files):
            path = installed.get(os.path.realpath(source))
            if path is None:
                continue
            counts["files"] += 1
            original = run_real(python, standins, path, packages, extra_path, {})
            if "error" in original:
                counts["real launch refuses the original"] += 1
                continue
            counts["real launch runs the original"] += 1
            model = load(path, workspace, {}, env)
            for fmt in FORMATS:
                flat = collect(model, fmt)
                theirs = kept_nodes(original["nodes"], model, flat)
                text, _ = flatten(model, fmt)
                target = os.path.join(flats, f"flat{index}{SUFFIX[fmt]}")
                with open(target, "w") as handle:
                    handle.write(text)
                mine = run_real(python, standins, target, packages, extra_path, {})
                if "error" in mine:
                    counts[f"{fmt}: real launch refuses the flat file"] += 1
                    if verbose:
                        print(f"refused ({fmt}): {source}: {mine['error']}")
                    continue
                for node in mine["nodes"]:  # compare() reads our side's args as a shell line
                    node["args"] = shlex.join(node.get("argv", node["args"].split()))
                tally: Counter[str] = Counter()
                notes: list[str] = []
                compare(mine["nodes"], theirs, tally, notes)
                if not notes:
                    counts[f"{fmt}: real launch reads the flat file as the original"] += 1
                    continue
                counts[f"{fmt}: differ"] += 1
                for note in notes:
                    field = re.search(r" (param|package|executable|namespace|container|"
                                      r"args|remaps)\b", note)
                    cause = ("node only in the original" if "only real" in note else
                             "node only in the flat file" if "only ours" in note else
                             f"node {field.group(1) if field else '?'} differs")
                    causes[f"{fmt}: {cause}"] += 1
                if verbose:
                    print(f"differ ({fmt}): {source}")
                    for note in notes[:6]:
                        print(f"  {note}")
    print("real ROS 2 launch, original against flat file")
    for key, value in counts.items():
        print(f"  {key}: {value}")
    print("differences, by cause")
    for key, value in sorted(causes.items()) or [("none", 0)]:
        print(f"  {key}: {value}")


def kept_nodes(nodes: list[dict[str, Any]], model: Any, flat: Flat) -> list[dict[str, Any]]:
    """The real launch's nodes less those the flattener says it leaves out (each matched
    by name, ``?`` for an unknown part or no name, and by package and executable), and
    their parameters less those it leaves out."""
    rest = list(nodes)
    for index in sorted(flat.left_out):
        decl = model.nodes[index]
        pattern = re.compile("(.+|<node_name_unspecified>)".join(
            map(re.escape, decl.name.split("?"))) + "$")
        for node in rest:
            if pattern.match(str(node["name"])) and all(
                    "?" in ours or ours == node[key] for key, ours in (
                        ("package", decl.package), ("executable", decl.executable))):
                rest.remove(node)
                break
    gone = {(model.nodes[i].name, key) for i, key in flat.params_left_out}

    def ours(name: str) -> str:  # an unnamed node is "?" on our side
        return name.replace("<node_name_unspecified>", "?")

    return [{**node, "params": {k: v for k, v in node["params"].items()
                                if (ours(node["name"]), k) not in gone}} for node in rest]


def _root(src: str, path: str) -> str:
    """The folder directly under SRC that holds ``path``."""
    rel = os.path.relpath(os.path.realpath(path), os.path.realpath(src))
    return os.path.join(src, rel.split(os.sep)[0])


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(prog="launch_flatten.py --ros2")
    parser.add_argument("folders", nargs="+")
    parser.add_argument("--real-python", help="python of launch_ros2_compare.py's venv")
    parser.add_argument("--src", help="launch_ros2_compare.py's SRC (FOLDERs under it)")
    parser.add_argument("-v", "--verbose", action="store_true")
    options = parser.parse_args(argv)
    folders = [os.path.abspath(f) for f in options.folders]
    env = dict(os.environ)
    workspace = scan(folders, env)
    files = [f for f in ros2_launch_files(folders) if ros_version(f, workspace) == 2]
    with tempfile.TemporaryDirectory() as out:
        ours(files, workspace, env, out, options.verbose)
    if options.real_python and options.src:
        real(files, os.path.abspath(options.src), options.real_python, options.verbose)
    return 0
