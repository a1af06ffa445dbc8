from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan


def load_launch(write_tree, launch: str, extra: dict[str, str] | None = None,
                args: dict[str, str] | None = None, env: dict[str, str] | None = None):
    files = {"src/pkg/package.xml": package_xml("pkg"), "src/pkg/launch/main.launch": launch}
    files.update(extra or {})
    root = write_tree(files)
    ws = scan([str(root / "src")], env or {})
    return load(str(root / "src/pkg/launch/main.launch"), ws, args or {}, env or {})


def test_nodes_params_and_remaps(write_tree):
    model = load_launch(write_tree, """
        <launch>
          <param name="frequency" type="double" value="1" />
          <param name="auto_int" value="3" />
          <param name="auto_bool" value="True" />
          <param name="auto_str" value="hello" />
          <remap from="a" to="b" />
          <node name="listener" pkg="example" type="reactive" args="--x 1">
            <param name="rate" value="2.5" />
            <param name="~private" value="p" />
            <remap from="chatter" to="/global/chatter" />
          </node>
        </launch>
        """)
    assert [(p.name, p.value, p.type) for p in model.params] == [
        ("/frequency", 1.0, "double"), ("/auto_int", 3, "int"), ("/auto_bool", True, "bool"),
        ("/auto_str", "hello", "str"), ("/listener/rate", 2.5, "double"),
        ("/listener/private", "p", "str")]
    node = model.nodes[0]
    assert (node.name, node.package, node.executable, node.args) == (
        "/listener", "example", "reactive", "--x 1")
    assert node.remaps == [("a", "b"), ("chatter", "/global/chatter")]
    assert node.location.file == "pkg/launch/main.launch"
    assert node.location.line == 7
    assert model.diagnostics == []


def test_groups_args_and_conditions(write_tree):
    model = load_launch(write_tree, """
        <launch>
          <arg name="robot" default="r1" />
          <arg name="sim" default="false" />
          <arg name="mystery" />
          <group ns="$(arg robot)">
            <remap from="scan" to="base_scan" />
            <node name="driver" pkg="p" type="d" ns="hw" />
            <group ns="/abs">
              <node name="n" pkg="p" type="d" />
            </group>
          </group>
          <node name="outside" pkg="p" type="d" />
          <node name="sim_only" pkg="p" type="d" if="$(arg sim)" />
          <node name="real_only" pkg="p" type="d" unless="$(arg sim)" />
          <node name="maybe" pkg="p" type="d" if="$(arg mystery)" />
          <node name="$(arg mystery)_node" pkg="p" type="d" />
        </launch>
        """, args={"robot": "bot"})
    names = [n.name for n in model.nodes]
    assert names == ["/bot/hw/driver", "/abs/n", "/outside", "/real_only", "/maybe", "/?_node"]
    assert model.nodes[0].remaps == [("scan", "base_scan")]
    assert model.nodes[2].remaps == []
    maybe = model.nodes[4]
    assert [(c.kind, c.statement, c.text) for c in maybe.conditions] == [
        ("launch", "if", "$(arg mystery)")]
    assert [d.code for d in model.diagnostics] == ["LAUNCH_ARG_UNSET", "LAUNCH_ARG_UNSET"]
    assert model.args == {"robot": "bot", "sim": "false", "mystery": None}


def test_include_with_args_ns_and_find(write_tree):
    model = load_launch(write_tree, """
        <launch>
          <include file="$(find pkg)/launch/part.launch" ns="left">
            <arg name="side" value="L" />
          </include>
          <include file="$(dirname)/part.launch" />
        </launch>
        """, extra={"src/pkg/launch/part.launch": """
        <launch>
          <arg name="side" default="none" />
          <node name="cam_$(arg side)" pkg="p" type="cam" />
        </launch>
        """})
    assert [n.name for n in model.nodes] == ["/left/cam_L", "/cam_none"]
    assert model.files == ["pkg/launch/main.launch", "pkg/launch/part.launch",
                           "pkg/launch/part.launch"]


def test_env_and_optenv(write_tree):
    model = load_launch(write_tree, """
        <launch>
          <node name="$(env ROBOT)" pkg="p" type="d" />
          <node name="$(env NOT_SET)" pkg="p" type="d" />
          <node name="$(optenv NOT_SET fallback)" pkg="p" type="d" />
          <node name="$(anon worker)" pkg="p" type="d" />
        </launch>
        """, env={"ROBOT": "atlas"})
    assert [n.name for n in model.nodes] == ["/atlas", "/?", "/fallback", "/worker_?"]


def test_bad_input_becomes_diagnostics(write_tree):
    model = load_launch(write_tree, """
        <launch>
          <nodes name="typo" />
          <node name="x" pkg="p" type="d" colour="red" />
          <node pkg="p" type="d" />
          <param value="1" />
          <node name="y" pkg="p" type="d" if="maybe" />
          <include file="$(find pkg)/launch/missing.launch" />
          <include file="$(find pkg)/launch/main.launch" />
          <node name="z" pkg="p" type="$(arg undeclared)" />
          <node name="e" pkg="p" type="$(eval 1 + 1)" />
        </launch>
        """)
    found = [(d.code, d.location.line) for d in model.diagnostics]
    assert found == [
        ("LAUNCH_UNKNOWN_TAG", 2), ("LAUNCH_UNKNOWN_ATTRIBUTE", 3),
        ("LAUNCH_MISSING_ATTRIBUTE", 4), ("LAUNCH_MISSING_ATTRIBUTE", 5),
        ("LAUNCH_BAD_VALUE", 6), ("LAUNCH_FILE_MISSING", 7), ("LAUNCH_INCLUDE_CYCLE", 8),
        ("LAUNCH_ARG_UNSET", 9)]
    assert [(n.name, n.executable) for n in model.nodes] == [
        ("/x", "d"), ("/z", "?"), ("/e", "2")]
    assert all(d.location.file == "pkg/launch/main.launch" for d in model.diagnostics)


def test_malformed_xml(write_tree):
    model = load_launch(write_tree, "<launch>\n  <node name='a'\n</launch>\n")
    assert [(d.code, d.location.line) for d in model.diagnostics] == [
        ("LAUNCH_XML_SYNTAX", 3)]
    assert model.nodes == []


def test_an_element_is_located_where_its_start_tag_begins(write_tree):
    """libxml2 numbers an element by the line its start tag ends on; a node whose
    attributes run over several lines (summit_xl's controller spawners) is where its
    ``<node`` is, past a comment and a CDATA section that hold ``<node`` too."""
    launch = (
        "<launch>\n"                                              # 1
        "  <!-- <node name=\"old\" pkg=\"a\" type=\"b\"/> -->\n"  # 2
        "  <node name=\"spawner\" pkg=\"cm\"\n"                   # 3
        "        type=\"spawner\"\n"                              # 4
        "        args=\"a b\"/>\n"                                # 5
        "  <rosparam><![CDATA[text: <node>]]></rosparam>\n"       # 6
        "  <node name=\"one\" pkg=\"p\" type=\"t\"><param\n"      # 7
        "      name=\"rate\" value=\"2\"/></node>\n"              # 8
        "</launch>\n")
    model = load_launch(write_tree, launch)
    assert [(n.name, n.location.line) for n in model.nodes] == [
        ("/spawner", 3), ("/one", 7)]
    assert {p.name: p.location.line for p in model.params} == {
        "/text": 6, "/one/rate": 7}


def test_an_argument_the_command_line_gives_passed_to_an_include(write_tree):
    """franka_ros (develop): a top-level file declares ``robot_ip`` / ``robot_ips``
    without a value, for the command line to give, and hands it to an include, as an
    ``<arg value="$(arg robot_ips)">`` of the include or through pass_all_args. That is
    an argument left unset (a warning, once per use), not an argument "not defined here"
    nor one "the include does not pass" (errors)."""
    model = load_launch(write_tree, """
        <launch>
          <arg name="robot_ip" />
          <include file="$(dirname)/part.launch" pass_all_args="true" />
          <include file="$(dirname)/part.launch" ns="two">
            <arg name="robot_ip" value="$(arg robot_ip)" />
          </include>
          <include file="$(dirname)/part.launch" ns="three" />
        </launch>
        """, extra={"src/pkg/launch/part.launch": """
        <launch>
          <arg name="robot_ip" />
          <node name="driver" pkg="p" type="d">
            <param name="ip" value="$(arg robot_ip)" />
          </node>
        </launch>
        """})
    found = [(d.code, d.location.file, d.location.line) for d in model.diagnostics]
    assert found == [
        ("LAUNCH_ARG_UNSET", "pkg/launch/part.launch", 4),
        ("LAUNCH_ARG_UNSET", "pkg/launch/main.launch", 5),
        # no value given at all: roslaunch refuses the file even with robot_ip:=...
        ("LAUNCH_ARG_REQUIRED", "pkg/launch/part.launch", 4)]
    assert [n.name for n in model.nodes] == ["/driver", "/two/driver", "/three/driver"]


def test_pass_all_args_hands_on_what_the_command_line_gives(write_tree):
    """franka_ros' example controllers: ``roslaunch ... robot_ip:=IP`` on a file that
    does not declare robot_ip and includes franka_control.launch, which requires it, with
    pass_all_args: roslaunch passes the command line's arguments on, so the argument is
    unset in this configuration (a warning), not refused; through a second pass_all_args
    too, but not through an include without it."""
    model = load_launch(write_tree, """
        <launch>
          <include file="$(dirname)/middle.launch" pass_all_args="true" />
        </launch>
        """, extra={"src/pkg/launch/middle.launch": """
        <launch>
          <include file="$(dirname)/part.launch" pass_all_args="true" />
          <include file="$(dirname)/part.launch" ns="two" />
        </launch>
        """, "src/pkg/launch/part.launch": """
        <launch>
          <arg name="robot_ip" />
          <node name="driver" pkg="p" type="d" args="$(arg robot_ip)" />
        </launch>
        """})
    found = [(d.code, d.location.file, d.location.line) for d in model.diagnostics]
    assert found == [("LAUNCH_ARG_UNSET", "pkg/launch/part.launch", 3),
                     ("LAUNCH_ARG_REQUIRED", "pkg/launch/part.launch", 3)]


def test_an_undeclared_argument_of_the_top_level_file_is_the_command_lines(write_tree):
    """cartographer_ros' demo_backpack_2d.launch: ``args="--clock $(arg bag_filename)"``
    with no <arg name="bag_filename">: roslaunch makes every ``name:=value`` of its
    command line an argument of the top-level file, declared or not (and pass_all_args
    hands them on), so the file is run as ``roslaunch ... bag_filename:=FILE``. Left
    unset here: a warning, not "not defined here" (an error); a file included without
    pass_all_args still lacks it (an error); a value the configuration gives is used."""
    extra = {"src/pkg/launch/part.launch": """
        <launch>
          <node name="play" pkg="p" type="d" args="$(arg bag)" />
        </launch>
        """}
    launch = """
        <launch>
          <node name="top" pkg="p" type="d" args="--clock $(arg bag)" />
          <include file="$(dirname)/part.launch" pass_all_args="true" />
          <include file="$(dirname)/part.launch" ns="two" />
        </launch>
        """
    model = load_launch(write_tree, launch, extra=extra)
    found = [(d.code, d.location.file, d.location.line) for d in model.diagnostics]
    assert found == [("LAUNCH_ARG_UNSET", "pkg/launch/main.launch", 2),
                     ("LAUNCH_ARG_UNSET", "pkg/launch/part.launch", 2),
                     ("LAUNCH_ARG_REQUIRED", "pkg/launch/part.launch", 2)]
    given = load_launch(write_tree, launch, extra=extra, args={"bag": "b.bag"})
    assert [(n.name, n.args) for n in given.nodes] == [
        ("/top", "--clock b.bag"), ("/play", "b.bag"), ("/two/play", "?")]
    assert [d.code for d in given.diagnostics] == ["LAUNCH_ARG_REQUIRED"]


def test_rosparam_text_an_unset_argument_makes_is_unknown_not_a_scalar(write_tree):
    """franka_combined_control.launch: ``<rosparam subst_value="True">$(arg
    robot_ips)</rosparam>``, robot_ips given on the command line as a YAML dictionary.
    Unset, the text is unknown: it may set anything under the namespace (``/?``), where
    it was refused as a non-dictionary value (a LAUNCH_YAML error)."""
    model = load_launch(write_tree, """
        <launch>
          <arg name="robot_ips" />
          <group ns="arm">
            <rosparam subst_value="true">$(arg robot_ips)</rosparam>
            <rosparam subst_value="true" param="one">$(arg robot_ips)</rosparam>
          </group>
          <rosparam>just text</rosparam>
        </launch>
        """)
    found = [(d.code, d.location.line) for d in model.diagnostics]
    assert found == [("LAUNCH_ARG_UNSET", 4), ("LAUNCH_ARG_UNSET", 5), ("LAUNCH_YAML", 7)]
    assert [(p.name, p.value) for p in model.params] == [("/arm/?", None), ("/arm/one", None)]


def test_an_included_file_outside_the_workspace_is_not_read(write_tree):
    """``<include file="$(env HOME)/gen/there.launch"/>``: a file outside the workspace
    and the installed packages is not read (as ``<rosparam file>``), whether it is on the
    analysing machine or not: what it would start stays unknown, no missing file."""
    import os

    probe = write_tree({"home/gen/there.launch": """
        <launch><node name="stray" pkg="pkg" type="n" /></launch>
        """})
    env = {"HOME": os.path.join(str(probe), "home")}
    model = load_launch(write_tree, """
        <launch>
          <include file="$(env HOME)/gen/there.launch" />
          <include file="$(env HOME)/gen/gone.launch" />
        </launch>
        """, env=env)
    assert [n.name for n in model.nodes] == []
    assert [(d.code, d.location.line) for d in model.diagnostics] == [
        ("LAUNCH_UNKNOWN_VALUE", 2), ("LAUNCH_UNKNOWN_VALUE", 3)]


def test_a_typed_param_of_unknown_value_gets_the_model_type_name(write_tree):
    """strands_navigation's manager.launch: ``<param name="white_list_file" value="$(arg
    white_list_file)" type="string"/>`` with the argument unset. Its type stayed the
    launch spelling "string", and parameter-type-mismatch reported "set as string but
    read as str" against a node reading it with a str default."""
    model = load_launch(write_tree, """
        <launch>
          <arg name="f" />
          <param name="a" value="$(arg f)" type="string" />
          <param name="b" value="$(arg f)" type="boolean" />
          <param name="c" value="$(arg f)" type="Double" />
          <param name="d" value="$(arg f)" />
        </launch>
        """)
    assert [(p.name, p.value, p.type) for p in model.params] == [
        ("/a", None, "str"), ("/b", None, "bool"), ("/c", None, "double"), ("/d", None, None)]


def test_a_node_child_of_another_case_is_roslaunchs_tag(write_tree):
    """roslaunch takes a <node>'s children by their lower-cased name (xmlloader's
    ``t.tagName.lower()``): Lslidar's ``<Param name=... value=...>`` sets the parameter,
    and its attributes are the param tag's, not unknown ones (two false
    LAUNCH_UNKNOWN_ATTRIBUTE warnings said they were ignored). An attribute no param has
    is still said; a top-level tag of another case is still unknown."""
    model = load_launch(write_tree, """
        <launch>
          <node name="driver" pkg="p" type="d">
            <Param name="topic" value="points" />
            <REMAP from="in" to="/scan" />
            <Param name="rate" valu="2" />
          </node>
          <Param name="top" value="1" />
        </launch>
        """)
    assert [(p.name, p.value) for p in model.params] == [("/driver/topic", "points")]
    assert model.nodes[0].remaps == [("in", "/scan")]
    found = [(d.code, d.location.line) for d in model.diagnostics]
    assert found == [("LAUNCH_UNKNOWN_ATTRIBUTE", 5), ("LAUNCH_BAD_VALUE", 5),
                     ("LAUNCH_UNKNOWN_TAG", 7)]
