"""The library calls behind the thin CLI: results out, nothing printed."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from haros_arch.api import analyse_path
from haros_arch.pipeline import Options
from haros_arch.project import ProjectError
from haros_arch.query import QueryError, compile
from haros_arch.query.command import NoConfiguration, check, query

ROOT = Path(__file__).resolve().parent.parent
PROJECT = ROOT / "fixtures" / "python" / "several_nodes" / "project.yaml"
OPTIONS = Options(cache_dir=None, jobs=1)


def test_a_project_file_gives_the_model_without_notes(capsys) -> None:
    analysis = analyse_path(str(PROJECT), OPTIONS)
    assert analysis.model is not None and analysis.error is None
    assert analysis.notes == []
    assert [c.name for c in analysis.model.configurations] == ["pair"]
    assert capsys.readouterr() == ("", "")


def test_a_folder_gives_notes_on_the_choice(capsys) -> None:
    analysis = analyse_path(str(PROJECT.parent / "src"), OPTIONS)
    assert analysis.model is not None
    assert analysis.notes and "launch file" in analysis.notes[0]
    assert capsys.readouterr() == ("", "")


def test_a_missing_workspace_is_an_error_not_a_model(tmp_path: Path) -> None:
    project = tmp_path / "p.yaml"
    project.write_text("project: p\nworkspace: nowhere\nconfigurations:\n"
                       "  c:\n    launch: [a/launch/a.launch]\n")
    analysis = analyse_path(str(project), OPTIONS)
    assert analysis.model is None
    assert analysis.error and "does not exist" in analysis.error


def test_a_bad_project_file_raises(tmp_path: Path) -> None:
    project = tmp_path / "p.yaml"
    project.write_text("project: [\n")
    with pytest.raises(ProjectError):
        analyse_path(str(project), OPTIONS)


def test_check_and_query_return_results(capsys) -> None:
    analysis = analyse_path(str(PROJECT), OPTIONS)
    assert analysis.model is not None
    checked = check(analysis.model, analysis.project)
    assert checked.shipped and len(checked.rules) >= checked.shipped
    assert set(checked.seconds) <= {r.id for r in checked.rules}
    assert checked.exit_code("never") == 0
    matches = query(analysis.model, compile("nodes"))  # source nodes: the whole model
    assert matches and {m.configuration for m in matches} == {None}
    matches = query(analysis.model, compile("nodes"), "pair")
    assert matches and {m.configuration for m in matches} == {"pair"}
    with pytest.raises(NoConfiguration, match="have: pair"):
        query(analysis.model, compile("nodes"), "nope")
    assert capsys.readouterr() == ("", "")


def test_query_errors_are_raised() -> None:
    with pytest.raises(QueryError):
        compile("nodes[")


def test_the_query_package_imports_no_reporter() -> None:
    for path in (ROOT / "haros_arch" / "query").glob("*.py"):
        tree = ast.parse(path.read_text())
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom):
                assert "report" not in (node.module or "").split("."), path
            elif isinstance(node, ast.Import):
                assert not any(".report" in a.name for a in node.names), path


def test_options_timings_get_the_seconds_of_every_stage() -> None:
    from haros_arch.pipeline import STAGES

    timings: dict[str, float] = {}
    analysis = analyse_path(str(PROJECT), Options(cache_dir=None, jobs=1, timings=timings))
    assert analysis.model is not None
    assert set(timings) == set(STAGES) - {"cache"} and all(t >= 0 for t in timings.values())
    assert timings["Python"] > 0  # the fixture's nodes are Python
