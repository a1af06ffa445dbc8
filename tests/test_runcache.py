"""A re-run with nothing changed is answered whole from the cache folder (runcache); any
change to a file the run reads, to the project or to the environment runs it again."""

from __future__ import annotations

import json
import os
import shutil
from pathlib import Path

from conftest import package_xml

from haros_arch import runcache
from haros_arch.model.serialise import model_to_data
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from tests.conftest import copied_old

FIXTURE = Path(__file__).resolve().parent.parent / "fixtures" / "python" / "several_nodes"


def _copy(tmp_path: Path) -> Path:
    return copied_old(FIXTURE, tmp_path / "ws") / "project.yaml"


def _run(project: Path, cache: Path, env: dict[str, str] | None = None
         ) -> tuple[str, dict[str, float]]:
    timings: dict[str, float] = {}
    model = analyse(load(str(project)), env or {},
                    Options(cache_dir=str(cache), jobs=1, timings=timings))
    return json.dumps(model_to_data(model), sort_keys=True), timings


def test_a_rerun_with_nothing_changed_is_the_kept_model(tmp_path: Path) -> None:
    project = _copy(tmp_path)
    first, timings = _run(project, tmp_path / "cache")
    assert "Python" in timings
    again, timings = _run(project, tmp_path / "cache")
    assert again == first
    assert set(timings) == {"cache"}  # no stage ran
    assert len(list((tmp_path / "cache" / "runs").glob("*-index.json"))) == 1


def test_a_changed_source_runs_again(tmp_path: Path) -> None:
    project = _copy(tmp_path)
    first, _ = _run(project, tmp_path / "cache")
    source = project.parent / "src" / "pair_nodes" / "pair_nodes" / "pair.py"
    source.write_text(source.read_text().replace("'reading'", "'readings'"))
    os.utime(source, (1_000_000_000, 1_000_000_000))  # same time as before: content counts
    changed, timings = _run(project, tmp_path / "cache")
    assert "Python" in timings and changed != first
    assert "readings" in changed and "readings" not in first


def test_a_new_file_the_project_and_the_environment_are_inputs(tmp_path: Path) -> None:
    project = _copy(tmp_path)
    _run(project, tmp_path / "cache")
    (project.parent / "src" / "pair_nodes" / "notes.txt").write_text("x")
    _, timings = _run(project, tmp_path / "cache")
    assert "scan" in timings  # a file more: run again (a glob or a launch file may see it)
    _, timings = _run(project, tmp_path / "cache", {"ROBOT": "r2"})
    assert "scan" in timings
    project.write_text(project.read_text().replace("project: several_nodes", "project: other"))
    other, timings = _run(project, tmp_path / "cache", {"ROBOT": "r2"})
    assert "scan" in timings and '"project": "other"' in other


def test_an_entry_that_does_not_read_back_is_a_miss(tmp_path: Path) -> None:
    project = _copy(tmp_path)
    first, _ = _run(project, tmp_path / "cache")
    for entry in (tmp_path / "cache" / "runs").glob("*.json"):
        if not entry.name.endswith("-index.json"):
            entry.write_text('{"model": {"configurations": 7}}')
    again, timings = _run(project, tmp_path / "cache")
    assert again == first and "scan" in timings


def test_only_the_newest_runs_are_kept(tmp_path: Path, monkeypatch) -> None:
    monkeypatch.setattr(runcache, "KEEP", 2)
    project = _copy(tmp_path)
    for robot in ("a", "b", "c", "d"):
        _run(project, tmp_path / "cache", {"ROBOT": robot})
    entries = [e for e in (tmp_path / "cache" / "runs").glob("*.json")
               if not e.name.endswith("-index.json")]
    assert len(entries) == 2


def test_workspaces_checked_in_turn_keep_their_runs(tmp_path: Path, monkeypatch) -> None:
    # entries are pruned per workspace: runs of other workspaces evict none of a
    # workspace's, however many; past WORKSPACES workspaces the oldest one's go, its stat
    # index too
    monkeypatch.setattr(runcache, "KEEP", 3)
    monkeypatch.setattr(runcache, "WORKSPACES", 3)
    projects = [_copy(tmp_path / name) for name in ("a", "b", "c", "d")]
    cache = tmp_path / "cache"
    first = {p: _run(p, cache)[0] for p in projects[:3]}
    for project in projects[:3]:  # each run again: answered from the cache
        again, timings = _run(project, cache)
        assert again == first[project] and set(timings) == {"cache"}, project
    _run(projects[3], cache)  # a fourth workspace: the first's entries go
    again, timings = _run(projects[0], cache)
    assert "graph" in timings
    indexes = list((cache / "runs").glob("*-index.json"))
    assert len(indexes) == 3  # workspaces b, c, d had theirs; a's is new again, b's gone
    again, timings = _run(projects[2], cache)
    assert again == first[projects[2]] and set(timings) == {"cache"}


def test_the_findings_of_a_kept_run_are_kept_with_it(tmp_path: Path, monkeypatch) -> None:
    from haros_arch.query import catalogue
    from haros_arch.query.command import check

    project = _copy(tmp_path)
    options = Options(cache_dir=str(tmp_path / "cache"), jobs=1)
    spec = load(str(project))
    first = check(analyse(spec, {}, options), spec).findings
    assert first
    calls: list[int] = []
    real = catalogue._run_catalogue

    def counted(*args, **kwargs):
        calls.append(1)
        return real(*args, **kwargs)

    monkeypatch.setattr(catalogue, "_run_catalogue", counted)
    again = analyse(spec, {}, options)
    assert check(again, spec).findings == first and calls == []  # read back
    subset = catalogue.run_catalogue(again, spec, catalogue.load_catalogue()[:3])
    assert calls == [1] and len(subset) < len(first)  # other rules: run
    uncached = analyse(spec, {}, Options(cache_dir=None, jobs=1))
    assert check(uncached, spec).findings == first and calls == [1, 1]


def _count_decodes(monkeypatch) -> list[int]:
    """One item per kept model decoded from here on."""
    decoded: list[int] = []
    real = runcache.from_data

    def counted(data):
        decoded.append(1)
        return real(data)

    monkeypatch.setattr(runcache, "from_data", counted)
    return decoded


def test_a_kept_run_checked_again_decodes_no_model(tmp_path: Path, monkeypatch) -> None:
    # (issue 24) check's findings and diagnostics are kept with the run: a re-run with
    # nothing changed reads them back and never decodes the kept model (half of such a
    # re-run on navigation2); the model is decoded when something asks for it
    from haros_arch.query.command import check

    project = _copy(tmp_path)
    options = Options(cache_dir=str(tmp_path / "cache"), jobs=1)
    spec = load(str(project))
    first = check(analyse(spec, {}, options), spec)
    decoded = _count_decodes(monkeypatch)
    again = analyse(spec, {}, options)
    checked = check(again, spec)
    assert (checked.findings, checked.diagnostics) == (first.findings, first.diagnostics)
    assert decoded == [] and again.project == spec.name
    assert [c.name for c in again.configurations] == [c.name for c in spec.configurations]
    assert decoded == [1]


def test_a_kept_model_changed_since_it_was_written_is_a_miss(tmp_path: Path) -> None:
    project = _copy(tmp_path)
    first, _ = _run(project, tmp_path / "cache")
    for entry in (tmp_path / "cache" / "runs").glob("*.json"):
        content = entry.read_bytes()
        if content.startswith(runcache.MODEL_HEAD):  # the same length, another text
            entry.write_bytes(content.replace(b'"several_nodes"', b'"several_nodez"'))
    again, timings = _run(project, tmp_path / "cache")
    assert again == first and "scan" in timings and "several_nodez" not in again


PAPER = FIXTURE.parent.parent / "paper_minimal"


def _copy_paper(tmp_path: Path) -> Path:
    return copied_old(PAPER, tmp_path / "paper") / "project.yaml"


def test_a_cpp_change_that_extracts_the_same_reuses_the_rest(tmp_path: Path) -> None:
    project = _copy_paper(tmp_path)
    first, _ = _run(project, tmp_path / "cache")
    source = project.parent / "src" / "example" / "src" / "active.cpp"
    source.write_text(source.read_text() + "\n// a comment\n")
    again, timings = _run(project, tmp_path / "cache")
    assert again == first
    assert "C++" in timings and "launch" not in timings and "graph" not in timings
    again, timings = _run(project, tmp_path / "cache")  # kept under the new key too
    assert again == first and set(timings) == {"cache"}
    aliases = [e for e in (tmp_path / "cache" / "runs").glob("*.json")
               if "same_as" in e.read_text()]
    assert len(aliases) == 1  # the new key names the first run's entry (and findings)


def test_repeated_cpp_changes_keep_finding_the_kept_run(tmp_path: Path, monkeypatch) -> None:
    monkeypatch.setattr(runcache, "KEEP", 3)  # a few entries: the oldest go first
    project = _copy_paper(tmp_path)
    first, _ = _run(project, tmp_path / "cache")
    source = project.parent / "src" / "example" / "src" / "active.cpp"
    text = source.read_text()
    for count in range(5):
        source.write_text(text + f"\n// comment {count}\n")
        again, timings = _run(project, tmp_path / "cache")
        assert again == first and "graph" not in timings, count


def test_a_cpp_change_that_extracts_otherwise_runs_again(tmp_path: Path) -> None:
    project = _copy_paper(tmp_path)
    first, _ = _run(project, tmp_path / "cache")
    source = project.parent / "src" / "example" / "src" / "active.cpp"
    source.write_text(source.read_text().replace('"monologue"', '"soliloquy"'))
    changed, timings = _run(project, tmp_path / "cache")
    assert "graph" in timings and "soliloquy" in changed and "soliloquy" not in first


EXAMPLES = FIXTURE.parent.parent.parent / "examples"


def _copy_examples(tmp_path: Path) -> Path:
    shutil.copytree(EXAMPLES, tmp_path / "examples")
    for folder, _dirs, files in os.walk(tmp_path / "examples"):
        for name in files:
            os.utime(os.path.join(folder, name), (1_000_000_000, 1_000_000_000))
    return tmp_path / "examples" / "project.yaml"


def test_a_cpp_change_does_not_extract_the_python_nodes_again(tmp_path: Path,
                                                              monkeypatch) -> None:
    from haros_arch.extract import python
    from haros_arch.extract.cpp import cache as cpp_cache

    project = _copy_examples(tmp_path)
    first, _ = _run(project, tmp_path / "cache")
    assert '"language": "python"' in first and '"language": "cpp"' in first
    source = project.parent / "src" / "demo_robot" / "src" / "driver.cpp"
    source.write_text(source.read_text() + "\n// a comment\n")

    def fails(*args: object, **kwargs: object) -> None:
        raise AssertionError("a Python node extracted again")

    with monkeypatch.context() as patch:
        patch.setattr(python, "extract_python", fails)
        patch.setattr(cpp_cache, "from_data", fails)  # no unit's kept calls read back
        again, timings = _run(project, tmp_path / "cache")
    assert "C++" in timings and "graph" not in timings  # the kept run answered
    fresh = analyse(load(str(project)), {}, Options(cache_dir=None, jobs=1))
    assert again == first == json.dumps(model_to_data(fresh), sort_keys=True)


def test_a_cpp_change_that_extracts_otherwise_takes_the_python_nodes_as_they_were(
        tmp_path: Path, monkeypatch) -> None:
    """Only C++ files changed and they give other calls: the run is made again, but the
    nodes of other languages, whose files are the same, are not read again: the model
    is the one a fresh run gives."""
    from haros_arch.extract import python

    project = _copy_examples(tmp_path)
    first, _ = _run(project, tmp_path / "cache")
    source = project.parent / "src" / "demo_robot" / "src" / "driver.cpp"
    # every call's line changes, and one call with it (lines moved alone: ``relocate``)
    source.write_text("// moved\n" + source.read_text().replace('"odom", 50', '"odom", 5'))

    def fails(*args: object, **kwargs: object) -> None:
        raise AssertionError("a Python node extracted again")

    with monkeypatch.context() as patch:
        patch.setattr(python, "extract_python", fails)
        changed, timings = _run(project, tmp_path / "cache")
    assert "graph" in timings and changed != first  # made again, Python nodes kept
    fresh = analyse(load(str(project)), {}, Options(cache_dir=None, jobs=1))
    assert changed == json.dumps(model_to_data(fresh), sort_keys=True)
    assert '"language": "python"' in changed
    source.write_text("// moved again\n" + source.read_text().replace(  # twice over
        '"odom", 5', '"odom", 50'))
    with monkeypatch.context() as patch:
        patch.setattr(python, "extract_python", fails)
        again, _ = _run(project, tmp_path / "cache")
    fresh = analyse(load(str(project)), {}, Options(cache_dir=None, jobs=1))
    assert again == json.dumps(model_to_data(fresh), sort_keys=True)


def test_a_python_change_after_a_cpp_change_is_in_the_model(tmp_path: Path) -> None:
    project = _copy_examples(tmp_path)
    first, _ = _run(project, tmp_path / "cache")
    cpp = project.parent / "src" / "demo_robot" / "src" / "driver.cpp"
    cpp.write_text(cpp.read_text() + "\n// a comment\n")
    _run(project, tmp_path / "cache")  # kept under the outer key of the C++ change
    script = project.parent / "src" / "demo_rover" / "scripts" / "safety_stop.py"
    script.write_text(script.read_text().replace('"cmd_vel"', '"cmd_vel_safe"'))
    os.utime(script, (1_000_000_000, 1_000_000_000))  # same time: its content counts
    changed, timings = _run(project, tmp_path / "cache")
    assert "Python" in timings and "cmd_vel_safe" in changed and "cmd_vel_safe" not in first
    fresh = analyse(load(str(project)), {}, Options(cache_dir=None, jobs=1))
    assert changed == json.dumps(model_to_data(fresh), sort_keys=True)
    cpp.write_text(cpp.read_text() + "// another\n")  # and a C++ change after it
    again, _ = _run(project, tmp_path / "cache")
    assert again == changed


def test_a_python_node_with_a_source_named_as_cpp_is_not_left_to_the_cpp_units(
        tmp_path: Path, monkeypatch) -> None:
    from haros_arch import pipeline
    from haros_arch.model.source import Node

    cpp = Node(package="p", executable="a", language="cpp")
    py = Node(package="p", executable="b", language="python",
              sources=["p/b.py"])
    assert pipeline._units_tell([cpp, py])
    odd = Node(package="p", executable="c", language="python",
               sources=["p/c.h"])
    assert not pipeline._units_tell([cpp, py, odd])  # no C++-only path then


HEADER_WORKSPACE = {
    "src/talk/package.xml": package_xml("talk"),
    "src/talk/CMakeLists.txt": """
        project(talk)
        find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
        include_directories(include)
        add_executable(talker src/talker.cpp)
        add_executable(listener src/listener.cpp)
        """,
    "src/talk/include/talk/names.h": '#define TOPIC "chatter"\n',
    "src/talk/src/talker.cpp": """
        #include <ros/ros.h>
        #include <std_msgs/String.h>
        #include "talk/names.h"
        int main(int argc, char** argv) {
          ros::init(argc, argv, "talker");
          ros::NodeHandle n;
          ros::Publisher p = n.advertise<std_msgs::String>(TOPIC, 1);
          return 0;
        }
        """,
    "src/talk/src/listener.cpp": """
        #include <ros/ros.h>
        #include <std_msgs/String.h>
        void heard(const std_msgs::String::ConstPtr& m) {}
        int main(int argc, char** argv) {
          ros::init(argc, argv, "listener");
          ros::NodeHandle n;
          ros::Subscriber s = n.subscribe("chatter", 1, heard);
          return 0;
        }
        """,
    "src/talk/launch/both.launch": """
        <launch>
          <node name="talker" pkg="talk" type="talker"/>
          <node name="listener" pkg="talk" type="listener"/>
        </launch>
        """,
    "project.yaml": "project: p\nworkspace: src\nconfigurations:\n"
                    "  c: [talk/launch/both.launch]\n",
}


def test_a_header_change_is_in_the_model_and_one_that_changes_nothing_reuses_it(
        tmp_path: Path, write_tree) -> None:
    root = write_tree(HEADER_WORKSPACE)
    project, header = root / "project.yaml", root / "src/talk/include/talk/names.h"
    first, _ = _run(project, tmp_path / "cache")
    assert '"chatter"' in first
    header.write_text('#define TOPIC "chatter"  // the same topic\n')
    same, timings = _run(project, tmp_path / "cache")
    assert same == first and "C++" in timings and "graph" not in timings
    header.write_text('#define TOPIC "babble"\n')
    changed, timings = _run(project, tmp_path / "cache")
    assert "graph" in timings and '"babble"' in changed and '"babble"' not in first
    fresh = analyse(load(str(project)), {}, Options(cache_dir=None, jobs=1))
    assert changed == json.dumps(model_to_data(fresh), sort_keys=True)


def test_the_example_gives_one_model_and_findings_cold_cached_and_touched(tmp_path: Path
                                                                           ) -> None:
    from haros_arch.query.command import document

    shutil.copytree(FIXTURE.parent.parent.parent / "examples", tmp_path / "examples")
    project = tmp_path / "examples" / "project.yaml"
    spec = load(str(project))
    cache = Options(cache_dir=str(tmp_path / "cache"), jobs=1)
    documents = [document(analyse(spec, {}, Options(cache_dir=None, jobs=1)), spec)]
    documents += [document(analyse(spec, {}, cache), spec) for _ in range(2)]
    source = next((tmp_path / "examples").rglob("*.cpp"))
    source.write_text(source.read_text() + "\n// touched\n")
    documents.append(document(analyse(spec, {}, cache), spec))
    texts = [json.dumps(d, sort_keys=True) for d in documents]
    assert texts[0] == texts[1] == texts[2] == texts[3]
    assert '"findings": []' not in texts[0]


def test_the_shells_bookkeeping_variables_are_not_inputs(tmp_path: Path) -> None:
    project = _copy(tmp_path)
    _run(project, tmp_path / "cache", {"_": "/usr/bin/a", "OLDPWD": "/x", "SHLVL": "1"})
    _, timings = _run(project, tmp_path / "cache", {"_": "/usr/bin/b", "SHLVL": "2"})
    assert set(timings) == {"cache"}


def test_check_verbose_says_the_queries_did_not_run(tmp_path: Path, capsys) -> None:
    from haros_arch.cli import main

    project = _copy(tmp_path)
    for _ in range(2):
        main(["check", str(project), "-v", "--fail-on", "never"])
    out = capsys.readouterr().out
    assert ("queries: not run (the findings of an earlier run were kept: nothing changed,"
            " or only lines of C++ sources moved)") in out
    assert out.count("queries: ") == 2  # the first run timed them


def test_a_file_larger_than_the_readers_read_counts_by_size_and_time(tmp_path: Path,
                                                                      monkeypatch) -> None:
    def digest_of(path: Path) -> str:
        snap = runcache.Snapshot(str(tmp_path / "index.json"))
        snap.path(str(path))
        snap.save()
        return snap.digest()

    monkeypatch.setattr(runcache, "MAX_FILE_BYTES", 10)
    big, small = tmp_path / "big.bag", tmp_path / "small.yaml"
    big.write_bytes(b"0123456789abcdef")
    small.write_bytes(b"0123")
    for path in (big, small):
        os.utime(path, (1_000_000_000, 1_000_000_000))
    before = digest_of(big), digest_of(small)
    for path in (big, small):  # touched: the same bytes, a later time
        os.utime(path, (1_000_000_001, 1_000_000_001))
    assert digest_of(small) == before[1]  # read again: the same content
    assert digest_of(big) != before[0]  # not read: its time counts


def test_a_model_that_does_not_read_back_whole_is_not_kept(tmp_path: Path,
                                                           monkeypatch) -> None:
    from haros_arch.model import load as model_load

    project = _copy(tmp_path)
    real = model_load.from_data

    def lossy(data):
        model = real(data)
        model.packages = model.packages[:-1]
        return model

    monkeypatch.setattr(runcache, "from_data", lossy)
    first, _ = _run(project, tmp_path / "cache")
    again, timings = _run(project, tmp_path / "cache")
    assert again == first and "scan" in timings  # ran again: nothing was kept


def test_a_model_whose_links_read_back_with_other_calls_is_not_kept(tmp_path: Path,
                                                                   monkeypatch) -> None:
    """A link whose call reads back otherwise (a parameter read's default lost) makes
    the JSON of the model read back differ (a link writes its call where its node type's
    first call of its kind and place is not it): the model is not kept, the next run
    runs again. Before, the JSON did not show it and the wrong model was kept."""
    from dataclasses import replace

    from haros_arch.model import load as model_load

    project = _copy(tmp_path)
    real = model_load.from_data

    def lossy(data):
        model = real(data)
        for link in model.configurations[0].links:
            if link.call is not None and link.kind == "read":
                link.call = replace(link.call, has_default=not link.call.has_default)
                break
        else:
            raise AssertionError("no parameter read in the fixture")
        return model

    monkeypatch.setattr(runcache, "from_data", lossy)
    first, _ = _run(project, tmp_path / "cache")
    again, timings = _run(project, tmp_path / "cache")
    assert again == first and "scan" in timings  # ran again: nothing was kept


def test_an_unchanged_runs_extract_text_is_kept_with_it(tmp_path: Path, monkeypatch) -> None:
    """`extract` twice with nothing changed makes the model's JSON document once and
    writes the same bytes; a changed source makes it again."""
    from haros_arch.cli import main
    from haros_arch.query import command

    project = _copy(tmp_path)
    made: list[int] = []
    original = command.document

    def counting(*args, **kwargs):
        made.append(1)
        return original(*args, **kwargs)

    monkeypatch.setattr(command, "document", counting)
    texts = []
    for name in ("a.json", "b.json"):
        assert main(["extract", str(project), "-q", "-o", str(tmp_path / name)]) == 0
        texts.append((tmp_path / name).read_bytes())
    assert len(made) == 1 and texts[0] == texts[1]
    source = next((tmp_path / "ws").rglob("*.py"))
    source.write_text(source.read_text() + "\n# changed\n")
    assert main(["extract", str(project), "-q", "-o", str(tmp_path / "c.json")]) == 0
    assert len(made) == 2 and (tmp_path / "c.json").read_bytes() == texts[0]


def test_an_unchanged_runs_report_page_is_kept_with_it(tmp_path: Path, monkeypatch) -> None:
    """`report` twice with nothing changed renders the page once and writes the same
    bytes; a changed source renders it again."""
    from haros_arch.cli import main
    from haros_arch.viz import command, html

    project = _copy(tmp_path)
    rendered: list[int] = []
    documents: list[int] = []
    original, document = html.render_report, command.model_data

    def counting(*args, **kwargs):
        rendered.append(1)
        return original(*args, **kwargs)

    def counting_documents(*args, **kwargs):
        documents.append(1)
        return document(*args, **kwargs)

    monkeypatch.setattr(html, "render_report", counting)
    monkeypatch.setattr(command, "model_data", counting_documents)
    pages = []
    for name in ("a.html", "b.html"):
        assert main(["report", str(project), "-o", str(tmp_path / name)]) == 0
        pages.append((tmp_path / name).read_bytes())
    assert len(rendered) == 1 and pages[0] == pages[1]
    assert len(documents) == 1  # a kept page needs no document of the model
    source = next((tmp_path / "ws").rglob("*.py"))
    source.write_text(source.read_text() + "\n# changed\n")
    assert main(["report", str(project), "-o", str(tmp_path / "c.html")]) == 0
    assert len(rendered) == 2


def test_a_kept_model_read_back_gives_a_cold_runs_findings_and_matches(tmp_path: Path
                                                                      ) -> None:
    """A kept model whose findings were not kept with it (``extract`` kept it under other
    rules, or the findings' entry was dropped) is checked again as read back: it gives
    what the run gave in memory. Before, links lost the calls of plugins and of node
    types from interface models (their defaults, tests, handles): on husky 31 undecided
    parameter reads instead of 6, and here a false ``parameter-read-not-set``."""
    from haros_arch import query
    from haros_arch.query.command import check

    shutil.copytree(FIXTURE.parent.parent / "cache_readback", tmp_path / "ws")
    spec = load(str(tmp_path / "ws" / "project.yaml"))
    cold = analyse(spec, {}, Options(cache_dir=None, jobs=1))
    options = Options(cache_dir=str(tmp_path / "cache"), jobs=1)
    analyse(spec, {}, options)  # kept, its findings not (no check ran)
    timings: dict[str, float] = {}
    kept = analyse(spec, {}, Options(cache_dir=str(tmp_path / "cache"), jobs=1,
                                     timings=timings))
    assert set(timings) == {"cache"}  # read back
    expected = check(cold, spec).findings
    # what rests on a plugin's calls (DWAPlannerROS' publishers) and on a model's
    # conditions (base_local_planner's odometry helper) is undecided, read back too
    assert {"publisher-without-subscriber-undecided",
            "subscriber-without-publisher-undecided"} <= {f.rule for f in expected}
    assert check(kept, spec).findings == expected
    text = "links[self.call.has_default or self.call.tested or self.call.searched]"
    for before, after in zip(cold.configurations, kept.configurations, strict=True):
        found = query.compile(text).run(query.config_scope(before, cold))
        again = query.compile(text).run(query.config_scope(after, kept))
        assert found and [(link.node.id, link.name, link.call) for link in again] == [
            (link.node.id, link.name, link.call) for link in found]


def test_entries_one_copy_and_configuration_wrote_give_another_what_it_gives_cold(
        tmp_path: Path) -> None:
    """One cache folder serves every workspace: a second copy of the workspace at another
    path, and one launch file of the first run as its own configuration, read the C++
    unit entries the first run wrote and give what they give with no cache."""
    from haros_arch.api import analyse_path
    from haros_arch.query.command import document

    first = _copy_paper(tmp_path)
    shutil.copytree(first.parent, tmp_path / "second")
    second = tmp_path / "second" / "project.yaml"
    launch = str(first.parent / "src" / "example" / "launch" / "minimal.launch")
    cache = Options(cache_dir=str(tmp_path / "cache"), jobs=1)
    cold = Options(cache_dir=None, jobs=1)

    def text(path: str, options: Options) -> str:
        analysis = analyse_path(path, options)
        assert analysis.model is not None
        return json.dumps(document(analysis.model, analysis.project), sort_keys=True)

    assert text(str(first), cache) == text(str(first), cold)
    assert list((tmp_path / "cache" / "cpp").glob("*.json"))  # units kept
    timings: dict[str, float] = {}
    assert text(str(second), Options(cache_dir=str(tmp_path / "cache"), jobs=1,
                                     timings=timings)) == text(str(second), cold)
    assert "C++" in timings  # not the first run's model: its own, from the unit entries
    assert text(launch, cache) == text(launch, cold)


def test_an_output_written_beside_the_project_is_no_input(tmp_path: Path, monkeypatch) -> None:
    """``extract -o model.json`` (``check -o``, ``report -o``) beside the project file or
    in the workspace: the next run with nothing else changed is the kept one, while a
    file the tool did not write there, or one changed since it wrote it, is an input."""
    from haros_arch import pipeline
    from haros_arch.cli import main

    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    project = _copy(tmp_path)
    ran: list[int] = []
    analyse_whole = pipeline._analyse

    def counted(*args, **kwargs):  # type: ignore[no-untyped-def]
        ran.append(1)
        return analyse_whole(*args, **kwargs)

    monkeypatch.setattr(pipeline, "_analyse", counted)
    model = project.parent / "model.json"
    for _ in range(2):
        assert main(["extract", str(project), "-o", str(model)]) == 0
    main(["check", str(project), "-o", str(project.parent / "findings.txt"),
          "--fail-on", "never"])
    main(["report", str(project), "-o", str(project.parent / "src" / "report.html")])
    assert len(ran) == 1, ran  # the first run only
    model.write_text(model.read_text() + " ")  # no longer as the tool wrote it
    main(["extract", str(project), "-o", str(tmp_path / "elsewhere.json")])
    assert len(ran) == 2
    (project.parent / "notes.txt").write_text("x")  # a file of someone else's
    main(["extract", str(project), "-o", str(tmp_path / "elsewhere.json")])
    assert len(ran) == 3


QOS_WORKSPACE = {
    "src/qos_demo/package.xml": package_xml("qos_demo", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"),
    "src/qos_demo/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.8)
        project(qos_demo)
        find_package(ament_cmake REQUIRED)
        find_package(rclcpp REQUIRED)
        find_package(std_msgs REQUIRED)
        add_executable(talker src/talker.cpp)
        ament_target_dependencies(talker rclcpp std_msgs)
        install(TARGETS talker DESTINATION lib/${PROJECT_NAME})
        ament_package()
        """,
    "src/qos_demo/src/talker.cpp": """
        #include <rclcpp/rclcpp.hpp>
        #include <std_msgs/msg/string.hpp>
        int main(int argc, char** argv) {
          rclcpp::init(argc, argv);
          auto node = std::make_shared<rclcpp::Node>("talker");
          auto latched = node->create_publisher<std_msgs::msg::String>(
              "status", rclcpp::QoS(1).reliable().transient_local());
          auto fast = node->create_publisher<std_msgs::msg::String>(
              "chatter", rclcpp::SensorDataQoS());
          rclcpp::spin(node);
        }
        """,
    "src/qos_demo/launch/talk.launch.xml": (
        '<launch><node pkg="qos_demo" exec="talker" name="talker"/></launch>\n'),
    "project.yaml": ("project: q\nworkspace: [src]\ndistro: jazzy\nconfigurations:\n"
                     "  c: [qos_demo/launch/talk.launch.xml]\n"),
}


def test_extracts_document_is_the_same_text_with_and_without_the_cache(
        tmp_path: Path, write_tree) -> None:
    """Byte for byte, as `extract -o` writes it: a kept model read back listed a QoS
    profile's keys sorted (the run cache kept its entry with sorted keys), the run
    without the cache in the order extraction made them (bench/cache_same.py said
    `DIFFERENT` on ros2_control_demos)."""
    from haros_arch.query.command import document
    from haros_arch.report.json import document_json

    root = write_tree(QOS_WORKSPACE)
    spec = load(str(root / "project.yaml"))
    cold = document_json(document(analyse(spec, {}, Options(cache_dir=None, jobs=1)), spec))
    assert '"history": "keep_last"' in cold
    cache = Options(cache_dir=str(tmp_path / "cache"), jobs=1)
    # made, then read back (the document made again from the kept model, as `extract`
    # does after a `check` kept the run)
    texts = [document_json(document(analyse(spec, {}, cache), spec)) for _ in range(2)]
    assert texts == [cold, cold]


def test_a_kept_run_imports_no_extractor(tmp_path: Path) -> None:
    # (issue 24) a re-run the cache answers needs neither the C++ extractor (libclang,
    # the stand-ins' tables) nor the launch readers: start-up is most of such a run
    import subprocess
    import sys

    project = _copy_paper(tmp_path)
    probe = ("import sys\nfrom haros_arch.cli import main\n"
             f"code = main(['check', {str(project)!r}, '--fail-on', 'never', '--format', 'json'])\n"
             "print(code, sorted(m for m in ('haros_arch.extract.cpp', "
             "'haros_arch.launch.ros1', 'haros_arch.launch.ros2') if m in sys.modules))\n")
    env = {**os.environ, "XDG_CACHE_HOME": str(tmp_path / "xdg")}
    said = [subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                           cwd=tmp_path, env=env, check=True).stdout.splitlines()[-1]
            for _ in range(2)]
    assert said[0].startswith("0 ['haros_arch.extract.cpp'")  # the cold run reads C++
    assert said[1] == "0 []"


def test_an_unchanged_runs_extract_summary_decodes_no_model(tmp_path: Path, monkeypatch,
                                                           capsys) -> None:
    """(issue 24) `extract` without `-q` prints a summary of the model and its
    diagnostics: a re-run with nothing changed prints the kept summary, the same text,
    without decoding the kept model; `-v`'s longer summary is its own."""
    from haros_arch.cli import main

    project = _copy(tmp_path)
    assert main(["extract", str(project), "-o", str(tmp_path / "a.json")]) == 0
    first = capsys.readouterr().out
    assert "configuration" in first and "wrote" in first
    decoded = _count_decodes(monkeypatch)
    assert main(["extract", str(project), "-o", str(tmp_path / "b.json")]) == 0
    again = capsys.readouterr().out
    assert decoded == [] and again == first.replace("a.json", "b.json")
    assert main(["extract", str(project), "-v", "-o", str(tmp_path / "c.json")]) == 0
    verbose = capsys.readouterr().out
    assert decoded == [1] and "  node  " in verbose and "  node  " not in first
