"""Every launch file of a workspace loaded, as `haros-arch` does without a project file
(each file with its arguments at their defaults, to find the configurations): the CPU
seconds of the loads and a digest of every launch model, to compare two checkouts.

    PYTHONPATH=CHECKOUT .venv/bin/python bench/launch_load.py WORKSPACE [--models FILE]

The haros_arch measured is the one Python imports (PYTHONPATH; first line). The models
are made with a fixed environment (PATH and HOME only), so that two checkouts' digests
can be compared: `--models FILE` writes one line per launch file (its path in the
workspace, its CPU seconds, the digest of its whole model); `cut -d' ' -f1,3` of two such
files must be the same. Time two checkouts as whole processes in turn (A B A B ...,
`/usr/bin/time -v` or any paired timer) for the ratio.
"""

from __future__ import annotations

import argparse
import dataclasses
import hashlib
import os
import sys
import time

import checkout  # bench/checkout.py: says which haros_arch is measured

from haros_arch.autoproject import find_launch_files
from haros_arch.launch import load
from haros_arch.workspace import scan

ENVIRONMENT = {"PATH": "/usr/bin:/bin", "HOME": "/root"}


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("workspace")
    parser.add_argument("--models", default=None)
    args = parser.parse_args(argv)
    checkout.announce(sys.stdout)
    workspace = scan([args.workspace], dict(ENVIRONMENT))
    lines: list[str] = []
    total = 0.0
    files = find_launch_files(workspace)
    whole = hashlib.sha1()
    for path in files:
        start = time.process_time()
        try:
            model = load(path, workspace, {}, dict(ENVIRONMENT))
        except RecursionError:
            continue
        spent = time.process_time() - start
        total += spent
        digest = hashlib.sha1(repr(dataclasses.asdict(model)).encode()).hexdigest()[:16]
        whole.update(digest.encode())
        lines.append(f"{os.path.relpath(path, args.workspace)} {spent:.3f} {digest}")
    print(f"{len(files)} launch files, {len(workspace.packages)} packages: "
          f"{total:.2f} s CPU loading them; models digest {whole.hexdigest()[:16]}")
    if args.models is not None:
        with open(args.models, "w", encoding="utf-8") as out:
            out.write("".join(f"{line}\n" for line in lines))


if __name__ == "__main__":
    main()
