"""A run after a C++ change that extracts the same answers with the kept run
(``pipeline._again``), also where plugin classes were read in a batch of their own and
where a unit kept in the cache used a message header a parse made on demand.

navigation2's bringup, one controller source with a comment added: the deferred plugin
libraries' batch prepares the headers it shares with the first batch again and says
``nlohmann/json.hpp`` missing again, which a single batch of every unit did not, so the
kept run was never taken (5 s instead of 1.4); and every run that parsed a unit removed
the message headers earlier parses had made on demand, so the units that used them
missed the cache on the next run and were parsed again, each time."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import pytest
from conftest import package_xml

import haros_arch.extract.cpp as cpp
from haros_arch.model.serialise import model_to_data
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

SOLVER_H = """
    #pragma once
    #include <rclcpp/rclcpp.hpp>
    #include <vendor_lib/thing.hpp>
    namespace demo {
    class Solver {
     public:
      virtual ~Solver() {}
      virtual void configure(rclcpp::Node::SharedPtr node) = 0;
    };
    }  // namespace demo
    """

FAST = """
    #include <rclcpp/rclcpp.hpp>
    #include <std_msgs/msg/int32.hpp>
    #include <pluginlib/class_list_macros.hpp>
    #include "demo/solver.hpp"
    namespace demo {
    class FastSolver : public Solver {
     public:
      void configure(rclcpp::Node::SharedPtr node) override {
        pub_ = node->create_publisher<std_msgs::msg::Int32>("solver_status", 10);
      }
     private:
      rclcpp::Publisher<std_msgs::msg::Int32>::SharedPtr pub_;
    };
    }  // namespace demo
    PLUGINLIB_EXPORT_CLASS(demo::FastSolver, demo::Solver)
    """

HOST = """
    #include <memory>
    #include <string>
    #include <rclcpp/rclcpp.hpp>
    #include <pluginlib/class_loader.hpp>
    #include "demo/solver.hpp"

    int main(int argc, char** argv) {
      rclcpp::init(argc, argv);
      auto node = std::make_shared<rclcpp::Node>("host");
      pluginlib::ClassLoader<demo::Solver> loader("demo", "demo::Solver");
      std::string solver_plugin = std::string("demo::FastSolver");
      if (!node->has_parameter("solver_plugin")) {
        node->declare_parameter("solver_plugin", solver_plugin);
      }
      solver_plugin = node->get_parameter("solver_plugin").as_string();
      std::shared_ptr<demo::Solver> solver = loader.createSharedInstance(solver_plugin);
      solver->configure(node);
      rclcpp::spin(node);
    }
    """

# a message type used with no include of its header: the parse makes it on demand
UNINCLUDED = """
    #include <rclcpp/rclcpp.hpp>

    int main(int argc, char** argv) {
      rclcpp::init(argc, argv);
      auto node = std::make_shared<rclcpp::Node>("stamper");
      auto pub = node->create_publisher<geometry_msgs::msg::QuaternionStamped>("heading", 5);
      rclcpp::spin(node);
    }
    """

PLAIN = """
    #include <rclcpp/rclcpp.hpp>
    #include <std_msgs/msg/int32.hpp>

    int main(int argc, char** argv) {
      rclcpp::init(argc, argv);
      auto node = std::make_shared<rclcpp::Node>("plain");
      auto pub = node->create_publisher<std_msgs::msg::Int32>("count", 5);
      rclcpp::spin(node);
    }
    """

PLUGINS_XML = """
    <library path="fast_solver">
      <class name="demo::FastSolver" type="demo::FastSolver" base_class_type="demo::Solver">
        <description>fast</description>
      </class>
    </library>
    """

LAUNCH = """
    <launch>
      <node pkg="demo" exec="host" name="host"/>
      <node pkg="demo" exec="stamper" name="stamper"/>
      <node pkg="demo" exec="plain" name="plain"/>
    </launch>
    """


def _workspace(write_tree: Any) -> Path:
    manifest = package_xml("demo", "ament_cmake").replace("</package>", "".join(
        f"<depend>{d}</depend>" for d in ("rclcpp", "pluginlib", "std_msgs",
                                          "geometry_msgs")) + "</package>")
    root: Path = write_tree({
        "src/demo/package.xml": manifest,
        "src/demo/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.8)\nproject(demo)\n"
            "find_package(ament_cmake REQUIRED)\nfind_package(rclcpp REQUIRED)\n"
            "find_package(pluginlib REQUIRED)\nfind_package(std_msgs REQUIRED)\n"
            "find_package(geometry_msgs REQUIRED)\n"
            "include_directories(include)\n"
            "add_library(fast_solver SHARED src/fast_solver.cpp)\n"
            "ament_target_dependencies(fast_solver rclcpp pluginlib std_msgs)\n"
            "pluginlib_export_plugin_description_file(demo plugins.xml)\n"
            "add_executable(host src/host.cpp)\n"
            "ament_target_dependencies(host rclcpp pluginlib)\n"
            "add_executable(stamper src/stamper.cpp)\n"
            "ament_target_dependencies(stamper rclcpp geometry_msgs)\n"
            "add_executable(plain src/plain.cpp)\n"
            "ament_target_dependencies(plain rclcpp std_msgs)\n"
            "install(TARGETS fast_solver host stamper plain DESTINATION lib/${PROJECT_NAME})\n"
            "ament_package()\n"),
        "src/demo/plugins.xml": PLUGINS_XML,
        "src/demo/include/demo/solver.hpp": SOLVER_H,
        "src/demo/src/fast_solver.cpp": FAST,
        "src/demo/src/host.cpp": HOST,
        "src/demo/src/stamper.cpp": UNINCLUDED,
        "src/demo/src/plain.cpp": PLAIN,
        "src/demo/launch/demo.launch.xml": LAUNCH,
        "project.yaml": ("project: p\nworkspace: [src]\ndistro: jazzy\nconfigurations:\n"
                         "  c: [demo/launch/demo.launch.xml]\n"),
    })
    for folder, _dirs, files in os.walk(root):  # old enough to trust the index
        for name in files:
            os.utime(os.path.join(folder, name), (1_000_000_000, 1_000_000_000))
    return root


@pytest.fixture
def parsed(monkeypatch: Any) -> list[str]:
    """The translation units each run parses (one job: in this process)."""
    seen: list[str] = []
    original = cpp._unit_and_data

    def counting(path: str, *args: Any) -> Any:
        seen.append(os.path.basename(path))
        return original(path, *args)

    monkeypatch.setattr(cpp, "_unit_and_data", counting)
    return seen


def _run(root: Path, cache: Path) -> tuple[Any, dict[str, float]]:
    timings: dict[str, float] = {}
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=str(cache), jobs=1, timings=timings))
    return model, timings


def _append(path: Path, text: str) -> None:
    path.write_text(path.read_text() + text)
    os.utime(path, (1_000_000_000, 1_000_000_000))


def test_a_comment_in_a_host_of_plugins_read_apart_reuses_the_kept_run(
        write_tree: Any, tmp_path: Path, parsed: list[str]) -> None:
    root = _workspace(write_tree)
    cold, seconds = _run(root, tmp_path / "cache")
    assert seconds["C++"] > 0  # the stage's seconds are said (were 0 after the last batch)
    assert sorted(parsed) == ["fast_solver.cpp", "host.cpp", "plain.cpp", "stamper.cpp"]
    assert parsed[-1] == "fast_solver.cpp"  # the plugin's batch, after the first one's
    missing = [d for d in cold.all_diagnostics if d.code == "CPP_INCLUDE_MISSING"]
    assert missing and all("vendor_lib/thing.hpp" in d.message for d in missing)
    config = cold.configurations[0]
    assert ("publish", "/solver_status") in {
        (link.kind, link.name) for link in config.links if link.node.name == "/host"}
    _append(root / "src/demo/src/host.cpp", "// a comment\n")
    parsed.clear()
    again, timings = _run(root, tmp_path / "cache")
    assert "graph" not in timings and "launch" not in timings  # the kept run answered
    assert parsed == ["host.cpp"]
    assert model_to_data(again) == model_to_data(cold)


def test_a_message_header_a_parse_made_keeps_its_unit_in_the_cache(
        write_tree: Any, tmp_path: Path, parsed: list[str]) -> None:
    root = _workspace(write_tree)
    cold, _ = _run(root, tmp_path / "cache")
    stamper = {(link.kind, link.name, link.type) for link in cold.configurations[0].links
               if link.node.name == "/stamper"}
    assert ("publish", "/heading", "geometry_msgs/msg/QuaternionStamped") in stamper
    for count in range(3):  # each run parses plain.cpp alone, again and again
        _append(root / "src/demo/src/plain.cpp", f'// {count}\n')
        parsed.clear()
        _run(root, tmp_path / "cache")
        assert parsed == ["plain.cpp"], count


def test_a_changed_source_makes_only_its_nodes_result_again(
        write_tree: Any, tmp_path: Path, parsed: list[str], monkeypatch: Any) -> None:
    """The other nodes' results are as their unchanged units made them
    (``cache.node_key``), and the model is a cold run's."""
    made: list[list[str]] = []
    original = cpp._node_result

    def counting(paths_units: Any, *args: Any) -> Any:
        made.append([os.path.basename(path) for path, _ in paths_units])
        return original(paths_units, *args)

    monkeypatch.setattr(cpp, "_node_result", counting)
    root = _workspace(write_tree)
    _run(root, tmp_path / "cache")
    assert sorted(made) == [["fast_solver.cpp"], ["host.cpp"], ["plain.cpp"], ["stamper.cpp"]]
    source = root / "src/demo/src/plain.cpp"
    source.write_text(source.read_text().replace('"count"', '"counted"'))
    made.clear()
    parsed.clear()
    changed, timings = _run(root, tmp_path / "cache")
    assert "graph" in timings and parsed == ["plain.cpp"]
    assert made == [["plain.cpp"]]
    assert ("publish", "/counted") in {(link.kind, link.name)
                                       for link in changed.configurations[0].links}
    made.clear()
    cold, _ = _run(root, tmp_path / "cold")
    assert len(made) == 4
    assert model_to_data(changed) == model_to_data(cold)


def test_a_changed_source_prepares_each_batchs_headers_once(
        write_tree: Any, tmp_path: Path, parsed: list[str], monkeypatch: Any) -> None:
    """The run compares what the units give (``pipeline._again``) and, when that differs,
    extracts them again: the second pass over the same batches takes the first's
    prepared headers (``extract.one_run``) instead of scanning every include again."""
    from haros_arch.extract.cpp import headers

    made: list[int] = []
    original = headers.IncludeSetup.__init__

    def counting(self: Any, *args: Any, **kwargs: Any) -> None:
        made.append(1)
        original(self, *args, **kwargs)

    monkeypatch.setattr(headers.IncludeSetup, "__init__", counting)
    root = _workspace(write_tree)
    _run(root, tmp_path / "cache")
    assert len(made) == 2  # the first batch and the deferred plugins'
    source = root / "src/demo/src/plain.cpp"
    source.write_text(source.read_text().replace('"count"', '"counted"'))
    made.clear()
    parsed.clear()
    changed, timings = _run(root, tmp_path / "cache")
    assert "graph" in timings and parsed == ["plain.cpp"]
    assert len(made) == 2  # not four
    made.clear()
    cold, _ = _run(root, tmp_path / "cold")
    assert model_to_data(changed) == model_to_data(cold)
    locks = list((tmp_path / "cache" / "generated").glob("*.lock"))
    assert locks and all(_unlocked(lock) for lock in locks)  # the run let its folder go


def _unlocked(lock: Path) -> bool:
    import fcntl

    handle = os.open(lock, os.O_RDWR)
    try:
        fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        return True
    except OSError:
        return False
    finally:
        os.close(handle)
