"""Hostile files end with a clear message, never a hang or a traceback: FIFOs where a
project file or package.xml belongs, YAML and JSON nested thousands deep, saved models whose
fields have the wrong types."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import package_xml

from haros_arch.cli import main
from haros_arch.workspace import scan


def run_cli(*args: str, timeout: float = 30) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "haros_arch.cli", *args], capture_output=True,
                          text=True, timeout=timeout)


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs FIFOs")
def test_fifo_project_file_is_refused_not_waited_on(tmp_path: Path) -> None:
    fifo = tmp_path / "project.yaml"
    os.mkfifo(fifo)
    done = run_cli("check", str(fifo))
    assert done.returncode == 2
    assert "not a regular file" in done.stderr


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs FIFOs")
def test_fifo_in_the_workspace_is_a_diagnostic(tmp_path: Path) -> None:
    good = tmp_path / "src" / "good"
    good.mkdir(parents=True)
    (good / "package.xml").write_text(package_xml("good"))
    bad = tmp_path / "src" / "bad"
    bad.mkdir()
    os.mkfifo(bad / "package.xml")
    workspace = scan([str(tmp_path / "src")], {})
    assert sorted(workspace.packages) == ["good"]
    assert any("not a regular file" in d.message for d in workspace.diagnostics)


def test_deep_project_file(tmp_path: Path, capsys) -> None:
    deep = tmp_path / "project.yaml"
    deep.write_text("nodes: " + "[" * 20000 + "]" * 20000 + "\n")
    assert main(["check", str(deep)]) == 2
    assert "nested too deep" in capsys.readouterr().err


@pytest.mark.parametrize("document", [
    {"schema": "haros-arch/1", "packages": [{"name": "p", "nodes": ["not an object"]}]},
    {"schema": "haros-arch/1", "configurations": [{"name": "c", "nodes": 5}]},
    {"schema": "haros-arch/1", "configurations": [{"name": "c", "links": [{"location": 3}]}]},
])
def test_model_with_wrong_field_types(tmp_path: Path, capsys, document: dict) -> None:
    saved = tmp_path / "model.json"
    saved.write_text(json.dumps(document))
    assert main(["query", "--model", str(saved), "configs"]) == 2
    assert "not a haros-arch model" in capsys.readouterr().err


def test_model_nested_too_deep(tmp_path: Path, capsys) -> None:
    saved = tmp_path / "model.json"
    saved.write_text('{"configurations": ' + "[" * 100000 + "]" * 100000 + "}")
    assert main(["query", "--model", str(saved), "configs"]) == 2
    assert main(["report", "--model", str(saved), "-o", str(tmp_path / "r.html")]) == 2


def test_package_of_is_the_innermost_package_folder(tmp_path: Path) -> None:
    from haros_arch.model.source import Package

    workspace = scan([str(tmp_path)], {})
    outer, inner = Package("outer", "outer"), Package("inner", "outer/sub/inner")
    outer.root, inner.root = str(tmp_path / "outer"), str(tmp_path / "outer" / "sub" / "inner")
    workspace.packages.update(outer=outer, inner=inner)
    assert workspace.package_of(str(tmp_path / "outer" / "sub" / "inner" / "a.cpp")) is inner
    assert workspace.package_of(str(tmp_path / "outer" / "sub" / "b.cpp")) is outer
    assert workspace.package_of(str(tmp_path / "outer")) is outer
    assert workspace.package_of(str(tmp_path / "outerx" / "c.cpp")) is None
    assert workspace.package_of("/") is None


def test_package_xml_with_a_huge_format_number(tmp_path: Path) -> None:
    # found by scripts/fuzz: int() of a 5,000-digit format raised ValueError
    package = tmp_path / "src" / "p"
    package.mkdir(parents=True)
    (package / "package.xml").write_text(
        package_xml("p").replace('format="2"', 'format="' + "9" * 5001 + '"'))
    workspace = scan([str(tmp_path / "src")], {})
    assert workspace.packages["p"].format == 1
    assert not any(d.code == "INTERNAL" for d in workspace.diagnostics)


def test_query_with_a_number_of_thousands_of_digits() -> None:
    # found by scripts/fuzz: int() of a 5,001-digit literal escaped as lark's VisitError
    from haros_arch import query

    with pytest.raises(query.QueryLimitError, match="characters long"):
        query.compile("topics[len(self.publishers) > " + "9" * 5001 + "]")
    assert query.compile("topics[len(self.publishers) > 99999]") is not None


def test_model_with_an_infinite_line_number(tmp_path: Path, capsys) -> None:
    # found by scripts/fuzz: a location line of 1e999 (JSON infinity) raised OverflowError
    saved = tmp_path / "model.json"
    saved.write_text('{"schema": "haros-arch/1", "configurations": [{"name": "c", "nodes": '
                     '[{"name": "/a", "location": {"file": "a.launch", "line": 1e999}}]}]}')
    assert main(["query", "--model", str(saved), "configs"]) == 2
    assert "not a haros-arch model" in capsys.readouterr().err
