"""bench/robust_bugs.py writes a bug's trees from a mirror with ``git archive``."""

from __future__ import annotations

import importlib.util
import json
import subprocess
import tarfile
from pathlib import Path

import pytest
import yaml
from conftest import ROOT


def _script():
    spec = importlib.util.spec_from_file_location("robust_bugs_script",
                                                  ROOT / "bench" / "robust_bugs.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.mark.skipif(not hasattr(tarfile, "data_filter"), reason="no tarfile filters")
def test_a_link_to_an_absolute_path_is_left_out_not_fatal(tmp_path: Path) -> None:
    # ros_kortex's tree holds catkin's workspace CMakeLists.txt, a link to
    # /opt/ros/<distro>/share/catkin/cmake/toplevel.cmake: tarfile's data filter refuses
    # it, which stopped the whole run with a traceback
    repo = tmp_path / "repo"
    (repo / "pkg" / "launch").mkdir(parents=True)
    (repo / "pkg" / "launch" / "a.launch").write_text("<launch/>\n")
    (repo / "CMakeLists.txt").symlink_to("/opt/ros/noetic/share/catkin/cmake/toplevel.cmake")
    (repo / "pkg" / "near").symlink_to("launch/a.launch")
    for args in (["init", "-q"], ["add", "-A"],
                 ["-c", "user.name=t", "-c", "user.email=t@t", "commit", "-qm", "one"]):
        subprocess.run(["git", "-C", str(repo), *args], check=True)
    dest = tmp_path / "out"
    _script().materialize(repo / ".git", "HEAD", dest)
    assert (dest / "pkg" / "launch" / "a.launch").read_text() == "<launch/>\n"
    assert not (dest / "CMakeLists.txt").is_symlink()
    assert not (dest / "CMakeLists.txt").exists()
    assert (dest / "pkg" / "near").is_symlink()  # a link inside the tree is kept


def test_the_fixed_tree_takes_the_launch_arguments_the_fix_renamed(tmp_path: Path) -> None:
    # teleop_twist_joy 80dd095 renames config/ps3-breaking.config.yaml to
    # ps3-braking.config.yaml: the fixed tree must be launched with joy_config:=ps3-braking,
    # or its launch fails on the old name and the finding is "gone" for the wrong reason
    repo = tmp_path / "mirrors" / "o+r" / "repo"
    (repo / "pkg" / "launch").mkdir(parents=True)
    (repo / "pkg" / "launch" / "a.launch").write_text("<launch/>\n")
    for args in (["init", "-q"], ["add", "-A"],
                 ["-c", "user.name=t", "-c", "user.email=t@t", "commit", "-qm", "one"],
                 ["-c", "user.name=t", "-c", "user.email=t@t", "commit", "-qm", "two",
                  "--allow-empty"]):
        subprocess.run(["git", "-C", str(repo), *args], check=True)
    fix = subprocess.run(["git", "-C", str(repo), "rev-parse", "HEAD"], check=True,
                         capture_output=True, text=True).stdout.strip()
    bug = {"id": "r/x", "repo": "o/r", "fix": fix, "launch": ["pkg/launch/a.launch"],
           "args": {"cfg": "old"}, "fixed_args": {"cfg": "new"}}
    trees = _script().prepare(bug, tmp_path / "mirrors", tmp_path / "out")
    assert isinstance(trees, dict)
    buggy = yaml.safe_load(trees["buggy"].read_text())["configurations"]["bug"]
    fixed = yaml.safe_load(trees["fixed"].read_text())["configurations"]["bug"]
    assert buggy["args"] == {"cfg": "old"}
    assert fixed["args"] == {"cfg": "new"}
    del bug["fixed_args"]  # without it both trees take the same arguments
    trees = _script().prepare(bug, tmp_path / "mirrors", tmp_path / "out2")
    assert isinstance(trees, dict)
    assert yaml.safe_load(trees["fixed"].read_text())["configurations"]["bug"]["args"] == {
        "cfg": "old"}


def test_a_bug_may_name_the_repositorys_own_workspace_folder(tmp_path: Path) -> None:
    # barc 34bc1c6: the repository holds workspace/src/barc and MATLAB/packages/barc, two
    # packages named barc; its catkin workspace is workspace/src, so the project must
    # read that folder alone, or the first barc found (MATLAB's) stands for the package
    repo = tmp_path / "mirrors" / "o+r" / "repo"
    (repo / "workspace" / "src" / "pkg" / "launch").mkdir(parents=True)
    (repo / "workspace" / "src" / "pkg" / "launch" / "a.launch").write_text("<launch/>\n")
    for args in (["init", "-q"], ["add", "-A"],
                 ["-c", "user.name=t", "-c", "user.email=t@t", "commit", "-qm", "one"],
                 ["-c", "user.name=t", "-c", "user.email=t@t", "commit", "-qm", "two",
                  "--allow-empty"]):
        subprocess.run(["git", "-C", str(repo), *args], check=True)
    fix = subprocess.run(["git", "-C", str(repo), "rev-parse", "HEAD"], check=True,
                         capture_output=True, text=True).stdout.strip()
    bug = {"id": "r/x", "repo": "o/r", "fix": fix, "launch": ["pkg/launch/a.launch"],
           "workspace": "workspace/src"}
    trees = _script().prepare(bug, tmp_path / "mirrors", tmp_path / "out")
    assert isinstance(trees, dict)
    for side in ("buggy", "fixed"):
        project = yaml.safe_load(trees[side].read_text())
        assert project["workspace"] == "src/r/workspace/src"
        assert (trees[side].parent / project["workspace"] / "pkg" / "launch"
                / "a.launch").is_file()
    del bug["workspace"]
    trees = _script().prepare(bug, tmp_path / "mirrors", tmp_path / "out2")
    assert isinstance(trees, dict)
    assert yaml.safe_load(trees["buggy"].read_text())["workspace"] == "src"


def test_configuration_not_seen_declared_is_the_undecided_form_of_arg_unset(
        monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    # turtlebot4_simulator decdf2b: x is used where an include not read (a launch file
    # the build makes) may have declared it; check says so in an info, which the
    # verdict takes as LAUNCH_ARG_UNSET's undecided form, not as a miss
    script = _script()
    report = {"findings": [], "diagnostics": [
        {"code": "LAUNCH_UNKNOWN_VALUE", "severity": "info",
         "location": {"file": "pkg/launch/ignition.launch.py", "line": 186},
         "message": "launch argument x is not seen declared (undecided: what was not "
                    "read may declare it: ...); what depends on it keeps '?'"},
        {"code": "LAUNCH_UNKNOWN_VALUE", "severity": "info",
         "location": {"file": "pkg/launch/ignition.launch.py", "line": 90},
         "message": "package ros_ign_gazebo is not in the workspace nor installed here"}]}

    def run(*args, **kwargs):
        return subprocess.CompletedProcess(args, 0, stdout=json.dumps(report), stderr="")

    monkeypatch.setattr(script.subprocess, "run", run)
    findings = script.check(tmp_path / "project.yaml")
    expect = {"rules": ["LAUNCH_ARG_UNSET"], "file": "ignition.launch.py", "text": ["x"]}
    assert script.pointing(findings, expect) == []
    assert [f["location"]["line"] for f in script.pointing(findings, expect, "-undecided")] \
        == [186]


def test_a_place_in_also_points_at_the_bug() -> None:
    # an unset argument is said once per configuration, at its first use: a use in the
    # file the bug names may be among its other places (``also``, locations as a
    # finding's are); before, the also entries were read as {"location": ...} and never
    # matched
    script = _script()
    said = {"code": "LAUNCH_ARG_UNSET", "severity": "warning",
            "message": "launch argument custom_param_file has no value",
            "location": {"file": "pkg/launch/main.launch", "line": 3},
            "also": [{"file": "pkg/launch/includes/move_base.launch.xml", "line": 24}]}
    expect = {"rules": ["LAUNCH_ARG_UNSET"], "file": "move_base.launch.xml",
              "text": ["custom_param_file"]}
    assert script.pointing([said], expect) == [said]
    assert script.pointing([{**said, "also": []}], expect) == []
