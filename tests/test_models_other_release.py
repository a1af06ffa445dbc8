"""A distribution without models of its own (melodic, kinetic; foxy, rolling) takes the
model of the nearest release of its ROS that has one: what that node publishes and
serves is known, what it lacks is not (its release may read or name other things), so
the node is partial and checks that claim something absent do not decide on it."""

from __future__ import annotations

import pytest
from conftest import package_xml

from haros_arch.models.attach import stand_ins
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue

LAUNCH = """
<launch>
  <node pkg="map_server" type="map_server" name="map_server" args="$(find robot)/map.yaml"/>
  <node pkg="amcl" type="amcl" name="amcl">
    <param name="odom_frame_id" value="odom"/>
    <param name="odom_frame" value="odom"/>
  </node>
</launch>
"""


def _analyse(write_tree, distro: str):
    root = write_tree({
        "src/robot/package.xml": package_xml("robot").replace(
            "</package>", "<exec_depend>map_server</exec_depend>"
                          "<exec_depend>amcl</exec_depend></package>"),
        "src/robot/CMakeLists.txt": "project(robot)\nfind_package(catkin REQUIRED)\n"
                                    "catkin_package()\n",
        "src/robot/map.yaml": "image: map.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n",
        "src/robot/launch/nav.launch": LAUNCH,
        "project.yaml": f"project: p\ndistro: {distro}\n"
                        "configurations:\n  c: [robot/launch/nav.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    return model, config


@pytest.mark.parametrize("distro", ["melodic", "kinetic"])
def test_an_older_ros1_release_takes_noetics_model_as_partial(write_tree, distro):
    model, config = _analyse(write_tree, distro)
    nodes = {n.name: n for n in config.nodes}
    for name in ("/map_server", "/amcl"):
        node = nodes[name].node
        assert node.model.startswith("noetic/"), node.model
        assert node.completeness == "partial"
        assert any("standing for another release" in r for r in node.completeness_reasons)
    assert "/map" in {link.topic_name for link in nodes["/map_server"].publishers}
    assert "/scan" in {link.topic_name for link in nodes["/amcl"].subscribers}
    codes = [d.code for d in config.diagnostics]
    assert "NODE_PACKAGE_UNKNOWN" not in codes
    (note,) = [d.message for d in config.diagnostics if d.code == "MODEL_DISTRO"]
    assert f"{distro} has none here: noetic's stand for it" in note
    findings = {f.rule for f in run_catalogue(model)}
    # amcl of noetic reads odom_frame_id, not odom_frame: another release might
    assert "parameter-set-not-read" not in findings
    assert "parameter-set-not-read-undecided" in findings


def test_noetic_takes_its_own_models_whole(write_tree):
    model, config = _analyse(write_tree, "noetic")
    nodes = {n.name: n for n in config.nodes}
    assert nodes["/amcl"].node.completeness == "model"
    (note,) = [d.message for d in config.diagnostics if d.code == "MODEL_DISTRO"]
    assert "stand for" not in note
    unread = [str(f.entities) for f in run_catalogue(model)
              if f.rule == "parameter-set-not-read"]
    assert len(unread) == 1 and "/amcl/odom_frame'" in unread[0]


def test_a_name_of_no_distribution_takes_no_model_and_says_so(write_tree):
    _, config = _analyse(write_tree, "noetc")
    codes = [d.code for d in config.diagnostics]
    assert codes.count("NODE_PACKAGE_UNKNOWN") == 2
    (note,) = [d.message for d in config.diagnostics if d.code == "MODEL_DISTRO"]
    assert "no ROS distribution of that name is known" in note


def test_the_nearest_release_first_the_newer_of_two_as_near():
    assert stand_ins("melodic")[:3] == ("noetic", "lunar", "kinetic")
    assert stand_ins("foxy")[:3] == ("galactic", "eloquent", "humble")
    assert stand_ins("rolling")[:2] == ("kilted", "jazzy")
    assert stand_ins("humble")[:2] == ("iron", "galactic")
    assert stand_ins("noetc") == ()
