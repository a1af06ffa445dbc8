"""README's "Use in CI" snippets and the pre-commit hook file: each is valid YAML of its
tool's shape, and every haros-arch command in them runs on the bundled example and
writes what the next step reads (SARIF, JUnit)."""

from __future__ import annotations

import json
import os
import re
import shlex
import shutil
import subprocess
from pathlib import Path

import pytest
import yaml
from conftest import ROOT
from lxml import etree

from haros_arch.cli import main


def snippets() -> dict[str, dict]:
    text = (ROOT / "README.md").read_text()
    section = text.split("## Use in CI", 1)[1].split("\n## ", 1)[0]
    found = {}
    for block in re.findall(r"```yaml\n(.*?)```", section, re.S):
        first = block.splitlines()[0].lstrip("# ").strip()
        found[first] = yaml.safe_load(block)
    return found


def commands(value) -> list[str]:
    """Every 'haros-arch ...' string anywhere in a parsed snippet."""
    if isinstance(value, dict):  # a hook's or a job's name is not a command
        return [c for k, v in value.items() if k != "name" for c in commands(v)]
    if isinstance(value, list):
        return [c for v in value for c in commands(v)]
    if isinstance(value, str) and value.startswith("haros-arch "):
        return [value]
    return []


def test_the_three_snippets_have_their_tools_shape() -> None:
    found = snippets()
    assert set(found) == {".github/workflows/architecture.yml", ".gitlab-ci.yml",
                          ".pre-commit-config.yaml", ".github/workflows/architecture-diff.yml"}
    pull = found[".github/workflows/architecture-diff.yml"]["jobs"]["haros-arch-diff"]
    assert pull["permissions"]["pull-requests"] == "write"
    assert pull["steps"][0]["with"]["fetch-depth"] == 0
    posted = next(s["run"] for s in pull["steps"] if "gh pr comment" in s.get("run", ""))
    assert any(s.get("run", "").endswith(f"-o {posted.split()[-1]} --fail-on never")
               for s in pull["steps"])
    workflow = found[".github/workflows/architecture.yml"]
    steps = workflow["jobs"]["haros-arch"]["steps"]
    upload = next(s for s in steps if str(s.get("uses", "")).startswith(
        "github/codeql-action/upload-sarif"))
    assert workflow["jobs"]["haros-arch"]["permissions"]["security-events"] == "write"
    assert any(upload["with"]["sarif_file"] in s.get("run", "") for s in steps)
    gitlab = found[".gitlab-ci.yml"]["haros-arch"]
    assert gitlab["artifacts"]["reports"]["junit"] in " ".join(gitlab["script"])
    hook = found[".pre-commit-config.yaml"]["repos"][0]["hooks"][0]
    assert hook["id"] == "haros-arch-check" and hook["pass_filenames"] is False
    re.compile(hook["files"])
    published = yaml.safe_load((ROOT / ".pre-commit-hooks.yaml").read_text())
    assert published[0]["id"] == hook["id"]
    assert published[0]["entry"].split() == ["haros-arch", "check"]
    re.compile(published[0]["files"])
    assert re.search(published[0]["files"], "src/robot/launch/robot.launch.py")


@pytest.mark.parametrize("command", sorted({c for s in snippets().values()
                                            for c in commands(s)}))
def test_each_command_runs_on_the_example(command: str, tmp_path: Path,
                                          monkeypatch: pytest.MonkeyPatch) -> None:
    shutil.copytree(ROOT / "examples", tmp_path / "repo")
    argv = shlex.split(command)[1:]
    if argv[0] == "diff":  # a pull request: the base branch, then a commit dropping a remap
        _pull_request(tmp_path / "repo")
        monkeypatch.setenv("GITHUB_BASE_REF", "main")
        argv = [os.path.expandvars(a) for a in argv]
    here = os.getcwd()
    os.chdir(tmp_path / "repo")
    try:
        code = main([*argv, "--no-cache"])
    finally:
        os.chdir(here)
    # the example has planted errors: --fail-on error fails, --fail-on never does not
    assert code == (0 if "never" in argv else 1)
    if "-o" in argv:
        written = tmp_path / "repo" / argv[argv.index("-o") + 1]
        if "sarif" in argv:
            assert json.loads(written.read_text())["runs"][0]["results"]
        if "markdown" in argv:
            assert written.read_text().startswith("### haros-arch: architecture diff")
        if "junit" in argv:
            assert etree.parse(str(written)).getroot().tag in ("testsuites", "testsuite")


def _pull_request(root: Path) -> None:
    def git(*args: str) -> None:
        subprocess.run(["git", "-C", str(root), "-c", "user.name=t", "-c", "user.email=t@t",
                        *args], check=True, capture_output=True)

    git("init", "-q")
    git("add", "-A")
    git("commit", "-qm", "base")
    git("update-ref", "refs/remotes/origin/main", "HEAD")
    launch = root / "src/demo_robot/launch/robot.launch"
    launch.write_text(launch.read_text().replace('<remap from="scan" to="base_scan" />', ""))
    git("commit", "-qam", "drop a remap")
