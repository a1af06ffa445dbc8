"""The roscpp extractor on the paper's running example and on small feature fixtures.

Each source is parsed once per module (module-scoped fixtures); tests read the result.
"""

from __future__ import annotations

import os

import pytest

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.model.source import PrimitiveCall
from haros_arch.workspace import Workspace, scan

HERE = os.path.dirname(os.path.abspath(__file__))
FIXTURES = os.path.join(os.path.dirname(HERE), "fixtures")
PAPER = os.path.join(FIXTURES, "paper_minimal")
PAPER_SRC = os.path.join(PAPER, "src", "example", "src")
FEATURES = os.path.join(FIXTURES, "cpp", "features")
FEATURES_SRC = os.path.join(FEATURES, "src", "demo", "src")
HAVE_ROS = os.path.isfile("/usr/include/ros/ros.h")


def summary(call: PrimitiveCall) -> tuple[object, ...]:
    return (call.kind, call.name, call.type, call.queue_size, call.latch, call.callback,
            tuple((c.statement, c.text) for c in call.conditions))


def codes(result: CppResult) -> list[str]:
    return [d.code for d in result.diagnostics]


def by_name(result: CppResult) -> dict[str, PrimitiveCall]:
    return {call.name: call for call in result.calls}


@pytest.fixture(scope="module")
def paper_ws() -> Workspace:
    return scan([PAPER])


@pytest.fixture(scope="module")
def features_ws() -> Workspace:
    return scan([FEATURES])


@pytest.fixture(scope="module")
def active(paper_ws: Workspace) -> CppResult:
    return extract_cpp([os.path.join(PAPER_SRC, "active.cpp")], paper_ws, cache_dir=None)


@pytest.fixture(scope="module")
def reactive(paper_ws: Workspace) -> CppResult:
    return extract_cpp([os.path.join(PAPER_SRC, "reactive.cpp")], paper_ws, cache_dir=None)


@pytest.fixture(scope="module")
def names(features_ws: Workspace) -> CppResult:
    return extract_cpp([os.path.join(FEATURES_SRC, "names.cpp")], features_ws, cache_dir=None)


@pytest.fixture(scope="module")
def conditions(features_ws: Workspace) -> CppResult:
    return extract_cpp([os.path.join(FEATURES_SRC, "conditions.cpp")], features_ws, cache_dir=None)


# -- the running example ---------------------------------------------------------------

def test_active_node(active: CppResult) -> None:
    assert active.rosname == "talker"
    assert [summary(c) for c in active.calls] == [
        ("read", "?", "double", None, False, None, ()),
        ("publish", "monologue", "std_msgs/String", 10, False, None, ()),
        ("client", "counter", "example/GetCounter", None, False, None, ()),
    ]
    assert [(c.location.file, c.location.line) for c in active.calls] == [
        ("src/example/src/active.cpp", 18), ("src/example/src/active.cpp", 20),
        ("src/example/src/active.cpp", 21)]
    assert active.calls[1].location.package == "example"
    assert "CPP_PARSE_ERROR" not in codes(active)
    assert "CPP_INCLUDE_MISSING" not in codes(active)


def test_reactive_node(reactive: CppResult) -> None:
    assert reactive.rosname == "listener"
    assert [summary(c) for c in reactive.calls] == [
        ("subscribe", "chatter", "std_msgs/String", 10, False, "callback", ()),
        ("server", "counter", "example/GetCounter", None, False, "getCounter", ()),
    ]
    assert codes(reactive) == []


def test_dynamic_name_is_reported(active: CppResult) -> None:
    dynamic = [d for d in active.diagnostics if d.code == "CPP_DYNAMIC_NAME"]
    assert [(d.location.line, d.location.column) for d in dynamic] == [(18, 5)]


@pytest.mark.skipif(not HAVE_ROS, reason="needs the ROS 1 headers in /usr/include")
@pytest.mark.parametrize("folder,source", [
    (PAPER_SRC, "active.cpp"), (PAPER_SRC, "reactive.cpp"), (FEATURES_SRC, "names.cpp")])
def test_system_headers_give_the_same_calls(
    folder: str, source: str, request: pytest.FixtureRequest
) -> None:
    standin = request.getfixturevalue(source.removesuffix(".cpp"))
    workspace = request.getfixturevalue("paper_ws" if folder == PAPER_SRC else "features_ws")
    real = extract_cpp([os.path.join(folder, source)], workspace, system_headers=True,
                       cache_dir=None)
    assert [summary(c) for c in real.calls] == [summary(c) for c in standin.calls]
    assert [c.location for c in real.calls] == [c.location for c in standin.calls]
    assert real.rosname == standin.rosname
    assert "CPP_PARSE_ERROR" not in codes(real)


# -- names -----------------------------------------------------------------------------

def test_features_parse_cleanly(names: CppResult, conditions: CppResult) -> None:
    assert "CPP_PARSE_ERROR" not in codes(names) + codes(conditions)
    assert names.rosname == "names"


@pytest.mark.parametrize("name,kind,type_,queue", [
    ("motors/speed", "publish", "std_msgs/Int32", 7),          # #define queue size
    ("motors/left/speed", "publish", "std_msgs/Int32", 3),     # NodeHandle(parent, ns)
    ("~status", "publish", "demo/Status", 1),                  # private handle, #define name
    ("scan", "subscribe", "demo/Status", 10),                  # const std::string
    ("/global/out", "publish", "std_msgs/String", 2),          # global name
    ("scan_?", "publish", "std_msgs/String", 1),               # runtime part
    ("robot/odom", "subscribe", "std_msgs/String", 1),         # local concatenation
    ("motors/reset", "client", "std_srvs/Trigger", None),
    ("shutdown", "client", "std_srvs/Trigger", None),          # ros::service::call
])
def test_names_types_and_queues(
    names: CppResult, name: str, kind: str, type_: str, queue: int | None
) -> None:
    call = by_name(names)[name]
    assert (call.kind, call.type, call.queue_size) == (kind, type_, queue)


def test_member_function_callbacks(names: CppResult) -> None:
    calls = by_name(names)
    assert summary(calls["input"]) == (
        "subscribe", "input", "std_msgs/String", 5, False, "Relay::onInput", ())
    assert summary(calls["reset"]) == (
        "server", "reset", "std_srvs/Trigger", None, False, "Relay::onReset", ())
    assert summary(calls["~output"]) == (
        "publish", "~output", "std_msgs/String", 1, True, None, ())


def test_free_function_callback_with_shared_ptr(names: CppResult) -> None:
    assert by_name(names)["scan"].callback == "onStatus"


@pytest.mark.parametrize("name,kind,type_", [
    ("~rate", "read", "int"), ("~frame_id", "read", "str"), ("verbose", "read", "bool"),
    ("ready", "write", "bool"), ("/use_sim_time", "read", "bool"),
    ("~count", "write", "double"), ("debug", "read", None), ("stale", "write", None),
])
def test_parameters(names: CppResult, name: str, kind: str, type_: str | None) -> None:
    call = by_name(names)[name]
    assert (call.kind, call.type) == (kind, type_)


# -- conditions ------------------------------------------------------------------------

@pytest.mark.parametrize("name,expected", [
    ("always", ()),
    ("then", (("if", "mode > 1"),)),
    ("otherwise", (("else", "mode > 1"),)),
    # a counting loop over literal bounds runs its body: no condition
    ("looped", ()),
    ("nested", (("while", "ros::ok()"), ("if", "mode == 3"))),
    ("one", (("switch", "mode == 1"),)),
    ("other", (("switch", "mode != 1"),)),
    ("tried", (("try", ""),)),
    ("caught", (("catch", "const std::exception& error"),)),
    ("done", (("do", "mode < 0"),)),
])
def test_conditions(conditions: CppResult, name: str, expected: tuple[object, ...]) -> None:
    call = by_name(conditions)[name]
    assert tuple((c.statement, c.text) for c in call.conditions) == expected
    assert all(c.kind == "source" for c in call.conditions)


def test_condition_location(conditions: CppResult) -> None:
    (condition,) = by_name(conditions)["then"].conditions
    assert (condition.location.file, condition.location.line, condition.location.column) == (
        "src/demo/src/conditions.cpp", 11, 3)


# -- bad input -------------------------------------------------------------------------

def test_syntax_error_keeps_the_other_calls(features_ws: Workspace) -> None:
    result = extract_cpp([os.path.join(FEATURES_SRC, "broken.cpp")], features_ws, cache_dir=None)
    errors = [d for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"]
    assert [(d.location.file, d.location.line) for d in errors] == [
        ("src/demo/src/broken.cpp", 9)]
    assert [c.name for c in result.calls] == ["before", "after"]


def test_missing_include_gets_an_empty_stand_in(features_ws: Workspace) -> None:
    result = extract_cpp([os.path.join(FEATURES_SRC, "missing.cpp")], features_ws, cache_dir=None)
    missing = [d for d in result.diagnostics if d.code == "CPP_INCLUDE_MISSING"]
    assert [(d.location.line, "acme_driver/driver.hpp" in d.message) for d in missing] == [
        (3, True)]
    assert "CPP_PARSE_ERROR" not in codes(result)
    assert [summary(c) for c in result.calls] == [
        ("publish", "acme/state", "std_msgs/String", 1, False, None, ())]


def test_unreadable_source_is_a_diagnostic(features_ws: Workspace) -> None:
    result = extract_cpp([os.path.join(FEATURES_SRC, "nope.cpp")], features_ws, cache_dir=None)
    assert result.calls == [] and codes(result) == ["FILE_UNREADABLE"]


def test_no_system_header_is_needed(
    features_ws: Workspace, names: CppResult, monkeypatch: pytest.MonkeyPatch
) -> None:
    from haros_arch.extract.cpp import toolchain

    def no_system() -> tuple[str, ...]:
        raise AssertionError("the default mode must not look at the system's headers")

    monkeypatch.setattr(toolchain, "system_include_dirs", no_system)
    again = extract_cpp([os.path.join(FEATURES_SRC, "names.cpp")], features_ws, cache_dir=None)
    assert [summary(c) for c in again.calls] == [summary(c) for c in names.calls]
    assert codes(again) == codes(names)
