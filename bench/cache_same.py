"""The caches never change a result: ``check --format json`` and ``extract`` as a user
runs them, on a copy of a workspace, with and without the cache, compared byte for byte.

    .venv/bin/python bench/cache_same.py WORKSPACE PROJECT [--cpp FILE] [--other FILE]
                                         [--launch FILE] [--keep DIR]

WORKSPACE is copied to a temporary folder (nothing is written into it); PROJECT (a
project file, a folder or a launch file), ``--cpp``, ``--other`` and ``--launch`` are
relative to it. Each step is two fresh processes (check, then extract) with one cache
folder (``XDG_CACHE_HOME``), never the user's:

- ``nocache`` ``--no-cache --jobs 1``, the reference; ``jobs2`` the same with ``--jobs 2``
- ``cold`` an empty cache; ``warm`` nothing changed; ``readback`` nothing changed, the
  kept findings removed first (the kept model read back and checked again, as when the
  findings' entry was dropped or ``extract`` kept the model under other rules)
- ``--cpp``: a comment appended to that C++ file, then ``cpp-nocache`` / ``cpp-cached``;
  then a comment line put before its first line (every call of the file moves: the run
  is made again from the unit, node and build-file caches), ``edit-nocache`` /
  ``edit-cached``
- ``--other``: a comment appended to that launch / YAML / Python file, the same pair
- ``copy-nocache`` / ``copy-cached``: a second copy of the workspace at another path,
  its cached run reading the entries the first copy wrote
- ``--launch``: that launch file of the first copy as the configuration, cached and not

Prints each step's seconds, configurations, links, findings and diagnostics, and each
pair that must be the same with ``same`` or ``DIFFERENT``; exit 1 on any difference.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
CPP = (".c", ".cc", ".cpp", ".cxx", ".h", ".hh", ".hpp", ".hxx")
XML = (".launch", ".xml", ".xacro", ".urdf")


def comment(path: str) -> None:
    """Append a comment in the file's language (C++, XML, else ``#``)."""
    ext = os.path.splitext(path)[1]
    text = ("// touched by cache_same.py" if ext in CPP else
            "<!-- touched by cache_same.py -->" if ext in XML else "# touched by cache_same.py")
    with open(path, "a", encoding="utf-8") as handle:
        handle.write(f"\n{text}\n")


def comment_first(path: str) -> None:
    """Put a C++ comment line before the file's first line."""
    with open(path, encoding="utf-8", errors="surrogateescape") as handle:
        text = handle.read()
    with open(path, "w", encoding="utf-8", errors="surrogateescape") as handle:
        handle.write("// edited by cache_same.py\n" + text)


def step(name: str, folder: str, target: str, cache: str, out: str,
         *options: str) -> dict[str, str]:
    """``check`` then ``extract`` of ``target`` in ``folder``; their outputs' text."""
    env = {**os.environ, "XDG_CACHE_HOME": cache, "PYTHONPATH": ROOT}
    start = time.perf_counter()
    texts: dict[str, str] = {}
    for command, extra in (("check", ["--format", "json", "--fail-on", "never"]),
                           ("extract", ["-q"])):
        path = os.path.join(out, f"{name}-{command}.json")
        subprocess.run([sys.executable, "-m", "haros_arch", command, *extra, "-o", path,
                        target, *options], cwd=folder, env=env, check=False,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        try:
            with open(path, encoding="utf-8") as handle:
                texts[command] = handle.read()
        except OSError:
            texts[command] = ""
    seconds = time.perf_counter() - start
    try:
        model = json.loads(texts["extract"])
        checked = json.loads(texts["check"])
        configs = model.get("configurations", ())
        counts = (f"configurations {len(configs)} links "
                  f"{sum(len(c.get('links', ())) for c in configs)} findings "
                  f"{len(checked['findings'])} diagnostics {len(checked['diagnostics'])}")
    except (ValueError, KeyError):
        counts = "no output"
    print(f"  {name:<14} {seconds:7.1f} s  {counts}", flush=True)
    return texts


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("workspace")
    parser.add_argument("project")
    parser.add_argument("--cpp")
    parser.add_argument("--other")
    parser.add_argument("--launch")
    parser.add_argument("--keep", help="work (and leave the outputs) in this folder")
    args = parser.parse_args()
    base = args.keep or tempfile.mkdtemp(prefix="cache-same-")
    os.makedirs(base, exist_ok=True)
    one, two = os.path.join(base, "one"), os.path.join(base, "two")
    out, cache = os.path.join(base, "out"), os.path.join(base, "cache")
    for folder in (one, two, out, cache):
        shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(out)
    shutil.copytree(args.workspace, one, symlinks=True)
    shutil.copytree(args.workspace, two, symlinks=True)
    print(f"{args.workspace} {args.project} (in {base})")
    runs: dict[str, dict[str, str]] = {}
    runs["nocache"] = step("nocache", one, args.project, cache, out, "--no-cache",
                           "--jobs", "1")
    runs["jobs2"] = step("jobs2", one, args.project, cache, out, "--no-cache", "--jobs", "2")
    for name in ("cold", "warm"):
        runs[name] = step(name, one, args.project, cache, out, "--jobs", "1")
    for entry in os.scandir(os.path.join(cache, "haros-arch", "runs")):
        if "-findings-" in entry.name:
            os.remove(entry.path)
    runs["readback"] = step("readback", one, args.project, cache, out, "--jobs", "1")
    pairs = [("nocache", other) for other in ("jobs2", "cold", "warm", "readback")]
    runs["copy-nocache"] = step("copy-nocache", two, args.project, cache, out,
                                "--no-cache", "--jobs", "1")
    runs["copy-cached"] = step("copy-cached", two, args.project, cache, out, "--jobs", "1")
    pairs.append(("copy-nocache", "copy-cached"))
    if args.launch:
        runs["launch-nocache"] = step("launch-nocache", one, args.launch, cache, out,
                                      "--no-cache", "--jobs", "1")
        runs["launch-cached"] = step("launch-cached", one, args.launch, cache, out,
                                     "--jobs", "1")
        pairs.append(("launch-nocache", "launch-cached"))
    for kind, touched in (("cpp", args.cpp), ("other", args.other)):
        if touched:
            comment(os.path.join(one, touched))
            runs[f"{kind}-nocache"] = step(f"{kind}-nocache", one, args.project, cache, out,
                                           "--no-cache", "--jobs", "1")
            runs[f"{kind}-cached"] = step(f"{kind}-cached", one, args.project, cache, out,
                                          "--jobs", "1")
            pairs.append((f"{kind}-nocache", f"{kind}-cached"))
    if args.cpp:
        comment_first(os.path.join(one, args.cpp))  # the cached run first: after cpp-cached
        runs["edit-cached"] = step("edit-cached", one, args.project, cache, out, "--jobs",
                                   "1")
        runs["edit-nocache"] = step("edit-nocache", one, args.project, cache, out,
                                    "--no-cache", "--jobs", "1")
        pairs.append(("edit-nocache", "edit-cached"))
    different = 0
    for first, second in pairs:
        for command in ("check", "extract"):
            same = runs[first][command] == runs[second][command] and runs[first][command]
            different += not same
            print(f"  {first:>14} vs {second:<14} {command:<8} "
                  f"{'same' if same else 'DIFFERENT'}")
    if not args.keep:
        shutil.rmtree(base, ignore_errors=True)
    return 1 if different else 0


if __name__ == "__main__":
    sys.exit(main())
