"""bench/robust_bugs.py writes a bug's trees from a mirror with ``git archive``."""

from __future__ import annotations

import importlib.util
import subprocess
import tarfile
from pathlib import Path

import pytest
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
