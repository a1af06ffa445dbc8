"""Launch models: the launch files of a package installed on the robot, not here, read from
its interface model (``models.launch_files``): an include of ``$(find sim_pkg)/launch/
world.launch`` starts the nodes that file starts, with the parameters of the YAML files
it loads from its package, placed at the model's upstream file and line."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.models.format import from_document
from haros_arch.models.generate import build_package, read_list, tasks
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

COMMIT = "0123456789abcdef0123456789abcdef01234567"
WORLD = """\
<launch>
  <!-- a comment the model drops -->
  <arg name="paused" default="false" doc="start paused"/>
  <arg name="gui" default="true"/>
  <group ns="sim">
    <node name="server" pkg="sim_pkg" type="server" args="$(arg paused)">
      <rosparam command="load" file="$(find sim_pkg)/config/server.yaml"/>
      <remap from="tick" to="/clock"/>
    </node>
  </group>
  <node if="$(arg gui)" name="client" pkg="sim_pkg" type="client"/>
  <include file="$(find sim_pkg)/launch/inner.launch">
    <arg name="rate" value="5"/>
  </include>
  <unknown_tag/>
</launch>
"""
INNER = """\
<launch>
  <arg name="rate"/>
  <param name="/sim/rate" value="$(arg rate)"/>
  <rosparam ns="sub" file="$(find sim_pkg)/config/subst.yaml" subst_value="true"/>
  <param name="/sim/text" textfile="$(find sim_pkg)/config/server.yaml"/>
</launch>
"""
SERVER_YAML = "update_rate: 100\nphysics:\n  gravity: -9.8\n"


def _model(tmp_path) -> dict:
    """The model ``models build`` makes of sim_pkg, from its source."""
    tree = tmp_path / "sources" / "example+sim@0123456789ab" / "sim_pkg"
    (tree / "launch").mkdir(parents=True)
    (tree / "config").mkdir()
    (tree / "package.xml").write_text(package_xml("sim_pkg"))
    (tree / "CMakeLists.txt").write_text("cmake_minimum_required(VERSION 3.0)\n"
                                         "project(sim_pkg)\nfind_package(catkin)\n"
                                         "catkin_package()\n")
    (tree / "launch" / "world.launch").write_text(WORLD)
    (tree / "launch" / "inner.launch").write_text(INNER)
    (tree / "launch" / "notes.xml").write_text("<launch/>\n")  # not a launch file name
    (tree / "config" / "server.yaml").write_text(SERVER_YAML)
    (tree / "config" / "unused.yaml").write_text("x: 1\n")  # no launch file loads it
    # a substitution: subst_value would change what it sets, so it is not kept
    (tree / "config" / "subst.yaml").write_text("rate: $(arg rate)\n")
    listed = tmp_path / "list.yaml"
    listed.write_text(f"- repository: github:example/sim\n  commit: {COMMIT}\n"
                      "  distro: noetic\n  packages: [sim_pkg]\n")
    (task,) = tasks(read_list(str(listed)), str(tmp_path / "sources"),
                    str(tmp_path / "no_overrides"), cache_dir=None)
    outcome = build_package(task)
    assert outcome.problem is None and outcome.text is not None
    assert outcome.files == (2, 1)  # what the build's report says it kept
    return json.loads(outcome.text)


def test_models_build_records_the_launch_files_and_the_parameter_files_they_load(tmp_path):
    data = _model(tmp_path)
    model = from_document(data)
    assert model.launch_files is not None
    assert sorted(model.launch_files) == ["launch/inner.launch", "launch/world.launch"]
    world = model.launch_files["launch/world.launch"]
    assert [(c["tag"], c["line"]) for c in world["children"]] == [
        ("arg", 3), ("arg", 4), ("group", 5), ("node", 11), ("include", 12)]
    assert world["children"][0]["attrs"] == {"name": "paused", "default": "false"}
    node = world["children"][2]["children"][0]
    assert [(c["tag"], c["line"]) for c in node["children"]] == [("rosparam", 7),
                                                                 ("remap", 8)]
    assert model.param_files == {"config/server.yaml": {
        "value": {"update_rate": 100, "physics": {"gravity": -9.8}},
        "lines": {"update_rate": 1, "physics": {"gravity": 3}}}}
    assert from_document(json.loads(json.dumps(data))).launch_files == model.launch_files


def _workspace(tmp_path, write_tree, model: dict, include: str):
    model["nodes"] = [{"package": "sim_pkg", "executable": "server", "kind": "executable",
                       "language": "cpp", "rosname": "server", "completeness": "complete",
                       "calls": [{"kind": "publish", "name": "tick",
                                  "type": "rosgraph_msgs/Clock"},
                                 {"kind": "read", "name": "~update_rate"}]}]
    root = write_tree({
        "ws/src/app/package.xml": package_xml("app"),
        "ws/src/app/launch/sim.launch": (
            "<launch>\n"
            f"  <include file=\"$(find sim_pkg)/launch/{include}\">\n"
            "    <arg name=\"gui\" value=\"false\"/>\n"
            "  </include>\n"
            "</launch>\n"),
        "ws/models/sim_pkg.json": json.dumps(model),
        "ws/project.yaml": ("project: p\nworkspace: src\ndistro: noetic\nmodels: [models]\n"
                            "configurations:\n  c: [app/launch/sim.launch]\n"),
    })
    result = analyse(load(str(root / "ws" / "project.yaml")), {},
                     Options(cache_dir=None, jobs=1))
    (config,) = result.configurations
    return config


def test_an_include_of_a_modelled_launch_file_starts_its_nodes(tmp_path, write_tree):
    config = _workspace(tmp_path, write_tree, _model(tmp_path), "world.launch")
    names = {n.name: n for n in config.nodes}
    assert "/sim/server" in names and "/client" not in names  # gui:=false
    server = names["/sim/server"]
    assert server.node is not None and server.node.model is not None
    assert server.location.file == (
        "github:example/sim@01234567/sim_pkg/launch/world.launch")
    assert server.location.line == 6
    published = {(link.rosname.full, link.node.name) for link in config.links
                 if link.kind == "publish"}
    assert ("/clock", "/sim/server") in published  # its remap, from the modelled file
    params = {p.name: p for p in config.parameters}
    assert params["/sim/server/update_rate"].value == 100
    assert params["/sim/server/physics/gravity"].value == -9.8
    where = params["/sim/server/physics/gravity"].location
    assert (where.file, where.line) == (
        "github:example/sim@01234567/sim_pkg/config/server.yaml", 3)
    assert params["/sim/rate"].value == 5  # the modelled include's include
    # a parameter file the model does not keep, and one it keeps parsed, not as text:
    # not known, said at the modelled line; the namespace loaded may hold anything
    inner = "github:example/sim@01234567/sim_pkg/launch/inner.launch"
    assert sorted((d.location.file, d.location.line) for d in config.diagnostics
                  if d.code == "LAUNCH_UNKNOWN_VALUE") == [(inner, 4), (inner, 5)]
    assert "/sub/?" in params and params["/sim/text"].value is None


def test_a_file_the_model_does_not_hold_stays_unknown(tmp_path, write_tree):
    config = _workspace(tmp_path, write_tree, _model(tmp_path), "missing.launch")
    unknown = [d for d in config.diagnostics if d.code == "LAUNCH_UNKNOWN_VALUE"]
    assert any("holds no file launch/missing.launch" in d.message for d in unknown)
    assert not [d for d in config.diagnostics if d.code == "LAUNCH_FILE_MISSING"]
    assert "/sim/server" not in {n.name for n in config.nodes}


def test_a_model_without_launch_files_leaves_the_include_unread(tmp_path, write_tree):
    model = _model(tmp_path)
    del model["launch_files"], model["param_files"]
    config = _workspace(tmp_path, write_tree, model, "world.launch")
    assert "/sim/server" not in {n.name for n in config.nodes}
    assert any(d.code == "LAUNCH_UNKNOWN_VALUE" and "sim_pkg" in d.message
               for d in config.diagnostics)


def test_the_shipped_noetic_launch_models_start_gazebo_and_mavros(write_tree):
    """gazebo_ros' empty_world.launch and mavros' px4.launch -> node.launch, from the
    shipped noetic models: the gazebo node with /use_sim_time, mavros' node with the
    plugin lists and configuration of px4_pluginlists.yaml / px4_config.yaml."""
    root = write_tree({
        "src/app/package.xml": package_xml("app"),
        "src/app/launch/sim.launch": (
            "<launch>\n"
            "  <include file=\"$(find gazebo_ros)/launch/empty_world.launch\">\n"
            "    <arg name=\"gui\" value=\"false\"/>\n"
            "  </include>\n"
            "  <include file=\"$(find mavros)/launch/px4.launch\">\n"
            "    <arg name=\"fcu_url\" value=\"udp://:14540@127.0.0.1:14557\"/>\n"
            "  </include>\n"
            "</launch>\n"),
        "project.yaml": ("project: p\nworkspace: src\ndistro: noetic\n"
                         "configurations:\n  c: [app/launch/sim.launch]\n"),
    })
    (config,) = analyse(load(str(root / "project.yaml")), {},
                        Options(cache_dir=None, jobs=1)).configurations
    nodes = {n.name: n for n in config.nodes}
    assert nodes["/gazebo"].node is not None
    assert nodes["/gazebo"].node.name == "gazebo_ros/gzserver"
    assert nodes["/mavros"].node is not None
    assert nodes["/mavros"].node.name == "mavros/mavros_node"
    assert "/gazebo_gui" not in nodes
    params = {p.name: p.value for p in config.parameters}
    assert params["/use_sim_time"] is True
    assert params["/mavros/fcu_url"] == "udp://:14540@127.0.0.1:14557"
    assert "safety_area" in params["/mavros/plugin_blacklist"]
    assert params["/mavros/conn/heartbeat_rate"] == 1.0
    assert not [d for d in config.diagnostics if d.code == "LAUNCH_UNKNOWN_VALUE"]
