"""A ROS 1 launch attribute with a ``$(`` never closed: roslaunch's state machine collects
a substitution only at its ``)``, so the text stays as written, without a word. carl_bot's
arm.launch (fix ae74256) set ``~using_recognition`` to ``"$(arg using_recognition"``, a
string where the node reads a bool; bwi_experimental's robot.launch (fix 00af504)
included ``$(find bridge_server/launch/rosbridge_websocket.launch``, a file that is not
there."""

from __future__ import annotations

from test_launch_ros1 import load_launch

from haros_arch.launch.ros1.substitution import collect, unclosed


def said(model) -> list[tuple[int, str]]:
    return [(d.location.line, d.message) for d in model.diagnostics
            if d.code == "LAUNCH_SUBST_UNCLOSED"]


def test_an_unclosed_substitution_is_said_and_the_text_kept(write_tree):
    model = load_launch(write_tree, """<launch>
          <arg name="using_recognition" default="true"/>
          <node pkg="carl" type="manip" name="manip">
            <param name="using_pickup" value="$(arg using_recognition)"/>
            <param name="using_recognition" value="$(arg using_recognition"/>
          </node>
        </launch>""")
    assert said(model) == [
        (5, 'the substitution "$(arg using_recognition" is never closed: roslaunch keeps '
            'it as plain text')]
    # as roslaunch: the closed one is the argument's value, the open one the raw text
    assert [(p.name, p.value) for p in model.params] == [
        ("/manip/using_pickup", True), ("/manip/using_recognition", "$(arg using_recognition")]


def test_closed_and_plain_dollars_are_not_said(write_tree):
    model = load_launch(write_tree, """<launch>
          <arg name="a" default="x"/>
          <param name="one" value="$(arg a)/b $(arg a)"/>
          <param name="price" value="5 $ (not a substitution)"/>
          <param name="shell" value="echo $HOME"/>
          <param name="eval" value="$(eval 1 + 2)"/>
          <param name="nested" value="$(eval optenv('PREFIX', arg('a')) + 'x')"/>
        </launch>""")
    assert said(model) == []
    # a whole $(eval) is one expression: its nested parentheses are not scanned
    assert [d.code for d in model.diagnostics if d.severity != "info"] == []
    assert [(p.name, p.value) for p in model.params if p.name == "/nested"] == [
        ("/nested", "xx")]


def test_unclosed_keeps_roslaunch_state_machine():
    assert unclosed("$(find pkg)/a $(arg b") == "$(arg b"
    assert unclosed("$(eval 1 + 2") == "$(eval 1 + 2"
    assert unclosed("$(arg a)") is None
    assert unclosed("a $ (b") is None  # '(' must follow '$' at once
    assert unclosed("$()") is None  # closed, though empty
    assert unclosed("$(eval optenv('X', arg('y')))") is None  # one expression
    assert collect("$(find pkg)/a $(arg b") == ["find pkg"]
