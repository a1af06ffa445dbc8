"""Bad Python input gives diagnostics or a result in bounded work, never an exception."""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.extract.python.modules import MAX_AST_NODES, MAX_PY_BYTES
from haros_arch.workspace import scan


def run(folder: Path, name: str):
    ws = scan([str(folder)])
    return extract_python([str(folder / "pkg" / "scripts" / name)], ws, package="pkg")


def codes(result) -> list[str]:
    return [d.code for d in result.diagnostics]


def test_file_above_the_size_limit_is_skipped(write_tree) -> None:
    line = "rospy.Publisher('t', String, queue_size=1)\n"
    big = "import rospy\n" + line * (5 * 1024 * 1024 // len(line) + 1)
    folder = write_tree({"pkg/package.xml": package_xml("pkg"), "pkg/scripts/big.py": big})
    result = run(folder, "big.py")
    assert len(big) > MAX_PY_BYTES
    assert result.calls == []
    assert codes(result) == ["FILE_TOO_LARGE"]


def test_generated_file_under_the_size_limit_is_bounded(write_tree) -> None:
    # many small statements: below the byte limit, above the AST node bound
    line = "x = [1, 2, 3, 4, 5, 6, 7, 8, 9]\n"
    text = "import rospy\n" + line * (MAX_AST_NODES // 14 + 1)  # 14 nodes a line
    folder = write_tree({"pkg/package.xml": package_xml("pkg"), "pkg/scripts/gen.py": text})
    result = run(folder, "gen.py")
    assert len(text) < MAX_PY_BYTES
    assert codes(result) == ["PY_TOO_COMPLEX"]


def test_many_calls_give_results(write_tree) -> None:
    calls = "".join(f"rospy.Publisher('t{i}', String, queue_size=1)\n" for i in range(2000))
    text = "import rospy\nfrom std_msgs.msg import String\n" + calls
    folder = write_tree({"pkg/package.xml": package_xml("pkg"), "pkg/scripts/many.py": text})
    result = run(folder, "many.py")
    assert len(result.calls) == 2000
    assert result.calls[-1].name == "t1999"


@pytest.mark.parametrize("text,line", [
    ("import rospy\nrospy.Publisher('a', String\n", 2),            # unclosed call
    ("import rospy\nx = (" * 1 + "(" * 300 + "1" + ")" * 300 + ")\n", 2),  # nesting
    # inconsistent indentation under Python 2 too (a tab is 8 columns there: a tab then
    # 8 spaces is one level, read as Python 2; a tab then 4 spaces is not)
    ("def f():\n\treturn 1\n    return 2\n", 3),
    ("import rospy\nx = 'a\x00b'\n", None),                       # null byte
])
def test_unparsable_files(write_tree, text: str, line: int | None) -> None:
    folder = write_tree({"pkg/package.xml": package_xml("pkg"), "pkg/scripts/bad.py": text})
    result = run(folder, "bad.py")
    assert result.calls == []
    assert codes(result) == ["PY_PARSE_ERROR"]
    if line is not None:
        assert result.diagnostics[0].location.line == line


def test_deep_expression_is_evaluated_in_bounded_depth(write_tree) -> None:
    name = " + ".join(["'a'"] * 500)  # parses, but deeper than the evaluator goes
    text = f"import rospy\nfrom std_msgs.msg import String\nrospy.Publisher({name}, String)\n"
    folder = write_tree({"pkg/package.xml": package_xml("pkg"), "pkg/scripts/deep.py": text})
    result = run(folder, "deep.py")
    assert [c.kind for c in result.calls] == ["publish"]
    assert "?" in result.calls[0].name


def test_expression_too_deep_for_the_parser(write_tree) -> None:
    name = " + ".join(["'a'"] * 5000)
    text = f"import rospy\nrospy.Publisher({name}, String)\n"
    folder = write_tree({"pkg/package.xml": package_xml("pkg"), "pkg/scripts/deep.py": text})
    assert codes(run(folder, "deep.py")) == ["PY_PARSE_ERROR"]


def test_recursive_helpers_terminate(write_tree) -> None:
    text = (
        "import rospy\nfrom std_msgs.msg import String\n"
        "def a(n):\n    rospy.Publisher(n, String)\n    return b(n + '/x')\n"
        "def b(n):\n    return a(n)\n"
        "a('top')\n")
    folder = write_tree({"pkg/package.xml": package_xml("pkg"), "pkg/scripts/rec.py": text})
    result = run(folder, "rec.py")
    # a('top') calls b which calls a again: the second a is not walked
    assert [c.name for c in result.calls] == ["top"]


def test_not_utf8_is_read_with_replacement(write_tree, tmp_path: Path) -> None:
    folder = write_tree({"pkg/package.xml": package_xml("pkg"), "pkg/scripts/enc.py": ""})
    (folder / "pkg" / "scripts" / "enc.py").write_bytes(
        b"import rospy\nfrom std_msgs.msg import String\n# caf\xe9\n"
        b"rospy.Publisher('ok', String)\n")
    result = run(folder, "enc.py")
    assert [c.name for c in result.calls] == ["ok"]
    assert codes(result) == ["FILE_ENCODING"]


def test_helper_fan_out_is_bounded_by_the_evaluation_budget(write_tree, monkeypatch) -> None:
    """Helpers that each call the one below many times: the work grows as fan-out ** depth
    (60 ** 4 calls from a 1 KB file ran for minutes). The walk's evaluation steps are
    bounded (``values.LIMITS``, smaller here to keep the test quick): a diagnostic, the
    calls before it kept."""
    from haros_arch.evaluate.operations import Limits
    from haros_arch.extract.python import values

    monkeypatch.setattr(values.Evaluator, "limits", Limits(steps=20_000))
    lines = ["import rospy", "from std_msgs.msg import String",
             "rospy.Publisher('/before', String, queue_size=1)",
             "def f0(x):", "    return x + 1"]
    for level in range(1, 5):
        lines += [f"def f{level}(x):", "    return " + " + ".join([f"f{level - 1}(x)"] * 8)]
    lines.append("rospy.Publisher('/n%d' % f4(1), String, queue_size=1)")
    folder = write_tree({"pkg/package.xml": package_xml("pkg"),
                         "pkg/scripts/fan.py": "\n".join(lines) + "\n"})
    result = run(folder, "fan.py")
    assert [c.name for c in result.calls][:1] == ["/before"]
    assert "PY_TOO_COMPLEX" in codes(result)
    assert any("evaluation steps" in d.message for d in result.diagnostics)


def test_byte_order_mark_is_not_text(write_tree) -> None:
    """Python itself skips a UTF-8 byte-order mark at the start of a source file."""
    folder = write_tree({"pkg/package.xml": package_xml("pkg"), "pkg/scripts/bom.py": ""})
    (folder / "pkg" / "scripts" / "bom.py").write_bytes(
        b"\xef\xbb\xbfimport rospy\nfrom std_msgs.msg import String\n"
        b"rospy.Publisher('ok', String, queue_size=1)\n")
    result = run(folder, "bom.py")
    assert [c.name for c in result.calls] == ["ok"]
    assert codes(result) == []


def test_a_package_that_imports_its_own_modules_from_itself(write_tree) -> None:
    # mavros' __init__.py: ``from . import system`` (the package is that very module),
    # then ``system.SystemPlugin`` in a class of it: the name is the submodule, found
    # once, not looked up in the package for ever (a RecursionError ended the run)
    folder = write_tree({
        "pkg/package.xml": package_xml("pkg"),
        "pkg/src/pkg/__init__.py": "from . import system\nfrom .system import TOPIC\n\n"
                                   "def topic():\n    return system.TOPIC\n",
        "pkg/src/pkg/system.py": "from . import system\nTOPIC = 'state'\n",
        "pkg/scripts/node.py": "import rospy\nfrom std_msgs.msg import String\n"
                               "import pkg\nfrom pkg import system\n"
                               "rospy.init_node('n')\n"
                               "rospy.Publisher(system.TOPIC, String, queue_size=1)\n"
                               "rospy.Publisher(pkg.topic(), String, queue_size=1)\n",
        "pkg/setup.py": "from setuptools import setup\nsetup(name='pkg', packages=['pkg'],"
                        " package_dir={'': 'src'})\n"})
    result = run(folder, "node.py")
    assert [c.name for c in result.calls if c.kind == "publish"] == ["state", "state"]


def test_an_api_module_of_the_workspace_is_read_by_its_rows(write_tree) -> None:
    # ros_comm holds rospy's own sources (clients/rospy/src/rospy): a script of its
    # topic_tools that calls rospy.ServiceProxy makes a service client, not a call of
    # the class in those sources (the model of topic_tools' mux_add had lost both)
    folder = write_tree({
        "pkg/package.xml": package_xml("pkg"),
        "rospy/package.xml": package_xml("rospy"),
        "rospy/src/rospy/__init__.py": "from .impl import ServiceProxy\n",
        "rospy/src/rospy/impl.py": "class ServiceProxy(object):\n"
                                   "    def __init__(self, name, cls):\n"
                                   "        self.name = name\n",
        "pkg/scripts/add.py": "import rospy\nfrom std_srvs.srv import Empty\n"
                              "rospy.init_node('adder')\n"
                              "rospy.ServiceProxy('mux/add', Empty)\n"})
    result = run(folder, "add.py")
    assert [(c.kind, c.name) for c in result.calls] == [("client", "mux/add")]
