"""Our xacro reader against the real xacro (PyPI ``xacro``, a test extra) on our own
fixtures: the expanded documents must be the same element for element. The real xacro
runs only here, on files we wrote; ``$(find)`` goes through a stand-in ament index."""

from __future__ import annotations

import sys
import types
from pathlib import Path
from typing import Any

import pytest
from conftest import FIXTURES
from lxml import etree

from haros_arch.robot import xacro as ours
from haros_arch.workspace import scan

real = pytest.importorskip("xacro")

ROOTS = {"bot_description": FIXTURES / "robot" / "ros1" / "bot_description",
         "bot2_description": FIXTURES / "robot" / "ros2" / "bot2_description"}


@pytest.fixture(autouse=True)
def ament_index(monkeypatch: pytest.MonkeyPatch) -> None:
    """The real xacro's $(find) asks ament_index_python: answer from the fixtures."""
    index = types.ModuleType("ament_index_python")
    packages = types.ModuleType("ament_index_python.packages")

    def share(name: str) -> str:
        return str(ROOTS[name])

    packages.get_package_share_directory = share  # type: ignore[attr-defined]
    index.packages = packages  # type: ignore[attr-defined]
    monkeypatch.setitem(sys.modules, "ament_index_python", index)
    monkeypatch.setitem(sys.modules, "ament_index_python.packages", packages)


def canonical(element: Any) -> Any:
    """Tag, attributes (ours without the private ones) and text, children in order."""
    attributes = {str(k): str(v) for k, v in element.attrib.items()
                  if not str(k).startswith("{urn:haros-arch}")}
    text = (element.text or "").strip()
    return (etree.QName(element).localname, attributes, text,
            [canonical(child) for child in element if isinstance(child.tag, str)])


def both(path: Path, env: dict[str, str], args: dict[str, str],
         monkeypatch: pytest.MonkeyPatch) -> tuple[Any, Any]:
    for key, value in env.items():
        monkeypatch.setenv(key, value)
    theirs = real.process_file(str(path), mappings=dict(args))
    expected = etree.fromstring(theirs.toxml().encode())
    workspace = scan([str(FIXTURES / "robot")], env)
    description = ours.expand(str(path), args, workspace, env)
    assert description.root is not None and not description.unknown
    return canonical(description.root), canonical(expected)


@pytest.mark.parametrize(("path", "env", "args"), [
    (ROOTS["bot_description"] / "urdf" / "bot.urdf.xacro", {"BOT_CAMERA": "0"}, {}),
    (ROOTS["bot_description"] / "urdf" / "bot.urdf.xacro", {"BOT_CAMERA": "true"},
     {"laser_enabled": "false"}),
    (ROOTS["bot_description"] / "urdf" / "bot.urdf.xacro", {"BOT_CAMERA": "0"},
     {"laser_topic": "rear/scan"}),
    (ROOTS["bot2_description"] / "urdf" / "bot2.urdf.xacro", {}, {"prefix": "a_"}),
])
def test_fixtures_expand_as_the_real_xacro_does(path: Path, env: dict[str, str],
                                               args: dict[str, str],
                                               monkeypatch: pytest.MonkeyPatch):
    mine, theirs = both(path, env, args, monkeypatch)
    assert mine == theirs


INLINE = {
    "lazy properties and macro scopes":
        '<xacro:property name="a" value="${b * 2}"/><xacro:property name="b" value="3"/>'
        '<xacro:macro name="m" params="b c:=7"><x v="${a} ${b} ${c}"/></xacro:macro>'
        '<xacro:m b="5"/><y v="${a}"/>',
    "blocks, multi-blocks and nested calls":
        '<xacro:macro name="wrap" params="name *first **rest">'
        '<g n="${name}"><xacro:insert_block name="first"/><xacro:insert_block name="rest"/>'
        '</g></xacro:macro>'
        '<xacro:macro name="leaf" params="i"><l i="${i}"/></xacro:macro>'
        '<xacro:wrap name="w"><one/><more><xacro:leaf i="1"/><xacro:leaf i="${1+1}"/></more>'
        '</xacro:wrap>',
    "conditions, element and attribute":
        '<xacro:property name="on" value="true"/>'
        '<xacro:if value="${on}"><a/></xacro:if><xacro:unless value="${on}"><b/></xacro:unless>'
        '<xacro:if value="0"><c/></xacro:if><xacro:unless value="false"><d/></xacro:unless>'
        '<xacro:element xacro:name="${\'e\' + \'f\'}" k="1"><xacro:attribute name="z" '
        'value="n${3*3}"/></xacro:element>',  # (a number alone breaks theirs)
    "an include with its own namespace":
        '<xacro:property name="k" value="1"/><xacro:include filename="parts.xacro" ns="p"/>'
        '<xacro:p.m v="${k}"/>',
    "macro arguments read as numbers":
        '<xacro:macro name="w" params="reflect s:=2.5 q:=\'x\'">'
        '<a v="${reflect * 3}" s="${s * 2}" q="${q}"/></xacro:macro>'
        '<xacro:w reflect="-1"/><xacro:w reflect="0.5" s="1" q="y"/>',
    "yaml files":
        '<xacro:property name="c" value="${xacro.load_yaml(\'limits.yaml\')}"/>'
        '<j lo="${c[\'joint\'][\'min\']}" hi="${c[\'joint\'][\'max\']}" n="${len(c)}"/>'
        # xacro's functions are names of its table, not a rewrite of the text
        '<t v="${\'xacro.load_yaml(1)\'}" w="${c[\'joint\'][\'min\'] if xacro.load_yaml '
        '(\'limits.yaml\') else 0}"/>',
    "arguments and escapes":
        '<xacro:arg name="n" default="4"/><a v="$(arg n)" w="${int(\'$(arg n)\') + 1}" '
        'd="$${not evaluated}"/>',
}


PARAMS = ["robot_ns:='''", "a:='x'y' b", 'a:="q"r" c:=1', "a:=${x} b:=$(arg y)",
          "a:=^|'d' b", "a:='it''s' c:=1", "a:= 'x", "a:=^ b", "a b:=2 *c **d",
          "a:=${x y} b", "a:=${x}y} z", "a:=$(find p)/x b:=3", "a:=x'y z'w q"]


@pytest.mark.parametrize("params", PARAMS)
def test_macro_parameters_read_as_the_real_xacro_does(params: str):
    theirs = []
    rest = params
    while rest:
        name, value, rest = real.parse_macro_arg(rest)
        theirs.append((name, value))
    assert ours.macro_params(params) == theirs


@pytest.mark.parametrize("name", list(INLINE))
def test_constructs_expand_as_the_real_xacro_does(name: str, tmp_path: Path,
                                                  monkeypatch: pytest.MonkeyPatch):
    (tmp_path / "parts.xacro").write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:property name="k" '
        'value="9"/><xacro:macro name="m" params="v"><p v="${v} ${k}"/></xacro:macro></robot>')
    (tmp_path / "limits.yaml").write_text("joint:\n  min: !degrees -90\n  max: !radians pi/4\n")
    path = tmp_path / "robot.urdf.xacro"
    path.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
                    + INLINE[name] + "</robot>")
    theirs = real.process_file(str(path), mappings={})
    expected = canonical(etree.fromstring(theirs.toxml().encode()))
    description = ours.expand(str(path), {}, scan([str(tmp_path)], {}), {})
    assert description.root is not None
    assert canonical(description.root) == expected
