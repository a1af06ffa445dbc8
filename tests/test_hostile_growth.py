"""Growth the fuzzer found after the first round of bounds (#20): work that grows with the
square of a file's size ends with a diagnostic, quickly."""

from __future__ import annotations

import math
import time

import pytest
import yaml
from conftest import package_xml

from haros_arch import safe_yaml
from haros_arch.launch import load
from haros_arch.workspace import scan


@pytest.mark.parametrize("text", [
    "1", "-1", "0x1F", "0o17", "017", "1_000", "+5", "1.5", "-.5", ".inf", "-.Inf", ".nan",
    "1e3", "6.8523015e+5", "true", "True", "yes", "Off", "n", "~", "null", "NULL", "abc",
    "/map", "a/b", "2001-12-14", "-", "--", "---", "a-b", "-a", "1-2", "0b101", "x~",
    "190:20:30", "a: 1", "[1, 2]", "'quoted'", "9" * 30, "",
])
def test_plain_scalars_read_as_the_full_yaml_reader_reads_them(text: str) -> None:
    full = yaml.safe_load(text)
    fast = safe_yaml.load(text)
    assert fast == full or (isinstance(full, float) and math.isnan(full) and math.isnan(fast))
    assert type(fast) is type(full)


DOCUMENTS = [
    "a: 1\nb: [x, 2.5, true, ~]\nc: {d: yes, e: '0x1F'}\n",
    "/**:\n  ros__parameters:\n    use_sim_time: false\n    rate: 20\n",
    "base: &b {x: 1}\nderived:\n  <<: *b\n  y: 2\n",
    "when: 2001-12-14\nbin: !!binary aGVsbG8=\nlong: >\n  folded\n  text\n",
    "- one\n- two: 2\n  three: 3\n",
]


@pytest.mark.parametrize("text", DOCUMENTS)
def test_documents_read_as_the_pure_reader_reads_them(text: str) -> None:
    """``load`` (libyaml's parser where PyYAML has it) gives what PyYAML's own reader
    gives, with our loaders' tags too."""
    from haros_arch.launch.ros1.params import RosparamLoader

    assert safe_yaml.load(text) == yaml.load(text, yaml.SafeLoader)
    assert safe_yaml.load(text, RosparamLoader) == yaml.load(text, RosparamLoader)
    assert safe_yaml.load("a: deg(180)", RosparamLoader) == {"a": math.pi}


@pytest.mark.parametrize("text", ["\ud800reach: 0.8\n", "a: [b\n", "a: \x7f\n", "a: b: c\n"])
def test_bad_text_is_a_yaml_error(text: str) -> None:
    """Text either reader refuses (a lone surrogate, which libyaml cannot even encode)
    is a YAML error with its place, never another exception."""
    with pytest.raises(yaml.YAMLError):
        safe_yaml.load(text)
    with pytest.raises(yaml.YAMLError):
        safe_yaml.compose(text)


def test_set_parameters_between_many_nodes_are_bounded(write_tree) -> None:
    # every node takes every SetParameter before it in its group: nodes x parameters
    body = '<set_parameter name="level" value="3"/><node pkg="pkg" exec="n"/>\n' * 700
    root = write_tree({"src/pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "src/pkg/launch/many.launch.xml": f"<launch><group>{body}</group>"
                                                         "</launch>\n"})
    ws = scan([str(root / "src")], {})
    started = time.process_time()  # work done, not how busy the machine is
    model = load(str(root / "src/pkg/launch/many.launch.xml"), ws, {}, {})
    assert time.process_time() - started < 10
    assert len(model.nodes) == 700
    assert [d.code for d in model.diagnostics] == ["LAUNCH_PY_BUDGET"]
    assert "parameter entries" in model.diagnostics[0].message


def test_a_query_whose_results_grow_without_bound_is_a_query_limit() -> None:
    from haros_arch import query
    from haros_arch.model import Model
    from haros_arch.query.errors import QueryLimitError

    items = "[" + ",".join(str(i) for i in range(100)) + "]"
    doubled = ", ".join(f"a{i} = a{i - 1} + a{i - 1}" for i in range(1, 16))
    text = (f"for x in {items}, y in {items}, z in {items} "
            f"let a0 = str(x) + 'abcdefg', {doubled} return a15")  # 10**6 results of 0.5 MB
    started = time.process_time()  # work done, not how busy the machine is
    with pytest.raises(QueryLimitError, match="results and the strings it builds"):
        query.search(text, query.model_scope(Model("m")))
    assert time.process_time() - started < 10
    # a query that returns a lot of small results is not refused
    assert len(query.search(f"for x in {items}, y in {items} return str(x) + str(y)",
                            query.model_scope(Model("m")))) == 10_000


def test_project_file_of_opening_brackets_is_refused_at_once(tmp_path) -> None:
    # found by scripts/fuzz: the project reader used the YAML reader without its bounds
    from haros_arch.project import ProjectError
    from haros_arch.project import load as load_project

    path = tmp_path / "project.yaml"
    path.write_text("[" * 200_000)
    started = time.process_time()  # work done, not how busy the machine is
    with pytest.raises(ProjectError, match="nested too deeply"):
        load_project(str(path))
    assert time.process_time() - started < 5


def test_python_node_reader_is_linear_in_a_chain_of_calls(write_tree) -> None:
    # found by scripts/fuzz: a.b().c().d()... evaluated each owner twice (2 ** length)
    from haros_arch.extract.python import extract_python

    text = ("import rospy\nrospy.init_node('n')\nrospy.spin()" + ".spin()" * 58 + "\n"
            "rospy.Publisher('t', rospy.AnyMsg, queue_size=1)\n")
    folder = write_tree({"pkg/package.xml": package_xml("pkg"), "pkg/scripts/n.py": text})
    started = time.process_time()  # work done, not how busy the machine is
    result = extract_python([str(folder / "pkg/scripts/n.py")], scan([str(folder)]),
                            package="pkg")
    assert time.process_time() - started < 5
    assert [str(c.name) for c in result.calls if c.kind == "publish"] == ["t"]


def test_key_lines_say_where_each_key_is_written() -> None:
    text = ("# a controller\n/arm:\n  ros__parameters:\n    gain: 2.0\n"
            "    pid: {p: 1, i: 2}\n    'quoted': x\n    list: [1, 2]\n")
    document, lines = safe_yaml.load_with_lines(text)  # one read gives both
    assert lines == {"/arm": {"ros__parameters": {
        "gain": 4, "pid": {"p": 5, "i": 5}, "quoted": 6, "list": 7}}}
    assert document["/arm"]["ros__parameters"]["pid"] == {"p": 1, "i": 2}
    with pytest.raises(yaml.YAMLError):  # does not read: said as load says it
        safe_yaml.load_with_lines("a: [")
    assert safe_yaml.load_with_lines("- 1\n- 2\n") == ([1, 2], None)  # no mapping
    # a key given twice: the keys of both mappings, as rcl merges them
    assert safe_yaml.load_with_lines("/**:\n  a: 1\n/**:\n  b: 2\n")[1] == {
        "/**": {"a": 2, "b": 4}}
