"""Differential tests: our ROS 1 launch interpreter against the real roslaunch.

Each fixture under ``fixtures/launch_ros1/ws`` is loaded by Debian's roslaunch (in a
``/usr/bin/python3`` subprocess, through ``bench/launch_roslaunch_dump.py``, which runs
nothing) and by ``haros_arch.launch.load``; every field roslaunch decides must agree.
Files roslaunch refuses must give us an error diagnostic.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
from pathlib import Path
from typing import Any

import pytest

from haros_arch.launch import LaunchModel, load
from haros_arch.workspace import scan

ROOT = Path(__file__).resolve().parent.parent
WS = ROOT / "fixtures" / "launch_ros1" / "ws" / "src"
PACKAGE_PATH = ROOT / "fixtures" / "launch_ros1" / "package_path"  # not in the workspace
ROS_PACKAGE_PATH = f"{WS}:{PACKAGE_PATH}"
LAUNCH = WS / "robot_bringup" / "launch"
ORACLE = ROOT / "bench" / "launch_roslaunch_dump.py"
SYSTEM_PYTHON = "/usr/bin/python3"

CASES: list[tuple[str, dict[str, str]]] = [
    ("params.launch", {}),
    ("names.launch", {}),
    ("args.launch", {}),
    ("args.launch", {"sim": "true", "robot": "scout", "use_lidar": "false"}),
    ("machines.launch", {}),
    # ROS 1 files named *.launch.xml, started on their own: by content, by package
    ("xml_suffix.launch", {}),
    ("../../robot_base/launch/includes/mobile_base.launch.xml", {"manager": "mgr"}),
    ("../../robot_base/launch/includes/planning_pipeline.launch.xml", {}),
    # $(find) through ROS_PACKAGE_PATH: searched recursively, rosbuild packages too
    ("package_path.launch", {}),
    ("private_top.launch", {}),  # ~name no node takes: /roslaunch/name
]
REFUSED: dict[str, str] = {
    "refused_if_unless.launch": "LAUNCH_IF_AND_UNLESS",
    "refused_duplicate.launch": "LAUNCH_NODE_DUPLICATE",
    "refused_missing_arg.launch": "LAUNCH_ARG_REQUIRED",
    "refused_cycle.launch": "LAUNCH_INCLUDE_CYCLE",
}
# roslaunch refuses these because a package is not found; a package we cannot find may be
# installed where we do not look, so ours is a warning: the value is unknown, and said so
NOT_FOUND: dict[str, str] = {
    # under CATKIN_IGNORE (on ROS_PACKAGE_PATH, not in the workspace), in a package, in a
    # .folder
    "refused_find_ignored.launch": "package ghost is not in the workspace nor installed",
    "refused_find_nested.launch": "package nested_hidden is not in the workspace",
    "refused_find_hidden.launch": "package secret is not in the workspace",
}


# a variable of the fixtures' environment, for both: ``env()`` in ``$(eval)`` is its text
FIXTURE_ENV = {"HAROS_FIXTURE_NUMBER": "1"}


def _roslaunch_available() -> bool:
    if not os.path.exists(SYSTEM_PYTHON):
        return False
    probe = subprocess.run([SYSTEM_PYTHON, "-c", "import roslaunch.config"],
                           capture_output=True, check=False)
    return probe.returncode == 0


pytestmark = pytest.mark.skipif(
    not _roslaunch_available(),
    reason="/usr/bin/python3 cannot import roslaunch (install python3-roslaunch: "
           "scripts/setup --ros)")


def oracle_env(tmp: Path) -> dict[str, str]:
    return {"PATH": "/usr/bin:/bin", "HOME": str(tmp), "ROS_HOME": str(tmp),
            "ROS_PACKAGE_PATH": ROS_PACKAGE_PATH, "LANG": "C.UTF-8", **FIXTURE_ENV}


def run_roslaunch(files: list[tuple[str, dict[str, str]]], tmp: Path) -> list[dict[str, Any]]:
    request = [[str(LAUNCH / name), [f"{k}:={v}" for k, v in args.items()]]
               for name, args in files]
    done = subprocess.run([SYSTEM_PYTHON, str(ORACLE), json.dumps(request)],
                          capture_output=True, text=True, env=oracle_env(tmp), timeout=120,
                          check=False)
    assert done.returncode == 0, done.stderr
    result: list[dict[str, Any]] = json.loads(done.stdout)
    return result


@pytest.fixture(scope="module")
def oracle(tmp_path_factory: pytest.TempPathFactory) -> dict[int, dict[str, Any]]:
    tmp = tmp_path_factory.mktemp("roslaunch")
    cases = CASES + [(name, {}) for name in REFUSED] + [(name, {}) for name in NOT_FOUND]
    return dict(enumerate(run_roslaunch(cases, tmp)))


def ours(name: str, args: dict[str, str]) -> LaunchModel:
    env = {"ROS_PACKAGE_PATH": ROS_PACKAGE_PATH, **FIXTURE_ENV}
    workspace = scan([str(WS)], env)
    return load(str(LAUNCH / name), workspace, args, env)


def flatten(name: str, value: Any) -> dict[str, Any]:
    if isinstance(value, dict) and not set(value) <= {"command", "binary"}:
        out: dict[str, Any] = {}
        for key, item in value.items():
            out.update(flatten(f"{name}/{key}", item))
        return out
    return {name: value}


def name_pattern(name: str) -> re.Pattern[str]:
    """Our name with ``?`` (an anonymous or unknown part) as a pattern."""
    return re.compile("^" + ".+".join(re.escape(p) for p in name.split("?")) + "$")


def node_rows(model: LaunchModel) -> list[dict[str, Any]]:
    return [{"name": n.name, "namespace": n.namespace, "package": n.package,
             "type": n.executable, "args": n.args, "remaps": [list(r) for r in n.remaps],
             "machine": n.machine, "respawn": n.respawn, "required": n.required,
             "test": n.is_test} for n in model.nodes if not n.conditions]


@pytest.mark.parametrize("index", range(len(CASES)),
                         ids=[f"{n}{'-' + '-'.join(a) if a else ''}" for n, a in CASES])
def test_same_as_roslaunch(index: int, oracle: dict[int, dict[str, Any]]) -> None:
    name, args = CASES[index]
    expected = oracle[index]
    assert "error" not in expected, expected
    model = ours(name, args)
    errors = [d for d in model.diagnostics if d.severity == "error"]
    assert errors == []
    mine = node_rows(model)
    assert len(mine) == len(expected["nodes"])
    for row, theirs in zip(mine, expected["nodes"], strict=True):
        assert name_pattern(row["name"]).match(theirs["name"]), (row, theirs)
        assert {k: v for k, v in row.items() if k != "name"} == \
            {k: v for k, v in theirs.items() if k != "name"}
    our_params: dict[str, Any] = {}
    our_types: dict[str, str | None] = {}
    for param in model.params:
        our_params.update(flatten(param.name, param.value))
        our_types[param.name] = param.type
    their_params: dict[str, Any] = {}
    for key, value in expected["params"].items():
        their_params.update(flatten(key, value))
    assert sorted(our_params) == sorted(their_params)
    for key, value in their_params.items():
        if isinstance(value, dict) and "command" in value:
            assert our_params[key] is None, key  # never run: unknown
        elif isinstance(value, dict) and "binary" in value:
            assert our_params[key] == value["binary"], key
            if key in our_types:  # a binfile: roslaunch gives an xmlrpc Binary
                assert our_types[key] == "binary", key
        elif isinstance(value, str) and "/fixtures/" in value:
            assert our_params[key] == value, key
        else:
            assert our_params[key] == value and type(our_params[key]) is type(value), key
    assert sorted(model.clear_params) == sorted(expected["clear_params"])


@pytest.mark.parametrize("name", sorted(REFUSED))
def test_refused_like_roslaunch(name: str, oracle: dict[int, dict[str, Any]]) -> None:
    assert "error" in oracle[len(CASES) + sorted(REFUSED).index(name)] or \
        "error" in oracle[len(CASES) + list(REFUSED).index(name)]
    model = ours(name, {})
    codes = {d.code for d in model.diagnostics if d.severity == "error"}
    assert REFUSED[name] in codes


@pytest.mark.parametrize("name", list(NOT_FOUND))
def test_not_found_like_roslaunch(name: str, oracle: dict[int, dict[str, Any]]) -> None:
    theirs = oracle[len(CASES) + len(REFUSED) + list(NOT_FOUND).index(name)]
    assert "ResourceNotFound" in theirs.get("error", ""), theirs
    model = ours(name, {})
    assert [p.value for p in model.params] == [None]
    assert any(d.code == "LAUNCH_UNKNOWN_VALUE" and NOT_FOUND[name] in d.message
               for d in model.diagnostics)
