"""gazebo_ros' gzclient in the shipped noetic model: empty_world.launch with the GUI on
starts ``gazebo_gui`` (gzclient), which loads the ROS API plugin into Gazebo's client
(``-g``), where only the plugin's Load() runs: ``~enable_ros_network`` read and the
physics reconfigure thread's two service clients, nothing served (no world is created
in the client)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load


def _analyse(write_tree, gui: str):
    root = write_tree({
        "src/app/package.xml": package_xml("app"),
        "src/app/launch/sim.launch": (
            "<launch>\n"
            "  <include file=\"$(find gazebo_ros)/launch/empty_world.launch\">\n"
            f"    <arg name=\"gui\" value=\"{gui}\"/>\n"
            "  </include>\n"
            "</launch>\n"),
        "project.yaml": ("project: p\nworkspace: src\ndistro: noetic\n"
                         "configurations:\n  c: [app/launch/sim.launch]\n"),
    })
    result = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = result.configurations
    return result, config


def test_gazebo_gui_runs_the_gzclient_model_with_the_plugins_load_interface(write_tree):
    result, config = _analyse(write_tree, "true")
    nodes = {n.name: n for n in config.nodes}
    gui = nodes["/gazebo_gui"]
    assert gui.node is not None
    assert gui.node.name == "gazebo_ros/gzclient"
    links = {(link.kind, link.rosname.full) for link in gui.links}
    assert links == {("read", "/gazebo_gui/enable_ros_network"),
                     ("client", "/gazebo_gui/set_physics_properties"),
                     ("client", "/gazebo_gui/get_physics_properties")}
    # the server's interface stays the server's: /gazebo serves the physics services
    server = {(link.kind, link.rosname.full) for link in nodes["/gazebo"].links}
    assert ("server", "/gazebo/set_physics_properties") in server
    assert ("publish", "/clock") in server
    codes = {d.code for d in (*result.diagnostics, *config.diagnostics)}
    assert "MODEL_NODE_MISSING" not in codes


def test_without_the_gui_there_is_no_gazebo_gui(write_tree):
    _, config = _analyse(write_tree, "false")
    assert "/gazebo_gui" not in {n.name for n in config.nodes}
