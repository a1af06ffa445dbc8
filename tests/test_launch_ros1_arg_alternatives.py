"""Two ``<arg>`` of one name under conditions that cannot both hold.

roslaunch declares an ``<arg>`` only where its ``if`` / ``unless`` holds, so TIAGo's
``move_base.launch`` (``flex_suffix`` ``_flex`` unless ``$(arg public_sim)``, ``""`` if
it) and its ``cartesian_impedance_controller.launch`` (``model_chains`` once per
``$(eval ee_suffix == 'pal-gripper')``, ``... in ['robotiq-2f-85', ...]``) declare each
argument once for any value (Debian's roslaunch loads them with either). With the
condition not known statically the second declaration is no error: the argument is the
one of either, its value unknown where the two differ. Declarations under the same
condition, or one under none, stay refused as roslaunch refuses them when both hold.
"""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.model.conditions import Condition, contradict
from haros_arch.workspace import scan


def load_launch(write_tree, launch: str, args: dict[str, str] | None = None):
    root = write_tree({"src/pkg/package.xml": package_xml("pkg"),
                       "src/pkg/launch/main.launch": launch})
    ws = scan([str(root / "src")], {})
    return load(str(root / "src/pkg/launch/main.launch"), ws, args or {}, {})


FLEX = """
    <launch>
      <arg name="public_sim" />
      <arg name="flex_suffix" value="_flex" unless="$(arg public_sim)"/>
      <arg name="flex_suffix" value=""      if="$(arg public_sim)"/>
      <param name="p" value="x$(arg flex_suffix)"/>
      <param name="q" value="$(arg flex_suffix)y" type="str"/>
    </launch>
    """


def errors(model) -> list[str]:
    return [d.message for d in model.diagnostics if d.severity == "error"]


def test_if_and_unless_of_an_unknown_condition_declare_one_argument(write_tree):
    model = load_launch(write_tree, FLEX)
    assert errors(model) == []
    params = {p.name: p.value for p in model.params}
    assert params["/p"] is None  # '_flex' or '': not known
    # each declaration is on the launch tree with the value it writes
    assert [(a.name, a.value) for a in model.tree[0].args if a.name == "flex_suffix"] == [
        ("flex_suffix", "_flex"), ("flex_suffix", "")]


def test_with_the_condition_known_the_branch_taken_gives_the_value(write_tree):
    # as Debian's roslaunch gives /p: x with public_sim:=true, x_flex with false
    for given, expected in (("true", "x"), ("false", "x_flex")):
        model = load_launch(write_tree, FLEX, {"public_sim": given})
        assert errors(model) == []
        assert {p.name: p.value for p in model.params}["/p"] == expected


def test_alternatives_of_one_value_keep_it(write_tree):
    model = load_launch(write_tree, """
        <launch>
          <arg name="mode" />
          <arg name="rate" value="10" if="$(eval mode == 'a')"/>
          <arg name="rate" value="10" if="$(eval mode == 'b')"/>
          <arg name="rate" value="20" if="$(eval mode in ['c', 'd'])"/>
          <param name="r" value="$(arg rate)"/>
        </launch>
        """)
    assert errors(model) == []
    assert [p.value for p in model.params] == [None]  # 10 or 20


def test_conditions_that_may_both_hold_are_still_refused(write_tree):
    for second in ('if="$(arg c)"', 'if="$(arg d)"', ""):
        model = load_launch(write_tree, f"""
            <launch>
              <arg name="c" />
              <arg name="d" />
              <arg name="s" value="1" if="$(arg c)"/>
              <arg name="s" value="2" {second}/>
            </launch>
            """)
        assert errors(model) == ["arg 's' has already been declared"], second
    # a third declaration under the first one's condition
    model = load_launch(write_tree, """
        <launch>
          <arg name="c" />
          <arg name="s" value="1" if="$(arg c)"/>
          <arg name="s" value="2" unless="$(arg c)"/>
          <arg name="s" value="3" if="$(arg c)"/>
        </launch>
        """)
    assert errors(model) == ["arg 's' has already been declared"]


def test_a_group_arg_does_not_leak_its_conditions_to_the_including_scope(write_tree):
    model = load_launch(write_tree, """
        <launch>
          <arg name="c" />
          <group if="$(arg c)">
            <arg name="s" value="1"/>
          </group>
          <group unless="$(arg c)">
            <arg name="s" value="2"/>
            <param name="p" value="$(arg s)"/>
          </group>
        </launch>
        """)
    assert errors(model) == []
    assert [p.value for p in model.params] == [2]


def test_membership_in_a_list_contradicts_another_string():
    def cond(text: str, statement: str = "if") -> Condition:
        return Condition(text, "launch", statement)

    listed = cond("$(eval ee in ['robotiq-2f-85', 'robotiq-2f-140'])")
    assert contradict(listed, cond("$(eval ee == 'pal-gripper')"))
    assert not contradict(listed, cond("$(eval ee == 'robotiq-2f-140')"))
    assert contradict(cond("$(eval arg('ee') not in ('a', 'b'))"), cond("$(eval ee == 'a')"))
    assert contradict(cond("$(eval ee in ('a',))", "unless"), cond("$(eval ee == 'a')"))
    assert not contradict(cond("$(eval ee in [x, 'a'])"), cond("$(eval ee == 'b')"))
