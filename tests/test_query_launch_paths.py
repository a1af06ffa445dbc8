"""absolute-paths-in-launch on a real launch: $(find) paths are portable, others not."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.model.load import from_data
from haros_arch.model.serialise import model_to_data
from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query.catalogue import load_catalogue, run_rule

LAUNCH = """
<launch>
  <arg name="map" default="$(find nav)/maps/lab.yaml" />
  <node name="map_server" pkg="nav" type="map_server" args="$(arg map)" />
  <param name="map_file" value="$(find nav)/maps/lab.yaml" />
  <param name="calibration" value="/home/alice/calib/camera.yaml" />
</launch>
"""


def test_find_paths_are_not_hard_coded(write_tree):
    root = write_tree({
        "src/nav/package.xml": package_xml("nav"),
        "src/nav/CMakeLists.txt": "project(nav)\n",
        "src/nav/launch/map.launch": LAUNCH,
        "src/nav/maps/lab.yaml": "image: lab.pgm\n",
        "project.yaml": "project: p\nconfigurations:\n  c: [nav/launch/map.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (rule,) = [r for r in load_catalogue() if r.id == "absolute-paths-in-launch"]
    reloaded = from_data(json.loads(json.dumps(model_to_data(model))))
    for found in (run_rule(rule, model), run_rule(rule, reloaded)):
        assert [f.entities for f in found] == [("parameter:/calibration",)]
    assert model.configurations[0].package_paths == [str(root / "src")]


ENVIRONMENT_LAUNCH = """
<launch>
  <node name="map_saver" pkg="nav" type="map_saver" args="-f $(optenv HOME /home/summit)/map" />
  <param name="map_file" value="$(env ROBOT_MAP)" />
  <param name="config" value="$(optenv ROBOT_CONFIG /opt/robot)/config.yaml" />
  <param name="calibration" value="/home/alice/calib/camera.yaml" />
</launch>
"""


def test_environment_paths_are_not_hard_coded(write_tree):
    """A path the launch file takes from the environment ($(env), $(optenv) when the
    variable is set) follows the machine that runs it (summit_xl_localization's
    map_saver.launch: ``-f $(optenv HOME /home/summit)/map``); the default of an
    optenv whose variable is not set is the file's own, hard-coded."""
    root = write_tree({
        "src/nav/package.xml": package_xml("nav"),
        "src/nav/CMakeLists.txt": "project(nav)\n",
        "src/nav/launch/save.launch": ENVIRONMENT_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [nav/launch/save.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")),
                    {"PATH": "", "HOME": "/home/bob/", "ROBOT_MAP": "/srv/maps/lab.yaml"})
    (rule,) = [r for r in load_catalogue() if r.id == "absolute-paths-in-launch"]
    reloaded = from_data(json.loads(json.dumps(model_to_data(model))))
    for found in (run_rule(rule, model), run_rule(rule, reloaded)):
        assert sorted(f.entities for f in found) == [
            ("parameter:/calibration",), ("parameter:/config",)]
    assert model.configurations[0].package_paths == ["/home/bob", "/srv/maps/lab.yaml"]
