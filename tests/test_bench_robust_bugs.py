"""bench/robust_bugs.py writes a bug's trees from a mirror with ``git archive``."""

from __future__ import annotations

import importlib.util
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
