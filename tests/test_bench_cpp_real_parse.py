"""bench/cpp_real.py, with which every C++ change is measured, gives libclang the same
translation units with the same arguments as the pipeline (``haros-arch extract
--no-cache``) for the same project: the project file's ``distro:`` and
``compile_commands:``, or a folder's ROS_DISTRO. It read a workspace folder only and
parsed for no distribution unless told ``--distro``, and it imported the haros_arch
beside the script whatever PYTHONPATH said, so a comparison of two checkouts run with
one checkout's script measured that checkout twice (survey Z21: sawyer's stand-in
errors, seen by the pipeline, never by the bench)."""

from __future__ import annotations

import importlib.util
import json
import os
import re
import sys

import pytest
from clang.cindex import Index
from conftest import package_xml

import haros_arch
from haros_arch.autoproject import open_project
from haros_arch.extract.cpp import visitor
from haros_arch.pipeline import Options, analyse

TALKER = """
#include <ros/ros.h>
#include <std_msgs/String.h>
int main(int argc, char ** argv) {
  ros::init(argc, argv, "talker");
  ros::NodeHandle nh;
#ifdef GIVEN_TOPIC
  ros::Publisher pub = nh.advertise<std_msgs::String>(GIVEN_TOPIC, 10);
#endif
  ros::spin();
}
"""

# the generated header folder and precompiled prelude of one run
_RUN_FOLDER = re.compile(r"[^\s\"']*haros-arch-(?:cpp|pch)-[^/\s\"']*")


def _tree(write_tree, project: bool):
    files = {
        "src/talk/package.xml": package_xml("talk", "catkin").replace(
            "</package>", "<depend>roscpp</depend><depend>std_msgs</depend></package>"),
        "src/talk/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0.2)\nproject(talk)\n"
                                   "find_package(catkin REQUIRED COMPONENTS roscpp)\n"
                                   "add_executable(talker src/talker.cpp)\n",
        "src/talk/src/talker.cpp": TALKER,
        "src/talk/launch/talk.launch": '<launch><node pkg="talk" type="talker" '
                                       'name="talker"/></launch>\n',
    }
    if project:
        files["project.yaml"] = ("project: talk\nworkspace: src\ndistro: noetic\n"
                                 "compile_commands: build\nconfigurations:\n"
                                 "  talk:\n    launch: [talk/launch/talk.launch]\n")
    root = write_tree(files)
    if project:
        source = root / "src/talk/src/talker.cpp"
        (root / "build").mkdir()
        (root / "build/compile_commands.json").write_text(json.dumps([{
            "directory": str(root / "build"), "file": str(source),
            "arguments": ["c++", '-DGIVEN_TOPIC="chatter"', "-c", str(source)]}]))
    return root


def _bench_script(monkeypatch):
    """bench/cpp_real.py of the checkout whose haros_arch is imported (its folder on
    sys.path, as when it runs: it imports bench/checkout.py)."""
    path = os.path.join(os.path.dirname(os.path.dirname(haros_arch.__file__)),
                        "bench", "cpp_real.py")
    monkeypatch.syspath_prepend(os.path.dirname(path))
    spec = importlib.util.spec_from_file_location("cpp_real_under_test", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _recorded(monkeypatch) -> list[tuple[str, tuple[str, ...], tuple[str, ...], int]]:
    """Every libclang parse from now on: the file, its arguments, the unsaved files'
    names and the options (one run's temporary folders named alike)."""
    parses: list[tuple[str, tuple[str, ...], tuple[str, ...], int]] = []
    inner = Index.parse

    def parse(self, path, args=None, unsaved_files=None, options=0):
        def plain(text: str) -> str:
            return _RUN_FOLDER.sub("$RUN", text)

        parses.append((path, tuple(plain(a) for a in args or ()),
                       tuple(sorted(plain(n) for n, _ in unsaved_files or ())), options))
        return inner(self, path, args=args, unsaved_files=unsaved_files, options=options)

    monkeypatch.setattr(Index, "parse", parse)
    # the bench's timing wraps these two in place: put them back after the test
    monkeypatch.setattr(visitor.CallFinder, "run", visitor.CallFinder.run)
    return parses


@pytest.mark.parametrize("project", [True, False], ids=["project file", "folder"])
def test_the_bench_parses_each_unit_as_the_pipeline_does(write_tree, monkeypatch,
                                                         project: bool) -> None:
    root = _tree(write_tree, project)
    given = str(root / "project.yaml") if project else str(root / "src")
    # a folder is read for the distribution of the environment, as the pipeline does
    monkeypatch.setenv("ROS_DISTRO", "melodic" if project else "noetic")
    script = _bench_script(monkeypatch)
    parses = _recorded(monkeypatch)
    analyse(open_project(given), dict(os.environ), Options(cache_dir=None, jobs=1))
    # the workspace's units (the stand-ins' precompiled prelude is made once a process)
    pipeline = sorted(p for p in parses if p[0].startswith(str(root)))
    parses.clear()
    monkeypatch.setattr(sys, "argv", ["cpp_real.py", given])
    script.main()
    bench = sorted(p for p in parses if p[0].startswith(str(root)))
    units = [p for p in pipeline if p[0].endswith("talker.cpp")]
    assert units, "the pipeline parsed the node's unit"
    # noetic's roscpp (1.16), the project file's over the environment's melodic (1.14)
    assert all("-DROS_VERSION_MINOR=16" in args for _, args, _, _ in units)
    if project:  # the flags of the project's compile_commands.json
        assert all('-DGIVEN_TOPIC="chatter"' in args for _, args, _, _ in units)
    assert bench == pipeline
