"""A ``<param>`` tag that sets again a name an earlier tag of the same element set: roslaunch
keeps the later value without a word, so the earlier is dead. diffbot's amcl.launch (fix
11ac235) set ``kld_err`` twice (0.02, then 0.99) and never ``kld_z``: amcl ran with its
default kld_z and a kld_err of 0.99."""

from __future__ import annotations

from test_launch_ros1 import load_launch


def twice(model) -> list[tuple[int, str]]:
    return [(d.location.line, d.message) for d in model.diagnostics
            if d.code == "LAUNCH_PARAM_SET_TWICE"]


def test_a_node_param_set_twice_is_said_at_the_second(write_tree):
    model = load_launch(write_tree, """<launch>
          <node pkg="amcl" type="amcl" name="amcl">
            <param name="kld_err" value="0.02"/>
            <param name="kld_err" value="0.99"/>
            <param name="odom_alpha1" value="0.2"/>
          </node>
          <param name="/robot_name" value="a"/>
          <param name="/robot_name" value="b"/>
        </launch>""")
    assert twice(model) == [
        (4, "parameter kld_err is set again here (first at line 3): roslaunch keeps the "
            "last value, the first is never used"),
        (8, "parameter /robot_name is set again here (first at line 7): roslaunch keeps "
            "the last value, the first is never used")]
    # the model keeps roslaunch's value: the last one
    assert [(p.name, p.value) for p in model.params if p.name.endswith("kld_err")] == [
        ("/amcl/kld_err", 0.99)]


def test_settings_meant_to_replace_each_other_are_not_said(write_tree):
    model = load_launch(write_tree, """<launch>
          <arg name="sim" default="false"/>
          <arg name="fast"/>
          <param name="rate" value="1" if="$(arg fast)"/>
          <param name="rate" value="2" unless="$(arg fast)"/>
          <param name="~speed" value="1"/>
          <node pkg="p" type="t" name="a">
            <param name="speed" value="2"/>
          </node>
          <node pkg="p" type="t" name="b">
            <param name="speed" value="2"/>
          </node>
          <group ns="one">
            <param name="level" value="1"/>
          </group>
          <group ns="two">
            <param name="level" value="1"/>
          </group>
          <param name="level" value="1"/>
          <group>
            <param name="level" value="2"/>
          </group>
          <include file="$(find pkg)/launch/part.launch"/>
          <include file="$(find pkg)/launch/part.launch"/>
        </launch>""", extra={"src/pkg/launch/part.launch": """<launch>
          <param name="shared" value="1"/>
        </launch>"""})
    assert twice(model) == []
