"""A launch argument left without a value is said once per configuration, at its first
use, with its other uses as ``also`` (osrf/subt 083c6a8a: a few top-level ``name`` /
``world_name`` arguments, one LAUNCH_ARG_UNSET per use, 1,090 in the JSON). Every use is
kept, in JSON, SARIF, JUnit and the text; another argument, or another diagnostic, is
not merged into it."""

from __future__ import annotations

import json
from pathlib import Path

from conftest import package_xml

from haros_arch.cli import main
from haros_arch.model.diagnostic import Diagnostic
from haros_arch.model.load import diagnostic_from_data
from haros_arch.model.location import Location
from haros_arch.model.serialise import to_data

NODE = """\
#!/usr/bin/env python
import rospy
rospy.init_node("cam")
"""

TOP = """\
<launch>
  <arg name="robot" />
  <arg name="world" />
  <param name="a" value="$(arg robot)/a" />
  <param name="b" value="$(arg robot)/b" />
  <param name="w" value="$(arg world)" />
  <include file="$(find cams)/launch/part.launch" pass_all_args="true" />
  <node pkg="cams" type="cam" name="cam" />
</launch>
"""

PART = """\
<launch>
  <arg name="robot" />
  <param name="c" value="$(arg robot)/c" />
</launch>
"""


def _tree(write_tree) -> Path:  # type: ignore[no-untyped-def]
    root = write_tree({
        "src/cams/package.xml": package_xml("cams"),
        "src/cams/CMakeLists.txt": "project(cams)\n",
        "src/cams/scripts/cam": NODE,
        "src/cams/launch/run.launch": TOP,
        "src/cams/launch/part.launch": PART,
        "project.yaml": "project: p\nconfigurations:\n  c: [cams/launch/run.launch]\n"
                        "  d: [cams/launch/run.launch]\n",
    })
    (root / "src/cams/scripts/cam").chmod(0o755)
    return root


def _check(root: Path, form: str, *extra: str) -> str:
    out = root / f"check.{form}"
    main(["check", str(root / "project.yaml"), "--format", form, "-o", str(out),
          "--fail-on", "never", *extra])
    return out.read_text()


def _place(data: dict[str, object]) -> tuple[object, object]:
    return data["file"], data["line"]


def test_the_json_says_an_unset_argument_once_with_its_uses(write_tree) -> None:
    report = json.loads(_check(_tree(write_tree), "json"))
    unset = {d["message"].split()[2]: d for d in report["diagnostics"]
             if d["code"] == "LAUNCH_ARG_UNSET"}
    # one per argument: two configurations load the same file, and the included file's
    # use of the same command-line argument is one more place of the same
    assert len([d for d in report["diagnostics"] if d["code"] == "LAUNCH_ARG_UNSET"]) == 2
    robot = unset["robot"]
    assert _place(robot["location"]) == ("cams/launch/run.launch", 4)
    assert [_place(where) for where in robot["also"]] == [
        ("cams/launch/run.launch", 5), ("cams/launch/part.launch", 3)]
    world = unset["world"]
    assert _place(world["location"]) == ("cams/launch/run.launch", 6)
    assert "also" not in world


def test_the_text_lists_the_other_uses_in_every_file(write_tree) -> None:
    root = _tree(write_tree)
    for extra in ((), ("-v",)):
        lines = _check(root, "text", *extra).splitlines()
        said = [n for n, line in enumerate(lines)
                if "[LAUNCH_ARG_UNSET]" in line and "robot" in line]
        assert len(said) == 1, extra
        assert lines[said[0] + 1].strip() == "also at: 5:0, cams/launch/part.launch:3:0"


def test_sarif_and_junit_keep_the_other_uses(write_tree) -> None:
    root = _tree(write_tree)
    sarif = json.loads(_check(root, "sarif"))
    (robot,) = [r for r in sarif["runs"][0]["results"] if r["ruleId"] == "LAUNCH_ARG_UNSET"
                and "robot" in r["message"]["text"]]
    related = [r["physicalLocation"]["artifactLocation"]["uri"]
               for r in robot["relatedLocations"]]
    assert [uri.rsplit("/", 1)[-1] for uri in related] == ["run.launch", "part.launch"]
    junit = _check(root, "junit")
    assert "also at: cams/launch/run.launch:5, cams/launch/part.launch:3" in junit


def test_said_once_merges_only_the_same_and_reads_back() -> None:
    from haros_arch.model.diagnostic import said_once

    def unset(name: str, line: int, code: str = "LAUNCH_ARG_UNSET") -> Diagnostic:
        return Diagnostic(code, "warning", f"launch argument {name} has no value",
                          Location("p", "f.launch", line))

    merged = said_once([unset("a", 3), unset("b", 4), unset("a", 3), unset("a", 7),
                        unset("a", 8, "OTHER"), unset("a", 9, "OTHER")])
    assert [(d.code, d.location.line, [w.line for w in d.also]) for d in merged] == [
        ("LAUNCH_ARG_UNSET", 3, [7]), ("LAUNCH_ARG_UNSET", 4, []),
        ("OTHER", 8, []), ("OTHER", 9, [])]
    assert diagnostic_from_data(to_data(merged[0])) == merged[0]
    assert "also" not in to_data(merged[1])
