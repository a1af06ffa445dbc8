"""What the launch stage reads again is read once: a parameter file's document (nav2's
bringup gives one file to twenty nodes, and a rewritten file is dumped, substituted and
read again for each), the dump of a rewritten document, a Python launch file's syntax
tree. Each reader still gets what a fresh read gives: its own objects, the aliases of
its document shared, unknown parts unknown, a refused text refused again."""

from __future__ import annotations

import pytest
import yaml

from haros_arch import safe_yaml
from haros_arch.launch.partial_yaml import MARK
from haros_arch.launch.ros2 import entities as e
from haros_arch.launch.ros2.naming import ParamFileLoader, load_param_file
from haros_arch.launch.ros2.python import checked_tree
from haros_arch.launch.ros2.runner import _dumped, _unknown_parts
from haros_arch.launch.ros2.substitutions import SubstitutionSyntax, parse
from haros_arch.workspace import Workspace

# long enough to be kept (short texts are cheap to read)
FILLER = "".join(f"    p{i}: {i}\n" for i in range(80))
PARAMS = f"""\
/**:
  ros__parameters:
    shared: &anchor [1, 2, 3]
    again: *anchor
controller:
  ros__parameters:
{FILLER}controller:
  ros__parameters:
    added: true
"""


def test_a_document_read_again_is_equal_and_a_fresh_object() -> None:
    first = load_param_file(PARAMS)
    second = load_param_file(PARAMS)
    assert first == second
    assert first is not second
    first["controller"]["ros__parameters"]["p1"] = "changed"
    first["/**"]["ros__parameters"]["shared"].append(4)
    third = load_param_file(PARAMS)
    assert third["controller"]["ros__parameters"]["p1"] == 1
    assert third["/**"]["ros__parameters"]["shared"] == [1, 2, 3]


def test_aliases_are_shared_within_a_document_read_again() -> None:
    load_param_file(PARAMS)
    again = load_param_file(PARAMS)["/**"]["ros__parameters"]
    assert again["shared"] is again["again"]


def test_the_loader_is_part_of_what_is_kept() -> None:
    # rcl merges a section given twice (ParamFileLoader); the safe loader keeps the last
    merged = safe_yaml.load(PARAMS, ParamFileLoader)["controller"]["ros__parameters"]
    plain = safe_yaml.load(PARAMS)["controller"]["ros__parameters"]
    assert merged["p0"] == 0 and merged["added"] is True
    assert plain == {"added": True}
    assert safe_yaml.load(PARAMS, ParamFileLoader)["controller"]["ros__parameters"] == merged


def test_key_lines_are_kept_apart_from_the_document() -> None:
    document, lines = safe_yaml.load_with_lines(PARAMS, ParamFileLoader)
    assert lines["controller"]["ros__parameters"]["added"] == 89
    again, lines_again = safe_yaml.load_with_lines(PARAMS, ParamFileLoader)
    assert again == document and lines_again == lines
    assert safe_yaml.load(PARAMS, ParamFileLoader) == document


def test_a_refused_text_is_refused_every_time() -> None:
    deep = "a: " + "[" * 1_100 + "]" * 1_100 + "\n" + FILLER
    for _ in range(2):
        with pytest.raises(safe_yaml.YAMLLimit):
            safe_yaml.load(deep)


def test_the_dump_tells_true_from_one_and_follows_the_document() -> None:
    # True == 1 and hash(True) == hash(1): a dump kept by the document's value would
    # give one the other's text
    assert _dumped({"rate": True}) == "rate: true\n"
    assert _dumped({"rate": 1}) == "rate: 1\n"
    assert _dumped({"rate": 1.0}) == "rate: 1.0\n"
    assert _dumped({"rate": "1"}) == "rate: '1'\n"
    shared = [1, 2]
    assert _dumped({"a": shared, "b": shared}) == yaml.safe_dump(
        {"a": shared, "b": shared}, default_flow_style=False)
    assert "&id001" in _dumped({"a": shared, "b": shared})
    assert "&id001" not in _dumped({"a": [1, 2], "b": [1, 2]})


def test_a_mark_written_with_escapes_stays_unknown() -> None:
    # yaml.safe_dump writes the mark's non-ASCII characters as escapes: the dumped text
    # of a rewritten document with an unknown value does not hold the mark as such
    text = yaml.safe_dump({"node": {"ros__parameters": {"frame": MARK, "rate": 5}}},
                          default_flow_style=False)
    assert MARK not in text
    document = _unknown_parts(safe_yaml.load(text), text)
    assert document == {"node": {"ros__parameters": {"frame": None, "rate": 5}}}
    plain = "node:\n  ros__parameters:\n    frame: map\n"
    assert _unknown_parts(safe_yaml.load(plain), plain) == {
        "node": {"ros__parameters": {"frame": "map"}}}


@pytest.mark.parametrize(("raw", "parsed"), [
    ("plain text, no substitution", ("plain text, no substitution",)),
    ("cost $5 and $(var x)/scan", ("cost $5 and ", e.Var(("x",)), "/scan")),
    ("escaped \\$(var x) here", ("escaped $(var x) here",)),
    ("$(var a 'b c')", (e.Var(("a",), ("b c",)),)),
    ("$(var a 'it\\'s $(var b)')", (e.Var(("a",), ("it's ", e.Var(("b",)))),)),
    ("$(var a \"x\")tail\\", (e.Var(("a",), ("x",)), "tail\\")),
    ("a: $(env HOME /root)\nb: $(var n)\n" * 2,
     ("a: ", e.Env(("HOME",), ("/root",)), "\nb: ", e.Var(("n",)), "\na: ",
      e.Env(("HOME",), ("/root",)), "\nb: ", e.Var(("n",)), "\n")),
    ("text ) more $(var b))", ("text ) more ", e.Var(("b",)), ")")),
])
def test_substitutions_in_long_text(raw: str, parsed: e.Text) -> None:
    assert parse(raw) == parsed


@pytest.mark.parametrize("raw", ["$(var a 'open", "$(var a", "$(var a b c)", "$(nothing x)"])
def test_substitution_syntax_errors_stay(raw: str) -> None:
    with pytest.raises(SubstitutionSyntax):
        parse(raw)


def test_a_launch_file_tree_is_read_once_per_text(tmp_path) -> None:
    workspace = Workspace(root=str(tmp_path))
    path = str(tmp_path / "a_launch.py")
    first, problem = checked_tree("x = 1\n", path, workspace)
    assert problem is None and first is not None
    assert checked_tree("x = 1\n", path, workspace)[0] is first
    other, _ = checked_tree("x = 2\n", path, workspace)
    assert other is not first
    for _ in range(2):
        tree, problem = checked_tree("def (:\n", path, workspace)
        assert tree is None and problem is not None and problem.code == "LAUNCH_PY_SYNTAX"
