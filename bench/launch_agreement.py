"""Agreement of our ROS 1 launch interpreter with the real roslaunch on a folder.

    .venv/bin/python bench/launch_agreement.py FOLDER [FOLDER ...] [-v]

Every ``*.launch`` (and ``*.xml`` with a ``<launch>`` root) under each FOLDER is loaded
by Debian's roslaunch (``/usr/bin/python3``, through ``launch_roslaunch_dump.py``, which
runs nothing) and by ``haros_arch.launch.load``, with the folder as the workspace and
``ROS_PACKAGE_PATH``. Prints, per folder and in total, the share of roslaunch's node
instances and parameters we reproduce exactly, and each difference (``-v``). Files that
roslaunch refuses are counted apart, with whether we report an error too.
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
from haros_arch.workspace import scan

HERE = Path(__file__).resolve().parent
ORACLE = HERE / "launch_roslaunch_dump.py"


def launch_files(folder: Path) -> list[Path]:
    out = []
    for path in sorted(folder.rglob("*")):
        if path.suffix not in (".launch", ".xml") or not path.is_file():
            continue
        if path.name.endswith((".launch.xml", ".launch.py")) and path.suffix != ".launch":
            continue
        head = path.read_text(errors="replace")[:4000]
        if path.suffix == ".xml" and not re.search(r"<launch[\s>]", head):
            continue
        out.append(path)
    return out


def roslaunch(files: list[Path], folder: Path) -> list[dict[str, Any]]:
    with tempfile.TemporaryDirectory() as tmp:
        env = {"PATH": "/usr/bin:/bin", "HOME": tmp, "ROS_HOME": tmp, "LANG": "C.UTF-8",
               "ROS_PACKAGE_PATH": str(folder)}
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


def compare(folder: Path, verbose: bool) -> tuple[int, int, int, int]:
    files = launch_files(folder)
    env = {"ROS_PACKAGE_PATH": str(folder)}
    workspace = scan([str(folder)], env)
    agree = total = refused = refused_seen = 0
    for path, theirs in zip(files, roslaunch(files, folder), strict=True):
        model = load(str(path), workspace, {}, env)
        rel = path.relative_to(folder)
        if "error" in theirs:
            refused += 1
            errors = [d for d in model.diagnostics if d.severity == "error"]
            refused_seen += bool(errors)
            if verbose:
                first = theirs["error"].splitlines()[-1][:160]
                print(f"  refused {rel}: roslaunch: {first}; ours: "
                      f"{[d.code for d in errors] or 'no error'}")
            continue
        nodes = [n for n in model.nodes if not n.conditions]
        for node in theirs["nodes"]:
            total += 1
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
                agree += 1
            elif verbose:
                diff = {k: (fields.get(k), v) for k, v in wanted.items() if fields.get(k) != v}
                print(f"  node {node['name']} in {rel}: ours/theirs {diff}")
        mine = leaf_parameters(model)
        expected: dict[str, Any] = {}
        for key, value in theirs["params"].items():
            flat(key, value, expected)
        for key, value in expected.items():
            total += 1
            if key in mine and same_value(mine[key], value):
                agree += 1
            elif verbose:
                print(f"  param {key} in {rel}: ours {mine.get(key, '<missing>')!r} "
                      f"theirs {value!r}")
        if verbose:
            for key in sorted(set(mine) - set(expected)):
                print(f"  extra param {key} in {rel}")
            for n in nodes:
                print(f"  extra node {n.name} in {rel}")
    return agree, total, refused, refused_seen


def main(argv: list[str]) -> int:
    verbose = "-v" in argv
    folders = [Path(a).resolve() for a in argv if a != "-v"]
    grand = [0, 0, 0, 0]
    for folder in folders:
        agree, total, refused, seen = compare(folder, verbose)
        grand = [a + b for a, b in zip(grand, (agree, total, refused, seen), strict=True)]
        share = agree / total if total else 1.0
        print(f"{folder.name}: {agree}/{total} node instances and parameters agree "
              f"({share:.1%}); roslaunch refused {refused} file(s), we report an error "
              f"for {seen} of them")
    agree, total, refused, seen = grand
    print(f"total: {agree}/{total} agree ({(agree / total if total else 1.0):.1%}); "
          f"refused by roslaunch: {refused}, of which we flag {seen}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
