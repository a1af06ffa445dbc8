"""A problem of an installed package's own launch file (read from its interface model)
that the workspace's include causes also names that include: the user cannot edit
mavros' node.launch, but the value it fails on (a ``config_yaml`` that is not there) is
the one the workspace's launch file gave it. PX4-Avoidance 5355f245: local_planner's
mavros.launch passed ``$(find local_planner)/resource/px4_config.yaml`` after the file
had moved to another package, and roslaunch stopped at node.launch's ``<rosparam>``."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load


def _configuration(write_tree, launch: str, extra: dict[str, str] | None = None):
    root = write_tree({
        "src/app/package.xml": package_xml("app"),
        "src/app/launch/fly.launch": launch,
        **(extra or {}),
        "project.yaml": ("project: p\nworkspace: src\ndistro: noetic\n"
                         "configurations:\n  c: [app/launch/fly.launch]\n"),
    })
    (config,) = analyse(load(str(root / "project.yaml")), {},
                        Options(cache_dir=None, jobs=1)).configurations
    return config


def _bad_values(config):
    return [d for d in config.diagnostics if d.code == "LAUNCH_BAD_VALUE"]


def test_a_missing_file_given_to_an_installed_launch_file_names_the_include(write_tree):
    config = _configuration(write_tree, (
        "<launch>\n"
        "  <group ns=\"uav\">\n"
        "    <include file=\"$(find mavros)/launch/node.launch\">\n"
        "      <arg name=\"pluginlists_yaml\"\n"
        "           value=\"$(find mavros)/launch/px4_pluginlists.yaml\"/>\n"
        "      <arg name=\"config_yaml\" value=\"$(find app)/resource/px4_config.yaml\"/>\n"
        "      <arg name=\"fcu_url\" value=\"udp://:14540@localhost:14557\"/>\n"
        "      <arg name=\"gcs_url\" value=\"\"/>\n"
        "      <arg name=\"tgt_system\" value=\"1\"/>\n"
        "      <arg name=\"tgt_component\" value=\"1\"/>\n"
        "    </include>\n"
        "  </group>\n"
        "</launch>\n"))
    (said,) = _bad_values(config)
    assert "px4_config.yaml" in said.message
    # where roslaunch fails: mavros' own file, upstream
    assert said.location.file.startswith("github:mavlink/mavros@")
    assert said.location.file.endswith("/launch/node.launch")
    # and the workspace's include that gave it the value
    assert [(a.file, a.line) for a in said.also] == [("app/launch/fly.launch", 3)]


def test_through_two_installed_files_the_workspace_include_is_named(write_tree):
    """fly.launch -> mavros' px4.launch -> node.launch: the include the workspace wrote,
    not px4.launch's own include of node.launch, which nobody here can change."""
    config = _configuration(write_tree, (
        "<launch>\n"
        "  <arg name=\"respawn\" default=\"maybe\"/>\n"
        "  <include file=\"$(find mavros)/launch/px4.launch\">\n"
        "    <arg name=\"respawn_mavros\" value=\"$(arg respawn)\"/>\n"
        "  </include>\n"
        "</launch>\n"))
    bad = [d for d in _bad_values(config) if "respawn" in d.message]
    assert bad
    for said in bad:
        assert said.location.file.endswith("/launch/node.launch")
        assert [(a.file, a.line) for a in said.also] == [("app/launch/fly.launch", 3)]


def test_a_problem_of_a_workspace_file_names_no_other_place(write_tree):
    """The workspace's own included file is the one to change: said there alone."""
    config = _configuration(write_tree, (
        "<launch>\n"
        "  <include file=\"$(find app)/launch/inner.launch\"/>\n"
        "</launch>\n"), {
        "src/app/launch/inner.launch": (
            "<launch>\n"
            "  <rosparam command=\"load\" file=\"$(find app)/config/none.yaml\"/>\n"
            "</launch>\n")})
    (said,) = _bad_values(config)
    assert (said.location.file, said.location.line) == ("app/launch/inner.launch", 2)
    assert said.also == ()
