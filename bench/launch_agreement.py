"""Agreement of our ROS 1 launch interpreter with the real roslaunch on folders.

    .venv/bin/python bench/launch_agreement.py FOLDER [FOLDER ...] [-v] [--env NAME=VALUE ...]

Every ``*.launch``, ``*.launch.xml``, ``*.test`` (and other ``*.xml`` with a ``<launch>``
root) under each FOLDER is loaded by Debian's roslaunch (``/usr/bin/python3``, through
``launch_roslaunch_dump.py``, which runs nothing) and by ``haros_arch.launch.load``, with
the folder as the workspace and every FOLDER given on ``ROS_PACKAGE_PATH`` (so one
repository's launch files find the packages of another, as in a real workspace). The
FOLDERs should be ROS 1 repositories: a ``*.launch.xml`` there is handed to roslaunch,
and to ours as it decides. Prints, per folder and in total, the share of roslaunch's node
instances (all fields: name, namespace, package, type, args, remaps, machine, respawn,
required, test) and of its parameters (name, value and type) we reproduce exactly, and
each difference (``-v``). ``--env`` sets a variable for both sides (a robot's env-hook
defaults, e.g. ``TURTLEBOT_BASE=kobuki``). Files that roslaunch refuses are counted
apart, with whether we report an error too.
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

from haros_arch.launch import load
from haros_arch.launch.ros1.dump import leaf_parameters
from haros_arch.workspace import Workspace, scan

HERE = Path(__file__).resolve().parent
ORACLE = HERE / "launch_roslaunch_dump.py"


def launch_files(folder: Path) -> list[Path]:
    out = []
    for path in sorted(folder.rglob("*")):
        if path.suffix not in (".launch", ".xml", ".test") or not path.is_file():
            continue
        head = path.read_text(errors="replace")[:4000]
        if path.suffix != ".launch" and not re.search(r"<launch[\s>]", head):
            continue
        out.append(path)
    return out


def environment(package_path: str, home: str, extra: dict[str, str]) -> dict[str, str]:
    """The environment both sides see."""
    return {"PATH": "/usr/bin:/bin", "HOME": home, "ROS_HOME": home, "LANG": "C.UTF-8",
            **extra, "ROS_PACKAGE_PATH": package_path}


def roslaunch(files: list[Path], env: dict[str, str]) -> list[dict[str, Any]]:
    done = subprocess.run(
        ["/usr/bin/python3", str(ORACLE), json.dumps([[str(f), []] for f in files])],
        capture_output=True, text=True, env=env, timeout=600, check=False)
    if done.returncode != 0:
        raise SystemExit(f"roslaunch oracle failed: {done.stderr[-2000:]}")
    result: list[dict[str, Any]] = json.loads(done.stdout)
    return result


def pattern(name: str) -> re.Pattern[str]:
    return re.compile("^" + ".+".join(re.escape(p) for p in name.split("?")) + "$")


def flat(name: str, value: Any, out: dict[str, Any]) -> None:
    if isinstance(value, dict) and not set(value) <= {"command", "binary"}:
        for key, item in value.items():
            flat(f"{name}/{key}", item, out)
    else:
        out[name] = value


def same_value(ours: Any, theirs: Any) -> bool:
    if isinstance(theirs, dict) and "command" in theirs:
        return ours is None
    if isinstance(theirs, dict) and "binary" in theirs:
        return ours == theirs["binary"]
    return ours == theirs and type(ours) is type(theirs)


def compare(folder: Path, package_path: str, extra: dict[str, str],
            verbose: bool) -> list[int]:
    """[nodes agreeing, nodes, parameters agreeing, parameters, refused, refused seen]"""
    files = launch_files(folder)
    with tempfile.TemporaryDirectory() as home:
        env = environment(package_path, home, extra)
        workspace = scan([str(folder)], env)
        return _compare(folder, files, roslaunch(files, env), workspace, env, verbose)


def _compare(folder: Path, files: list[Path], results: list[dict[str, Any]],
             workspace: Workspace, env: dict[str, str], verbose: bool) -> list[int]:
    counts = [0] * 6
    for path, theirs in zip(files, results, strict=True):
        model = load(str(path), workspace, {}, env)
        rel = path.relative_to(folder)
        if "error" in theirs:
            counts[4] += 1
            errors = [d for d in model.diagnostics if d.severity == "error"]
            counts[5] += bool(errors)
            if verbose:
                first = theirs["error"].splitlines()[-1][:160]
                print(f"  refused {rel}: roslaunch: {first}; ours: "
                      f"{[d.code for d in errors] or 'no error'}")
            continue
        nodes = [n for n in model.nodes if not n.conditions]
        for node in theirs["nodes"]:
            counts[1] += 1
            match = [n for n in nodes if pattern(n.name).match(node["name"] or "")]
            fields = {}
            if match:
                n = match[0]
                fields = {"namespace": n.namespace, "package": n.package,
                          "type": n.executable, "args": n.args,
                          "remaps": [list(r) for r in n.remaps], "machine": n.machine,
                          "respawn": n.respawn, "required": n.required, "test": n.is_test}
                nodes.remove(n)
            wanted = {k: v for k, v in node.items() if k != "name"}
            if fields == wanted:
                counts[0] += 1
            elif verbose:
                diff = {k: (fields.get(k), v) for k, v in wanted.items() if fields.get(k) != v}
                print(f"  node {node['name']} in {rel}: ours/theirs {diff}")
        mine = leaf_parameters(model)
        patterns = {pattern(k): k for k in mine if "?" in k}  # anonymous names
        expected: dict[str, Any] = {}
        for key, value in theirs["params"].items():
            flat(key, value, expected)
        for key, value in expected.items():
            counts[3] += 1
            ours = key if key in mine else next(
                (k for p, k in patterns.items() if p.match(key)), None)
            if ours is not None and same_value(mine[ours], value):
                counts[2] += 1
                mine.pop(ours)
            elif verbose:
                print(f"  param {key} in {rel}: ours "
                      f"{mine.get(ours, '<missing>') if ours else '<missing>'!r} "
                      f"theirs {value!r}")
        if verbose:
            for key in sorted(set(mine) - set(expected)):
                print(f"  extra param {key} in {rel}")
            for n in nodes:
                print(f"  extra node {n.name} in {rel}")
    return counts


def share(agree: int, total: int) -> str:
    return f"{agree}/{total} ({agree / total if total else 1.0:.1%})"


def main(argv: list[str]) -> int:
    verbose = "-v" in argv
    extra = dict(argv[i + 1].split("=", 1) for i, a in enumerate(argv[:-1]) if a == "--env")
    values = {argv[i + 1] for i, a in enumerate(argv[:-1]) if a == "--env"}
    folders = [Path(a).resolve() for a in argv if a not in ("-v", "--env") and a not in values]
    package_path = ":".join(str(f) for f in folders)
    grand = [0] * 6
    for folder in folders:
        counts = compare(folder, package_path, extra, verbose)
        grand = [a + b for a, b in zip(grand, counts, strict=True)]
        print(f"{folder.name}: nodes {share(*counts[0:2])}, parameters "
              f"{share(*counts[2:4])}, all {share(counts[0] + counts[2], counts[1] + counts[3])}"
              f"; roslaunch refused {counts[4]} file(s), we report an error for "
              f"{counts[5]} of them")
    print(f"total: nodes {share(*grand[0:2])}, parameters {share(*grand[2:4])}, all "
          f"{share(grand[0] + grand[2], grand[1] + grand[3])}; refused by roslaunch: "
          f"{grand[4]}, of which we flag {grand[5]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
