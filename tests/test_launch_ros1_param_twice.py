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


def test_a_node_param_before_its_rosparam_file_is_kept_and_not_said(write_tree):
    # roslaunch's _node_tag puts a node's <param> tags in its context (force_local) and
    # adds them after all its children, so they win over its <rosparam> files whatever
    # the order: the file's value of the key is the one replaced, the usual pattern of
    # defaults in a file, one value changed by a tag (no LAUNCH_PARAM_OVERRIDDEN in ROS 1)
    model = load_launch(write_tree, """<launch>
          <node pkg="amcl" type="amcl" name="amcl">
            <param name="kld_err" value="0.05"/>
            <rosparam file="$(find pkg)/config/amcl.yaml"/>
          </node>
        </launch>""", extra={"src/pkg/config/amcl.yaml": "kld_err: 0.01\nkld_z: 0.99\n"})
    assert not [d for d in model.diagnostics if d.code in (
        "LAUNCH_PARAM_SET_TWICE", "LAUNCH_PARAM_OVERRIDDEN")]
    # both settings are kept, in roslaunch's order: the tag's last
    assert [(p.name, p.value) for p in model.params if p.name.startswith("/amcl/kld")] == [
        ("/amcl/kld_err", 0.01), ("/amcl/kld_z", 0.99), ("/amcl/kld_err", 0.05)]
