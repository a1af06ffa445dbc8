"""Hostile inputs to the readers, one per class the fuzzing harness and the hostile-input
campaign found: each ends with a diagnostic (or the reader's documented error) quickly."""

from __future__ import annotations

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
    started = time.monotonic()
    model = load(str(root / "src/pkg/launch" / name), ws, {}, {})
    assert time.monotonic() - started < 10
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

    started = time.monotonic()
    result = evaluate(BUILDING[case], None, BUILTINS)
    assert time.monotonic() - started < 5
    assert isinstance(result, Unknown) and result.kind == "limit", result


def test_format_fields_do_not_reach_attributes() -> None:
    from haros_arch.launch.expression import BUILTINS, Unknown, evaluate

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
