"""The one safe evaluator and every reader configured on it, against each hostile class of
issue #20 (inputs written here): each ends as an unknown value or a diagnostic within 10 s."""

from __future__ import annotations

import ast
import time

import pytest
from conftest import package_xml

from haros_arch import pysetup
from haros_arch.evaluate import python as core
from haros_arch.evaluate.module import run_module
from haros_arch.launch import expression, load
from haros_arch.workspace import scan

# one expression per class; each would take minutes or gigabytes if Python ran it
HOSTILE = {
    "format width from an argument": "'{0:{1}}'.format('a', 10**10)",
    "%* width": "'%*d' % (10**9, 1)",
    "join of a big list": "','.join(['x' * 10**5] * 10**5)",
    "replace of the empty string": "('x' * 10**5).replace('', 'y' * 10**3)",
    "repeated multiplication": "'ab' * 10**5 * 10**5",
    "range built whole": "len(range(10**9)) + len(list(range(10**9)))",
    "str of a shared structure": "len(str([[[1] * 1000] * 1000] * 1000))",
    "integer squaring": "(10**1000 * 10**1000) * (10**1000 * 10**1000) * 10**3000",
    "power chain": "(((10**200)**200)**200)**200",
    "power 256 chain": "((7**256)**256)**256",
    "sum of lists": "len(sum([[1] * 10**5] * 10**5, []))",
    "equality of huge shared lists": "[[[1] * 1000] * 1000] * 1000 == [[[1] * 1000] * 1000] * 1000",
    "f-string width": "f'{1:{10**10}}'",
    "shift": "1 << 10**9",
    "zfill": "'1'.zfill(10**10)",
    "sorted shared structure": "len(sorted([[[1] * 300] * 300] * 300))",
    "count in a shared structure": "([[[1] * 300] * 300] * 300).count([[1] * 300] * 300)",
    "hash of a shared tuple": "len({(((((1,) * 30,) * 30,) * 30,) * 30,) * 30: 1})",
    "missing key of a shared tuple": "{1: 2}[(((((1,) * 30,) * 30,) * 30,) * 30,) * 30]",
}


@pytest.mark.parametrize("case", sorted(HOSTILE))
def test_core_refuses_each_hostile_class(case: str) -> None:
    started = time.process_time()  # work done, not how busy the machine is
    result = core.evaluate(HOSTILE[case])
    assert time.process_time() - started < 10
    assert isinstance(result, core.Unknown) and result.kind == "limit", result


@pytest.mark.parametrize("text", ["'{0.__class__}'.format(1)", "'{0[__class__]}'.format({})",
                                  "'{0.real}'.format(1)", "(1).__class__", "'x'.__len__()",
                                  "__import__('os')", "[c for c in ().__class__.__bases__]"])
def test_core_refuses_dunders_and_attribute_fields(text: str) -> None:
    result = core.evaluate(text)
    assert isinstance(result, core.Unknown) and result.kind == "unsupported", result


def test_launch_eval_refuses_double_underscores_anywhere() -> None:
    # roslaunch's rule, kept for ROS 2's $(eval) too: even inside a string
    assert core.evaluate("'a__b'.upper()") == "A__B"
    result = expression.evaluate("'a__b'.upper()")
    assert isinstance(result, core.Unknown) and "double underscore" in result.reason


def test_a_nul_character_is_not_python() -> None:
    result = core.evaluate("1\x00+2")
    assert isinstance(result, core.Unknown) and result.kind == "syntax"


def test_error_reasons_stay_short() -> None:
    result = core.evaluate("{1: 2}[('x' * 1000,) * 100]")
    assert isinstance(result, core.Unknown) and result.kind == "error"
    assert len(result.reason) < 300


def test_core_still_computes_what_launch_files_write() -> None:
    assert core.evaluate("'{0:>{1}}|{2:.2f}|%03d' % 7", None) == "{0:>{1}}|{2:.2f}|007"
    assert core.evaluate("'{0:>{1}}|{2:.2f}'.format('a', 3, 3.14159)") == "  a|3.14"
    assert core.evaluate("f'{3.14159:.1f}_{\"x\"!r}'") == "3.1_'x'"
    assert core.evaluate("sum([[1], [2]], []) == [1, 2] and 2 ** 100 > 0") is True


def test_module_statements_keep_one_budget_per_file() -> None:
    text = "x = 'ab'\n" + "x = x + x\n" * 40 + "y = 'still read'\n"
    module = run_module(ast.parse(text))
    assert isinstance(module.names["x"], core.Unknown) and module.names["x"].kind == "limit"
    assert module.names["y"] == "still read"
    steps = run_module(ast.parse("a = [0] * 1000\n" + "b = a == a\n" * 1000))
    assert isinstance(steps.names["b"], core.Unknown)


def _write(tmp_path, files: dict[str, str]):
    for rel, text in files.items():
        path = tmp_path / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return scan([str(tmp_path / "src")], {})


def _launch(tmp_path, name: str, text: str):
    ws = _write(tmp_path, {"src/pkg/package.xml": package_xml("pkg", "ament_cmake"),
                           f"src/pkg/launch/{name}": text})
    started = time.process_time()  # work done, not how busy the machine is
    model = load(str(tmp_path / "src/pkg/launch" / name), ws, {}, {})
    assert time.process_time() - started < 10
    return model


def _ros1_eval(expression_text: str) -> str:
    return (f'<launch><arg name="v" value="$(eval {expression_text})"/>'
            '<node pkg="pkg" type="n" name="n"><param name="p" value="$(arg v)"/></node>'
            '</launch>')


def _ros2_eval(expression_text: str) -> str:
    return (f'<launch><let name="v" value="$(eval &quot;{expression_text}&quot;)"/>'
            '<node pkg="pkg" exec="n" name="$(var v)"/></launch>')


def _ros2_python(expression_text: str) -> str:
    return ("from launch import LaunchDescription\n"
            "from launch_ros.actions import Node\n\n"
            "def generate_launch_description():\n"
            f"    x = str({expression_text})\n"
            "    return LaunchDescription([Node(package='pkg', executable='n', name=x)])\n")


LAUNCH_FILES = {"a.launch": _ros1_eval, "a.launch.xml": _ros2_eval, "a_launch.py": _ros2_python}


@pytest.mark.parametrize("case", sorted(HOSTILE))
@pytest.mark.parametrize("name", sorted(LAUNCH_FILES))
def test_launch_files_give_a_diagnostic(tmp_path, name: str, case: str) -> None:
    text = HOSTILE[case]
    if name != "a_launch.py":  # in XML
        text = text.replace("<<", "&lt;&lt;").replace('"', "&quot;")
    model = _launch(tmp_path, name, LAUNCH_FILES[name](text))
    assert model.diagnostics and all(len(str(n.name)) < 1000 for n in model.nodes)


@pytest.mark.parametrize("case", sorted(HOSTILE))
def test_setup_py_gives_a_diagnostic(tmp_path, case: str) -> None:
    setup = ("from setuptools import setup\n"
             f"name = str({HOSTILE[case]})\n"
             "setup(name='pkg', entry_points={'console_scripts': [name + ' = pkg.n:main']})\n")
    ws = _write(tmp_path, {"src/pkg/package.xml": package_xml("pkg", "ament_python"),
                           "src/pkg/setup.py": setup})
    started = time.process_time()  # work done, not how busy the machine is
    nodes, found = pysetup.parse_package(ws.packages["pkg"], ws)
    assert time.process_time() - started < 10
    assert not nodes and {d.code for d in found} == {"PYSETUP_DYNAMIC"}
    assert any(d.location.line == 2 for d in found), "the bound is said where it was reached"


@pytest.mark.parametrize("case", sorted(HOSTILE))
def test_python_node_reader_keeps_the_name_unknown(tmp_path, case: str) -> None:
    from haros_arch.extract.python import extract_python

    text = ("import rospy\nfrom std_msgs.msg import String\nrospy.init_node('n')\n"
            f"rospy.Publisher('t' + str({HOSTILE[case]}), String, queue_size=1)\n")
    ws = _write(tmp_path, {"src/pkg/package.xml": package_xml("pkg"),
                           "src/pkg/scripts/n.py": text})
    started = time.process_time()  # work done, not how busy the machine is
    result = extract_python([str(tmp_path / "src/pkg/scripts/n.py")], ws, package="pkg")
    assert time.process_time() - started < 10
    assert len(result.calls) == 1 and str(result.calls[0].name).startswith("t")
    assert len(str(result.calls[0].name)) < 1000


def test_python_launch_parameter_of_a_shared_structure_is_bounded(tmp_path) -> None:
    # 27 million items behind 900 references: what reads the parameters would walk them all
    text = ("from launch import LaunchDescription\n"
            "from launch_ros.actions import Node\n\n"
            "def generate_launch_description():\n"
            "    c = [[[1] * 300] * 300] * 300\n"
            "    return LaunchDescription([Node(package='pkg', executable='n', name='n',\n"
            "                                   parameters=[{'p': c}])])\n")
    model = _launch(tmp_path, "a_launch.py", text)
    assert any("steps" in d.message for d in model.diagnostics)


def test_python_node_reader_folds_constants_through_the_evaluator(tmp_path) -> None:
    from haros_arch.extract.python import extract_python

    text = ("import rospy\nfrom std_msgs.msg import String\nSIM = False\nN = 3\n"
            "rospy.init_node('n')\n"
            "rospy.Publisher('/sim' if SIM else '/real', String, queue_size=1)\n"
            "rospy.Publisher('/many' if N >= 2 and not SIM else '/one', String, queue_size=-N)\n"
            "rospy.Publisher('/x' if rospy.get_param('~a') else '/y', String, queue_size=1)\n")
    ws = _write(tmp_path, {"src/pkg/package.xml": package_xml("pkg"),
                           "src/pkg/scripts/n.py": text})
    result = extract_python([str(tmp_path / "src/pkg/scripts/n.py")], ws, package="pkg")
    names = [str(c.name) for c in result.calls if c.kind == "publish"]
    assert names == ["/real", "/many", "?"]
