"""A project of several workspace folders (``workspace: [a, b]``) reads the files of
every folder as its own, not those of the first only: the headers beside a later
folder's sources were never scanned (their message headers not made, so each such type
an error), clang's errors in them were not the unit's, their text was not read for
values, and the report quoted none of their lines. On a project of six trees whose
second was autoware_core, autoware_core's nodes lost 444 of their 1,182 calls."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp
from haros_arch.viz.sources import collect_snippets
from haros_arch.workspace import Workspace, scan
from tests.conftest import package_xml

TALKER_HPP = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include "talker/names.hpp"
namespace talker {
constexpr int kDepth = 7;
class Talker : public rclcpp::Node {
 public:
  Talker();
 private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
  void heard(const std_msgs::msg::String & message);
};
}
"""

NAMES_HPP = """
#pragma once
namespace talker { inline const char * kHeard = "heard"; }
"""

TALKER_CPP = """
#include "talker.hpp"
namespace talker {
Talker::Talker() : rclcpp::Node("talker") {
  pub_ = create_publisher<std_msgs::msg::String>("chatter", kDepth);
  sub_ = create_subscription<std_msgs::msg::String>(
    kHeard, 10, std::bind(&Talker::heard, this, std::placeholders::_1));
}
void Talker::heard(const std_msgs::msg::String &) {}
}
"""


def _trees(tmp_path: Path) -> tuple[Path, Path, Path]:
    first, second = tmp_path / "first", tmp_path / "second"
    files = {
        first / "other/package.xml": package_xml("other", "ament_cmake"),
        first / "other/src/other.cpp": "int other() { return 0; }\n",
        second / "talker/package.xml": package_xml("talker", "ament_cmake"),
        second / "talker/src/talker.hpp": TALKER_HPP,
        second / "talker/include/talker/names.hpp": NAMES_HPP,
        second / "talker/src/talker.cpp": TALKER_CPP,
    }
    for path, text in files.items():
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text.lstrip("\n"))
    return first, second, second / "talker/src/talker.cpp"


def _calls(result) -> list[tuple]:
    return sorted((c.kind, c.name, c.type, c.queue_size) for c in result.calls)


def test_a_later_folders_node_is_extracted_as_when_it_is_the_only_folder(tmp_path) -> None:
    first, second, source = _trees(tmp_path)
    alone = extract_cpp([str(source)], scan([str(second)]), cache_dir=None)
    both = extract_cpp([str(source)], scan([str(first), str(second)]), cache_dir=None)
    assert _calls(alone) == [("publish", "chatter", "std_msgs/msg/String", 7),
                             ("subscribe", "heard", "std_msgs/msg/String", 10)]
    assert _calls(both) == _calls(alone)
    missing = [d for d in both.diagnostics if d.code in ("CPP_INCLUDE_MISSING",
                                                          "CPP_PARSE_ERROR")]
    assert missing == []


def test_holds_every_workspace_folder_and_nothing_beside_them(tmp_path) -> None:
    first, second = tmp_path / "ws", tmp_path / "ws2"
    for folder in (first, second):
        folder.mkdir()
    workspace = scan([str(first), str(second)])
    assert workspace.holds(str(first / "a" / "b.hpp"))
    assert workspace.holds(str(second / "b.hpp"))
    assert not workspace.holds(str(tmp_path / "ws3" / "b.hpp"))
    assert not workspace.holds(str(tmp_path / "b.hpp"))
    only = Workspace(root=str(first))  # no roots given: the root is the one folder
    assert only.holds(str(first / "x.cpp")) and not only.holds(str(second / "x.cpp"))


def test_the_report_quotes_the_lines_of_every_workspace_folder(tmp_path) -> None:
    first, second, source = _trees(tmp_path)
    (tmp_path / "elsewhere.cpp").write_text("int secret = 1;\n")
    data = {"model": [
        {"file": "other/src/other.cpp", "line": 1},  # relative: the first folder
        {"file": str(source), "line": 4},  # absolute: a later folder's file
        {"file": str(tmp_path / "elsewhere.cpp"), "line": 1},  # in no folder
        {"file": str(second / ".." / "elsewhere.cpp"), "line": 1},  # climbs out
    ]}
    snippets = collect_snippets(data, [str(first), str(second)])
    assert sorted(snippets) == sorted(["other/src/other.cpp", str(source)])
    assert "create_publisher" in snippets[str(source)]["4"]
    # one folder: an absolute path is never read
    assert sorted(collect_snippets(data, str(first))) == ["other/src/other.cpp"]


def test_later_folders_are_labelled_by_their_names(tmp_path) -> None:
    from haros_arch.viz.sources import folder_labels

    a, b, c = tmp_path / "ws", tmp_path / "x" / "deps", tmp_path / "y" / "deps"
    assert folder_labels(str(a)) == []
    assert folder_labels([str(a), str(tmp_path / "tools")]) == [
        [str(tmp_path / "tools"), "tools"]]
    assert folder_labels([str(a), str(b), str(c)]) == [[str(b), "x/deps"], [str(c), "y/deps"]]
