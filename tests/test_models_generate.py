"""`haros-arch models build`: interface models from pinned sources, by our extractor."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from haros_arch.cli import main
from haros_arch.models.format import from_document
from haros_arch.models.generate import ListError, build_package, read_list, run, tasks

FIXTURE = os.path.join(os.path.dirname(__file__), "..", "fixtures", "models", "generate")
LIST = os.path.join(FIXTURE, "list.yaml")
SOURCES = os.path.join(FIXTURE, "sources")
OVERRIDES = os.path.join(FIXTURE, "overrides")


def _outcome(overrides: str = OVERRIDES):
    (task,) = tasks(read_list(LIST), SOURCES, overrides, cache_dir=None)
    return build_package(task)


def _with_override(tmp_path: Path, text: str):
    """The tiny driver modelled with ``text`` as its noetic override file."""
    folder = tmp_path / "noetic"
    folder.mkdir()
    (folder / "tiny_driver.yaml").write_text(text)
    return _outcome(str(tmp_path))


def test_a_package_is_modelled_with_its_source_and_what_stayed_partial():
    outcome = _outcome(overrides=os.path.join(FIXTURE, "none"))
    model = from_document(json.loads(outcome.text))
    assert model.source == {"repository": "github:example/tiny_drivers", "branch": "main",
                            "commit": "0123456789abcdef0123456789abcdef01234567",
                            "path": "tiny_driver"}
    assert (model.package, model.distro, model.version) == ("tiny_driver", "noetic", "2.0.1")
    laser = model.node("laser")
    publish = next(c for c in laser.calls if c.kind == "publish")
    assert (publish.name, publish.name_param, publish.name_default, publish.type) == (
        "?", "~topic", "scan", "sensor_msgs/LaserScan")
    rate = next(c for c in laser.calls if c.name == "~rate")
    assert rate.has_default and rate.default == 10.0
    assert laser.completeness == "complete"
    broken = model.node("broken")
    assert broken.completeness == "partial" and broken.calls == []
    assert "syntax error" in broken.completeness_reasons[0]
    # relay subscribes each element of its list parameter ~topics: no '?' left
    assert list(outcome.partial) == ["broken"] and outcome.unresolved == 0
    subscribe = next(c for c in model.node("relay").calls if c.kind == "subscribe")
    assert (subscribe.name, subscribe.name_param, subscribe.name_each) == ("?", "~topics", ".")


def test_an_override_completes_a_partial_model():
    model = from_document(json.loads(_outcome().text))
    broken = model.node("broken")
    assert [(c.kind, c.name, c.type, c.origin) for c in broken.calls] == [
        ("publish", "out", "std_msgs/String", "override")]
    assert broken.completeness == "complete"
    assert "noetic/tiny_driver.yaml" in broken.completeness_reasons[0]
    assert model.override == "noetic/tiny_driver.yaml"


def test_the_cli_writes_one_file_per_package_and_reports(tmp_path, capsys):
    code = main(["models", "build", LIST, "--sources", SOURCES, "--overrides", OVERRIDES,
                 "-o", str(tmp_path), "--jobs", "1", "--no-cache"])
    out = capsys.readouterr().out
    assert code == 0
    assert "noetic/tiny_driver: 3 nodes" in out and "complete" in out
    assert (tmp_path / "noetic" / "tiny_driver.json").is_file()


def test_a_missing_tree_or_a_bad_list_is_reported(tmp_path, capsys):
    code = main(["models", "build", LIST, "--sources", str(tmp_path), "-o", str(tmp_path)])
    assert code == 1 and "no source tree" in capsys.readouterr().out
    bad = tmp_path / "bad.yaml"
    bad.write_text("- repository: github:a/b\n  commit: 12\n")
    with pytest.raises(ListError, match="entry 1: commit"):
        read_list(str(bad))
    assert main(["models", "build", str(bad)]) == 2


def test_a_process_pool_gives_the_same_models():
    work = tasks(read_list(LIST), SOURCES, OVERRIDES, cache_dir=None) * 2
    first, second = run(work, jobs=2)
    assert first.text == second.text == _outcome().text


def test_a_dask_cluster_gives_the_same_models():
    distributed = pytest.importorskip("distributed")
    work = tasks(read_list(LIST), SOURCES, OVERRIDES, cache_dir=None)
    with distributed.LocalCluster(n_workers=1, processes=False, dashboard_address=None) as cluster:
        (outcome,) = run(work, scheduler=cluster.scheduler_address)
    assert outcome.text == _outcome().text


def test_an_override_puts_a_call_under_the_condition_its_caller_writes(tmp_path):
    outcome = _with_override(tmp_path, (
        "nodes:\n  tiny_driver/laser:\n    conditions:\n"
        "      - calls: tiny_driver/scripts/laser:7\n"
        "        text: argv[1] == '--replay'\n        at: tiny_driver/scripts/laser:3\n"
        "      - calls: tiny_driver/scripts/laser:99\n        text: x\n        at: a:1\n"))
    model = from_document(json.loads(outcome.text))
    publish = next(c for c in model.node("laser").calls if c.kind == "publish")
    (problem,) = outcome.override_problems
    assert "names no call" in problem
    (condition,) = publish.conditions
    assert (condition.text, condition.location.file, condition.location.line) == (
        "argv[1] == '--replay'", "tiny_driver/scripts/laser", 3)
    assert publish.origin == "override"


def test_trees_listed_with_an_entry_are_needed_and_recorded(tmp_path):
    listed = tmp_path / "list.yaml"
    listed.write_text(Path(LIST).read_text(encoding="utf-8") + (
        "  with:\n    - repository: github:example/tiny_msgs\n"
        "      commit: 89abcdef0123456789abcdef0123456789abcdef\n"))
    (entry,) = read_list(str(listed))
    assert entry.context_folders == ["example+tiny_msgs@89abcdef0123"]
    (task,) = tasks([entry], SOURCES, OVERRIDES, cache_dir=None)
    assert "example+tiny_msgs@89abcdef0123" in build_package(task).problem
    (tmp_path / "sources").symlink_to(SOURCES)
    msgs = tmp_path / "more" / "example+tiny_msgs@89abcdef0123" / "tiny_msgs"
    msgs.mkdir(parents=True)
    (task,) = tasks([entry], str(tmp_path / "sources"), OVERRIDES, cache_dir=None)
    task = type(task)(task.entry, task.package, task.tree, task.overrides, None,
                      (str(msgs.parent),))
    model = from_document(json.loads(build_package(task).text))
    assert model.source["with"] == ("github:example/tiny_msgs@"
                                    "89abcdef0123456789abcdef0123456789abcdef")


def test_an_override_names_a_call_by_each_element_of_a_list_parameter(tmp_path):
    outcome = _with_override(tmp_path, (
        "nodes:\n  tiny_driver/relay:\n    names:\n"
        "      - calls: tiny_driver/scripts/relay:8\n        param: ~topics\n"
        "        each: .\n"))
    subscribe = next(c for c in from_document(json.loads(outcome.text)).node("relay").calls
                     if c.kind == "subscribe")
    assert (subscribe.name_param, subscribe.name_each, subscribe.origin) == (
        "~topics", ".", "override")
    assert outcome.override_problems == []


def test_an_override_names_calls_by_a_numbered_family_rewrites_and_drops(tmp_path):
    outcome = _with_override(tmp_path, (
        "nodes:\n"
        "  tiny_driver/relay:\n    names:\n"
        "      - {calls: tiny_driver/scripts/relay:8, name: '?', param: ~input,"
        " numbered: true}\n"
        "  tiny_driver/laser:\n    rosname: laser\n    drop: [tiny_driver/scripts/laser]\n"
        "    partial: its topics follow a file it reads\n"))
    model = from_document(json.loads(outcome.text))
    subscribe = next(c for c in model.node("relay").calls if c.kind == "subscribe")
    assert (subscribe.name, subscribe.name_param, subscribe.name_each, subscribe.origin) == (
        "?", "~input", "#", "override")
    laser = model.node("laser")
    assert laser.calls == [] and laser.completeness == "partial"
    assert laser.completeness_reasons == [
        "override noetic/tiny_driver.yaml: its topics follow a file it reads"]
    assert json.loads(outcome.text)["schema"] == "haros-arch-model/2"
    assert outcome.override_problems == []


def test_an_override_entry_that_mixes_each_and_numbered_is_refused(tmp_path):
    problems = _with_override(tmp_path, (
        "nodes:\n  tiny_driver/relay:\n    names:\n"
        "      - {calls: tiny_driver/scripts/relay:8, param: ~input, each: ., numbered: true}\n"
        "    drop: [tiny_driver/scripts/nowhere]\n")).override_problems
    assert len(problems) == 2  # names entries are tried before the rest of the block
    assert "names no call" in problems[0] and "tiny_driver/scripts/nowhere" in problems[1]


def test_an_override_names_a_call_by_the_value_of_a_parameter_with_a_default(tmp_path):
    outcome = _with_override(tmp_path, (
        "nodes:\n  tiny_driver/relay:\n    names:\n"
        "      - {calls: tiny_driver/scripts/relay:8, name: '?', param: ~input,"
        " default: chatter}\n"))
    subscribe = next(c for c in from_document(json.loads(outcome.text)).node("relay").calls
                     if c.kind == "subscribe")
    assert (subscribe.name_param, subscribe.name_default, subscribe.name_each) == (
        "~input", "chatter", None)
    assert outcome.override_problems == []


def test_an_override_puts_the_calls_of_an_unknown_handle_in_a_namespace():
    from haros_arch.model.location import Location
    from haros_arch.model.source import Node, PrimitiveCall
    from haros_arch.models.generate import _override_handles

    def call(kind, name, file="src/f.cpp"):
        return PrimitiveCall(kind, name, location=Location("p", file, 3),
                             handle_namespace="?" if name.startswith("?/") else None)

    node = Node("p", "filter", calls=[call("read", "?/rate"), call("read", "/global"),
                                       call("publish", "?/out"),
                                       call("read", "?/other", "src/g.cpp")])
    found: list = []
    _override_handles(node, [{"file": "src/f.cpp", "kinds": ["read"], "namespace": "~"},
                             {"file": "src/none.cpp", "kinds": ["read"], "namespace": "~"}],
                      "noetic/p.yaml", found)
    assert [(c.name, c.origin) for c in node.calls] == [
        ("~rate", "override"), ("/global", "source"), ("?/out", "source"),
        ("?/other", "source")]
    assert [d.code for d in found] == ["HINT_INVALID"]


def test_an_override_puts_the_calls_of_an_unknown_private_namespace_in_one():
    """MoveIt's OMPL planner serves its reconfigure server on ``NodeHandle(nh_,
    ompl_ns)`` (ompl_planner_manager.cpp:112-114), extracted ``~?/set_parameters``."""
    from haros_arch.model.location import Location
    from haros_arch.model.source import Node, PrimitiveCall
    from haros_arch.models.generate import _override_handles

    node = Node("p", "planner", calls=[
        PrimitiveCall("server", "~?/set_parameters", location=Location("p", "f.cpp", 4),
                      handle_namespace="~?"),
        PrimitiveCall("publish", "~?x/y", location=Location("p", "f.cpp", 4))])
    found: list = []
    _override_handles(node, [{"file": "f.cpp", "kinds": ["server", "publish"],
                              "namespace": "~ompl"}], "noetic/p.yaml", found)
    assert [c.name for c in node.calls] == ["~ompl/set_parameters", "~?x/y"]
    assert found == []


def test_an_override_drops_the_calls_of_one_line_and_names_those_of_another():
    """move_group's dynamic_reconfigure members, also taken for default-constructed
    servers at their declarations (trajectory_execution_manager.cpp:82), are dropped by
    line; the planning scene monitor's, in a namespace of its own, is put there by line."""
    from haros_arch.model.location import Location
    from haros_arch.model.source import Node, PrimitiveCall
    from haros_arch.models.generate import _override_drop, _override_handles

    def call(name, line):
        return PrimitiveCall("server", name, location=Location("p", "m.cpp", line))

    node = Node("p", "host", calls=[call("~set_parameters", 64), call("~set_parameters", 82),
                                    call("?/set_parameters", 65), call("?/other", 90)])
    found: list = []
    _override_drop(node, ["m.cpp:82"], "noetic/p.yaml", found)
    _override_handles(node, [{"file": "m.cpp", "line": 65, "kinds": ["server"],
                              "namespace": "~monitor"}], "noetic/p.yaml", found)
    assert [(c.name, c.location.line) for c in node.calls] == [
        ("~set_parameters", 64), ("~monitor/set_parameters", 65), ("?/other", 90)]
    assert found == []
    _override_drop(node, ["m.cpp:7"], "noetic/p.yaml", found)
    assert [d.code for d in found] == ["HINT_INVALID"]


def test_override_names_apply_before_hints_complete_unknown_calls(tmp_path):
    """A hint completes a call whose name has ``?``; a names entry for that call's line
    is applied first, so the hint is a call of its own (MoveIt's OMPL planner: its
    loop's reads named per line, the samplers' seeds added as getters)."""
    outcome = _with_override(tmp_path, (
        "nodes:\n  tiny_driver/relay:\n    names:\n"
        "      - {calls: tiny_driver/scripts/relay:8, name: chatter}\n"
        "    subscribers:\n      - {topic: other, msg_type: std_msgs/String}\n"))
    node = from_document(json.loads(outcome.text)).node("relay")
    assert sorted(c.name for c in node.calls if c.kind == "subscribe") == [
        "chatter", "other"]
    assert outcome.override_problems == []


def test_an_override_call_the_extraction_finds_is_kept_once_as_extracted(tmp_path):
    """cartographer_ros' override lists the publishers the extractor missed; once the
    extractor reads them, the model keeps each once, at its place in the code."""
    outcome = _with_override(tmp_path, (
        "nodes:\n  tiny_driver/laser:\n    getters:\n"
        "      - {parameter: '~rate', param_type: double}\n"
        "      - {parameter: '~extra', param_type: str}\n"))
    model = from_document(json.loads(outcome.text))
    reads = sorted((c.name, c.origin, c.location.line) for c in model.node("laser").calls
                   if c.kind == "read")
    assert reads == [("~extra", "override", 0), ("~rate", "source", 8),
                     ("~topic", "source", 6)]


def test_an_override_gives_reads_at_a_line_the_default_a_helper_takes(tmp_path):
    """MoveIt's kinematics solvers read through ``lookupParam(name, value, default)``,
    whose default the extraction does not see: ``defaults: [file:line]``."""
    outcome = _with_override(tmp_path, (
        "nodes:\n  tiny_driver/relay:\n    defaults: [tiny_driver/scripts/relay:6]\n"))
    node = from_document(json.loads(outcome.text)).node("relay")
    read = next(c for c in node.calls if c.kind == "read")
    assert (read.name, read.has_default) == ("~topics", True)
    assert outcome.override_problems == []


def test_paths_into_the_trees_of_a_build_are_relative_to_their_tree():
    from haros_arch.models.generate import _tree_relative

    tree, other = "/b/sources/o+p@0123456789ab", "/b/sources/o+q@89abcdef0123"
    text = json.dumps({"sources": ["p/src/a.cpp", f"{other}/q/src/lib.cpp"],
                       "file": f"{other}/q/src/lib.cpp",
                       "reasons": [f"{tree}/p/src/a.cpp:3: C++ error"],
                       "default": "/b/elsewhere/x"})
    assert json.loads(_tree_relative(text, [tree, other + "/"])) == {
        "sources": ["p/src/a.cpp", "q/src/lib.cpp"], "file": "q/src/lib.cpp",
        "reasons": ["p/src/a.cpp:3: C++ error"], "default": "/b/elsewhere/x"}


def test_no_shipped_model_names_a_path_of_the_machine_that_built_it():
    # a controller's test executable runs controller_manager's code, in ros_control's
    # tree: its sources and locations are relative to that tree
    import glob

    from haros_arch.models import library

    found = []
    for path in sorted(glob.glob(os.path.join(library.DATA, "*", "*.json"))):
        with open(path, encoding="utf-8") as handle:
            data = json.load(handle)
        for node in data.get("nodes", []):
            files = [*node.get("sources", []),
                     *(c["location"]["file"] for c in node.get("calls", [])
                       if c.get("location") and c["location"].get("file"))]
            found += [(os.path.basename(path), f) for f in files if os.path.isabs(f)]
            found += [(os.path.basename(path), r) for r in node.get(
                "completeness_reasons", []) if "/tmp/" in r]
    assert found == []


DUAL_CMAKE = """\
cmake_minimum_required(VERSION 3.10)
project(dual_bridge)
if("$ENV{ROS_VERSION}" STREQUAL "1")
  find_package(catkin REQUIRED COMPONENTS roscpp)
  catkin_package()
  add_executable(bridge ros1/bridge.cpp)
elseif("$ENV{ROS_VERSION}" STREQUAL "2")
  find_package(ament_cmake REQUIRED)
  find_package(rclcpp REQUIRED)
  add_executable(bridge ros2/bridge.cpp)
  install(TARGETS bridge DESTINATION lib/${PROJECT_NAME})
  ament_package()
else()
  message(FATAL_ERROR "ROS_VERSION environment variable must be 1 or 2")
endif()
"""

DUAL_ROS2 = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("bridge");
  auto pub = node->create_publisher<std_msgs::msg::String>("status", 10);
  rclcpp::spin(node);
  return 0;
}
"""

DUAL_ROS1 = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
int main(int argc, char ** argv) {
  ros::init(argc, argv, "bridge");
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<std_msgs::String>("ros1_status", 10);
  ros::spin();
  return 0;
}
"""


@pytest.mark.parametrize(("distro", "topic"), [("jazzy", "status"), ("noetic", "ros1_status")])
def test_a_package_for_both_ros_versions_is_modelled_for_its_distribution(
        tmp_path, distro, topic):
    """foxglove_bridge builds for ROS 1 or 2 on ``$ENV{ROS_VERSION}``, which the
    distribution's setup script sets: the build read with no environment made the jazzy
    model of its ROS 1 nodelet only, without the ROS 2 node ``foxglove_bridge``."""
    commit = "0123456789abcdef0123456789abcdef01234567"
    listed = tmp_path / "list.yaml"
    listed.write_text(f"- repository: github:example/dual_bridge\n  commit: {commit}\n"
                      f"  distro: {distro}\n  packages: [dual_bridge]\n")
    tree = tmp_path / "sources" / "example+dual_bridge@0123456789ab"
    (tree / "ros1").mkdir(parents=True)
    (tree / "ros2").mkdir()
    (tree / "package.xml").write_text(
        '<?xml version="1.0"?>\n<package format="3">\n  <name>dual_bridge</name>\n'
        '  <version>1.0.0</version>\n  <description>d</description>\n'
        '  <maintainer email="a@b.c">a</maintainer>\n  <license>MIT</license>\n'
        '  <buildtool_depend condition="$ROS_VERSION == 1">catkin</buildtool_depend>\n'
        '  <buildtool_depend condition="$ROS_VERSION == 2">ament_cmake</buildtool_depend>\n'
        '  <depend condition="$ROS_VERSION == 1">roscpp</depend>\n'
        '  <depend condition="$ROS_VERSION == 2">rclcpp</depend>\n'
        '  <depend>std_msgs</depend>\n  <export>\n'
        '    <build_type condition="$ROS_VERSION == 1">catkin</build_type>\n'
        '    <build_type condition="$ROS_VERSION == 2">ament_cmake</build_type>\n'
        '  </export>\n</package>\n')
    (tree / "CMakeLists.txt").write_text(DUAL_CMAKE)
    (tree / "ros1" / "bridge.cpp").write_text(DUAL_ROS1)
    (tree / "ros2" / "bridge.cpp").write_text(DUAL_ROS2)
    (task,) = tasks(read_list(str(listed)), str(tmp_path / "sources"),
                    os.path.join(FIXTURE, "none"), cache_dir=None)
    outcome = build_package(task)
    model = from_document(json.loads(outcome.text))
    assert [n.executable for n in model.nodes] == ["bridge"]
    assert [(c.kind, c.name) for c in model.node("bridge").calls] == [("publish", topic)]


VERSIONED_CMAKE = """\
cmake_minimum_required(VERSION 3.10)
project(versioned)
find_package(ament_cmake REQUIRED)
find_package(rclcpp REQUIRED)
if(rclcpp_VERSION VERSION_LESS 9.0.0)
  add_definitions(-DUSE_OLD_DECLARE_PARAMETER)
endif()
add_executable(node src/node.cpp)
install(TARGETS node DESTINATION lib/${PROJECT_NAME})
ament_package()
"""

VERSIONED_NODE = """\
#include <rclcpp/rclcpp.hpp>
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("versioned");
#ifdef USE_OLD_DECLARE_PARAMETER
  node->declare_parameter("old_rate", rclcpp::ParameterValue(1.0));
#else
  node->declare_parameter<double>("rate", 1.0);
#endif
  rclcpp::spin(node);
  return 0;
}
"""


def test_a_build_test_on_the_client_library_version_is_decided_for_the_distribution(
        tmp_path):
    """mavros defines USE_OLD_DECLARE_PARAMETER ``if(rclcpp_VERSION VERSION_LESS
    9.0.0)`` (Foxy's); the build read for a list entry's distribution finds jazzy's
    rclcpp, so the test is decided and the model whole, not partial for a condition
    'the extraction does not apply' (every mavros plugin was)."""
    commit = "0123456789abcdef0123456789abcdef01234567"
    listed = tmp_path / "list.yaml"
    listed.write_text(f"- repository: github:example/versioned\n  commit: {commit}\n"
                      "  distro: jazzy\n  packages: [versioned]\n")
    tree = tmp_path / "sources" / "example+versioned@0123456789ab"
    (tree / "src").mkdir(parents=True)
    (tree / "package.xml").write_text(
        '<?xml version="1.0"?>\n<package format="3">\n  <name>versioned</name>\n'
        '  <version>1.0.0</version>\n  <description>d</description>\n'
        '  <maintainer email="a@b.c">a</maintainer>\n  <license>MIT</license>\n'
        '  <buildtool_depend>ament_cmake</buildtool_depend>\n  <depend>rclcpp</depend>\n'
        '  <export>\n    <build_type>ament_cmake</build_type>\n  </export>\n</package>\n')
    (tree / "CMakeLists.txt").write_text(VERSIONED_CMAKE)
    (tree / "src" / "node.cpp").write_text(VERSIONED_NODE)
    (task,) = tasks(read_list(str(listed)), str(tmp_path / "sources"),
                    os.path.join(FIXTURE, "none"), cache_dir=None)
    model = from_document(json.loads(build_package(task).text))
    node = model.node("node")
    assert [(c.kind, c.name) for c in node.calls] == [("declare", "rate")]
    assert node.completeness == "complete", node.completeness_reasons
