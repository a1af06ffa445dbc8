"""The workspace's include folders are searched through one header map (``header_map``):
the parse opens the same files as a search of the folders in their order would."""

from __future__ import annotations

import os

import pytest

from haros_arch.extract.cpp import extract_cpp, header_map, toolchain
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <shared/names.hpp>
#include <shared/Other.hpp>
#include <shared/other.hpp>
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("talker");
  auto a = node->create_publisher<std_msgs::msg::String>(NAME, 10);
  auto b = node->create_publisher<std_msgs::msg::String>(UPPER, 10);
  auto c = node->create_publisher<std_msgs::msg::String>(LOWER, 10);
  return 0;
}
"""


def _workspace(write_tree):
    """Three packages whose include folders hold the same names: ``shared/names.hpp``
    in two, ``shared/Other.hpp`` and ``shared/other.hpp`` (the same but for case)."""
    root = write_tree({
        "alpha/package.xml": package_xml("alpha", "ament_cmake"),
        "alpha/include/shared/names.hpp": '#define NAME "from_alpha"\n',
        "alpha/include/shared/Other.hpp": '#define UPPER "upper"\n',
        "beta/package.xml": package_xml("beta", "ament_cmake"),
        "beta/include/shared/names.hpp": '#define NAME "from_beta"\n',
        "beta/include/shared/other.hpp": '#define LOWER "lower"\n',
        "node/package.xml": package_xml("node", "ament_cmake"),
        "node/src/main.cpp": NODE,
    })
    return root, root / "node" / "src" / "main.cpp"


def _names(result) -> list[str]:
    return sorted(c.name for c in result.calls if c.kind == "publish")


def test_the_map_finds_what_the_folders_in_their_order_find(write_tree, monkeypatch) -> None:
    root, main = _workspace(write_tree)
    workspace = scan([str(root)])
    used: list[list[str] | None] = []
    real = header_map.search_path

    def spy(path, folders, dotted=None):
        found = real(path, folders, dotted)
        used.append(found)
        return found

    monkeypatch.setattr(header_map, "search_path", spy)
    mapped = extract_cpp([str(main)], workspace, cache_dir=None)
    assert used and used[0] is not None and used[0][0].endswith(".hmap")
    # the two folders that hold names differing only in case are searched after the map
    assert sorted(os.path.basename(os.path.dirname(f)) for f in used[0][1:]) == [
        "alpha", "beta"]
    monkeypatch.setattr(header_map, "search_path", lambda path, folders, dotted=None: None)
    searched = extract_cpp([str(main)], workspace, cache_dir=None)
    assert _names(mapped) == _names(searched)
    # the first package's folder comes first on the include path, as it is listed
    assert _names(mapped) == ["from_alpha", "lower", "upper"]


def test_clang_reads_the_map_in_place_of_the_folder(tmp_path) -> None:
    folder = tmp_path / "include"
    (folder / "pkg" / "deep").mkdir(parents=True)
    (folder / "pkg" / "deep" / "value.hpp").write_text("int value();\n")
    (folder / "pkg" / "top.h").write_text('#include <pkg/deep/value.hpp>\n')
    source = tmp_path / "unit.cpp"
    source.write_text("#include <pkg/top.h>\nint main() { return value(); }\n")
    entries = header_map.search_path(str(tmp_path / "ws.hmap"), [str(folder)])
    assert entries == [str(tmp_path / "ws.hmap")]
    tu = toolchain.index().parse(str(source), args=["-x", "c++", "-I", entries[0]])
    assert not [d for d in tu.diagnostics if d.severity >= 3]
    assert sorted(i.include.name for i in tu.get_includes()) == [
        str(folder / "pkg" / "deep" / "value.hpp"), str(folder / "pkg" / "top.h")]


@pytest.mark.parametrize("limit", [1])
def test_folders_too_large_are_searched_as_folders(tmp_path, monkeypatch, limit) -> None:
    folder = tmp_path / "include"
    folder.mkdir()
    for name in ("a.h", "b.h"):
        (folder / name).write_text("\n")
    monkeypatch.setattr(header_map, "MAX_FILES", limit)
    assert header_map.search_path(str(tmp_path / "ws.hmap"), [str(folder)]) is None
    assert not (tmp_path / "ws.hmap").exists()


def test_a_symbolic_link_cycle_ends(tmp_path) -> None:
    folder = tmp_path / "include"
    (folder / "pkg").mkdir(parents=True)
    (folder / "pkg" / "a.h").write_text("\n")
    os.symlink(folder, folder / "pkg" / "loop")
    found = header_map._names([str(folder)])
    assert found is not None
    names, clashing = found
    assert b"pkg/a.h" in names and not clashing
    assert all(name.count(b"loop") <= 1 for name in names)
