"""Hostile inputs to the readers, one per class the fuzzing harness and the hostile-input
campaign found: each ends with a diagnostic (or the reader's documented error) quickly."""

from __future__ import annotations

import shutil
import time

import pytest
from conftest import package_xml

from haros_arch.launch import load
from haros_arch.launch.ros1.params import ParamError, load_yaml
from haros_arch.launch.ros2.substitutions import SubstitutionSyntax, parse
from haros_arch.workspace import scan


def launch(write_tree, name: str, text: str, extra: dict[str, str] | None = None,
           build: str = "ament_cmake"):
    files = {"src/pkg/package.xml": package_xml("pkg", build), f"src/pkg/launch/{name}": text}
    files.update(extra or {})
    root = write_tree(files)
    ws = scan([str(root / "src")], {})
    started = time.process_time()  # work done, not how busy the machine is
    model = load(str(root / "src/pkg/launch" / name), ws, {}, {})
    assert time.process_time() - started < 10
    return model


def messages(model) -> str:
    return "\n".join(f"{d.code} {d.message}" for d in model.diagnostics)


@pytest.mark.parametrize("char", ["\x7f", "\x0c"])
def test_control_character_in_rosparam_yaml_is_a_param_error(char: str) -> None:
    with pytest.raises(ParamError, match="invalid YAML"):
        load_yaml(f"a: 1{char}\n")


def test_substitutions_nested_thousands_deep_are_refused() -> None:
    with pytest.raises(SubstitutionSyntax, match="nested more than"):
        parse("$(eval " * 3000 + "1" + ")" * 3000)
    assert parse("$(var " * 5 + "a" + ")" * 5)  # a few levels are fine


def test_deep_substitutions_in_a_yaml_launch_file_are_a_diagnostic(write_tree) -> None:
    text = 'launch:\n- let: {name: a, value: "' + "$(eval " * 3000 + "1" + ")" * 3000 + '"}\n'
    model = launch(write_tree, "deep.launch.yaml", text)
    assert "nested more than" in messages(model)


# -- string and number building: the evaluators check the size before they make a value ----
BUILDING = {
    "format width from an argument": "'{0:{1}}'.format('a', 10**10)",
    "%* width": "'%*d' % (10**9, 1)",
    "join of big strings": "','.join(['x' * 10**5] * 10**5)",
    "replace of the empty string": "('x' * 10**5).replace('', 'y' * 10**5)",
    "range built whole": "len(range(10**9))",
    "sum of lists": "len(sum([[1] * 10**4] * 10**4, []))",
    "power chain": "((10**200)**200)**200",
    "squaring": "(10**1000 * 10**1000) * (10**1000 * 10**1000)",
    "str of a shared structure": "len(str([[[1] * 1000] * 1000] * 1000))",
    "f-string width": "f'{1:{10**10}}'",
}


@pytest.mark.parametrize("case", sorted(BUILDING))
def test_eval_refuses_to_build_huge_values(case: str) -> None:
    from haros_arch.launch.expression import BUILTINS, Unknown, evaluate

    started = time.process_time()  # work done, not how busy the machine is
    result = evaluate(BUILDING[case], None, BUILTINS)
    assert time.process_time() - started < 5
    assert isinstance(result, Unknown) and result.kind == "limit", result


def test_format_fields_do_not_reach_attributes() -> None:
    from haros_arch.evaluate.python import BUILTINS, Unknown, evaluate

    # the core evaluator (the one setup.py and Python files go through) refuses the field
    result = evaluate("'{0.__class__}'.format(1)", None, BUILTINS)
    assert isinstance(result, Unknown) and "attribute" in result.reason
    assert evaluate("'{0.real}'.format(1)", None, BUILTINS) != "1"
    # what real launch files write still works
    assert evaluate("'{0:{1}}|{2:>4}|{k}'.format('a', 3, 7, k=1)", None, BUILTINS) == "a  |   7|1"
    assert evaluate("'%5.1f|%*d' % (3.14159, 3, 7)", None, BUILTINS) == "  3.1|  7"
    assert evaluate("','.join(['a', 'b'])", None, BUILTINS) == "a,b"


PYTHON_BUILDING = {
    "format width": "x = '{0:{1}}'.format('a', 10**10)",
    "%* width": "x = '%*d' % (10**9, 1)",
    "power chain": "x = (((10**200)**200)**200)**200",
    "squaring": "x = 10**200\n    for i in range(40):\n        x = x * x",
    "join": "x = ''.join(['x' * 10**5] * 10**5)",
    "attribute field": "x = '{0.__class__}'.format(1)",
}


@pytest.mark.parametrize("case", sorted(PYTHON_BUILDING))
def test_python_launch_refuses_to_build_huge_values(write_tree, case: str) -> None:
    text = ("from launch import LaunchDescription\n"
            "from launch_ros.actions import Node\n\n"
            "def generate_launch_description():\n"
            f"    {PYTHON_BUILDING[case]}\n"
            "    return LaunchDescription([Node(package='pkg', executable='n', name=x)])\n")
    model = launch(write_tree, "big_launch.py", text)
    assert model.diagnostics, "the bound is said"
    assert all(n.name != "{0.__class__}" and "class" not in str(n.name) for n in model.nodes)


# -- YAML: aliases and nesting are bounded the same way on every path -----------------------
def _alias_bomb() -> str:
    lines = ["a0: &a0 [x, x, x, x, x, x, x, x, x, x]"]
    for i in range(1, 9):
        lines.append(f"a{i}: &a{i} [" + ", ".join([f"*a{i - 1}"] * 10) + "]")
    return "\n".join(lines) + "\nnode:\n  ros__parameters:\n    p: *a8\n"


def test_alias_bomb_in_a_ros2_parameter_file_is_a_diagnostic(write_tree) -> None:
    text = ('<launch><node pkg="pkg" exec="n" name="n">'
            '<param from="$(find-pkg-share pkg)/config/bomb.yaml"/></node></launch>')
    model = launch(write_tree, "bomb.launch.xml", text,
                   {"src/pkg/config/bomb.yaml": _alias_bomb()})
    assert "aliases expanded" in messages(model)
    with pytest.raises(ParamError, match="aliases expanded"):  # the ROS 1 path, shared
        load_yaml(_alias_bomb())


def test_yaml_launch_file_nested_thousands_deep_is_a_diagnostic(write_tree) -> None:
    model = launch(write_tree, "deep.launch.yaml", "launch: " + "[" * 5000 + "]" * 5000)
    assert "LAUNCH_YAML_SYNTAX" in messages(model) and "nested" in messages(model)
    model = launch(write_tree, "deep2.launch.yaml",
                   "launch:\n- let: {name: a, value: " + "[" * 150 + "]" * 150 + "}\n")
    assert "nested more than" in messages(model)


@pytest.mark.parametrize("text", ["%YAML " + "9" * 5000 + "\n---\na: 1\n", "a: " + "9" * 5000])
def test_huge_numbers_in_yaml_are_refused(text: str, tmp_path) -> None:
    from haros_arch.project import ProjectError
    from haros_arch.project import load as load_project

    with pytest.raises(ParamError):
        load_yaml(text)
    if text.startswith("%YAML"):
        path = tmp_path / "project.yaml"
        path.write_text(text.replace("a: ", "project: "))
        with pytest.raises(ProjectError):
            load_project(str(path))


def test_query_round_and_int_stay_bounded() -> None:
    from haros_arch import query
    from haros_arch.model import Model
    from haros_arch.query.errors import QueryError

    scope = query.model_scope(Model("m"))
    started = time.process_time()  # work done, not how busy the machine is
    assert query.search("return round(5, 0-1000000000)", scope) == [0]
    assert time.process_time() - started < 5
    assert query.search("return round(1250, 0-2)", scope) == [1200]
    with pytest.raises(QueryError, match="infinity"):
        query.search("return int(float('1e400'))", scope)


def test_yaml_opening_brackets_without_end_is_refused_at_once() -> None:
    started = time.process_time()  # work done, not how busy the machine is
    with pytest.raises(ParamError, match="nested"):
        load_yaml("baud: " + "[" * 200_000)
    assert time.process_time() - started < 5
    assert load_yaml('a: "' + "[" * 300 + '"') == {"a": "[" * 300}  # in a string: fine


def test_billion_laughs_through_ros1_args_is_a_diagnostic(write_tree) -> None:
    args = "".join(f'<arg name="a{i + 1}" default="' + f"$(arg a{i})" * 10 + '"/>'
                   for i in range(9))
    text = (f'<launch><arg name="a0" default="xxxxxxxxxx"/>{args}'
            '<node pkg="pkg" type="n" name="n"><param name="p" value="$(arg a9)"/></node>'
            '</launch>')
    model = launch(write_tree, "laughs.launch", text, build="catkin")
    assert "longer than 100000 characters" in messages(model)


def test_scan_does_not_follow_links_to_root_or_ancestors(write_tree) -> None:
    import os

    root = write_tree({"ws/src/good/package.xml": package_xml("good"),
                       "elsewhere/kept/package.xml": package_xml("kept")})
    os.symlink("/", root / "ws/src/slash")
    os.symlink(root / "ws", root / "ws/src/good_parent")
    os.makedirs(root / "ws/src/deep/er")
    os.symlink("../..", root / "ws/src/deep/er/up")
    os.symlink(root / "elsewhere", root / "ws/src/external")  # a checkout kept elsewhere
    started = time.process_time()  # work done, not how busy the machine is
    workspace = scan([str(root / "ws/src")], {})
    assert time.process_time() - started < 5
    assert sorted(workspace.packages) == ["good", "kept"]


# -- an exception that escapes one file's work is a diagnostic for that file ----------------
def test_a_bug_in_one_launch_file_is_an_internal_diagnostic(monkeypatch, tmp_path) -> None:
    from conftest import FIXTURES

    import haros_arch.launch as launch_module
    from haros_arch.pipeline import analyse
    from haros_arch.project import load as load_project

    real = launch_module.load

    def buggy(path, *args, **kwargs):
        if path.endswith("broken.launch"):
            raise KeyError("a bug of ours")
        return real(path, *args, **kwargs)

    monkeypatch.setattr(launch_module, "load", buggy)
    src = FIXTURES / "paper_minimal" / "src"
    broken = tmp_path / "src" / "example" / "launch"
    shutil.copytree(src, tmp_path / "src")
    (broken / "broken.launch").write_text("<launch/>")
    project = tmp_path / "project.yaml"
    project.write_text("project: p\npackages: [example]\nconfigurations:\n"
                       "  good: {launch: [example/launch/minimal.launch]}\n"
                       "  bad: {launch: [example/launch/broken.launch]}\n")
    model = analyse(load_project(str(project)), {})
    configs = {c.name: c for c in model.configurations}
    assert configs["good"].nodes, "the other file's work is kept"
    internal = [d for c in model.configurations for d in c.diagnostics
                if d.code == "INTERNAL"] + [d for d in model.diagnostics if d.code == "INTERNAL"]
    assert internal and "broken.launch" in internal[0].message
    assert "KeyError" in internal[0].message and internal[0].location.line == 5


def test_a_bug_in_one_manifest_is_an_internal_diagnostic(monkeypatch, write_tree) -> None:
    import haros_arch.workspace as workspace_module

    real = workspace_module.parse_manifest

    def buggy(path, *args, **kwargs):
        if "/bad/" in path:
            raise AttributeError("a bug of ours")
        return real(path, *args, **kwargs)

    monkeypatch.setattr(workspace_module, "parse_manifest", buggy)
    root = write_tree({"src/good/package.xml": package_xml("good"),
                       "src/bad/package.xml": package_xml("bad")})
    workspace = scan([str(root / "src")], {})
    assert sorted(workspace.packages) == ["good"]
    assert [d.code for d in workspace.diagnostics] == ["INTERNAL"]


@pytest.mark.parametrize("key", ["queries", "rules"])
def test_bad_severity_of_the_projects_own_query_is_a_project_error(tmp_path, key: str) -> None:
    from haros_arch.project import ProjectError
    from haros_arch.project import load as load_project

    item = ('  - query: "nodes"\n    severity: fatal\n' if key == "queries"
            else '  mine:\n    query: "nodes"\n    severity: [1]\n')
    path = tmp_path / "project.yaml"
    path.write_text(f"project: p\n{key}:\n{item}")
    with pytest.raises(ProjectError, match="severity must be one of") as caught:
        load_project(str(path))
    assert (":4:" if key == "queries" else ":5:") in str(caught.value)  # the severity's line


# -- every output writes any name -------------------------------------------------------------
HOSTILE_NAME = "/bad\udc80\x1b[31m\x00\x7f\x0c"


def test_text_junit_and_html_write_names_with_surrogates_and_control_characters() -> None:
    import io
    import json
    from xml.dom import minidom

    from rich.console import Console

    from haros_arch.diagnostics import make
    from haros_arch.model.location import Location
    from haros_arch.report.junit import to_junit
    from haros_arch.report.text import print_diagnostics
    from haros_arch.viz.html import json_for_script

    found = make("INTERNAL", Location(None, "a\udc80.py", 3), path=HOSTILE_NAME,
                 detail="x", at="y")
    stream = io.StringIO()
    print_diagnostics([found], Console(file=stream, soft_wrap=True, no_color=True))
    text = stream.getvalue()
    text.encode("utf-8")
    assert "\\udc80" in text and "\\x1b[31m" in text
    assert not {"\x1b", "\x00", "\x7f", "\x0c"} & set(text)  # the name's raw characters
    junit = to_junit([], [found], [])
    minidom.parseString(junit.encode("utf-8"))  # well-formed XML 1.0
    assert "\\udc80" in junit
    script = json_for_script({"name": HOSTILE_NAME})
    assert json.loads(script.encode("utf-8")) == {"name": HOSTILE_NAME}


@pytest.mark.parametrize("grow", ["name = name + name", "n = n * n"])
def test_python_node_reader_stops_doubling_values(write_tree, grow: str) -> None:
    from haros_arch.extract.python import extract_python

    text = ("import rospy\nfrom std_msgs.msg import String\nname = 'x' * 1\nname = 'abcdefgh'\n"
            "n = 10 ** 1\nn = 99999999999999999999\n" + (grow + "\n") * 40
            + "rospy.init_node('n')\nrospy.Publisher(name + str(n), String, queue_size=1)\n")
    folder = write_tree({"pkg/package.xml": package_xml("pkg"), "pkg/scripts/grow.py": text})
    started = time.process_time()  # work done, not how busy the machine is
    result = extract_python([str(folder / "pkg" / "scripts" / "grow.py")], scan([str(folder)]),
                            package="pkg")
    assert time.process_time() - started < 10
    assert len(result.calls) == 1 and len(str(result.calls[0].name)) < 1000


def test_compiler_warnings_about_workspace_python_are_not_printed(write_tree) -> None:
    import warnings

    text = ("from launch import LaunchDescription\n"
            "def generate_launch_description():\n"
            "    x = 1if True else '\\d'\n"
            "    return LaunchDescription([])\n")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        launch(write_tree, "warn_launch.py", text)
    assert not [w for w in caught if issubclass(w.category, SyntaxWarning)]


def test_comparing_huge_shared_lists_is_charged_by_their_size() -> None:
    from haros_arch.launch.expression import BUILTINS, Unknown, evaluate

    started = time.process_time()  # work done, not how busy the machine is
    result = evaluate("[[[1] * 1000] * 1000] * 1000 == [[[1] * 1000] * 1000] * 1000", None,
                      BUILTINS)
    assert time.process_time() - started < 5
    assert isinstance(result, Unknown) and result.kind == "limit"
    assert evaluate("[1, 2] == [1, 2] and 'ab' in 'xaby'", None, BUILTINS) is True
