"""What the build-file stage read off C++ files in an earlier run is taken again where
the files are unchanged (``facts.KeptFacts``), with the same model as a cold run."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from haros_arch import facts
from haros_arch.facts import KeptFacts, decode, encode, same
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.command import document
from tests.conftest import copied_old

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"


def test_plain_data_reads_back_with_its_types() -> None:
    value = [None, True, 1, 2.5, "s", ("a", 1), {"x", "y"}, frozenset({("p", 2)}),
             {"k": [1, (2, 3)], ("t", 1): {"z"}}, []]
    data = json.loads(json.dumps(encode(value)))
    assert same(decode(data), value)
    assert not same([1], [True]) and not same(("a",), ["a"])
    for bad in (object(), float("nan"), {1: object()}):
        with pytest.raises(TypeError):
            encode(bad)


def test_a_fact_is_taken_again_only_while_its_cpp_files_are_unchanged(tmp_path: Path
                                                                       ) -> None:
    source = tmp_path / "a.cpp"
    source.write_text("int main() {}\n")
    notes = tmp_path / "notes.txt"
    notes.write_text("x")
    made = KeptFacts()
    made.note("main words", str(source), {"main"}, [str(source), str(notes)])
    made.note("text", str(source), "int main() {}\n", [str(source)])  # texts: not kept
    made.note("odd", str(source), object(), [str(source)])  # not plain data
    data = json.loads(json.dumps(made.to_data()))
    again = KeptFacts(data)
    assert again.restore("main words", str(source)) == ({"main"},
                                                         frozenset({str(source), str(notes)}))
    assert again.restore("text", str(source)) is None
    assert again.restore("odd", str(source)) is None
    assert KeptFacts(again.to_data()).restore("main words", str(source)) is not None
    source.write_text("int main() { return 1; }\n")
    assert KeptFacts(data).restore("main words", str(source)) is None
    assert KeptFacts({"paths": 3, "facts": {}}).restore("main words", str(source)) is None


def _examples(tmp_path: Path) -> Path:
    return copied_old(EXAMPLES, tmp_path / "examples") / "project.yaml"


def _document(project: Path, cache: Path | None) -> str:
    spec = load(str(project))
    model = analyse(spec, {}, Options(cache_dir=None if cache is None else str(cache),
                                      jobs=1))
    return json.dumps(document(model, spec), sort_keys=True)


def test_a_package_read_again_takes_the_facts_of_its_unchanged_files(
        tmp_path: Path, monkeypatch) -> None:
    project = _examples(tmp_path)
    monkeypatch.chdir(tmp_path)
    cache = tmp_path / "cache"
    _document(project, cache)
    restored: list[tuple[str, str]] = []
    original = facts.KeptFacts.restore

    def spy(self: KeptFacts, kind: str, source: str) -> object:
        found = original(self, kind, source)
        if found is not None:
            restored.append((kind, source))
        return found

    monkeypatch.setattr(facts.KeptFacts, "restore", spy)
    changed = project.parent / "src" / "demo_robot" / "src" / "monitor.cpp"
    text = changed.read_text()
    assert text.count('"robot1"') == 1
    changed.write_text(text.replace('"robot1"', '"robot9"'))  # a call changed: read again
    again = _document(project, cache)
    assert again == _document(project, None) and '"robot9"' in again
    sources = {os.path.basename(source) for _kind, source in restored}
    assert "driver.cpp" in sources and "monitor.cpp" not in sources
