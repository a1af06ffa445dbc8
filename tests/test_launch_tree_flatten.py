"""``haros-arch launch --flatten``: one roslaunch file that starts and sets what the
original does, checked with the real roslaunch (Debian's) and with our own loader."""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import pytest
from test_launch_ros1_roslaunch import CASES, FIXTURE_ENV, ROS_PACKAGE_PATH, run_roslaunch
from test_launch_ros1_roslaunch import pytestmark as needs_roslaunch
from test_launch_tree import tree

from haros_arch.cli import main
from haros_arch.launch import load
from haros_arch.launch.ros1.dump import leaf_parameters
from haros_arch.launch.ros1.flatten import flatten
from haros_arch.workspace import scan

WS = Path(__file__).resolve().parent.parent / "fixtures" / "launch_ros1" / "ws" / "src"
LAUNCH = WS / "robot_bringup" / "launch"


def flattened(name: str, args: dict[str, str], out: Path) -> tuple[Path, list[str]]:
    env = {"ROS_PACKAGE_PATH": ROS_PACKAGE_PATH, **FIXTURE_ENV}
    model = load(str(LAUNCH / name), scan([str(WS)], env), args, env)
    text, notes = flatten(model)
    out.write_text(text)
    return out, notes


def leaves(params: dict[str, Any]) -> dict[str, Any]:
    """Parameters as the master holds them: mappings unrolled to their leaves."""
    out: dict[str, Any] = {}
    stack = list(params.items())
    while stack:
        name, value = stack.pop()
        if isinstance(value, dict) and value and not set(value) <= {"command", "binary"}:
            stack.extend((f"{name}/{k}", v) for k, v in value.items())
        else:
            out[name] = value
    return out


def typed(params: dict[str, Any]) -> dict[str, Any]:
    """Values with their types: 1 and 1.0 (int and double parameters) differ."""
    return {k: json.dumps(v, sort_keys=True) for k, v in params.items()}


ANON = re.compile(r"_[A-Za-z0-9_]*_\d+_\d+(?=/|$)")  # roslaunch's anon: _host_pid_random


def unanon(data: dict[str, Any]) -> dict[str, Any]:
    """A roslaunch dump with its random anonymous names made one: each run draws new."""
    if "error" in data:
        return data
    nodes = [{**n, "name": ANON.sub("_ANON", n["name"] or "")} for n in data["nodes"]]
    params = {ANON.sub("_ANON", k): v for k, v in data["params"].items()}
    cleared = [ANON.sub("_ANON", k) for k in data["clear_params"]]
    return {**data, "nodes": nodes, "params": params, "clear_params": cleared}


def node_key(node: dict[str, Any]) -> str:
    return str(node["name"])


@needs_roslaunch
@pytest.mark.parametrize(("index", "case"), list(enumerate(CASES)))
def test_roslaunch_reads_the_flattened_file_as_the_original(
        index: int, case: tuple[str, dict[str, str]], tmp_path: Path) -> None:
    name, args = case
    path, notes = flattened(name, args, tmp_path / f"flat{index}.launch")
    original, flat = map(unanon, run_roslaunch([(name, args), (str(path), {})], tmp_path))
    assert "error" not in flat, (flat, path.read_text())
    # what the notes say is left out (a ? stands for a part not known, as an anon name)
    left_out = [re.compile(".+".join(map(re.escape, line.split()[1].split("?"))) + "$")
                for line in notes]

    def kept(name: str) -> bool:
        return not any(p.match(name) for p in left_out)

    theirs = {k: v for k, v in leaves(original["params"]).items() if kept(k)}
    assert typed(leaves(flat["params"])) == typed(theirs)
    kept_nodes = [n for n in original["nodes"] if kept(n["name"])]
    assert sorted(flat["clear_params"]) == sorted(original["clear_params"])
    assert sorted(flat["nodes"], key=node_key) == sorted(kept_nodes, key=node_key)


@pytest.mark.parametrize(("index", "case"), list(enumerate(CASES)))
def test_our_loader_reads_the_flattened_file_as_the_original(
        index: int, case: tuple[str, dict[str, str]], tmp_path: Path) -> None:
    name, args = case
    env = {"ROS_PACKAGE_PATH": ROS_PACKAGE_PATH, **FIXTURE_ENV}
    workspace = scan([str(WS)], env)
    model = load(str(LAUNCH / name), workspace, args, env)
    text, notes = flatten(model)
    (tmp_path / "flat.launch").write_text(text)
    again = load(str(tmp_path / "flat.launch"), workspace, {}, env)
    assert not [d for d in again.diagnostics if d.severity != "info"]
    kept = [n for n in model.nodes if not any(line.startswith(f"node {n.name} ")
                                              for line in notes)]

    def fields(nodes: list[Any]) -> list[tuple[Any, ...]]:
        return sorted((n.name, n.package, n.executable, n.namespace, n.args, n.remaps,
                       n.machine, n.respawn, n.required, n.is_test, n.env) for n in nodes)

    assert fields(again.nodes) == fields(kept)
    left_out = {line.split()[1] for line in notes if line.startswith("parameter ")}
    assert typed(leaf_parameters(again)) == typed(
        {k: v for k, v in leaf_parameters(model).items() if k not in left_out})


def test_flattened_file_loads_back_with_the_same_nodes_and_parameters(
        tmp_path: Path) -> None:
    tree(tmp_path, {})
    workspace = scan([str(tmp_path)], {})
    model = load(str(tmp_path / "pkg/launch/main.launch"), workspace, {"mode": "false"}, {})
    text, notes = flatten(model)
    assert notes == []
    (tmp_path / "flat.launch").write_text(text)
    again = load(str(tmp_path / "flat.launch"), workspace, {}, {})
    assert [(n.name, n.package, n.executable, n.namespace, n.remaps) for n in again.nodes] == [
        (n.name, n.package, n.executable, n.namespace, n.remaps) for n in model.nodes]
    assert typed(leaf_parameters(again)) == typed(leaf_parameters(model))
    assert [n.name for n in model.nodes] == ["/r1/driver", "/sensors/laser", "/talker"]
    assert "<include" not in text and "if=" not in text


def test_an_undecided_node_is_left_out_and_said(tmp_path: Path) -> None:
    tree(tmp_path, {})
    workspace = scan([str(tmp_path)], {})
    model = load(str(tmp_path / "pkg/launch/main.launch"), workspace, {}, {})
    text, notes = flatten(model)
    assert [line.split(" runs only")[0] for line in notes] == [
        "node /moder (pkg/launch/main.launch:18)"]
    assert "haros-arch: node /moder" in text and 'name="moder"' not in text


def test_an_anonymous_node_keeps_its_anon_name(tmp_path: Path) -> None:
    path, notes = flattened("args.launch", {}, tmp_path / "flat.launch")
    assert notes == []
    assert '<node pkg="robot_base" type="helper_node" name="$(anon helper)"/>' in (
        path.read_text())


def test_cli_flatten_writes_xml_and_says_what_it_leaves_out(tmp_path: Path,
                                                            capsys: Any) -> None:
    tree(tmp_path, {})
    main_file = str(tmp_path / "pkg/launch/main.launch")
    assert main(["launch", main_file, "--workspace", str(tmp_path), "--flatten"]) == 0
    out, err = capsys.readouterr()
    assert out.startswith("<launch>") and '<node pkg="pkg" type="t" name="talker">' in out
    assert "note: node /moder (pkg/launch/main.launch:18) runs only if ($(arg mode))" in err
    assert main(["launch", main_file, "--workspace", str(tmp_path), "--flatten",
                 "--format", "yaml"]) == 2
    assert "as xml only" in capsys.readouterr().err
