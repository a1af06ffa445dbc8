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
