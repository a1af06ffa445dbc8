"""ROS 2 code that picks calls by rclcpp's version (navigation2 1.5.0 declares
``introspection_mode`` only under ``#if RCLCPP_VERSION_GTE(29, 0, 0)``): the stand-ins
announced Jazzy's rclcpp whatever the project's distribution, so a launch file's
``introspection_mode`` was "set but never read" for Kilted and Rolling too. The version
now follows the project's ``distro:`` (else ROS_DISTRO); with none known, a call the
default version leaves out is read from a parse with another distribution's version,
and every call of a branch on the version is made under that branch's condition,
which no configuration decides: checks that rest on it are undecided. Only a branch
that no parse reads makes the node partial (CPP_VERSION_UNKNOWN)."""

from __future__ import annotations

import os
import re

import pytest
from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp, versions
from haros_arch.extract.cpp.headers import STANDIN
from haros_arch.pipeline import Options, analyse, source_distro
from haros_arch.project import load
from haros_arch.query.catalogue import load_catalogue, run_rule
from haros_arch.workspace import scan

NODE = """
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp/version.h>
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("server");
  node->declare_parameter("rate", 10);
#if RCLCPP_VERSION_GTE(29, 0, 0)
  node->declare_parameter("introspection_mode", std::string("disabled"));
#else
  (void)node;
#endif
  rclcpp::spin(node);
}
"""

LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package='srv', executable='server', parameters=[
        {'rate': 5, 'introspection_mode': 'metadata'}])])
"""


def _tree(write_tree, project: str):
    return write_tree({
        "src/srv/package.xml": package_xml("srv", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend></package>"),
        "src/srv/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(srv)\n"
                                  "add_executable(server src/server.cpp)\n",
        "src/srv/src/server.cpp": NODE,
        "src/srv/launch/srv.launch.py": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [srv/launch/srv.launch.py]\n"
                        + project,
    })


def _model(write_tree, project: str, env: dict[str, str] | None = None):
    root = _tree(write_tree, project)
    return analyse(load(str(root / "project.yaml")),
                   {"PATH": os.environ.get("PATH", ""), **(env or {})},
                   Options(cache_dir=None))


def _findings(model) -> list[tuple[str, str]]:
    rule = next(r for r in load_catalogue() if r.id == "parameter-set-not-read")
    return [(f.rule, f.message.split(" ")[0]) for f in run_rule(rule, model)]


def _declared(model) -> set[str]:
    node = next(n for p in model.packages for n in p.nodes if n.executable == "server")
    return {c.name for c in node.calls if c.kind == "declare"}


def test_jazzy_does_not_read_what_kilted_reads(write_tree) -> None:
    model = _model(write_tree, "distro: jazzy\n")
    assert _declared(model) == {"rate"}
    assert _findings(model) == [("parameter-set-not-read", "/server/introspection_mode")]
    assert not [d for d in model.diagnostics if d.code == "CPP_VERSION_UNKNOWN"]


@pytest.mark.parametrize("distro", ["kilted", "rolling"])
def test_kilted_and_rolling_read_it(write_tree, distro: str) -> None:
    model = _model(write_tree, f"distro: {distro}\n")
    assert _declared(model) == {"rate", "introspection_mode"}
    assert _findings(model) == []


def test_ros_distro_of_the_environment_chooses_when_the_project_does_not(write_tree) -> None:
    model = _model(write_tree, "", {"ROS_DISTRO": "kilted"})
    assert _declared(model) == {"rate", "introspection_mode"}
    # the project file's distro wins over the environment's
    model = _model(write_tree, "distro: jazzy\n", {"ROS_DISTRO": "kilted"})
    assert _declared(model) == {"rate"}


def test_no_distribution_known_leaves_the_read_undecided(write_tree) -> None:
    model = _model(write_tree, "")
    node = next(n for p in model.packages for n in p.nodes if n.executable == "server")
    # the branch left out is read from a parse with Rolling's rclcpp: a call under the
    # version's condition, not an interface nobody read (navigation2's node_utils.hpp:402
    # made 34 of the 40 nodes of cloned_multi_tb3_simulation partial)
    assert node.completeness == "complete"
    assert not [d for d in model.diagnostics if d.code == "CPP_VERSION_UNKNOWN"]
    made = {c.name: [str(k) for k in c.conditions] for c in node.calls
            if c.kind == "declare"}
    assert made == {"rate": [], "introspection_mode": ["#if (RCLCPP_VERSION_GTE(29, 0, 0))"]}
    # not "never read", nor read for sure: the version decides, and it is not known
    assert _findings(model) == [("parameter-set-not-read-undecided", "1")]


def test_the_configurations_disagreeing_is_no_distribution(write_tree) -> None:
    root = _tree(write_tree, "")
    text = (root / "project.yaml").read_text().replace(
        "  c: [srv/launch/srv.launch.py]\n",
        "  c:\n    launch: [srv/launch/srv.launch.py]\n    environment: {ROS_DISTRO: jazzy}\n"
        "  d:\n    launch: [srv/launch/srv.launch.py]\n    environment: {ROS_DISTRO: kilted}\n")
    (root / "project.yaml").write_text(text)
    assert source_distro(load(str(root / "project.yaml")), {}) is None
    text = text.replace("{ROS_DISTRO: kilted}", "{ROS_DISTRO: jazzy}")
    (root / "project.yaml").write_text(text)
    assert source_distro(load(str(root / "project.yaml")), {"ROS_DISTRO": "kilted"}) == "jazzy"


def _calls(tmp_path, text: str, distro: str | None):
    source = tmp_path / "n.cpp"
    source.write_text(text)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro=distro)
    return ({(c.kind, c.name) for c in result.calls},
            [d.location.line for d in result.diagnostics if d.code == "CPP_VERSION_UNKNOWN"])


BRANCHES = """
#include <rclcpp/rclcpp.hpp>
void f(rclcpp::Node & node) {
#if RCLCPP_VERSION_MAJOR >= 30
  node.declare_parameter("rolling_only", 1);
#elif RCLCPP_VERSION_GTE(29, 5, 0)
  node.declare_parameter("kilted", 1);
#else
  node.declare_parameter("older", 1);
#endif
}
"""


@pytest.mark.parametrize(("distro", "name"), [
    ("humble", "older"), ("iron", "older"), ("jazzy", "older"), ("kilted", "kilted"),
    ("rolling", "rolling_only")])
def test_each_distribution_takes_its_own_branch(tmp_path, distro: str, name: str) -> None:
    calls, unknown = _calls(tmp_path, BRANCHES, distro)
    assert calls == {("declare", name)}
    assert unknown == []


def _conditions(tmp_path, text: str, distro: str | None) -> dict[str, list[str]]:
    source = tmp_path / "n.cpp"
    source.write_text(text)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro=distro)
    return {c.name: [str(k) for k in c.conditions] for c in result.calls}


def test_without_a_distribution_each_branch_is_read_under_its_condition(tmp_path) -> None:
    calls, unknown = _calls(tmp_path, BRANCHES, None)
    # jazzy's (the stand-ins' own), Rolling's and Kilted's: each version's parse reads one
    assert calls == {("declare", "older"), ("declare", "rolling_only"), ("declare", "kilted")}
    assert unknown == []
    assert _conditions(tmp_path, BRANCHES, None) == {
        "rolling_only": ["#if (RCLCPP_VERSION_MAJOR >= 30)"],
        "kilted": ["#elif (RCLCPP_VERSION_GTE(29, 5, 0))"],
        "older": ["#else (RCLCPP_VERSION_MAJOR >= 30)"]}
    # a distribution that is no ROS 2 one we know is none known
    assert _calls(tmp_path, BRANCHES, "noetic") == (calls, [])
    # a known one keeps its branch alone, under no condition
    assert _conditions(tmp_path, BRANCHES, "kilted") == {"kilted": []}


SAME_AND_OTHER = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
using S = std_msgs::msg::String;
void f(rclcpp::Node::SharedPtr node) {
#if RCLCPP_VERSION_GTE(30, 0, 0)
  auto a = rclcpp::create_publisher<S>(*node, "status", 10);
  node->declare_parameter("new_rate", 1);
#else
  auto a = node->create_publisher<S>("status", 10);
  node->declare_parameter("old_rate", 1);
#endif
}
"""


def test_a_call_each_branch_makes_is_one_call_under_no_condition(tmp_path) -> None:
    # navigation2's tf2_factories.hpp:107-111 makes the TransformBroadcaster from
    # ``*node`` from Rolling on, from ``node`` before: /tf is published whatever the
    # version; each branch's own parameter is read only under its condition
    source = tmp_path / "n.cpp"
    source.write_text(SAME_AND_OTHER)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None, distro=None)
    made = sorted((c.kind, c.name, c.location.line, tuple(str(k) for k in c.conditions))
                  for c in result.calls)
    assert made == [
        ("declare", "new_rate", 8, ("#if (RCLCPP_VERSION_GTE(30, 0, 0))",)),
        ("declare", "old_rate", 11, ("#else (RCLCPP_VERSION_GTE(30, 0, 0))",)),
        ("publish", "status", 10, ())]
    assert not [d for d in result.diagnostics if d.code == "CPP_VERSION_UNKNOWN"]
    # with no #else, the branch's call is the version's alone
    source.write_text(SAME_AND_OTHER.replace("#else", "#endif\n#if 1"))
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None, distro=None)
    assert {(c.name, c.location.line, bool(c.conditions)) for c in result.calls} == {
        ("status", 7, True), ("new_rate", 8, True), ("status", 11, False),
        ("old_rate", 12, False)}


UNREADABLE = """
#include <rclcpp/rclcpp.hpp>
void f(rclcpp::Node & node) {
  node.declare_parameter("always", 1);
#if RCLCPP_VERSION_GTE(29, 0, 0)
  node.declare_parameter("newer", 1, 2, 3, 4, 5, 6, 7);
#endif
#if RCLCPP_VERSION_GTE(99, 0, 0)
  node.declare_parameter("no_release_yet", 1);
#endif
}
"""


def test_a_branch_no_parse_reads_whole_is_said(tmp_path) -> None:
    # the other versions' parses leave an error in the branch (line 6): what it does is
    # not known, the node partial; the branch on a version newer than every release of
    # the table (line 9) is read by a parse with the version it names
    calls, unknown = _calls(tmp_path, UNREADABLE, None)
    assert {("declare", "always"), ("declare", "no_release_yet")} <= calls
    assert unknown == [6]
    said = [d.message for d in extract_cpp([str(tmp_path / "n.cpp")], scan([str(tmp_path)]),
                                           cache_dir=None, distro="jazy").diagnostics
            if d.code == "CPP_VERSION_UNKNOWN"]
    assert len(said) == 1 and "jazy is no ROS 2 distribution of ours" in said[0]


# navigation2's obstacle_layer.cpp:288-307: one branch per API of message_filters and
# point_cloud_transport, the second on a version between kilted's 29.5 and rolling's 30
# (a rolling release of its time) that no distribution of the table has
FOUR_BRANCHES = """
#include <rclcpp/rclcpp.hpp>
void f(rclcpp::Node & node) {
#if RCLCPP_VERSION_GTE(30, 0, 0)
  node.declare_parameter("rolling", 1);
#elif RCLCPP_VERSION_GTE(29, 6, 0)
  node.declare_parameter("between", 1);
#elif RCLCPP_VERSION_MAJOR >= 29
  node.declare_parameter("kilted", 1);
#else
  node.declare_parameter("older", 1);
#endif
}
"""


def test_a_branch_on_a_version_no_distribution_has_is_read_under_its_condition(
        tmp_path) -> None:
    calls, unknown = _calls(tmp_path, FOUR_BRANCHES, None)
    assert calls == {("declare", n) for n in ("rolling", "between", "kilted", "older")}
    assert unknown == []
    assert _conditions(tmp_path, FOUR_BRANCHES, None)["between"] == [
        "#elif (RCLCPP_VERSION_GTE(29, 6, 0))"]
    # a known distribution keeps its branch alone: kilted's 29.5.5 is not 29.6
    assert _conditions(tmp_path, FOUR_BRANCHES, "kilted") == {"kilted": []}


@pytest.mark.parametrize(("text", "named"), [
    ("RCLCPP_VERSION_GTE(29, 6, 0)", {(29, 6, 0)}),
    ("RCLCPP_VERSION_MAJOR >= 31 && !RCLCPP_VERSION_GTE(31, 2, 0)",
     {(31, 0, 0), (32, 0, 0), (31, 2, 0)}),
    ("defined(FOO)", set())])
def test_the_versions_a_condition_names(text: str, named) -> None:
    assert versions.RCLCPP.named(text) == named
    # jazzy's own version is never parsed again; the table's others come too, newest first
    others = versions.RCLCPP.others([text, "RCLCPP_VERSION_GTE(28, 1, 14)"])
    assert (28, 1, 14) not in others and others == sorted(others, reverse=True)
    assert named | {(30, 1, 3), (29, 5, 5), (2, 4, 3)} <= set(others)


@pytest.mark.parametrize(("text", "version", "taken"), [
    ("RCLCPP_VERSION_GTE(29, 0, 0)", (29, 0, 0), True),
    ("RCLCPP_VERSION_GTE(29, 0, 0)", (28, 1, 14), False),
    ("RCLCPP_VERSION_MAJOR >= 30 && RCLCPP_VERSION_MINOR > 0", (30, 1, 3), True),
    ("!RCLCPP_VERSION_GTE(30, 0, 0) || RCLCPP_VERSION_MAJOR == 16", (30, 1, 3), False),
    ("RCLCPP_VERSION_GTE(29, 0, 0) && defined(FOO)", (30, 1, 3), None)])
def test_a_condition_on_the_version_is_read(text: str, version, taken) -> None:
    assert versions.holds(text, versions.RCLCPP, version) is taken


def test_a_taken_branch_or_another_macro_says_nothing(tmp_path) -> None:
    text = ("#include <rclcpp/rclcpp.hpp>\nvoid f(rclcpp::Node & node) {\n"
            "#if RCLCPP_VERSION_GTE(16, 0, 0)\n  node.declare_parameter(\"a\", 1);\n#endif\n"
            "#ifdef SOMETHING_ELSE\n  node.declare_parameter(\"b\", 1);\n#endif\n}\n")
    assert _calls(tmp_path, text, None) == ({("declare", "a")}, [])


@pytest.mark.parametrize(("library", "header"), [
    (versions.RCLCPP, "rclcpp/rclcpp.hpp"), (versions.ROSCPP, "ros/common.h")])
def test_the_stand_in_announces_the_default_of_the_table(library, header: str) -> None:
    with open(os.path.join(STANDIN, header), encoding="utf-8") as f:
        text = f.read()
    found = tuple(int(re.search(rf"#define {library.prefix}_{part} \(?(\d+)\)?",
                                text).group(1)) for part in ("MAJOR", "MINOR", "PATCH"))
    assert found == library.table[library.default]
    # given as flags, the table's version replaces it
    assert f"#ifndef {library.prefix}_MAJOR" in text


ROS1 = """
#include <ros/ros.h>
int main(int argc, char ** argv) {
  ros::init(argc, argv, "n");
  ros::NodeHandle pnh("~");
#if ROS_VERSION_MINIMUM(1, 13, 1)
  ros::SteadyTimer t = pnh.createSteadyTimer(ros::WallDuration(0.5),
                                             [](const ros::SteadyTimerEvent&) {});
  pnh.param("steady", true);
#else
  pnh.param("wall", true);
#endif
}
"""


@pytest.mark.parametrize(("distro", "name", "unknown"), [
    ("noetic", "~steady", []), ("melodic", "~steady", []), ("kinetic", "~wall", []),
    (None, "~steady ~wall", []), ("jazzy", "~steady ~wall", [])])
def test_roscpp_s_version_follows_the_distribution(tmp_path, distro, name, unknown) -> None:
    # ROS_VERSION_MINIMUM was no macro of the stand-ins: an error, and the #else read
    source = tmp_path / "n.cpp"
    source.write_text(ROS1)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro=distro)
    # (with no ROS 1 distribution known, Kinetic's parse reads the ``#else``)
    assert {(c.kind, c.name) for c in result.calls} == {("read", n) for n in name.split()}
    assert [d.location.line for d in result.diagnostics
            if d.code == "CPP_VERSION_UNKNOWN"] == unknown
    assert not [d for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"]


def test_a_branch_inside_code_skipped_for_another_reason_says_nothing(tmp_path) -> None:
    text = ("#include <rclcpp/rclcpp.hpp>\nvoid f(rclcpp::Node & node) {\n"
            "#ifdef _WIN32\n#if RCLCPP_VERSION_MAJOR >= 30\n"
            "  node.declare_parameter(\"windows\", 1);\n#endif\n#endif\n}\n")
    assert _calls(tmp_path, text, None) == (set(), [])


def test_kilted_s_action_introspection_parses(tmp_path) -> None:
    # nav2's setIntrospectionMode configures an action client or server as from Kilted:
    # the rclcpp_action stand-ins lacked the method, an error made nodes partial
    text = ("#include <rclcpp/rclcpp.hpp>\n#include <rclcpp_action/rclcpp_action.hpp>\n"
            "#include <nav2_msgs/action/spin.hpp>\n"
            "template<typename T> void configure(T & it, rclcpp::Node & node) {\n"
            "#if RCLCPP_VERSION_GTE(29, 0, 0)\n"
            "  it->configure_introspection(node.get_clock(), rclcpp::ServicesQoS(),\n"
            "                              RCL_SERVICE_INTROSPECTION_METADATA);\n#endif\n}\n"
            "void f(rclcpp::Node & node, rclcpp_action::Client<nav2_msgs::action::Spin>::"
            "SharedPtr c, rclcpp_action::Server<nav2_msgs::action::Spin>::SharedPtr s) {\n"
            "  configure(c, node);\n  configure(s, node);\n}\n")
    source = tmp_path / "n.cpp"
    source.write_text(text)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="kilted")
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []


def test_a_run_for_another_distribution_does_not_reuse_the_cached_parse(tmp_path) -> None:
    tree = tmp_path / "ws"
    tree.mkdir()
    source = tree / "n.cpp"
    source.write_text(BRANCHES)
    cache = str(tmp_path / "cache")

    def declared(distro: str | None) -> set[str]:
        result = extract_cpp([str(source)], scan([str(tree)]), cache_dir=cache,
                             distro=distro)
        return {c.name for c in result.calls}

    assert declared("jazzy") == {"older"}
    assert declared("kilted") == {"kilted"}
    assert declared("rolling") == {"rolling_only"}
    assert declared("jazzy") == {"older"}  # read back from the cache
    assert os.listdir(cache)
