"""Recall of ``haros-arch check`` on real architecture bugs from the ROBUST dataset.

    .venv/bin/python bench/robust_bugs.py [--data FILE] [--mirrors DIR] [--keep DIR]
                                          [--only ID ...] [--folders] [-v]

``robust_bugs.yaml`` beside this script lists the bugs of ROBUST (github:robust-rosin/robust,
one ``.bug`` file per bug) whose fault is in the architecture (a name, remap, namespace,
parameter or queue size), each with the repository and fix commit the ``.bug`` file names,
whether a static tool could see it at all (and why not), and for those it could: the
launch files the bug is about, and the finding that would point at it (rule ids, the file
it is reported in, a text of its message or entities).

For each bug in scope, both trees are written into a temporary folder (``--keep DIR``
keeps them, ``DIR/<system>-<id>/{buggy,fixed}``): the fix commit's parent (buggy) and the
fix commit (fixed; its launch files are ``fixed_launch`` and its launch arguments
``fixed_args`` when the fix renamed them), under ``src/<repository>`` (the workspace is
``src``, or ``src/<repository>/<workspace>`` when the bug gives the repository's own
workspace folder, e.g. ``workspace/src`` beside other packages' copies), with the
repositories the launch files need from the same organisation (``deps``) at their last
commit before the fix's date (or the commit given). A project file that launches the
bug's launch files is written beside, and ``python -m haros_arch check project.yaml
--format json`` runs on each (one process each, ``--jobs 1``). Per bug it prints:

- ``found``: a finding of the expected rules whose location and text point at the bug,
  and ``gone after fix`` when the fixed tree no longer has it (else ``stays after fix``);
- ``undecided``: only the rule's ``-undecided`` info points at it (the tool says it
  cannot decide; the reason is in that info's message). That info names its first case
  only: a bug's ``expect.unseen`` query (``haros-arch query``) tells whether the bug's
  case is among the others (no finding, a node of unknown interface in the way); a
  ROS 2 launch configuration used where an action not seen may have declared it (the
  info ``LAUNCH_UNKNOWN_VALUE``, "is not seen declared (undecided: ...)") is the
  undecided form of ``LAUNCH_ARG_UNSET``;
- ``missed``: neither (also a bug in code no launch file starts: ``not_launched``);
- ``skipped``: a mirror or a commit is not on disk (fetch github:owner/name first);
- ``setup error``: check reports the project file itself (a launch file it names is
  not there): the data file is wrong, not the tool;
- ``tool error``: check stopped without its JSON (an internal error), with its last line.

``--data real_bugs.yaml`` (a file beside this script, or a path) reads another list of the
same format: ``real_bugs.yaml`` holds bugs we found ourselves in the history of public
repositories (fix commits whose diff changes a name, remap, namespace or parameter between
code and launch files), each with its ``source``.

``--folders`` gives the project one workspace folder per repository (``workspace:
[src/<repository>, src/<dep>, ...]``, as a user with separate checkouts writes it) instead
of ``src``: a bug with ``deps`` is then found across several folders, and the verdicts
should be the same.

Recall is found / (bugs in scope that ran). Mirrors are the bare repositories the
``fetch`` tool brings (``DIR/owner+name/repo``). Nothing goes to the network.
"""

from __future__ import annotations

import argparse
import json
import re
import subprocess
import sys
import tarfile
import tempfile
import time
from io import BytesIO
from pathlib import Path
from typing import Any

import yaml

HERE = Path(__file__).resolve().parent
UNDECIDED = "-undecided"  # suffix of a rule's info on the matches it cannot decide
DATA = HERE / "robust_bugs.yaml"


def git_dir(mirrors: Path, repo: str) -> Path | None:
    """The bare git directory of ``owner/name`` under the mirrors, or None."""
    base = mirrors / repo.replace("/", "+") / "repo"
    for candidate in (base / ".git", base):
        if (candidate / "HEAD").is_file():
            return candidate
    return None


def git(gitdir: Path, *args: str) -> str | None:
    done = subprocess.run(["git", f"--git-dir={gitdir}", *args], capture_output=True,
                          text=True, check=False)
    return done.stdout.strip() if done.returncode == 0 else None


def _inside(member: tarfile.TarInfo, dest: str) -> tarfile.TarInfo | None:
    """tarfile's ``data`` filter, leaving out (not failing on) what it refuses: a link
    to an absolute path or out of the tree (ros_kortex's CMakeLists.txt, catkin's
    workspace link to /opt/ros/.../toplevel.cmake), as a blob the mirror lacks is."""
    try:
        return tarfile.data_filter(member, dest)
    except tarfile.FilterError:
        return None


def materialize(gitdir: Path, rev: str, dest: Path) -> None:
    """``rev``'s tree under ``dest``; blobs a mirror lacks are left out."""
    dest.mkdir(parents=True, exist_ok=True)
    done = subprocess.run(["git", f"--git-dir={gitdir}", "archive", rev], capture_output=True,
                          check=False)
    if done.returncode == 0:
        with tarfile.open(fileobj=BytesIO(done.stdout)) as archive:
            if hasattr(tarfile, "data_filter"):  # Python 3.10.12+, 3.11.4+
                archive.extractall(dest, filter=_inside)
            else:
                archive.extractall(dest)  # a tree of our own mirror
        return
    sys.path.insert(0, str(HERE))
    from diff_real import _copy_tree  # the same blob-by-blob copy the diff bench uses

    _copy_tree(str(gitdir), rev, str(dest))


def prepare(bug: dict[str, Any], mirrors: Path, root: Path, folders: bool = False
            ) -> str | dict[str, Path]:
    """Both trees and project files of one bug, or why it is skipped; ``folders``: one
    workspace folder per repository."""
    main = git_dir(mirrors, bug["repo"])
    if main is None:
        return f"no mirror of {bug['repo']}"
    fix = git(main, "rev-parse", "--verify", "-q", bug["fix"] + "^{commit}")
    parent = git(main, "rev-parse", "--verify", "-q", bug["fix"] + "^")
    if fix is None or parent is None:
        return f"commit {bug['fix'][:10]} or its parent not in the mirror of {bug['repo']}"
    date = git(main, "show", "-s", "--format=%cI", fix)
    deps: list[tuple[Path, str, str]] = []
    for dep in bug.get("deps", []):
        name, _, pinned = dep.partition("@")
        gitdir = git_dir(mirrors, name)
        if gitdir is None:
            return f"no mirror of {name}"
        rev = pinned or git(gitdir, "rev-list", "-1", f"--before={date}", "--all")
        if not rev:
            return f"no commit of {name} before {date}"
        deps.append((gitdir, rev, name.split("/")[1]))
    trees = {}
    for side, rev in (("buggy", parent), ("fixed", fix)):
        folder = root / side
        materialize(main, rev, folder / "src" / bug["repo"].split("/")[1])
        for gitdir, dep_rev, name in deps:
            materialize(gitdir, dep_rev, folder / "src" / name)
        launch = bug.get("fixed_launch", bug["launch"]) if side == "fixed" else bug["launch"]
        args = bug.get("args", {})
        if side == "fixed":
            args = bug.get("fixed_args", args)
        workspace: str | list[str] = "src" if not folders else [
            f"src/{bug['repo'].split('/')[1]}", *(f"src/{name}" for _, _, name in deps)]
        if bug.get("workspace"):  # the repository's own workspace folder, alone
            workspace = f"src/{bug['repo'].split('/')[1]}/{bug['workspace']}"
        project = {"project": f"{bug['id'].replace('/', '-')}-{side}", "workspace": workspace,
                   "configurations": {"bug": {"launch": launch, "args": args}}}
        if bug.get("environment"):
            project["environment"] = bug["environment"]
        (folder / "project.yaml").write_text(yaml.safe_dump(project, sort_keys=False))
        trees[side] = folder / "project.yaml"
    return trees


class CheckFailed(Exception):
    """check stopped without its JSON (an internal error): the bug's line says why."""


def check(project: Path) -> list[dict[str, Any]]:
    """The findings of ``check`` on ``project``, then its warning and error diagnostics
    (each with its ``code``, no ``rule``)."""
    done = subprocess.run([sys.executable, "-m", "haros_arch", "check", str(project),
                           "--format", "json", "--jobs", "1"],
                          capture_output=True, text=True, cwd=project.parent, check=False)
    try:
        report = json.loads(done.stdout)
        diagnostics = report.get("diagnostics", [])
        return [*report["findings"], *(d for d in diagnostics
                                       if d.get("severity") in ("warning", "error")),
                # a ROS 2 launch configuration used where an action not seen may have
                # declared it: LAUNCH_ARG_UNSET's undecided form, an info
                *({**d, "code": "LAUNCH_ARG_UNSET" + UNDECIDED} for d in diagnostics
                  if d.get("code") == "LAUNCH_UNKNOWN_VALUE"
                  and "is not seen declared (undecided" in d.get("message", ""))]
    except (ValueError, KeyError):
        last = (done.stderr.strip().splitlines() or ["no output"])[-1]
        raise CheckFailed(f"{project.parent.name}: {last[:300]}") from None


def pointing(findings: list[dict[str, Any]], expect: dict[str, Any], suffix: str = ""
             ) -> list[dict[str, Any]]:
    """The findings of the expected rules (``rule + suffix``) that point at the bug; an
    expected rule in capitals is a diagnostic's code (a warning the launch or graph
    stage gives: ``LAUNCH_PARAMS_NO_NODE``)."""
    rules = {rule + suffix for rule in expect["rules"]}
    out = []
    for finding in findings:
        if finding.get("rule", finding.get("code")) not in rules:
            continue
        # ``also``: a finding's other places, a diagnostic's said once (an unset
        # argument's other uses), each a location
        files = [finding.get("location") or {}, *finding.get("also", [])]
        wanted = expect.get("file") or []
        wanted = [wanted] if isinstance(wanted, str) else wanted
        if wanted and not any(str(f.get("file", "")).endswith(tuple(wanted)) for f in files):
            continue
        text = finding["message"] + " " + " ".join(finding.get("entities", []))
        if all(word in text for word in expect.get("text", [])):
            out.append(finding)
    return out


def setup_error(findings: list[dict[str, Any]]) -> str | None:
    """What check says is wrong with the project file itself (a launch file not found)."""
    for finding in findings:
        if str((finding.get("location") or {}).get("file", "")).endswith("project.yaml"):
            return finding["message"]
    return None


def verdict(bug: dict[str, Any], trees: dict[str, Path], verbose: bool) -> str:
    buggy = check(trees["buggy"])
    fixed = check(trees["fixed"])
    wrong = setup_error(buggy) or setup_error(fixed)
    if wrong:
        return f"setup error ({wrong})"
    found = pointing(buggy, bug["expect"])
    if verbose:
        for finding in found or pointing(buggy, bug["expect"], UNDECIDED):
            print(f"    {finding.get('rule', finding.get('code'))}: {finding['message'][:300]}")
    if found:
        after = "gone after fix" if not pointing(fixed, bug["expect"]) else "stays after fix"
        return f"found, {after}"
    if pointing(buggy, bug["expect"], UNDECIDED):
        return "undecided"
    unseen = bug["expect"].get("unseen")
    if unseen and any(pointing(buggy, {**bug["expect"], "file": [], "text": []},
                               UNDECIDED)) and matches(trees["buggy"], unseen):
        # the rule's undecided info names its first case only: the query says whether
        # this one is among them (no finding, a node of unknown interface in the way)
        return "undecided"
    return "missed"


def matches(project: Path, text: str) -> bool:
    """Whether ``haros-arch query`` finds anything for ``text`` on the project."""
    done = subprocess.run([sys.executable, "-m", "haros_arch", "query", str(project), text],
                          capture_output=True, text=True, cwd=project.parent, check=False)
    counted = re.search(r"^(\d+) match\(es\)\s*\Z", done.stdout, re.MULTILINE)
    return done.returncode == 0 and counted is not None and int(counted.group(1)) > 0


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--data", default=str(DATA),
                        help="the list of bugs (a file beside this script or a path)")
    parser.add_argument("--mirrors", default="/work/.mirror", type=Path)
    parser.add_argument("--keep", type=Path, help="write the trees here and keep them")
    parser.add_argument("--only", nargs="*", default=[], help="bug ids (system/id or id)")
    parser.add_argument("--folders", action="store_true",
                        help="one workspace folder per repository, not one src folder")
    parser.add_argument("-v", "--verbose", action="store_true")
    args = parser.parse_args(argv)
    data = Path(args.data)
    if not data.is_file() and (HERE / data).is_file():
        data = HERE / data
    bugs = yaml.safe_load(data.read_text())["bugs"]
    counts: dict[str, int] = {}
    with tempfile.TemporaryDirectory(prefix="robust-") as scratch:
        base = args.keep or Path(scratch)
        for bug in bugs:
            if args.only and not {bug["id"], bug["id"].split("/")[1]} & set(args.only):
                continue
            if not bug.get("in_scope"):
                print(f"{bug['id']:24} out of scope: {bug['why']}")
                counts["out of scope"] = counts.get("out of scope", 0) + 1
                continue
            start = time.monotonic()
            if bug.get("not_launched"):
                print(f"{bug['id']:24} missed (no configuration has it: {bug['not_launched']})")
                counts["missed"] = counts.get("missed", 0) + 1
                continue
            trees = prepare(bug, args.mirrors, base / bug["id"].replace("/", "-"),
                            args.folders)
            if isinstance(trees, str):
                result = f"skipped ({trees})"
            else:
                try:
                    result = verdict(bug, trees, args.verbose)
                except CheckFailed as failed:
                    result = f"tool error ({failed})"
            key = result.split(" (")[0].split(",")[0]
            counts[key] = counts.get(key, 0) + 1
            print(f"{bug['id']:24} {result}  [{time.monotonic() - start:.0f} s]", flush=True)
    ran = sum(n for k, n in counts.items() if k in ("found", "undecided", "missed"))
    print("totals: " + ", ".join(f"{k} {n}" for k, n in sorted(counts.items())))
    if ran:
        print(f"recall: {counts.get('found', 0)}/{ran} = {counts.get('found', 0) / ran:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
