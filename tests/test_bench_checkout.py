"""Each bench script measures the haros_arch that PYTHONPATH gives (``bench/checkout.py``):
most put their own checkout first on ``sys.path``, so comparing two checkouts with one
checkout's scripts measured that one twice (the fault bench/cpp_real.py had)."""

from __future__ import annotations

import ast
import os
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import ROOT

BENCH = ROOT / "bench"
SCRIPTS = sorted(p for p in BENCH.rglob("*.py") if "haros_arch" in p.read_text())
# the folders a script may still put on sys.path: its own (the bench's modules) and one
# an environment variable names (launch_ros2_compare's stand-ins of ROS 2 packages)
ALLOWED = {"os.path.dirname(os.path.abspath(__file__))", "str(HERE)",
           'os.environ["BENCH_STANDINS"]'}
FAKE = ("import sys\nsys.stderr.write('the haros_arch of PYTHONPATH\\n')\n"
        "raise SystemExit(97)\n")


def _path_changes(path: Path) -> list[str]:
    """The source of each folder ``path`` inserts or appends to ``sys.path``."""
    text = path.read_text()
    found = []
    for node in ast.walk(ast.parse(text)):
        if (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
                and node.func.attr in ("insert", "append")
                and ast.unparse(node.func.value) == "sys.path"):
            found.append(ast.unparse(node.args[-1]))
    return found


def _imports_at_load(path: Path) -> bool:
    """Whether the script imports haros_arch when it is loaded (not in a function)."""
    names = []
    for node in ast.parse(path.read_text()).body:
        if isinstance(node, ast.ImportFrom):
            names.append(node.module or "")
        elif isinstance(node, ast.Import):
            names += [alias.name for alias in node.names]
    return any(name.split(".")[0] == "haros_arch" for name in names)


def test_the_scripts_are_found():
    names = {p.name for p in SCRIPTS}
    assert {"cpp_real.py", "cpp_census.py", "scale.py", "models_real.py"} <= names


@pytest.mark.parametrize("script", SCRIPTS, ids=lambda p: str(p.relative_to(BENCH)))
def test_no_script_puts_a_checkout_first(script: Path):
    assert set(_path_changes(script)) <= ALLOWED


@pytest.mark.parametrize("script", [p for p in SCRIPTS if _imports_at_load(p)],
                         ids=lambda p: str(p.relative_to(BENCH)))
def test_a_script_imports_the_haros_arch_of_pythonpath(script: Path, tmp_path):
    fake = tmp_path / "haros_arch"
    fake.mkdir()
    (fake / "__init__.py").write_text(FAKE)
    env = {**os.environ, "PYTHONPATH": str(tmp_path)}
    done = subprocess.run([sys.executable, str(script), "--help"], capture_output=True,
                          text=True, env=env, cwd=tmp_path, timeout=120)
    assert done.returncode == 97, done.stdout + done.stderr
    assert "the haros_arch of PYTHONPATH" in done.stderr


def test_checkout_says_which_haros_arch(capsys):
    sys.path.insert(0, str(BENCH))
    try:
        import checkout
    finally:
        sys.path.remove(str(BENCH))
    import haros_arch

    where = checkout.announce()
    assert where == os.path.dirname(os.path.dirname(os.path.abspath(haros_arch.__file__)))
    assert capsys.readouterr().err == f"haros_arch from {where}\n"
