"""ROS 2 launch: XML / YAML front ends, substitutions and ROS 2 naming, inline cases."""

from __future__ import annotations

import pytest
from conftest import package_xml

from haros_arch.launch import load
from haros_arch.launch.ros2 import entities as e
from haros_arch.launch.ros2 import is_ros2
from haros_arch.launch.ros2.naming import (
    node_namespace,
    params_for_node,
    parse_ros_args,
    pattern_matches,
)
from haros_arch.launch.ros2.substitutions import SubstitutionSyntax, parse
from haros_arch.workspace import scan


def run(write_tree, name: str, text: str, extra: dict[str, str] | None = None,
        args: dict[str, str] | None = None, env: dict[str, str] | None = None):
    files = {"src/pkg/package.xml": package_xml("pkg", "ament_cmake"),
             f"src/pkg/launch/{name}": text}
    files.update(extra or {})
    root = write_tree(files)
    ws = scan([str(root / "src")], env or {})
    return load(str(root / "src/pkg/launch" / name), ws, args or {}, env or {}), root


def codes(model) -> list[str]:
    return [d.code for d in model.diagnostics]


# -- substitutions -------------------------------------------------------------------
def test_parse_nested_and_quoted_substitutions():
    assert parse("$(var ns)/scan") == (e.Var(("ns",)), "/scan")
    assert parse("$(env HOME '/tmp x')") == (e.Env(("HOME",), ("/tmp x",)),)
    assert parse("$(var $(var which))") == (e.Var((e.Var(("which",)),)),)
    assert parse("$(eval '\\'$(var a)\\' == \\'b\\'')") == (
        e.Eval(("'", e.Var(("a",)), "' == 'b'")),)
    for bad in ("$(var a", "$(nosuch x)", "$(var)", "$(var 'open)"):
        with pytest.raises(SubstitutionSyntax):
            parse(bad)


# -- naming --------------------------------------------------------------------------
def test_node_namespace_rules():
    assert node_namespace(None, None) == "/"
    assert node_namespace("/robot1", None) == "/robot1"
    assert node_namespace("/robot1", "sensors") == "/robot1/sensors"
    assert node_namespace("/robot1", "/abs") == "/abs"
    assert node_namespace(None, "rel//x/") == "/rel/x"


def test_ros_args_node_targeted_rules_and_renames():
    parsed = parse_ros_args(["-r", "talker:chatter:=a", "-r", "other:chatter:=b",
                             "-r", "x:=y", "-r", "__ns:=/n", "--remap", "__node:=t2",
                             "-p", "rate:=3", "-p", "other:rate:=4", "--params-file",
                             "f.yaml", "--log-level", "debug"], "talker")
    assert parsed.remaps == [("chatter", "a"), ("x", "y")]
    assert (parsed.namespace, parsed.node_name) == ("/n", "t2")
    assert parsed.params == [("rate", "3")]
    assert parsed.params_files == ["f.yaml"]


def test_param_file_patterns_follow_rcl():
    assert pattern_matches("/**", "/a/b/c")
    assert pattern_matches("/**/amcl", "/r1/amcl") and pattern_matches("/**/amcl", "/amcl")
    assert pattern_matches("/*/amcl", "/r1/amcl") and not pattern_matches("/*/amcl", "/amcl")
    assert pattern_matches("/amcl", "/amcl") and not pattern_matches("/amcl", "/r1/amcl")
    document = {"/**": {"ros__parameters": {"use_sim_time": True, "x": 1}},
                "r1": {"amcl": {"ros__parameters": {"x": 2, "laser": {"max": 5}}}},
                "amcl": {"ros__parameters": {"x": 3}}}
    assert params_for_node(document, "/r1/amcl") == [
        ("use_sim_time", True), ("x", 2), ("laser.max", 5)]
    assert params_for_node(document, "/amcl") == [("use_sim_time", True), ("x", 3)]


# -- format detection ------------------------------------------------------------------
def test_is_ros2_by_extension_and_content(tmp_path):
    ros1 = tmp_path / "a.launch"
    ros1.write_text('<launch><node pkg="p" type="t" name="n"/></launch>')
    ros2 = tmp_path / "b.launch"
    ros2.write_text('<launch><node pkg="p" exec="t" name="n"/></launch>')
    xml = tmp_path / "c.xml"
    xml.write_text('<launch><let name="a" value="1"/></launch>')
    assert not is_ros2(str(ros1))
    assert is_ros2(str(ros2)) and is_ros2(str(xml))
    assert is_ros2("x.launch.py") and is_ros2("x.launch.yaml") and is_ros2("x.launch.xml")


# -- XML -------------------------------------------------------------------------------
def test_xml_nodes_scopes_and_global_actions(write_tree):
    model, _ = run(write_tree, "main.launch.xml", """
        <launch>
          <arg name="ns" default="r1"/>
          <let name="rate" value="$(eval '2 * 5')"/>
          <set_parameter name="use_sim_time" value="true"/>
          <group scoped="true">
            <push-ros-namespace namespace="$(var ns)"/>
            <set_remap from="cmd_vel" to="cmd_vel_safe"/>
            <node pkg="drive" exec="base" name="base" namespace="hw" args="--port /dev/x">
              <param name="rate" value="$(var rate)"/>
              <remap from="odom" to="/odom"/>
            </node>
          </group>
          <node pkg="drive" exec="base" name="outside"/>
          <group scoped="false">
            <push_ros_namespace namespace="leaky"/>
          </group>
          <node pkg="drive" exec="base" name="after" ros_args="-r __node:=renamed"/>
        </launch>
        """)
    nodes = {n.name: n for n in model.nodes}
    # launch_ros writes its own ``-r __node:=after`` after the ros_args, and rcl takes
    # the first node-name rule: the node is "renamed"
    assert list(nodes) == ["/r1/hw/base", "/outside", "/leaky/renamed"]
    base = nodes["/r1/hw/base"]
    assert base.remaps == [("cmd_vel", "cmd_vel_safe"), ("odom", "/odom")]
    assert base.args == "--port /dev/x" and base.ros_version == 2
    assert nodes["/outside"].remaps == []
    params = {p.name: p.value for p in model.params}
    assert params == {"/r1/hw/base/use_sim_time": True, "/r1/hw/base/rate": 10,
                      "/outside/use_sim_time": True, "/leaky/renamed/use_sim_time": True}
    assert model.diagnostics == []


def test_xml_unknown_condition_makes_node_conditional_and_known_one_drops_it(write_tree):
    model, _ = run(write_tree, "main.launch.xml", """
        <launch>
          <arg name="sim" default="false"/>
          <arg name="hw"/>
          <node pkg="p" exec="e" name="simulator" if="$(var sim)"/>
          <node pkg="p" exec="e" name="real" unless="$(var sim)"/>
          <node pkg="p" exec="e" name="driver" if="$(var hw)">
            <param name="port" value="/dev/ttyUSB0"/>
          </node>
          <node pkg="p" exec="e" name="both" if="$(and $(not $(var sim)) $(var hw))"/>
        </launch>
        """)
    assert [n.name for n in model.nodes] == ["/real", "/driver", "/both"]
    driver = model.nodes[1]
    assert [(c.text, c.kind, c.statement, c.location.line) for c in driver.conditions] == [
        ("$(var hw)", "launch", "if", 6)]
    assert model.params[0].conditions == driver.conditions
    assert "LAUNCH_ARG_UNSET" in codes(model)


def test_command_is_never_run_and_file_content_stays_in_workspace(write_tree, tmp_path):
    marker = tmp_path / "ran"
    outside = tmp_path.parent / "secret_outside.txt"
    outside.write_text("secret")
    model, _root = run(write_tree, "main.launch.xml", f"""
        <launch>
          <node pkg="p" exec="e" name="a">
            <param name="desc" value="$(command 'touch {marker}')"/>
            <param name="inside" value="$(file-content $(dirname)/note.txt)"/>
            <param name="outside" value="$(file-content {outside})"/>
          </node>
        </launch>
        """, extra={"src/pkg/launch/note.txt": "hello"})
    assert not marker.exists()
    values = {p.key: p.value for p in model.params}
    assert values == {"desc": None, "inside": "hello", "outside": None}
    # the file outside is not read; the command is not run, as ROS 1's command= is not
    assert codes(model).count("LAUNCH_UNSUPPORTED") == 1
    assert any(d.code == "LAUNCH_UNKNOWN_VALUE" and "touch" in d.message and
               "is not run" in d.message for d in model.diagnostics)


def test_xml_containers_and_load_composable_node(write_tree):
    model, _ = run(write_tree, "main.launch.xml", """
        <launch>
          <push-ros-namespace namespace="cam"/>
          <node_container pkg="rclcpp_components" exec="component_container" name="box"
                          namespace="">
            <composable_node pkg="image_proc" plugin="image_proc::RectifyNode" name="rect">
              <remap from="image" to="image_raw"/>
              <param name="interpolation" value="1"/>
            </composable_node>
          </node_container>
          <load_composable_node target="/cam/box">
            <composable_node pkg="image_proc" plugin="image_proc::DebayerNode"
                             name="debayer" namespace="/abs"/>
          </load_composable_node>
        </launch>
        """)
    assert [(n.name, n.composable, n.container) for n in model.nodes] == [
        ("/cam/box", False, None), ("/cam/rect", True, "/cam/box"),
        ("/abs/debayer", True, "/cam/box")]
    assert [(p.name, p.value) for p in model.params] == [("/cam/rect/interpolation", 1)]


def test_xml_reports_unknown_tags_attributes_and_syntax(write_tree):
    model, _ = run(write_tree, "main.launch.xml", """
        <launch>
          <nodes pkg="p"/>
          <node pkg="p" exec="e" name="n" colour="red"/>
          <node pkg="p" name="no_exec"/>
          <node pkg="p" exec="e" name="$(var)"/>
        </launch>
        """)
    found = sorted((d.code, d.location.line) for d in model.diagnostics)
    assert found == [("LAUNCH_BAD_VALUE", 5), ("LAUNCH_MISSING_ATTRIBUTE", 4),
                     ("LAUNCH_UNEXPECTED_ATTRIBUTE", 3), ("LAUNCH_UNKNOWN_TAG", 2)]
    broken, _ = run(write_tree, "bad.launch.xml", "<launch><node></launch>")
    assert codes(broken) == ["LAUNCH_XML_SYNTAX"] and broken.nodes == []


def test_yaml_launch_and_include_with_args(write_tree):
    model, _ = run(write_tree, "main.launch.yaml", """
        launch:
        - arg: {name: robot, default: bot}
        - include:
            file: $(dirname)/part.launch.xml
            arg:
            - {name: prefix, value: $(var robot)}
        - group:
            scoped: false
            children:
            - push-ros-namespace: {namespace: outer}
        - node:
            pkg: p
            exec: e
            name: last
            param:
            - {name: gains, value: [1.0, 2.5]}
            - {name: flag, value: true}
        """, extra={"src/pkg/launch/part.launch.xml": """
        <launch>
          <arg name="prefix"/>
          <node pkg="p" exec="e" name="$(var prefix)_driver"/>
        </launch>
        """})
    assert [n.name for n in model.nodes] == ["/bot_driver", "/outer/last"]
    assert {p.key: p.value for p in model.params} == {"gains": [1.0, 2.5], "flag": True}
    assert [p.type for p in model.params] == ["double[]", "bool"]
    assert model.files == ["pkg/launch/main.launch.yaml", "pkg/launch/part.launch.xml"]
    bad, _ = run(write_tree, "bad.launch.yaml", "launch: [\n  - node: {pkg: p\n")
    assert codes(bad) == ["LAUNCH_YAML_SYNTAX"]


def test_backslash_escapes_as_launch_reads_them():
    # checked against launch's parse_substitution (jazzy): every literal is unescaped
    assert parse("[\\'ndt\\',\\'yabloc\\']") == ("['ndt','yabloc']",)
    assert parse("\\$(var x)") == ("$(var x)",)
    assert parse("a\\b") == ("ab",) and parse("a\\") == ("a\\",)
    assert parse("$(env A\\)b x)") == (e.Env(("A)b",), ("x",)),)
    assert parse("$(env A\\ b)") == (e.Env(("A\\",), ("b",)),)
    assert parse("$(env A\\'b)") == (e.Env(("A'b",), None),)


def test_escaped_quotes_reach_eval(write_tree):
    # Autoware's pose_twist_estimator.launch.xml: a list written with \' then eval'd
    model, _ = run(write_tree, "main.launch.xml", """
        <launch>
          <arg name="pose_source" default="ndt"/>
          <let name="available" value="[\\'ndt\\',\\'yabloc\\']"/>
          <let name="split"
               value="list(set('$(var pose_source)'.split('_')).intersection($(var available)))"/>
          <let name="sources" value="$(eval $(var split))"/>
          <group if="$(eval &quot;'ndt' in $(var sources)&quot;)">
            <node pkg="p" exec="ndt" name="ndt"/>
          </group>
          <group if="$(eval &quot;'yabloc' in $(var sources)&quot;)">
            <node pkg="p" exec="yabloc" name="yabloc"/>
          </group>
        </launch>
    """)
    assert [(n.name, n.conditions) for n in model.nodes] == [("/ndt", ())]


def test_allow_substs_file_with_an_unknown_value_is_read(write_tree):
    model, _ = run(write_tree, "main.launch.xml", """
        <launch>
          <arg name="robot" default="r1"/>
          <node pkg="p" exec="e" name="cfg">
            <param from="$(find-pkg-share pkg)/config/p.yaml" allow_substs="true"/>
          </node>
        </launch>
    """, extra={"src/pkg/config/p.yaml": """
        cfg:
          ros__parameters:
            frame: $(var robot)/base
            port: $(env ROBOT_PORT_UNSET)
            $(env SIDE_UNSET)_limit: 2.0
            rate: 10
    """})
    assert {p.name: p.value for p in model.params} == {
        "/cfg/frame": "r1/base", "/cfg/port": None, "/cfg/?_limit": 2.0, "/cfg/rate": 10}
    assert "LAUNCH_UNKNOWN_VALUE" in codes(model)


def test_a_key_given_twice_in_a_parameter_file_merges_as_rcl_reads_it():
    from haros_arch.launch.ros2.naming import load_param_file, params_for_node

    document = load_param_file(
        "/**:\n  tb3:\n    ros__parameters: {wheels: {radius: 0.03}, a: 1}\n"
        "/**:\n  ctrl:\n    ros__parameters: {b: 2}\n"
        "  tb3:\n    ros__parameters: {wheels: {separation: 0.16}, a: 3}\n")
    assert params_for_node(document, "/tb3") == [
        ("wheels.radius", 0.03), ("wheels.separation", 0.16), ("a", 3)]
    assert params_for_node(document, "/ctrl") == [("b", 2)]


def test_an_action_attribute_launch_does_not_read_fails_the_launch(write_tree):
    # rmf_demos 080bb7b / 5af125a: ROS 1's required= on a <node>, help= on an <arg>;
    # launch checks an action's own attributes and stops ("Unexpected attribute(s)"),
    # not a nested entity's, and takes shell= / node-name= on a node
    model, _ = run(write_tree, "main.launch.xml", """
        <launch>
          <arg name="map" default="m" help="the map"/>
          <node pkg="p" exec="e" name="n" required="true" shell="false">
            <param name="a" value="1" colour="red"/>
          </node>
          <node pkg="p" exec="e" node-name="m"/>
        </launch>
        """)
    found = sorted((d.code, d.location.line, d.severity) for d in model.diagnostics)
    # (the argument map, which nothing reads, is not LAUNCH_ARG_UNUSED: its name is
    # written again, in its help text)
    assert found == [("LAUNCH_UNEXPECTED_ATTRIBUTE", 2, "error"),
                     ("LAUNCH_UNEXPECTED_ATTRIBUTE", 3, "error"),
                     ("LAUNCH_UNKNOWN_ATTRIBUTE", 4, "warning")]
    assert "required=" in next(d for d in model.diagnostics if d.location.line == 3).message
    # in YAML a node's env (like its param and remap) is a list of entities, not an
    # attribute
    yaml_model, _ = run(write_tree, "main.launch.yaml", """
        launch:
        - node: {pkg: p, exec: e, name: n, respawn_if_dead: "true",
                 env: [{name: A, value: B}], remap: [{from: a, to: b}]}
        """)
    assert [(d.code, d.message) for d in yaml_model.diagnostics] == [
        ("LAUNCH_UNEXPECTED_ATTRIBUTE", "ros2 launch refuses <node> with attribute "
                                        "respawn_if_dead= (Unexpected attribute): the "
                                        "launch fails")]
