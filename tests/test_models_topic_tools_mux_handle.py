"""topic_tools' mux and demux advertise ``selected`` and serve ``select``, ``add``,
``list`` and ``delete`` on ``ros::NodeHandle mux_nh("mux")`` (``demux_nh("demux")``,
ros_comm mux.cpp:313-380, demux.cpp:269-295). roscpp resolves and remaps a handle's
namespace before the names in it, so ``<remap from="mux" to="base_mux"/>``, the way
topic_tools documents running several muxes, moves all five to ``/base_mux/...``:
no two muxes share ``/mux/selected`` or ``/mux/select``, and the remap is used."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue


def _configuration(root):
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    return model, config


def _names(config, node, kind):
    instance = next(n for n in config.nodes if n.name == node)
    return sorted(link.name for link in instance.links if link.kind == kind)


def test_a_remapped_mux_handle_moves_its_selected_topic_and_services(write_tree):
    root = write_tree({
        "src/robot/package.xml": package_xml("robot"),
        "src/robot/CMakeLists.txt": "project(robot)\n",
        "src/robot/launch/muxes.launch": """
            <launch>
              <node pkg="topic_tools" type="mux" name="base_mux" args="cmd_vel nav_vel joy_vel">
                <remap from="mux" to="base_mux"/>
              </node>
              <node pkg="topic_tools" type="mux" name="image_mux" args="image cam_a cam_b">
                <remap from="mux" to="image_mux"/>
              </node>
              <node pkg="topic_tools" type="demux" name="split" args="in out_a out_b">
                <remap from="demux" to="split"/>
              </node>
              <node pkg="topic_tools" type="mux" name="plain" args="out in_a"/>
            </launch>
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [robot/launch/muxes.launch]\n",
    })
    model, config = _configuration(root)
    assert _names(config, "/base_mux", "publish") == ["/base_mux/selected", "/cmd_vel"]
    assert _names(config, "/base_mux", "server") == [
        "/base_mux/add", "/base_mux/delete", "/base_mux/list", "/base_mux/select",
        "/cmd_vel_select"]
    assert "/image_mux/selected" in _names(config, "/image_mux", "publish")
    assert _names(config, "/split", "server") == [
        "/split/add", "/split/delete", "/split/list", "/split/select"]
    assert "/split/selected" in _names(config, "/split", "publish")
    # not remapped: the documented default names
    assert "/mux/selected" in _names(config, "/plain", "publish")
    assert "/mux/select" in _names(config, "/plain", "server")
    findings = run_catalogue(model)
    rules = {f.rule for f in findings}
    assert "multiple-publishers" not in rules
    assert "multiple-service-servers" not in rules
    assert "remap-unused" not in rules
