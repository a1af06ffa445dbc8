"""An edit of a C++ source that moves lines and changes no call: the kept run's model and
findings renumbered (``relocate``, ``runcache.relocated``), the same as a cold run's."""

from __future__ import annotations

import json
from pathlib import Path

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.command import document
from haros_arch.relocate import Files
from tests.conftest import copied_old

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"


def _examples(tmp_path: Path) -> Path:
    return copied_old(EXAMPLES, tmp_path / "examples") / "project.yaml"


def _document(project: Path, cache: Path | None) -> tuple[str, dict[str, float]]:
    """The model and findings of a run (``extract``'s document), and its stages."""
    spec = load(str(project))
    timings: dict[str, float] = {}
    model = analyse(spec, {}, Options(cache_dir=None if cache is None else str(cache),
                                      jobs=1, timings=timings))
    return json.dumps(document(model, spec), sort_keys=True), timings


def test_lines_moved_in_cpp_sources_give_a_cold_runs_model_and_findings(tmp_path: Path,
                                                                        monkeypatch
                                                                        ) -> None:
    project = _examples(tmp_path)
    monkeypatch.chdir(tmp_path)
    cache = tmp_path / "cache"
    first, _ = _document(project, cache)
    controller = project.parent / "src" / "demo_robot" / "src" / "controller.cpp"
    driver = project.parent / "src" / "demo_robot" / "src" / "driver.cpp"
    lines = controller.read_text().split("\n")
    middle = len(lines) // 2
    edits = [  # each on top of the last: a run renumbers a renumbered run's model
        (controller, "\n".join(["// a comment", *lines])),
        (controller, "\n".join(["// a comment", *lines[:middle], "", "  // more", "",
                                *lines[middle:]])),
        (driver, "// the driver\n\n" + driver.read_text()),
        (controller, "\n".join(lines[:middle] + lines[middle:])),  # back, the driver not
    ]
    for number, (source, text) in enumerate(edits):
        source.write_text(text)
        again, timings = _document(project, cache)
        cold, _ = _document(project, None)
        assert again == cold, number
        # neither the configurations built nor their launch files loaded
        assert "graph" not in timings and "launch" not in timings, number
        assert "C++" in timings, number
        if number < 3:
            assert again != first  # lines did move
    same, timings = _document(project, cache)  # then kept as any run
    assert set(timings) == {"cache"} and same == again


def test_an_edit_that_changes_a_call_builds_the_configurations_again(tmp_path: Path,
                                                                    monkeypatch) -> None:
    project = _examples(tmp_path)
    monkeypatch.chdir(tmp_path)
    cache = tmp_path / "cache"
    _document(project, cache)
    source = project.parent / "src" / "demo_robot" / "src" / "monitor.cpp"
    text = source.read_text()
    assert text.count('"robot1"') == 1
    source.write_text("// moved\n" + text.replace('"robot1"', '"robot9"'))
    again, timings = _document(project, cache)
    assert "graph" in timings and "launch" in timings and '"robot9"' in again
    assert again == _document(project, None)[0]


def test_a_script_only_rosrun_finds_is_taken_again_without_the_launch_files(
        tmp_path: Path, monkeypatch) -> None:
    """A relocated run takes the packages and rosrun's scripts the launch files gave the
    kept run (``pipeline._Launches``); the battery monitor, installed by no rule here,
    is found by rosrun's search of the package only."""
    project = _examples(tmp_path)
    monkeypatch.chdir(tmp_path)
    build = project.parent / "src" / "demo_robot" / "CMakeLists.txt"
    text = build.read_text()
    start = text.index("catkin_install_python(")
    build.write_text(text[:start] + text[text.index(")", start) + 1:])
    cache = tmp_path / "cache"
    first, _ = _document(project, cache)
    assert '"battery_monitor.py"' in first
    source = project.parent / "src" / "demo_robot" / "src" / "driver.cpp"
    source.write_text("// moved\n" + source.read_text())
    again, timings = _document(project, cache)
    assert "graph" not in timings and "launch" not in timings
    assert again == _document(project, None)[0] and '"battery_monitor.py"' in again


def test_launch_files_that_give_other_packages_than_before_make_the_run_whole(
        tmp_path: Path, monkeypatch) -> None:
    """Not expected (the same files give the same), but if the launch files loaded late
    gave other packages or scripts than the kept run's record says, the run is made
    whole from the start."""
    from haros_arch import pipeline

    project = _examples(tmp_path)
    monkeypatch.chdir(tmp_path)
    cache = tmp_path / "cache"
    _document(project, cache)
    monkeypatch.setattr(pipeline._Launches, "agrees", lambda *_args: False)
    source = project.parent / "src" / "demo_robot" / "src" / "monitor.cpp"
    source.write_text("// moved\n" + source.read_text().replace('"robot1"', '"robot9"'))
    again, timings = _document(project, cache)
    assert "graph" in timings and '"robot9"' in again
    assert again == _document(project, None)[0]


FILE = "src/a/node.cpp"


def _location(line: int, path: str = FILE) -> str:
    return f'{{"package": "a", "file": "{path}", "line": {line}, "column": 3}}'


def test_a_shift_maps_each_old_line_to_its_new_one() -> None:
    files = Files(["/ws/" + FILE], "/ws")
    old = f'[{_location(12)}, {_location(30)}, "under if (x) ({FILE}:30)"]'
    new = f'[{_location(14)}, {_location(33)}, "under if (x) (/ws/{FILE}:33)"]'
    assert files.line_maps(old, new) is None  # the path written otherwise: not the same
    new = f'[{_location(14)}, {_location(33)}, "under if (x) ({FILE}:33)"]'
    maps = files.line_maps(old, new)
    assert maps == {"/ws/" + FILE: {12: 14, 30: 33}}
    assert files.renumbered(f'{{"at": {_location(30)}, "m": "{FILE}:12:4"}}', maps) == (
        f'{{"at": {_location(33)}, "m": "{FILE}:14:4"}}')
    assert files.renumbered(_location(13), maps) is None  # a line the maps do not know
    other = _location(13, "src/b/node.cpp")  # another file: as it is
    assert files.renumbered(other, maps) == other
    # another file whose path ends as this one's, or this one's written otherwise: not
    # read as a place, so not renumbered, so the text is not given
    assert files.renumbered(f'"/elsewhere/{FILE}:13"', maps) is None
    assert files.renumbered(f'"at ~{FILE}:12"', maps) is None
    assert files.renumbered(f'"at `{FILE}:12`"', maps) == f'"at `{FILE}:14`"'


def test_a_map_that_would_reorder_places_is_none() -> None:
    files = Files(["/ws/" + FILE], "/ws")
    # two calls that swapped places: lines not in the same order
    assert files.line_maps(f"[{_location(5)}, {_location(9)}]",
                           f"[{_location(9)}, {_location(5)}]") is None
    # one old line to two new ones, two old lines to one new one
    assert files.line_maps(f"[{_location(5)}, {_location(5)}]",
                           f"[{_location(6)}, {_location(7)}]") is None
    assert files.line_maps(f"[{_location(5)}, {_location(6)}]",
                           f"[{_location(7)}, {_location(7)}]") is None
    # a line quoted in a string gains a digit: a list sorted by such strings may reorder
    assert files.line_maps(f'["{FILE}:99"]', f'["{FILE}:100"]') is None
    assert files.line_maps(_location(99), _location(100)) is not None  # a number sorts
    # anything else differs: no map
    assert files.line_maps(f'[{_location(5)}, "x"]', f'[{_location(6)}, "y"]') is None


def test_places_of_spellings_that_overlap() -> None:
    """A changed file spelt relative and absolute, another whose name begins with its
    name, a name with no line after it, a path of another tree ending the same."""
    files = Files(["/ws/src/a.cpp", "/ws/src/a.cpp.in", "/ws/x/b.hpp"], "/ws")
    text = ('"/ws/src/a.cpp:3 src/a.cpp.in:4 (src/a.cpp", "line": 5 src/a.cpp: '
            'x/b.h:6 x/b.hpp:7 /other/src/a.cpp:8"')
    pieces, found, other = files.places(text)
    assert found == [("/ws/src/a.cpp", 3, True), ("/ws/src/a.cpp.in", 4, True),
                     ("/ws/x/b.hpp", 7, True)]
    assert other  # `(src/a.cpp", "line"`: a location's form after no quote; /other/...
    assert "".join(p + str(line) for p, (_f, line, _q)
                   in zip(pieces[:-1], found, strict=True)) + pieces[-1] == text
    assert Files(["/ws/src/a.cpp"], "/ws").places('{"file": "src/a.cpp", "line": 9}') == (
        ['{"file": "src/a.cpp", "line": ', "}"], [("/ws/src/a.cpp", 9, False)], False)


def test_extracts_document_after_lines_moved_is_the_last_one_renumbered(
        tmp_path: Path, monkeypatch) -> None:
    """``extract``'s document (indented JSON, characters beyond ASCII as they are) of a
    relocated run: the earlier run's renumbered, not made again, the same text as a cold
    run's."""
    from haros_arch.report import json as report_json

    project = _examples(tmp_path)
    monkeypatch.chdir(tmp_path)
    cache = tmp_path / "cache"
    spec = load(str(project))

    def text(cached: bool) -> str:
        model = analyse(spec, {}, Options(cache_dir=str(cache) if cached else None, jobs=1))
        return report_json.document_text(model, spec)

    first = text(True)
    controller = project.parent / "src" / "demo_robot" / "src" / "controller.cpp"
    controller.write_text("// ünïcödé comment\n\n" + controller.read_text())
    cold = text(False)
    made = report_json.document_json
    monkeypatch.setattr(report_json, "document_json", lambda data: (_ for _ in ()).throw(
        AssertionError("the document was made again")))
    again = text(True)
    assert again == cold and again != first
    monkeypatch.setattr(report_json, "document_json", made)


def test_places_in_an_indented_document() -> None:
    root = "/ws"
    files = Files(["/ws/src/ñodo.cpp"], root, indented=True)
    text = json.dumps({"a": {"file": "src/ñodo.cpp", "line": 9, "column": 2},
                       "m": "at src/ñodo.cpp:12: x"}, indent=2, ensure_ascii=False)
    _pieces, found, other = files.places(text)
    assert not other
    assert found == [("/ws/src/ñodo.cpp", 9, False), ("/ws/src/ñodo.cpp", 12, True)]
    assert files.renumbered(text, {"/ws/src/ñodo.cpp": {9: 11, 12: 14}}) == json.dumps(
        {"a": {"file": "src/ñodo.cpp", "line": 11, "column": 2},
         "m": "at src/ñodo.cpp:14: x"}, indent=2, ensure_ascii=False)
    # the compact reader does not take the indented form: not one of its places
    assert Files(["/ws/src/ñodo.cpp"], root).places(text)[1] == []


def test_extracts_summary_after_lines_moved_is_the_last_one_renumbered(
        tmp_path: Path, monkeypatch) -> None:
    """``extract``'s summary of a relocated run: the earlier run's lines renumbered (the
    model is not decoded for them), the same as a cold run's, with and without -v."""
    from haros_arch import runcache
    from haros_arch.report.text import summary_lines

    project = _examples(tmp_path)
    monkeypatch.chdir(tmp_path)
    cache = tmp_path / "cache"
    spec = load(str(project))

    def summary(cached: bool, verbose: bool) -> tuple[list[str], bool]:
        model = analyse(spec, {}, Options(cache_dir=str(cache) if cached else None, jobs=1))
        made: list[bool] = []

        def compute() -> list[str]:
            made.append(True)
            return summary_lines(model, verbose)

        return runcache.summary(model, verbose, compute), bool(made)

    first = {verbose: summary(True, verbose)[0] for verbose in (False, True)}
    monitor = project.parent / "src" / "demo_robot" / "src" / "monitor.cpp"
    monitor.write_text("// a comment\n\n\n" + monitor.read_text())
    for verbose in (False, True):
        cold, _ = summary(False, verbose)
        again, made = summary(True, verbose)
        assert again == cold and not made, verbose
        # a diagnostic's place in that file (CPP_DYNAMIC_NAME), moved
        assert "demo_robot/src/monitor.cpp:17:" in "\n".join(first[verbose])
        assert "demo_robot/src/monitor.cpp:20:" in "\n".join(again)


def test_a_summary_that_lists_places_by_line_alone_is_not_renumbered() -> None:
    """``also at`` under a file's name lists its other places as ``line:col``: a text
    whose ``path:line`` places are renumbered would keep those as they were."""
    from haros_arch.model.diagnostic import Diagnostic
    from haros_arch.model.location import Location
    from haros_arch.report.text import Lines, bare_places, print_diagnostics

    def said(file: str, *lines: int) -> list[Diagnostic]:
        return [Diagnostic(code="CPP_X", severity="warning", message="the same",
                           location=Location(file=file, line=line, column=1))
                for line in lines]

    printed = Lines()
    print_diagnostics([*said("src/a.cpp", 3, 9), *said("src/b.cpp", 4)], printed,
                      verbose=False)
    assert any("also at: 9:1" in line for line in printed.lines)
    assert bare_places(printed.lines, ["src/a.cpp"])
    assert not bare_places(printed.lines, ["src/b.cpp", "src/c.cpp"])


def _page(spec, cache: Path | None) -> str:
    """The report page of a run (``haros-arch report``'s, read back where it is kept)."""
    from haros_arch.viz import command

    model = analyse(spec, {}, Options(cache_dir=None if cache is None else str(cache), jobs=1))
    return command.report_page(model, command.project_findings(model, spec),
                               command.workspace_root(spec, None), spec)


def test_reports_page_after_lines_moved_is_the_last_one_renumbered(
        tmp_path: Path, monkeypatch) -> None:
    """The report page of a relocated run: the earlier run's page with its data
    renumbered and the lines it shows of the changed file read again (one inserted among
    them), not rendered again, the same text as a cold run's."""
    from haros_arch.viz import html

    project = _examples(tmp_path)
    monkeypatch.chdir(tmp_path)
    cache = tmp_path / "cache"
    spec = load(str(project))
    first = _page(spec, cache)
    monitor = project.parent / "src" / "demo_robot" / "src" / "monitor.cpp"
    lines = monitor.read_text().split("\n")
    assert "subscribe" in lines[16]  # the call at line 17 (CPP_DYNAMIC_NAME)
    monitor.write_text("\n".join(["// ünïcödé <&>", *lines[:16], "  // shown above it",
                                  *lines[16:]]))
    cold = _page(spec, None)
    assert "// shown above it" in cold and "// shown above it" not in first
    monkeypatch.setattr(html, "render_report", lambda *a, **k: (_ for _ in ()).throw(
        AssertionError("the page was rendered again")))
    again = _page(spec, cache)
    assert again == cold


def test_a_page_whose_data_names_a_changed_file_otherwise_is_rendered(
        tmp_path: Path, monkeypatch) -> None:
    """A page is renumbered only when its data holds every place of the changed files
    the model and findings hold: one it does not read as a place (here, the page's data
    with the file's places taken out) makes the page rendered again."""
    from haros_arch.viz import html

    project = _examples(tmp_path)
    monkeypatch.chdir(tmp_path)
    cache = tmp_path / "cache"
    spec = load(str(project))
    first = _page(spec, cache)
    assert '"file":"demo_robot/src/monitor.cpp","line":17' in first
    pages = list(cache.glob("**/runs/*-report-*.txt"))
    assert pages
    for entry in pages:  # the places written otherwise
        entry.write_text(entry.read_text().replace(
            '"demo_robot/src/monitor.cpp","line":', '"demo_robot/src/monitor.cpp","at":'))
    monitor = project.parent / "src" / "demo_robot" / "src" / "monitor.cpp"
    monitor.write_text("// moved\n" + monitor.read_text())
    rendered: list[bool] = []
    made = html.render_report
    monkeypatch.setattr(html, "render_report",
                        lambda *a, **k: rendered.append(True) or made(*a, **k))
    again = _page(spec, cache)
    assert rendered and '"file":"demo_robot/src/monitor.cpp","line":18' in again


def test_an_edit_that_changes_a_lines_length_in_place_is_the_same_run(
        tmp_path: Path, monkeypatch) -> None:
    """A comment made longer above the code moves no line: the units give what they
    gave (the facts name their call sites by line and column, not by byte offset), so
    the kept run answers as for a comment appended (no build files, launch files or
    configurations read again)."""
    project = _examples(tmp_path)
    monkeypatch.chdir(tmp_path)
    cache = tmp_path / "cache"
    driver = project.parent / "src" / "demo_robot" / "src" / "driver.cpp"
    text = driver.read_text()
    driver.write_text("// one\n" + text)
    first, _ = _document(project, cache)
    driver.write_text("// a longer comment in its place\n" + text)
    again, timings = _document(project, cache)
    assert set(timings) == {"cache", "scan", "C++"}
    assert again == first == _document(project, None)[0]
