"""A run after a C++ change that extracts otherwise reads again only the build files of
the packages whose reading read a changed C++ file (``pipeline._build_files``): the
others' nodes are as the earlier run's reading gave them. navigation2's bringup after
one changed controller source: 0.9 s of build files -> 0.23 s (nav2_controller's own,
which reads that source for its export macros and ``main()``)."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import pytest
from conftest import package_xml

from haros_arch import files, pipeline
from haros_arch.model.serialise import model_to_data
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

PLUGIN = """
    #include <rclcpp/rclcpp.hpp>
    #include <pluginlib/class_list_macros.hpp>
    #include "tools/base.hpp"
    namespace tools {
    class Loud : public Base {
     public:
      void start(rclcpp::Node::SharedPtr node) override {
        pub_ = node->create_publisher<std_msgs::msg::String>("shout", 10);
      }
     private:
      rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
    };
    }  // namespace tools
    EXPORT
    """

BASE = """
    #pragma once
    #include <rclcpp/rclcpp.hpp>
    #include <std_msgs/msg/string.hpp>
    namespace tools {
    class Base {
     public:
      virtual ~Base() {}
      virtual void start(rclcpp::Node::SharedPtr node) = 0;
    };
    }  // namespace tools
    """

HOST = """
    #include <memory>
    #include <string>
    #include <rclcpp/rclcpp.hpp>
    #include <pluginlib/class_loader.hpp>
    #include "tools/base.hpp"

    int main(int argc, char** argv) {
      rclcpp::init(argc, argv);
      auto node = std::make_shared<rclcpp::Node>("host");
      pluginlib::ClassLoader<tools::Base> loader("tools", "tools::Base");
      std::string tool = std::string("tools::Loud");
      if (!node->has_parameter("tool")) {
        node->declare_parameter("tool", tool);
      }
      tool = node->get_parameter("tool").as_string();
      std::shared_ptr<tools::Base> made = loader.createSharedInstance(tool);
      made->start(node);
      auto pub = node->create_publisher<std_msgs::msg::String>("TOPIC", 5);
      rclcpp::spin(node);
    }
    """


PLAIN = """
    #include <rclcpp/rclcpp.hpp>
    #include <std_msgs/msg/string.hpp>

    int main(int argc, char** argv) {
      rclcpp::init(argc, argv);
      auto node = std::make_shared<rclcpp::Node>("plain");
      auto pub = node->create_publisher<std_msgs::msg::String>("count", 5);
      rclcpp::spin(node);
    }
    """


def _workspace(write_tree: Any) -> Path:
    def manifest(name: str, *deps: str) -> str:
        return package_xml(name, "ament_cmake").replace("</package>", "".join(
            f"<depend>{d}</depend>" for d in deps) + "</package>")

    root: Path = write_tree({
        "src/tools/package.xml": manifest("tools", "rclcpp", "pluginlib", "std_msgs"),
        "src/tools/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.8)\nproject(tools)\n"
            "find_package(ament_cmake REQUIRED)\nfind_package(rclcpp REQUIRED)\n"
            "find_package(pluginlib REQUIRED)\nfind_package(std_msgs REQUIRED)\n"
            "include_directories(include)\n"
            "add_library(loud SHARED src/loud.cpp)\n"
            "ament_target_dependencies(loud rclcpp pluginlib std_msgs)\n"
            "pluginlib_export_plugin_description_file(tools plugins.xml)\n"
            "add_executable(host src/host.cpp)\n"
            "ament_target_dependencies(host rclcpp pluginlib std_msgs)\n"
            "install(TARGETS loud host DESTINATION lib/${PROJECT_NAME})\nament_package()\n"),
        "src/tools/plugins.xml": (
            '<library path="loud_plugins"><class name="tools::Loud" type="tools::Loud" '
            'base_class_type="tools::Base"><description>d</description></class></library>\n'),
        "src/tools/include/tools/base.hpp": BASE,
        "src/tools/src/loud.cpp": PLUGIN.replace(
            "EXPORT", "PLUGINLIB_EXPORT_CLASS(tools::Loud, tools::Base)"),
        "src/tools/src/host.cpp": HOST.replace("TOPIC", "chatter"),
        "src/other/package.xml": manifest("other", "rclcpp", "std_msgs"),
        "src/other/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.8)\nproject(other)\n"
            "find_package(ament_cmake REQUIRED)\nfind_package(rclcpp REQUIRED)\n"
            "find_package(std_msgs REQUIRED)\n"
            "add_executable(plain src/plain.cpp)\n"
            "ament_target_dependencies(plain rclcpp std_msgs)\n"
            "install(TARGETS plain DESTINATION lib/${PROJECT_NAME})\nament_package()\n"),
        "src/other/src/plain.cpp": PLAIN,
        "src/tools/launch/all.launch.xml": (
            '<launch><node pkg="tools" exec="host" name="host"/>'
            '<node pkg="other" exec="plain" name="plain"/></launch>\n'),
        "project.yaml": ("project: p\nworkspace: [src]\ndistro: jazzy\n"
                         "configurations:\n  c: [tools/launch/all.launch.xml]\n"),
    })
    for folder, _dirs, names in os.walk(root):  # old enough to trust the index
        for name in names:
            os.utime(os.path.join(folder, name), (1_000_000_000, 1_000_000_000))
    return root


@pytest.fixture
def read(monkeypatch: Any) -> list[str]:
    """The packages whose build files each run reads."""
    seen: list[str] = []
    original = pipeline.read_build_files

    def counting(package: Any, workspace: Any) -> Any:
        seen.append(package.name)
        return original(package, workspace)

    monkeypatch.setattr(pipeline, "read_build_files", counting)
    return seen


def _run(root: Path, cache: Path | None) -> Any:
    return analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                   Options(cache_dir=str(cache) if cache else None, jobs=1))


def _edit(path: Path, old: str, new: str) -> None:
    text = path.read_text()
    assert old in text
    path.write_text(text.replace(old, new))
    os.utime(path, (1_000_000_000, 1_000_000_000))


def _links(model: Any) -> set[tuple[str, str]]:
    return {(link.kind, link.name) for link in model.configurations[0].links
            if link.node.name == "/host"}


def test_a_changed_source_reads_again_only_its_packages_build_files(
        write_tree: Any, tmp_path: Path, read: list[str]) -> None:
    root = _workspace(write_tree)
    first = _run(root, tmp_path / "cache")
    assert sorted(read) == ["other", "tools"]
    assert {("publish", "/chatter"), ("publish", "/shout")} <= _links(first)
    _edit(root / "src/other/src/plain.cpp", '"count"', '"totals"')
    read.clear()
    changed = _run(root, tmp_path / "cache")
    assert read == ["other"]  # its reading read plain.cpp; tools' read none of it
    assert ("publish", "/totals") in {(link.kind, link.name) for link in
                                     changed.configurations[0].links}
    _edit(root / "src/tools/src/host.cpp", '"chatter"', '"talking_now"')
    read.clear()
    changed = _run(root, tmp_path / "cache")
    assert {("publish", "/talking_now"), ("publish", "/shout")} <= _links(changed)
    assert read == ["tools"]
    read.clear()
    cold = _run(root, None)
    assert model_to_data(changed) == model_to_data(cold)


def test_a_source_whose_export_changed_gives_its_package_as_read_anew(
        write_tree: Any, tmp_path: Path, read: list[str]) -> None:
    root = _workspace(write_tree)
    _run(root, tmp_path / "cache")
    _edit(root / "src/tools/src/loud.cpp", "PLUGINLIB_EXPORT_CLASS(tools::Loud, tools::Base)",
          "// no export")
    read.clear()
    changed = _run(root, tmp_path / "cache")
    assert "tools" in read
    assert ("publish", "/shout") not in _links(changed)  # no class exported: none loaded
    assert model_to_data(changed) == model_to_data(_run(root, None))


def test_a_fact_kept_for_a_run_reads_its_files_again_for_each_block() -> None:
    memo: dict[str, Any] = {}

    def compute() -> int:
        files.note_read("/a.cpp")
        with files.recording():  # a block within: what it reads is the outer's too
            files.note_read("/b.hpp")
        return 7

    with files.recording() as first:
        assert files.kept_in(memo, "k", compute) == 7
    with files.recording() as second:  # kept: computed once, its files read again
        assert files.kept_in(memo, "k", lambda: 8) == 7
    assert first == second == {"/a.cpp", "/b.hpp"}
    with files.recording() as outer, files.recording() as inner:
        files.note_read("/c.cpp")
    assert outer == inner == {"/c.cpp"}
