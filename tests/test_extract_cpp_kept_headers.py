"""The synthesised headers' folder kept in the cache folder from run to run: each run
that parses makes it hold exactly its own headers, and a run that finds it held by
another uses a folder of its own."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

from haros_arch.extract.cpp import extract_cpp
from haros_arch.extract.cpp.headers import IncludeSetup
from haros_arch.workspace import scan

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures" / "cpp"

SOURCE = """\
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include "demo_extra/extra.hpp"

class Extra : public rclcpp::Node
{
public:
  Extra() : Node("extra")
  {
    chatter_ = create_publisher<std_msgs::msg::String>("chatter", 10);
    demo_extra::advertise(*this);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr chatter_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Extra>());
}
"""

HEADER = """\
#pragma once
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
namespace demo_extra
{
inline void advertise(rclcpp::Node & node)
{
  static auto pub = node.create_publisher<std_msgs::msg::String>("extra", 10);
}
}
"""


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    target = tmp_path / "ws"
    shutil.copytree(FIXTURES / "ros2", target)
    (target / "src" / "demo2" / "src" / "extra.cpp").write_text(SOURCE)
    return target


def kept_folder(store: Path) -> Path:
    found = [p for p in (store / "generated").iterdir() if p.is_dir()]
    assert len(found) == 1
    return found[0]


def test_a_header_stood_in_for_is_not_found_once_the_workspace_has_it(
        workspace: Path, tmp_path: Path) -> None:
    """The stand-in a run writes for a missing header stays in the kept folder, which
    clang searches first: the next run must not find it there once the workspace has
    the real header."""
    store = tmp_path / "cache"
    source = str(workspace / "src" / "demo2" / "src" / "extra.cpp")
    first = extract_cpp([source], scan([str(workspace)]), cache_dir=str(store))
    assert [c.name for c in first.calls if c.kind == "publish"] == ["chatter"]
    assert list(kept_folder(store).rglob("extra.hpp"))  # the empty stand-in, kept
    header = workspace / "src" / "demo2" / "include" / "demo_extra" / "extra.hpp"
    header.parent.mkdir(parents=True)
    header.write_text(HEADER)
    second = extract_cpp([source], scan([str(workspace)]), cache_dir=str(store))
    assert sorted(c.name for c in second.calls if c.kind == "publish") == ["chatter", "extra"]
    assert not list(kept_folder(store).rglob("extra.hpp"))


def test_kept_headers_give_what_a_fresh_folder_gives(workspace: Path, tmp_path: Path) -> None:
    store = tmp_path / "cache"
    talker = str(workspace / "src" / "demo2" / "src" / "talker.cpp")
    fresh = extract_cpp([talker], scan([str(workspace)]), cache_dir=None)
    extract_cpp([talker], scan([str(workspace)]), cache_dir=str(store))
    kept = kept_folder(store)
    (kept / "stale" / "deeper").mkdir(parents=True)
    (kept / "stale" / "deeper" / "old.hpp").write_text("#error stale\n")
    status = next(kept.rglob("status.hpp"))
    status.write_text("#error a header of another run\n")
    with open(talker, "a") as handle:  # parsed again, with the kept folder
        handle.write("// changed\n")
    again = extract_cpp([talker], scan([str(workspace)]), cache_dir=str(store))

    def rows(result: object) -> list[tuple[object, ...]]:
        return [(c.kind, c.name, c.type, c.qos) for c in result.calls]  # type: ignore[attr-defined]

    assert rows(again) == rows(fresh)
    assert not (kept / "stale").exists()
    assert "#error" not in status.read_text()


def test_a_folder_another_run_holds_is_not_shared(workspace: Path, tmp_path: Path) -> None:
    store = tmp_path / "cache"
    ws = scan([str(workspace)])
    first = IncludeSetup(ws, [], False, kept_in=str(store))
    try:
        assert first.generated.startswith(str(store))
        second = IncludeSetup(ws, [], False, kept_in=str(store))
        assert not second.generated.startswith(str(store))
        second.close()
        assert not os.path.exists(second.generated)
    finally:
        first.close()
    third = IncludeSetup(ws, [], False, kept_in=str(store))  # free again
    assert third.generated == first.generated
    third.close()
    assert os.path.isdir(first.generated)


def test_an_unwritable_cache_folder_falls_back_to_a_temporary_one(
        workspace: Path, tmp_path: Path) -> None:
    blocked = tmp_path / "file"
    blocked.write_text("not a folder")
    setup = IncludeSetup(scan([str(workspace)]), [], False, kept_in=str(blocked))
    assert not setup.generated.startswith(str(blocked)) and os.path.isdir(setup.generated)
    setup.close()
    assert not os.path.exists(setup.generated)
