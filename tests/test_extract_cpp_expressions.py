"""ROS calls anywhere in an expression: loop and branch conditions, ternaries, ``&&``,
returns and other calls' arguments, each with the conditions under which it runs; and
all of them still found after more clang errors than clang reports by default (a
generated dynamic_reconfigure config known only by name, as in navigation's amcl when
its .cfg is not there)."""

from __future__ import annotations

import os
import shutil

import pytest

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.workspace import scan

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "expressions")
LOCALISER = os.path.join(ROOT, "src", "localiser", "src", "localiser.cpp")


@pytest.fixture(scope="module")
def localiser() -> CppResult:
    return extract_cpp([LOCALISER], scan([ROOT]), cache_dir=None)


def test_more_errors_than_clang_reports_by_default(tmp_path) -> None:
    # without its .cfg the config is known only by name: each field read is an error
    copy = tmp_path / "expressions"
    shutil.copytree(ROOT, copy)
    os.remove(copy / "src" / "localiser" / "cfg" / "Localiser.cfg")
    result = extract_cpp([str(copy / os.path.relpath(LOCALISER, ROOT))], scan([str(copy)]),
                         cache_dir=None)
    fields = [d for d in result.diagnostics if d.code == "CPP_MESSAGE_FIELD"]
    assert len(fields) == 24  # every one reported, none lost to an error limit
    assert [d for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []
    assert len(result.calls) == len(CALLS)


def test_the_fields_of_the_cfg_parse(localiser: CppResult) -> None:
    # its .cfg declares alpha1 only: the 23 other fields the code reads are errors
    errors = [d.message for d in localiser.diagnostics if d.code in (
        "CPP_MESSAGE_FIELD", "CPP_PARSE_ERROR")]
    assert len(errors) == 23
    assert all("in 'localiser::LocaliserConfig'" in e for e in errors)
    assert not any("'alpha1'" in e for e in errors)


CALLS = [
    ("publish", "status", "std_msgs/String", 49, ()),                 # return
    ("client", "static_map", "nav_msgs/GetMap", 60, ()),              # while condition
    ("read", "~use_map_topic", None, 75, ()),                         # if condition
    ("subscribe", "map", "nav_msgs/OccupancyGrid", 77, (("if", 'pnh.hasParam("use_map_topic")'),)),
    ("read", "~retries", "int", 79, ()),                              # for condition
    ("read", "~ready", "bool", 84, ()),                               # do-while condition
    ("read", "~mode", "int", 85, ()),                                 # switch condition
    ("publish", "pose_fast", "std_msgs/String", 90, (("if", "fast"),)),
    ("publish", "pose_slow", "std_msgs/String", 91, (("else", "fast"),)),
    ("read", "~rate", "double", 92, (("if", "fast"),)),               # fast && ...
    ("publish", "particles", "std_msgs/String", 96, ()),              # argument of a call
    ("read", "~fallback_rate", "double", 98, (("else", "ready"),)),   # ready || ...
    ("write", "~initial_pose_x", "double", 101, ()),                  # tf2 LinearMath
]


@pytest.mark.parametrize(("kind", "name", "ctype", "line", "conditions"), CALLS)
def test_call_in_expression(localiser: CppResult, kind: str, name: str, ctype: str | None,
                            line: int, conditions: tuple[tuple[str, str], ...]) -> None:
    found = [c for c in localiser.calls if (c.kind, c.name) == (kind, name)]
    assert len(found) == 1
    call = found[0]
    assert (call.type, call.location.line) == (ctype, line)
    assert tuple((c.statement, c.text) for c in call.conditions) == conditions


def test_no_other_calls(localiser: CppResult) -> None:
    assert len(localiser.calls) == 13


def test_member_initialisers() -> None:
    """A lambda called in a member initialiser, a lambda passed in one, and a default
    member initialiser of a ROS 2 node class."""
    source = os.path.join(ROOT, "src", "sampler", "src", "sampler.cpp")
    found = extract_cpp([source], scan([ROOT]), cache_dir=None)
    rows = [(c.kind, c.name, c.queue_size, c.location.line,
             tuple((x.statement, x.text) for x in c.conditions)) for c in found.calls]
    assert rows == [
        ("subscribe", "samples", 10, 19, ()),
        ("publish", "heartbeat", 1, 25, (("if", "!heartbeat_"),)),
        ("publish", "status", 5, 34, ()),
    ]
    assert found.rosname == "sampler"
    assert [d.code for d in found.diagnostics] == []
