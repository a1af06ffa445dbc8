"""``haros-arch diff``: known changes to the bundled example give exactly their diff;
findings match by rule, entities and configuration (not by line); ``--rev`` analyses
git revisions without touching the working tree and reuses the C++ parse cache."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
from collections.abc import Callable
from pathlib import Path

import pytest
from conftest import ROOT

from haros_arch import diff
from haros_arch.autoproject import open_choice
from haros_arch.cli import main
from haros_arch.model.finding import Finding
from haros_arch.model.location import Location
from haros_arch.model.model import Model
from haros_arch.pipeline import analyse
from haros_arch.query.catalogue import run_catalogue

ROBOT = "src/demo_robot/launch/robot.launch"
SAFETY = "src/demo_rover/scripts/safety_stop.py"
FILTER = "src/demo_rover/src/lidar_filter.cpp"


def edit(path: str, old: str, new: str) -> Callable[[Path], None]:
    def apply(root: Path) -> None:
        file = root / path
        text = file.read_text()
        assert old in text
        file.write_text(text.replace(old, new, 1))
    return apply


def side(root: Path) -> tuple:
    here = os.getcwd()
    os.chdir(root)
    try:
        choice = open_choice("project.yaml")
        model = analyse(choice.project)
        return model, run_catalogue(model, choice.project)
    finally:
        os.chdir(here)


@pytest.fixture(scope="module")
def base(tmp_path_factory: pytest.TempPathFactory) -> tuple:
    root = tmp_path_factory.mktemp("base")
    shutil.copytree(ROOT / "examples", root, dirs_exist_ok=True)
    return side(root)


def lines(result: diff.DiffResult) -> list[str]:
    """Each configuration's changes and findings, as the text output writes them."""
    return [line for line in diff.to_text(result).splitlines()[1:] if line]


CASES = {
    "new publisher": edit(SAFETY, '"cmd_vel", 10)\n', '"cmd_vel", 10)\n'
                          '        self.create_publisher(Twist, "stopped", 10)\n'),
    "topic renamed on one side": edit(SAFETY, '"scan_filtered"', '"scan_clean"'),
    "dropped remap": edit(ROBOT, '      <remap from="scan" to="base_scan" />\n', ""),
    "parameter default changed": edit(SAFETY, '"stop_distance", 0.3', '"stop_distance", 0.4'),
    "node no longer launched": edit(
        ROBOT, '    <node name="battery" pkg="demo_robot" type="battery_monitor.py">\n'
               '      <param name="threshold" value="0.25" />\n    </node>\n', ""),
    "qos change": edit(FILTER, '"scan_filtered", rclcpp::SensorDataQoS()',
                       '"scan_filtered", 10'),
    "node moved to a namespace": edit(
        ROBOT, '<node name="battery" pkg="demo_robot"',
        '<node name="battery" ns="power" pkg="demo_robot"'),
    "interface no longer known": edit(SAFETY, "def main():", "def main(:"),
    "code moved": edit(SAFETY, '"""Stops', '\n\n\n"""Stops'),
}
PY = "demo_rover/scripts/safety_stop.py"
BATTERY = "demo_robot/scripts/battery_monitor.py"
CONTROLLER = "demo_robot/src/controller.cpp:31:33"
QOS_ERROR = ("- gone error [qos-incompatible] /rover/lidar_filter -> /rover/safety_stop on "
             "/rover/scan_filtered: the publisher is best-effort but the subscriber requires "
             "reliable  (demo_rover/src/lidar_filter.cpp:19:18)")
# the robot cases: configuration robot; robot_without_monitor (robot2) changes alike
EXPECTED = {
    "new publisher": [
        "configuration rover (changed)",
        f"+ topic /rover/stopped  ({PY}:19:9)",
        f"+ link publish /rover/safety_stop /rover/stopped  ({PY}:19:9)",
        "+ new info [publisher-without-subscriber] /rover/safety_stop publishes "
        f"/rover/stopped but nothing subscribes to it  ({PY}:19:9)"],
    # nothing publishes scan_clean now (every node of the rover is known, its component
    # container too): a new warning on the renamed side, a new info on the other, and
    # the QoS mismatch with the filter's publisher is gone
    "topic renamed on one side": [
        "configuration rover (changed)",
        f"+ topic /rover/scan_clean  ({PY}:17:9)",
        f"+ link subscribe /rover/safety_stop /rover/scan_clean  ({PY}:17:9)",
        f"- link subscribe /rover/safety_stop /rover/scan_filtered  ({PY}:17:9)",
        "+ new info [publisher-without-subscriber] /rover/lidar_filter publishes "
        "/rover/scan_filtered but nothing subscribes to it  "
        "(demo_rover/src/lidar_filter.cpp:19:18)",
        "+ new warning [subscriber-without-publisher] /rover/safety_stop subscribes to "
        f"/rover/scan_clean but nothing publishes it  ({PY}:17:9)",
        QOS_ERROR],
    "dropped remap": [
        "configuration robot (changed)",
        "~ node /robot1/controller  (demo_robot/launch/robot.launch:13)",
        '    remaps: [["scan", "base_scan"]] -> []',
        f"- topic /robot1/base_scan  ({CONTROLLER})",
        f"+ topic /robot1/scan  ({CONTROLLER})",
        f"- link subscribe /robot1/controller /robot1/base_scan  ({CONTROLLER})",
        f"+ link subscribe /robot1/controller /robot1/scan  ({CONTROLLER})",
        "+ new warning [subscriber-without-publisher] /robot1/controller subscribes to "
        f"/robot1/scan but nothing publishes it  ({CONTROLLER})",
        "- gone warning [subscriber-without-publisher] /robot1/controller subscribes to "
        f"/robot1/base_scan but nothing publishes it  ({CONTROLLER})"],
    # the launch file still sets 0.5: only the code's default changed
    "parameter default changed": [
        "configuration rover (changed)",
        f"~ link read /rover/safety_stop /rover/safety_stop/stop_distance  ({PY}:14:30)",
        "    default: 0.3 -> 0.4"],
    "node no longer launched": [
        "configuration robot (changed)",
        "- node /robot1/battery  (demo_robot/launch/robot.launch:10)",
        f"- topic /robot1/battery/level  ({BATTERY}:17:26)",
        f"- topic /robot1/battery/low  ({BATTERY}:16:24)",
        f"- link action-client /robot1/battery /robot1/dock  ({BATTERY}:19:21)",
        f"- link client /robot1/battery /robot1/driver/reset  ({BATTERY}:18:22)",
        f"- link publish /robot1/battery /robot1/battery/low  ({BATTERY}:16:24)",
        f"- link read /robot1/battery /robot1/battery/threshold  ({BATTERY}:15:26)",
        f"- link subscribe /robot1/battery /robot1/battery/level  ({BATTERY}:17:26)",
        "- parameter /robot1/battery/threshold  (demo_robot/launch/robot.launch:11)",
        "- gone info [publisher-without-subscriber] /robot1/battery publishes "
        f"/robot1/battery/low but nothing subscribes to it  ({BATTERY}:16:24)",
        "- gone warning [subscriber-without-publisher] /robot1/battery subscribes to "
        f"/robot1/battery/level but nothing publishes it  ({BATTERY}:17:26)"],
    "qos change": [
        "configuration rover (changed)",
        "~ link publish /rover/lidar_filter /rover/scan_filtered  "
        "(demo_rover/src/lidar_filter.cpp:19:18)",
        '    qos: {"depth": 5, "durability": "volatile", "history": "keep_last", '
        '"reliability": "best_effort"} -> {"depth": 10, "durability": "volatile", '
        '"history": "keep_last", "reliability": "reliable"}; queue_size: 5 -> 10',
        QOS_ERROR],
    # one instance renamed: its private parameters and topics moved with it and are not
    # listed; what it reaches outside its name (the driver's reset, the dock action) now
    # resolves in its new namespace, where nothing serves it
    "node moved to a namespace": [
        "configuration robot (changed)",
        "~ node /robot1/power/battery  (demo_robot/launch/robot.launch:10)",
        '    name: "/robot1/battery" -> "/robot1/power/battery"',
        *[f"+ topic /robot1/power/dock/{end}  ({BATTERY}:19:21)"
          for end in ("cancel", "feedback", "goal", "result", "status")],
        f"+ service /robot1/power/driver/reset  ({BATTERY}:18:22)",
        f"+ action /robot1/power/dock  ({BATTERY}:19:21)",
        f"- link action-client /robot1/battery /robot1/dock  ({BATTERY}:19:21)",
        f"+ link action-client /robot1/power/battery /robot1/power/dock  ({BATTERY}:19:21)",
        f"- link client /robot1/battery /robot1/driver/reset  ({BATTERY}:18:22)",
        "+ link client /robot1/power/battery /robot1/power/driver/reset  "
        f"({BATTERY}:18:22)",
        # the dock action and the driver's reset service are still served in /robot1
        "+ new warning [client-without-server] /robot1/power/battery's action-client of "
        f"/robot1/power/dock has no server in this configuration  ({BATTERY}:19:21)",
        "+ new warning [client-without-server] /robot1/power/battery's client of "
        f"/robot1/power/driver/reset has no server in this configuration  ({BATTERY}:18:22)",
        "+ new info [publisher-without-subscriber] /robot1/power/battery publishes "
        f"/robot1/power/battery/low but nothing subscribes to it  ({BATTERY}:16:24)",
        "+ new warning [subscriber-without-publisher] /robot1/power/battery subscribes to "
        f"/robot1/power/battery/level but nothing publishes it  ({BATTERY}:17:26)",
        "- gone info [publisher-without-subscriber] /robot1/battery publishes "
        f"/robot1/battery/low but nothing subscribes to it  ({BATTERY}:16:24)",
        "- gone warning [subscriber-without-publisher] /robot1/battery subscribes to "
        f"/robot1/battery/level but nothing publishes it  ({BATTERY}:17:26)"],
    # a syntax error: the node's calls are unknown now (partial), so its links are gone
    # and the rules that need its side cannot decide (the "-undecided" infos, checked
    # below); the parse error says why
    "interface no longer known": [
        "configuration rover (changed)",
        "~ node /rover/safety_stop  (demo_rover/launch/rover.launch.py:36:14)",
        '    completeness: "complete" -> "partial"',
        f"- topic /rover/cmd_vel  ({PY}:18:20)",
        f"- link publish /rover/safety_stop /rover/cmd_vel  ({PY}:18:20)",
        f"- link read /rover/safety_stop /rover/safety_stop/stop_distance  ({PY}:14:30)",
        f"- link subscribe /rover/safety_stop /rover/scan_filtered  ({PY}:17:9)",
        "- gone info [publisher-without-subscriber] /rover/safety_stop publishes "
        f"/rover/cmd_vel but nothing subscribes to it  ({PY}:18:20)",
        QOS_ERROR,
        "- gone warning [subscriber-without-publisher] /rover/lidar_filter subscribes to "
        "/rover/lidar/scan but nothing publishes it  (demo_rover/src/lidar_filter.cpp:21:21)",
        "diagnostics",
        "+ new warning [PY_NODE_PARTIAL] node demo_rover/safety_stop.py: its calls may be "
        "incomplete, 1 place(s) in its Python sources where calls may be missing or made "
        "by code not read (first: "
        f"{PY}:25: Python syntax error: invalid syntax)  (demo_rover/CMakeLists.txt:16:1)",
        f"+ new error [PY_PARSE_ERROR] Python syntax error: invalid syntax  ({PY}:25:10)"],
    # lines moved: no link, resource or finding changes (they are not keyed by line)
    "code moved": [],
}


def _robot2(lines: list[str]) -> list[str]:
    return [line.replace("/robot1/", "/robot2/").replace(
        "configuration robot ", "configuration robot_without_monitor ") for line in lines]


@pytest.mark.parametrize("case", sorted(CASES))
def test_each_known_change_gives_exactly_its_diff(case: str, base: tuple,
                                                  tmp_path: Path) -> None:
    shutil.copytree(ROOT / "examples", tmp_path, dirs_exist_ok=True)
    CASES[case](tmp_path)
    model, findings = side(tmp_path)
    result = diff.compare(base[0], model, base[1], findings)
    expected = EXPECTED[case]
    if expected and expected[0].startswith("configuration robot "):
        # the second robot configuration (robot2) changes alike
        expected = expected + _robot2(expected)
    undecided = [(f.status, f.finding.rule) for f in result.findings
                 if f.finding.rule.endswith("-undecided")]
    shown = [line.strip() for line in lines(result) if "-undecided]" not in line]
    assert shown == [e.strip() for e in expected]
    assert undecided == ([] if case != "interface no longer known" else [
        ("new", "parameter-set-not-read-undecided"),
        ("new", "publisher-without-subscriber-undecided"),
        ("new", "subscriber-without-publisher-undecided")])


def git(repo: Path, *args: str) -> str:
    return subprocess.run(["git", "-C", str(repo), "-c", "user.name=t", "-c",
                           "user.email=t@t", *args], check=True, capture_output=True,
                          text=True).stdout


@pytest.fixture
def repo(tmp_path: Path) -> Path:
    """The example in a git repository: a base commit, then a head commit that drops a
    remap (a new warning) and raises the controller's max_speed."""
    root = tmp_path / "repo"
    shutil.copytree(ROOT / "examples", root)
    # a header of the workspace: cache entries name it by path, and check it is unchanged
    (root / "src/demo_robot/src/limits.h").write_text("#define MAX_SPEED 1.0\n")
    edit("src/demo_robot/src/driver.cpp", "#include <string>\n",
         '#include <string>\n#include "limits.h"\n')(root)
    git(root, "init", "-q")
    git(root, "add", "-A")
    git(root, "commit", "-qm", "base")
    CASES["dropped remap"](root)
    edit(ROBOT, 'value="0.8"', 'value="1.2"')(root)
    git(root, "commit", "-qam", "head")
    return root


def run(argv: list[str], cwd: Path, capsys: pytest.CaptureFixture[str]
        ) -> tuple[int, str, str]:
    here = os.getcwd()
    os.chdir(cwd)
    try:
        code = main(argv)
    finally:
        os.chdir(here)
    said = capsys.readouterr()
    return code, said.out, said.err


def test_rev_analyses_git_objects_and_reuses_the_parse_cache(
        repo: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    from haros_arch.extract.cpp import cache

    stored: list[str] = []  # a unit is stored when it missed the cache and was parsed
    store = cache.Cache.store
    monkeypatch.setattr(cache.Cache, "store", lambda self, entry, *rest: (
        stored.append(entry), store(self, entry, *rest))[1])
    (repo / ROBOT).write_text("not committed")  # the working tree is not read or touched
    code, out, _ = run(["diff", "--rev", "HEAD~1..HEAD", "project.yaml", "--jobs", "1",
                        "--format", "json"], repo, capsys)
    assert code == 0
    data = json.loads(out)
    robot = next(c for c in data["configurations"] if c["name"] == "robot")
    assert {"kind": "parameter", "key": "/robot1/controller/max_speed", "status": "changed",
            "location": "demo_robot/launch/robot.launch:14",
            "fields": {"value": {"old": 0.8, "new": 1.2}}} in robot["changes"]
    assert [(f["status"], f["rule"], f["entities"]) for f in robot["findings"]] == [
        ("new", "subscriber-without-publisher",
         ["node:/robot1/controller", "topic:/robot1/scan"]),
        ("gone", "subscriber-without-publisher",
         ["node:/robot1/controller", "topic:/robot1/base_scan"])]
    assert data["summary"] == {"changed": 4, "added": 4, "removed": 4,
                               "new warning": 2, "gone warning": 2}
    assert (repo / ROBOT).read_text() == "not committed"
    assert git(repo, "status", "--porcelain").split() == ["M", ROBOT]
    # both revisions were written at one path: the head's four unchanged C++ sources hit
    # the entries the base's parse stored
    cached = list((tmp_path / "cache" / "haros-arch" / "cpp").glob("*.json"))
    assert len(stored) == len(cached) == len(list((repo / "src").rglob("*.cpp"))) == 4
    # and a later run (the next pull request) at the same path parses nothing again
    assert run(["diff", "--rev", "HEAD~1..HEAD", "project.yaml", "--jobs", "1"], repo,
               capsys)[0] == 0
    assert len(stored) == 4


def test_saved_models_markdown_and_fail_on(repo: Path, tmp_path: Path,
                                           capsys: pytest.CaptureFixture[str]) -> None:
    old, new = tmp_path / "old.json", tmp_path / "new.json"
    git(repo, "checkout", "-q", "HEAD~1")
    assert run(["extract", "project.yaml", "-q", "-o", str(old)], repo, capsys)[0] == 0
    git(repo, "checkout", "-q", "-")
    assert run(["extract", "project.yaml", "-q", "-o", str(new)], repo, capsys)[0] == 0
    code, out, _ = run(["diff", str(old), str(new), "--format", "markdown", "--fail-on",
                     "new-warning"], repo, capsys)
    assert code == 1  # a new warning appears
    assert out.splitlines()[2].endswith(
        "new.json: 4 added, 4 removed, 4 changed; 2 new warning finding(s), "
        "2 gone warning finding(s)")
    assert "**New findings**" in out
    assert "\n- - " not in out  # a nested list, not what we mean
    assert "\n- new warning \\[subscriber-without-publisher\\] /robot1/controller" in out
    assert out.count("<details>") == out.count("</details>") == 2
    assert "| changed | parameter | /robot1/controller/max\\_speed |" in out
    code, out, _ = run(["diff", str(old), str(new), "--fail-on", "new-error"], repo, capsys)
    assert code == 0
    assert "  ~ parameter /robot1/controller/max_speed  (demo_robot/launch/robot.launch:14)" \
        "\n      value: 0.8 -> 1.2\n" in out
    # the same model on both sides: nothing changes, nothing fails
    code, out, _ = run(["diff", str(new), str(new), "--fail-on", "new-warning"], repo, capsys)
    assert code == 0 and out.endswith("no change to the graph; no finding appears or "
                                      "disappears\n")


def test_bad_inputs_say_so(repo: Path, tmp_path: Path,
                           capsys: pytest.CaptureFixture[str]) -> None:
    broken = tmp_path / "broken.json"
    broken.write_text("{not json")
    assert main(["diff", str(broken), str(broken)]) == 2
    assert "is not a haros-arch model" in capsys.readouterr().err
    code, _, err = run(["diff", "--rev", "HEAD~1..nosuchrev"], repo, capsys)
    assert code == 2 and "nosuchrev" in err
    code, _, err = run(["diff", "--rev", "HEAD~1..HEAD", "missing.yaml"], repo, capsys)
    assert code == 2 and "missing.yaml does not exist at HEAD~1" in err
    assert main(["diff", str(broken)]) == 2
    code, _, err = run(["diff", "--rev=--output=x..HEAD"], repo, capsys)
    assert code == 2 and "--rev takes BASE..HEAD" in err and not (repo / "x").exists()


def test_rev_notes_name_the_repository_not_the_temporary_tree(
        repo: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = run(["diff", "--rev", "HEAD~1..HEAD", "src"], repo, capsys)
    assert code == 0
    assert "HEAD~1: 2 packages in src;" in err and "haros-arch-diff" not in err


def test_findings_match_by_rule_entities_and_configuration_not_line_or_repeat() -> None:
    def found(line: int, topic: str, config: str = "c") -> Finding:
        return Finding("r", "warning", "t", f"m {line}", config, ("node:/a", topic),
                       Location(file="a.py", line=line), (config,))

    same = diff.compare(Model("p"), Model("p"), [found(3, "topic:/?#2")],
                        [found(9, "topic:/?#3")])
    assert same.findings == []
    moved = diff.compare(Model("p"), Model("p"), [found(3, "topic:/x")],
                         [found(3, "topic:/y"), found(3, "topic:/x", "d")])
    assert [(f.status, f.configuration, f.finding.entities[1]) for f in moved.findings] == [
        ("new", "c", "topic:/y"), ("gone", "c", "topic:/x"), ("new", "d", "topic:/x")]
    assert moved.fails("new-warning") and not moved.fails("new-error")


def test_renames_pair_instances_by_their_nearest_namespace() -> None:
    from haros_arch.model.runtime import Configuration, NodeInstance
    from haros_arch.model.source import Node

    def model(prefix: str) -> Model:
        runs = Node("teleop", "kb")
        config = Configuration("c", nodes=[NodeInstance(f"/{robot}/{prefix}/kb", runs)
                                           for robot in ("alpha", "beta")])
        return Model("p", configurations=[config])

    result = diff.compare(model("joy"), model("keys"))
    assert [(c.status, c.key, c.fields["name"]) for c in result.changes] == [
        ("renamed", "/alpha/keys/kb", ("/alpha/joy/kb", "/alpha/keys/kb")),
        ("renamed", "/beta/keys/kb", ("/beta/joy/kb", "/beta/keys/kb"))]


def test_markdown_groups_alike_configurations_and_stays_under_its_limit() -> None:
    from haros_arch.model.runtime import Configuration, NodeInstance

    def model(names: list[str]) -> Model:
        return Model("p", configurations=[
            Configuration(c, nodes=[NodeInstance(n) for n in names]) for c in ("a", "b")])

    result = diff.compare(model([f"/n{i}" for i in range(40)]), model([]))
    text = diff.to_markdown(result)
    assert text.count("<details>") == 1 and "configurations a, b: changed, 40 change(s)" in text
    short = diff.to_markdown(result, limit=600)
    assert len(short) < 800 and short.count("<details>") == short.count("</details>") == 1
    shown = short.count("| removed | node |")
    assert shown and short.rstrip().endswith(
        f"*{40 - shown} more entries left out (the comment's size limit): run haros-arch "
        "diff for all of them*")
