"""Hostile launch files: diagnostics in bounded time and memory, nothing executed."""

from __future__ import annotations

import json
from pathlib import Path

from conftest import package_xml

from haros_arch.cli import main
from haros_arch.launch import load
from haros_arch.workspace import scan

LAUGHS = """<?xml version="1.0"?>
<!DOCTYPE launch [
  <!ENTITY a "aaaaaaaaaa">
  <!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;">
  <!ENTITY c "&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;">
  <!ENTITY d "&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;">
  <!ENTITY e "&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;">
  <!ENTITY f "&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;">
  <!ENTITY g "&f;&f;&f;&f;&f;&f;&f;&f;&f;&f;">
  <!ENTITY h "&g;&g;&g;&g;&g;&g;&g;&g;&g;&g;">
  <!ENTITY i "&h;&h;&h;&h;&h;&h;&h;&h;&h;&h;">
]>
<launch><param name="lol" value="&i;" /></launch>
"""


def run(write_tree, files: dict[str, str], main_file: str = "src/pkg/launch/main.launch"):
    root = write_tree({"src/pkg/package.xml": package_xml("pkg"), **files})
    ws = scan([str(root / "src")], {})
    return root, load(str(root / main_file), ws, {}, {})


def test_billion_laughs_is_not_expanded(write_tree):
    _, model = run(write_tree, {"src/pkg/launch/main.launch": LAUGHS})
    assert all(len(str(p.value or "")) < 1000 for p in model.params)
    assert model.diagnostics and model.diagnostics[0].code == "LAUNCH_XML_SYNTAX"


def test_external_entity_is_not_read(write_tree, tmp_path):
    secret = tmp_path / "secret.txt"
    secret.write_text("TOP-SECRET")
    text = (f'<?xml version="1.0"?>\n<!DOCTYPE launch [<!ENTITY x SYSTEM "file://{secret}">]>\n'
            '<launch><param name="leak" value="&x;" /></launch>\n')
    _, model = run(write_tree, {"src/pkg/launch/main.launch": text})
    assert "TOP-SECRET" not in json.dumps([str(p.value) for p in model.params])


def test_huge_file_is_refused(write_tree):
    big = "<launch>\n" + "<!-- padding -->\n" * (50 * 1024 * 1024 // 17) + "</launch>\n"
    _, model = run(write_tree, {"src/pkg/launch/main.launch": big})
    assert [d.code for d in model.diagnostics] == ["FILE_TOO_LARGE"]
    assert model.nodes == []


def test_include_cycle_through_two_files(write_tree):
    _, model = run(write_tree, {
        "src/pkg/launch/main.launch":
            '<launch><include file="$(dirname)/other.launch" /></launch>',
        "src/pkg/launch/other.launch":
            '<launch><node name="n" pkg="p" type="t" />'
            '<include file="$(dirname)/main.launch" /></launch>'})
    assert [d.code for d in model.diagnostics] == ["LAUNCH_INCLUDE_CYCLE"]
    assert [n.name for n in model.nodes] == ["/n"]


def test_eval_import_is_never_run(write_tree, tmp_path):
    marker = tmp_path / "pwned"
    launch = ("<launch>"
              f"<param name=\"a\" value=\"$(eval __import__('os').system('touch {marker}'))\" />"
              f"<param name=\"b\" value=\"$(eval open('{marker}', 'w'))\" />"
              "<param name=\"c\" value=\"$(eval 9 ** 9 ** 9)\" />"
              f"<param name=\"d\" command=\"touch {marker}\" />"
              "</launch>")
    _, model = run(write_tree, {"src/pkg/launch/main.launch": launch})
    assert not marker.exists()
    codes = [d.code for d in model.diagnostics]
    assert codes.count("LAUNCH_BAD_VALUE") == 1  # __ is refused, as roslaunch does
    assert "LAUNCH_UNKNOWN_VALUE" in codes
    assert {p.name: p.value for p in model.params} == {"/a": None, "/b": None, "/c": None,
                                                        "/d": None}


def test_yaml_alias_bomb_is_bounded(write_tree):
    lines = ["a: &a [x, x, x, x, x, x, x, x, x, x]"]
    for i, name in enumerate("bcdefghij"):
        prev = "abcdefghij"[i]
        lines.append(f"{name}: &{name} [*{prev}, *{prev}, *{prev}, *{prev}, *{prev}, "
                     f"*{prev}, *{prev}, *{prev}, *{prev}, *{prev}]")
    launch = ("<launch><rosparam><![CDATA[\n" + "\n".join(lines)
              + "\n]]></rosparam></launch>")
    _, model = run(write_tree, {"src/pkg/launch/main.launch": launch})
    assert [d.code for d in model.diagnostics] == ["LAUNCH_YAML"]


def test_cli_launch_json(write_tree, capsys):
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg"),
        "src/pkg/launch/main.launch": (
            '<launch><arg name="robot" /><group ns="$(arg robot)">'
            '<node name="drv" pkg="pkg" type="drv" args="-v"><remap from="a" to="b" />'
            '<param name="rate" value="5" /></node></group>'
            '<param name="unknown" command="xacro robot.urdf" /></launch>')})
    code = main(["launch", "pkg", "launch/main.launch", "--arg", "robot:=r1",
                 "--workspace", str(Path(root)), "--format", "json"])
    assert code == 0
    data = json.loads(capsys.readouterr().out)
    assert [(n["name"], n["package"], n["executable"], n["namespace"], n["args"],
             n["remaps"]) for n in data["nodes"]] == [
        ("/r1/drv", "pkg", "drv", "/r1/", "-v", [["a", "b"]])]
    assert data["parameters"] == {"/r1/drv/rate": 5, "/unknown": None}
    assert main(["launch", "pkg", "launch/main.launch", "--arg", "robot",
                 "--workspace", str(root)]) == 2
