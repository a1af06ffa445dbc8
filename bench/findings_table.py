"""Every warning and error finding of ``check`` on real workspaces, with verdicts.

    .venv/bin/python bench/findings_table.py [--root DIR] [--out FILE.json] [PROJECT ...]
    .venv/bin/python bench/findings_table.py --table FILE.json [--verdicts FILE.yaml]

The first form runs ``haros-arch check --format json`` (one job, a time limit) on each
project file (default: ``bench/findings_projects/*.yaml``, which name fetched
workspaces under /work/ws) with the haros_arch of ``--root`` (default: this checkout;
give another checkout to measure before a change), prints the count of findings per
severity and per rule, and writes the warnings and errors to ``--out``. The second
form prints them as a markdown table joined with ``--verdicts`` (default:
``bench/findings_verdicts.yaml``: for each project, rule and message, ``verdict`` true or
``false`` and why, written by reading the source each finding points at) and the share
of true ones.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
from collections import Counter
from pathlib import Path
from typing import Any

import yaml

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent


def run_check(project: Path, root: Path, seconds: int) -> dict[str, Any] | None:
    env = {**os.environ, "PYTHONPATH": str(root), "COLUMNS": "200"}
    result = subprocess.run(
        [sys.executable, "-m", "haros_arch.cli", "check", str(project), "--format", "json",
         "--fail-on", "never", "--jobs", "1"], capture_output=True, text=True, env=env,
        timeout=seconds, check=False, cwd=root)
    if result.returncode != 0:
        print(f"{project.stem}: check failed: {result.stderr.strip()[-600:]}", flush=True)
        return None
    data: dict[str, Any] = json.loads(result.stdout)
    return data


def measure(args: argparse.Namespace) -> None:
    projects = [Path(p).resolve() for p in args.projects] or sorted(
        (HERE / "findings_projects").glob("*.yaml"))
    kept: list[dict[str, Any]] = []
    totals: Counter[str] = Counter()
    for project in projects:
        data = run_check(project, Path(args.root).resolve(), args.seconds)
        if data is None:
            continue
        findings = data["findings"]
        counts = Counter(f["severity"] for f in findings)
        totals.update(counts)
        rules = Counter(f["rule"] for f in findings if f["severity"] != "info")
        print(f"{project.stem}: {counts['error']} error(s), {counts['warning']} "
              f"warning(s), {counts['info']} info(s); "
              + ", ".join(f"{rule} {n}" for rule, n in sorted(rules.items())), flush=True)
        for finding in findings:
            if finding["severity"] in ("error", "warning"):
                kept.append({"project": project.stem, **finding})
    print(f"total: {totals['error']} error(s), {totals['warning']} warning(s), "
          f"{totals['info']} info(s)")
    if args.out:
        Path(args.out).write_text(json.dumps(kept, indent=1) + "\n", "utf-8")


def _where(finding: dict[str, Any]) -> str:
    where = finding.get("location") or {}
    return f"{where.get('file')}:{where.get('line')}" if where.get("file") else "-"


def table(args: argparse.Namespace) -> None:
    findings = json.loads(Path(args.table).read_text("utf-8"))
    verdicts = yaml.safe_load(Path(args.verdicts).read_text("utf-8")) \
        if Path(args.verdicts).is_file() else []
    lookup = {(v["project"], v["rule"], v["message"]): v for v in verdicts or ()}
    print("| project | rule | configurations | finding | where | true? | why |")
    print("|---|---|---|---|---|---|---|")
    judged = true = 0
    for f in findings:
        v = lookup.get((f["project"], f["rule"], f["message"]))
        verdict = "?" if v is None else "true" if v["verdict"] else "false"
        judged += v is not None
        true += bool(v and v["verdict"])
        configs = ", ".join(f.get("configurations") or [f.get("configuration") or ""])
        message = f["message"].replace("|", "\\|")
        why = (v or {}).get("why", "").replace("|", "\\|")
        print(f"| {f['project']} | {f['rule']} | {configs} | {message} | {_where(f)} | "
              f"{verdict} | {why} |")
    share = f"{100 * true / judged:.0f}%" if judged else "-"
    print(f"\n{len(findings)} warning and error finding(s), {judged} checked against the "
          f"sources, {true} true ({share})")


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("projects", nargs="*")
    parser.add_argument("--root", default=str(ROOT), help="the haros_arch checkout to run")
    parser.add_argument("--out", help="write the warnings and errors here (JSON)")
    parser.add_argument("--seconds", type=int, default=1800)
    parser.add_argument("--table", help="print this JSON (from --out) as a markdown table")
    parser.add_argument("--verdicts", default=str(HERE / "findings_verdicts.yaml"))
    args = parser.parse_args()
    if args.table:
        table(args)
    else:
        measure(args)


if __name__ == "__main__":
    main()
