"""With no distribution known, a workspace header's branch that the stand-ins' version
leaves out is read by a parse with another release's version (``_other_version``), once
per run for every unit that includes the header; what that parse read is kept with the
cache, so a run after an edit of one source parses that source again but not the
header's branch (navigation2's dwb_local_planner.cpp: 1.1 of its 2.1 s)."""

from __future__ import annotations

import contextlib

from haros_arch.extract import cpp
from haros_arch.extract.cpp import extract_cpp
from haros_arch.extract.cpp.headers import IncludeSetup
from haros_arch.workspace import scan

HEADER = """
#pragma once
#include <rclcpp/rclcpp.hpp>
#include <rclcpp/version.h>
inline void declare_mode(rclcpp::Node & node) {
#if RCLCPP_VERSION_GTE(29, 0, 0)
  node.declare_parameter("introspection_mode", std::string("disabled"));
#endif
  node.declare_parameter("rate", 10);
}
"""

NODE = """
#include <memory>
#include "srv/util.hpp"
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("server");
  declare_mode(*node);
  rclcpp::spin(node);
}
"""


def _run(tree, cache: str, monkeypatch) -> tuple[list[tuple[str, str, str]], int]:
    """The calls of a run in a new process (the run's own memory of branches empty), and
    how many parses it made with another version."""
    cpp._OTHER_READ.clear()
    parses: list[tuple] = []
    announcing = IncludeSetup.announcing

    @contextlib.contextmanager
    def counted(self, *version):
        parses.append(version)
        with announcing(self, *version):
            yield

    monkeypatch.setattr(IncludeSetup, "announcing", counted)
    result = extract_cpp([str(tree / "srv" / "src" / "server.cpp")], scan([str(tree)]),
                         cache_dir=cache, distro=None)
    monkeypatch.setattr(IncludeSetup, "announcing", announcing)
    return sorted((c.kind, c.name, str(c.conditions)) for c in result.calls), len(parses)


def _workspace(tmp_path, header_text: str):
    tree = tmp_path / "ws"
    (tree / "srv" / "include" / "srv").mkdir(parents=True)
    (tree / "srv" / "src").mkdir(parents=True)
    (tree / "srv" / "package.xml").write_text(
        "<package format='3'><name>srv</name><version>1.0.0</version>"
        "<description>d</description><maintainer email='a@b.c'>a</maintainer>"
        "<license>MIT</license><buildtool_depend>ament_cmake</buildtool_depend>"
        "<depend>rclcpp</depend><export><build_type>ament_cmake</build_type></export>"
        "</package>")
    (tree / "srv" / "include" / "srv" / "util.hpp").write_text(header_text)
    (tree / "srv" / "src" / "server.cpp").write_text(NODE)
    return tree, tree / "srv" / "include" / "srv" / "util.hpp", tree / "srv" / "src" / "server.cpp"


def test_a_headers_branch_read_by_another_parse_is_kept_with_the_cache(
        tmp_path, monkeypatch) -> None:
    tree, header, source = _workspace(tmp_path, HEADER)
    cache = str(tmp_path / "cache")
    cold, parsed = _run(tree, cache, monkeypatch)
    assert any(name == "introspection_mode" and "RCLCPP_VERSION_GTE(29, 0, 0)" in conditions
               for _, name, conditions in cold)
    assert parsed == 1
    source.write_text(NODE + "// edited\n")  # the unit is parsed again, not the branch
    again, parsed = _run(tree, cache, monkeypatch)
    assert again == cold and parsed == 0
    # the header changed: its branch is read again
    header.write_text(HEADER.replace('"disabled"', '"metadata"'))
    source.write_text(NODE + "// edited twice\n")
    changed, parsed = _run(tree, cache, monkeypatch)
    assert changed == cold and parsed == 1
    # no cache: nothing kept, each run its own parse
    assert _run(tree, None, monkeypatch)[1] == 1


def test_a_branch_no_parse_read_whole_is_kept_as_such(tmp_path, monkeypatch) -> None:
    """The other parse's verdict that it did not read a branch whole (an error in it) is
    kept too: the node stays partial without another parse."""
    tree, _header, source = _workspace(tmp_path, HEADER.replace(
        'std::string("disabled"));', 'std::string("disabled"));\n  int broken = ;'))
    cache = str(tmp_path / "cache")
    cold, parsed = _run(tree, cache, monkeypatch)
    assert parsed >= 1 and not any(name == "introspection_mode" for _, name, _ in cold)
    source.write_text(NODE + "// edited\n")
    again, parsed = _run(tree, cache, monkeypatch)
    assert again == cold and parsed == 0
