"""The persistent cache of C++ results and the parallel parse of a node's sources."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

from haros_arch.extract.cpp import cache, extract_cpp
from haros_arch.workspace import scan

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures" / "cpp"


def rows(result: object) -> list[tuple[object, ...]]:
    return [(c.kind, c.name, c.type, c.qos, c.name_param, c.location, c.conditions)
            for c in result.calls]  # type: ignore[attr-defined]


@pytest.fixture
def workspace_copy(tmp_path: Path) -> Path:
    target = tmp_path / "ws"
    shutil.copytree(FIXTURES / "ros2", target)
    return target


def test_cached_result_equals_parsed_one(workspace_copy: Path, tmp_path: Path,
                                         monkeypatch: pytest.MonkeyPatch) -> None:
    ws = scan([str(workspace_copy)])
    source = str(workspace_copy / "src" / "demo2" / "src" / "talker.cpp")
    store = str(tmp_path / "cache")
    first = extract_cpp([source], ws, cache_dir=store)
    assert os.listdir(os.path.join(store, "cpp"))
    from haros_arch.extract import cpp

    def no_parse(*args: object) -> None:
        raise AssertionError("an unchanged source must come from the cache")

    monkeypatch.setattr(cpp, "_parse", no_parse)
    second = extract_cpp([source], ws, cache_dir=store)
    assert rows(second) == rows(first) and second.rosname == first.rosname
    assert [d.code for d in second.diagnostics] == [d.code for d in first.diagnostics]


def test_changed_message_definition_invalidates(workspace_copy: Path, tmp_path: Path,
                                                monkeypatch: pytest.MonkeyPatch) -> None:
    from haros_arch.extract import cpp

    parses: list[str] = []
    real_parse = cpp._parse

    def counting(path: str, *args: object) -> object:
        parses.append(path)
        return real_parse(path, *args)  # type: ignore[arg-type]

    monkeypatch.setattr(cpp, "_parse", counting)
    ws = scan([str(workspace_copy)])
    source = str(workspace_copy / "src" / "demo2" / "src" / "talker.cpp")
    store = str(tmp_path / "cache")
    extract_cpp([source], ws, cache_dir=store)
    extract_cpp([source], ws, cache_dir=store)
    assert len(parses) == 1
    (workspace_copy / "src" / "demo2" / "msg" / "Status.msg").write_text("string label\n")
    again = extract_cpp([source], ws, cache_dir=store)  # the synthesised header changed
    assert len(parses) == 2
    assert [c.name for c in again.calls][:2] == ["chatter", "status"]


def test_corrupt_entry_is_ignored(workspace_copy: Path, tmp_path: Path) -> None:
    ws = scan([str(workspace_copy)])
    source = str(workspace_copy / "src" / "demo2" / "src" / "mover.cpp")
    store = tmp_path / "cache"
    first = extract_cpp([source], ws, cache_dir=str(store))
    for entry in (store / "cpp").iterdir():
        entry.write_text('{"headers": [], "result": {"calls": [{"kind": 1}]}}')
    again = extract_cpp([source], ws, cache_dir=str(store))
    assert rows(again) == rows(first)


@pytest.mark.parametrize("second", ['{"result": {"calls": [{"kind": 1}]}}', "not JSON"])
def test_a_corrupt_result_line_is_parsed_again_and_not_needed_for_digests(
        workspace_copy: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
        second: str) -> None:
    # an entry is two lines: headers and digest, then the result; a run that only
    # compares digests (``unit_digests``) reads the first line alone
    from haros_arch.extract import cpp

    ws = scan([str(workspace_copy)])
    source = str(workspace_copy / "src" / "demo2" / "src" / "mover.cpp")
    store = tmp_path / "cache"
    first = extract_cpp([source], ws, cache_dir=str(store))
    digests = cpp.unit_digests([source], ws, cache_dir=str(store)).units
    for entry in (store / "cpp").iterdir():
        head = entry.read_text().splitlines()[0]
        entry.write_text(head + "\n" + second)
    real_parse = cpp._parse

    def no_parse(*args: object) -> None:
        raise AssertionError("the digest is on the entry's first line")

    monkeypatch.setattr(cpp, "_parse", no_parse)
    assert cpp.unit_digests([source], ws, cache_dir=str(store)).units == digests
    monkeypatch.setattr(cpp, "_parse", real_parse)
    again = extract_cpp([source], ws, cache_dir=str(store))
    assert rows(again) == rows(first)


def test_parallel_parse_gives_the_same_calls(workspace_copy: Path) -> None:
    ws = scan([str(workspace_copy)])
    folder = workspace_copy / "src" / "demo2" / "src"
    sources = [str(folder / "talker.cpp"), str(folder / "mover.cpp")]
    serial = extract_cpp(sources, ws, cache_dir=None, jobs=1)
    parallel = extract_cpp(sources, ws, cache_dir=None, jobs=2)
    assert rows(parallel) == rows(serial)
    # talker.cpp's Talker is a component no main() builds; mover.cpp's main() makes
    # /base/mover: the first node of this process (extract_cpp_several_nodes)
    assert parallel.rosname == serial.rosname == "/base/mover"


def test_default_folder_follows_xdg(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    assert cache.default_folder("/ws") == str(tmp_path / "haros-arch")


def test_the_key_covers_every_module_the_extractor_runs(workspace_copy: Path,
                                                        tmp_path: Path) -> None:
    # an entry must not outlive a change to any code that made it: the extractor reads the
    # model, the expression evaluator and the build readers from outside its own folder
    import sys

    source = str(workspace_copy / "src" / "demo2" / "src" / "talker.cpp")
    extract_cpp([source], scan([str(workspace_copy)]), cache_dir=str(tmp_path / "cache"))
    import haros_arch

    package = os.path.dirname(os.path.abspath(haros_arch.__file__))
    covered = {os.path.abspath(path) for path in cache.tool_files()}
    used = {os.path.abspath(module.__file__) for name, module in list(sys.modules.items())
            if name.startswith("haros_arch.") and getattr(module, "__file__", None)}
    outside = {path for path in used
               if not path.startswith(os.path.join(package, "extract", "cpp") + os.sep)}
    assert outside, "the extractor should import modules outside its folder"
    assert used - covered == set()
