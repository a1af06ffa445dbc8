"""Two nodes whose names read the same with ``?`` in them are one name only when the
unknown parts are the same values. dvrk_robot's dvrk_master_slave_rviz.launch starts a
joint_state_publisher in ``/dvrk/$(arg master)`` and another in ``/dvrk/$(arg slave)``,
both arguments for the command line to give: both read
``/dvrk/?/joint_state_publisher``, and were a LAUNCH_NODE_DUPLICATE error that only
``master:=X slave:=X`` would make. One argument (or environment variable) used twice is
one value wherever it is used: that stays roslaunch's refusal. An unknown that is no
such substitution (an ``$(eval)`` that may have different inputs) is not known to be
another of the same spelling."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan


def _duplicates(write_tree, launch: str, extra: dict[str, str] | None = None
                ) -> list[tuple[int, str]]:
    files = {"src/pkg/package.xml": package_xml("pkg"), "src/pkg/launch/main.launch": launch}
    files.update(extra or {})
    root = write_tree(files)
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/pkg/launch/main.launch"), ws, {}, {})
    return [(d.location.line, d.message) for d in model.diagnostics
            if d.code == "LAUNCH_NODE_DUPLICATE"]


def test_names_of_two_unset_arguments_are_not_known_to_collide(write_tree):
    assert _duplicates(write_tree, """
        <launch>
          <arg name="master"/>
          <arg name="slave"/>
          <group ns="/dvrk/$(arg master)"><node name="jsp" pkg="p" type="j"/></group>
          <group ns="/dvrk/$(arg slave)"><node name="jsp" pkg="p" type="j"/></group>
          <node name="$(arg master)_view" pkg="p" type="v"/>
          <node name="$(arg slave)_view" pkg="p" type="v"/>
        </launch>
        """) == []


def test_names_of_one_unset_argument_collide(write_tree):
    found = _duplicates(write_tree, """
        <launch>
          <arg name="arm"/>
          <group ns="/dvrk/$(arg arm)"><node name="jsp" pkg="p" type="j"/></group>
          <group ns="dvrk/$(arg arm)"><node name="jsp" pkg="p" type="j"/></group>
          <node name="$(env ROBOT)_view" pkg="p" type="v"/>
          <node name="$(env ROBOT)_view" pkg="p" type="v"/>
        </launch>
        """)
    assert [line for line, _ in found] == [4, 6]
    assert "/dvrk/?/jsp" in found[0][1]


def test_an_argument_passed_to_two_includes_is_one_value(write_tree):
    """The value an include is given carries the including file's unknown: one
    argument handed to two includes of a file names both nodes alike."""
    part = """
        <launch>
          <arg name="robot"/>
          <node name="$(arg robot)_driver" pkg="p" type="d"/>
        </launch>
        """
    extra = {"src/pkg/launch/part.launch": part}
    same = _duplicates(write_tree, """
        <launch>
          <arg name="left"/>
          <include file="$(dirname)/part.launch"><arg name="robot" value="$(arg left)"/></include>
          <include file="$(dirname)/part.launch"><arg name="robot" value="$(arg left)"/></include>
        </launch>
        """, extra)
    assert [line for line, _ in same] == [3]  # part.launch
    assert _duplicates(write_tree, """
        <launch>
          <arg name="left"/>
          <arg name="right"/>
          <include file="$(dirname)/part.launch"><arg name="robot" value="$(arg left)"/></include>
          <include file="$(dirname)/part.launch"><arg name="robot" value="$(arg right)"/></include>
        </launch>
        """, extra) == []


def test_an_eval_of_an_unknown_is_not_known_to_be_another(write_tree):
    assert _duplicates(write_tree, """
        <launch>
          <arg name="n"/>
          <group ns="a"><arg name="k" default="1"/>
            <node name="$(eval arg('n') + arg('k'))" pkg="p" type="v" ns="/x"/></group>
          <group ns="b"><arg name="k" default="2"/>
            <node name="$(eval arg('n') + arg('k'))" pkg="p" type="v" ns="/x"/></group>
        </launch>
        """) == []
