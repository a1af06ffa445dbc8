"""A ``<node machine="c1">`` whose ``<machine>`` the tool does not see. roslaunch looks
a node's machine up once every file is loaded (``ROSLaunchConfig.assign_machines``):
a machine declared after the node, in the same file or in a file included later, is
known. PR2's pr2_bringup/pr2.launch takes its machines from ``$(find pr2_machine)/
pr2.machine``: with pr2_machine not in the workspace, its 22 nodes were each an error
``unknown machine 'c1'`` though the include not read may declare it (undecided, an
info); with the package there its machines are read. A file of a package that is
there but missing the file (omniveyor's pcv_base includes ``$(find omniveyor_mobility)/
launch/local.machine``, which its tree lacks, for ten nodes on ``machine="AGV"``) is
said missing once; its machines are undecided too, not ten more errors. A machine no
file declares, with every include read, stays the error roslaunch gives."""

from __future__ import annotations

from test_launch_ros1 import load_launch

MACHINE = '<launch><machine name="c1" address="c1" default="true"/></launch>\n'


def codes(model) -> list[tuple[str, str, int]]:
    return sorted((d.code, d.severity, d.location.line) for d in model.diagnostics)


def test_machine_of_an_include_not_read_is_undecided(write_tree) -> None:
    model = load_launch(write_tree, """<launch>
      <include file="$(find absent_machine)/robot.machine"/>
      <node name="a" pkg="pkg" type="x" machine="c1"/>
      <node name="b" pkg="pkg" type="x" machine="c1"/>
    </launch>""")
    said = codes(model)
    assert not any(code == "LAUNCH_BAD_VALUE" for code, _, _ in said), said
    notes = [d.message for d in model.diagnostics if d.location.line in (3, 4)]
    assert len(notes) == 1 and "'c1'" in notes[0] and "main.launch:2" in notes[0] and (
        "1 more" in notes[0]), notes


def test_machine_of_an_included_file_is_read(write_tree) -> None:
    model = load_launch(write_tree, """<launch>
      <include file="$(find pkg)/launch/robot.machine"/>
      <node name="a" pkg="pkg" type="x" machine="c1"/>
    </launch>""", extra={"src/pkg/launch/robot.machine": MACHINE})
    assert codes(model) == []
    assert [n.machine for n in model.nodes] == ["c1"]


def test_machine_declared_after_the_node_is_known(write_tree) -> None:
    model = load_launch(write_tree, """<launch>
      <node name="a" pkg="pkg" type="x" machine="c1"/>
      <include file="$(find pkg)/launch/robot.machine"/>
      <machine name="c2" address="c2"/>
      <node name="b" pkg="pkg" type="x" machine="c2"/>
    </launch>""", extra={"src/pkg/launch/robot.machine": MACHINE})
    assert codes(model) == []


def test_machine_declared_nowhere_is_an_error(write_tree) -> None:
    model = load_launch(write_tree, """<launch>
      <include file="$(find pkg)/launch/robot.machine"/>
      <node name="a" pkg="pkg" type="x" machine="c3"/>
    </launch>""", extra={"src/pkg/launch/robot.machine": MACHINE})
    assert codes(model) == [("LAUNCH_BAD_VALUE", "error", 3)]
    assert "unknown machine 'c3'" in model.diagnostics[0].message


def test_machine_of_a_missing_included_file_is_undecided(write_tree) -> None:
    model = load_launch(write_tree, """<launch>
      <include file="$(find pkg)/launch/local.machine"/>
      <node name="a" pkg="pkg" type="x" machine="AGV"/>
      <node name="b" pkg="pkg" type="x" machine="AGV"/>
    </launch>""", extra={"src/pkg/launch/other.launch": "<launch/>\n"})
    said = codes(model)
    assert not any(code == "LAUNCH_BAD_VALUE" for code, _, _ in said), said
    assert [line for _, severity, line in said if severity == "error"] == [2], said
    notes = [d.message for d in model.diagnostics if d.location.line == 3]
    assert len(notes) == 1 and "'AGV'" in notes[0] and "main.launch:2" in notes[0], notes
