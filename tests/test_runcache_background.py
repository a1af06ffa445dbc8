"""(issue 24) A command keeps its run's model in the cache from a forked copy of the
process while it goes on with its queries or report (``runcache.background``): the store
runs elsewhere, is over when the command ends, is seen by a later run of the same
process, and a stop ends it without an entry half written."""

from __future__ import annotations

import json
import os
import shutil
from pathlib import Path

import pytest

from haros_arch import pipeline, runcache
from haros_arch.cli import main
from haros_arch.model.diagnostic import Diagnostic
from haros_arch.model.model import Model

FIXTURE = Path(__file__).resolve().parent.parent / "fixtures" / "python" / "several_nodes"


def _model() -> Model:
    model = Model("p")
    model.diagnostics.append(Diagnostic(code="LAUNCH_UNKNOWN_VALUE", message="m",
                                        severity="info"))
    return model


@pytest.fixture
def writers(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A file each store appends its process id to (a forked store's too)."""
    where = tmp_path / "writers.txt"
    real = runcache._store

    def recorded(folder: str, key: str, model: Model) -> None:
        with open(where, "a", encoding="utf-8") as handle:
            handle.write(f"{os.getpid()}\n")
        real(folder, key, model)

    monkeypatch.setattr(runcache, "_store", recorded)
    return where


def test_a_store_within_background_is_made_by_another_process(
        tmp_path: Path, writers: Path) -> None:
    folder = str(tmp_path / "cache")
    model = _model()
    with runcache.background():
        runcache.store(folder, "k1", model)
        model.diagnostics.clear()  # what the command does next is not what was kept
        kept = runcache.load(folder, "k1", "p")  # waits for the store under way
        assert kept is not None
        assert [d.code for d in kept.diagnostics] == ["LAUNCH_UNKNOWN_VALUE"]
    assert [int(p) for p in writers.read_text().split()] != [os.getpid()]
    assert len(writers.read_text().split()) == 1
    runcache.store(folder, "k2", _model())  # outside: in line, as before
    assert writers.read_text().split()[-1] == str(os.getpid())
    assert runcache.load(folder, "k2", "p") is not None


def test_the_store_has_ended_when_the_block_is_left(tmp_path: Path, writers: Path) -> None:
    folder = tmp_path / "cache"
    with runcache.background():
        runcache.store(str(folder), "k1", _model())
    # no wait here: the entry is there, whole
    text = (folder / "runs" / "k1.json").read_bytes()
    assert text.startswith(runcache.MODEL_HEAD)
    assert runcache.load(str(folder), "k1", "p") is not None


def test_a_stop_ends_a_store_under_way(tmp_path: Path,
                                       monkeypatch: pytest.MonkeyPatch) -> None:
    import time

    folder = tmp_path / "cache"
    started = tmp_path / "started"
    real = runcache._store

    def slow(folder_: str, key: str, model: Model) -> None:
        started.write_text("yes")
        time.sleep(60)  # ended by the stop long before
        real(folder_, key, model)

    monkeypatch.setattr(runcache, "_store", slow)
    with pytest.raises(KeyboardInterrupt), runcache.background():
        runcache.store(str(folder), "k1", _model())
        while not started.exists():
            time.sleep(0.01)
        raise KeyboardInterrupt
    assert not (folder / "runs" / "k1.json").exists()
    assert runcache._BACKGROUND == []


def test_a_command_run_twice_reads_the_model_its_first_run_kept(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str],
        writers: Path) -> None:
    shutil.copytree(FIXTURE, tmp_path / "ws")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    project = str(tmp_path / "ws" / "project.yaml")
    assert main(["check", project, "--format", "json", "--fail-on", "never"]) == 0
    first = json.loads(capsys.readouterr().out)
    assert [int(p) for p in writers.read_text().split()] != [os.getpid()]

    def not_again(*_args: object, **_kwargs: object) -> Model:
        raise AssertionError("analysed again")

    monkeypatch.setattr(pipeline, "_analyse", not_again)
    assert main(["check", project, "--format", "json", "--fail-on", "never"]) == 0
    assert json.loads(capsys.readouterr().out) == first
