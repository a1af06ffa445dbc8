"""ROS 1 ``<include file>``, ``<rosparam file>`` and ``<param textfile>`` with a relative
path: roslaunch opens them from the folder it runs in, which nothing in the workspace
says. The tool resolved them against its own working folder: from the package's folder
the include's node started and the file's parameters were set, from another the same
launch file had two errors (LAUNCH_FILE_MISSING, LAUNCH_BAD_VALUE)."""

from __future__ import annotations

import pytest
from test_launch_ros1 import load_launch

MAIN = """
    <launch>
      <include file="launch/other.launch"/>
      <node pkg="pkg" type="x" name="n">
        <rosparam file="config/p.yaml" command="load"/>
        <param name="doc" textfile="config/doc.txt"/>
      </node>
    </launch>
    """

EXTRA = {"src/pkg/launch/other.launch":
         '<launch><node pkg="pkg" type="y" name="other"/></launch>\n',
         "src/pkg/config/p.yaml": "speed: 2.0\n",
         "src/pkg/config/doc.txt": "text\n"}


@pytest.mark.parametrize("folder", ["src/pkg", "src"])
def test_relative_paths_are_unknown_wherever_the_tool_runs(write_tree, monkeypatch,
                                                           folder):
    root = write_tree(EXTRA)
    monkeypatch.chdir(root / folder)
    model = load_launch(write_tree, MAIN, extra=EXTRA)
    assert [n.name for n in model.nodes] == ["/n"]
    assert not any(p.name in ("/n/speed", "/n/doc") and p.value is not None
                   for p in model.params), [(p.name, p.value) for p in model.params]
    said = [(d.code, d.location.line) for d in model.diagnostics]
    assert said == [("LAUNCH_UNKNOWN_VALUE", 2), ("LAUNCH_UNKNOWN_VALUE", 4),
                    ("LAUNCH_UNKNOWN_VALUE", 5)], said
