"""Strings built from partly known values (``evaluate.partial``), as the Python launch-file
reader and the Python node reader use them: one implementation of ``format``, ``%`` and
``join`` over values some parts of which are not known, and the launch reader's operations
on known values through the one evaluator."""

from __future__ import annotations

import pytest
from conftest import package_xml
from test_launch_ros2_python import run as run_launch

from haros_arch.evaluate import budget, partial
from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan


def _text(value: object) -> str:
    return f"<{value}>"


def _unknown(reason: str) -> str:
    return "?"


@pytest.mark.parametrize(("template", "args", "kwargs", "expected"), [
    ("{}/{}", ["a", "b"], {}, "<a>/<b>"),
    ("{{x}}/{0}", ["a"], {}, "{x}/<a>"),
    ("{name}-{1}", ["a", "b"], {"name": "n"}, "<n>-<b>"),
    ("{0:>10}/{0!r}/{0!s}", ["a"], {}, "?/?/<a>"),  # a spec or repr of a partial value
    ("{0.real}/{0[1]}/{5}", ["a"], {}, "?/?/?"),  # no attribute, no index, no argument
    ("{", ["a"], {}, "?"),  # str.format raises: nothing known
    # ``:s`` formats a string as it is (duckietown's ``'{:s}/{:s}'.format(ns, name)``)
    ("{:s}/{0:s}/{0!s:s}/{0:10s}", ["a"], {}, "<a>/<a>/<a>/?"),
])
def test_format_parts(template, args, kwargs, expected) -> None:
    assert "".join(partial.format_parts(template, args, kwargs, _text, _unknown)) == expected


@pytest.mark.parametrize(("template", "values", "expected"), [
    ("%s/%d%%", ("a", 1), "<a>/<1>%"),
    ("%s", "a", "<a>"),
    ("%05d/%.2f/%(k)s/%*d", (1, 2.0, 3, 4), "?/?/?/?"),  # padding not known statically
    ("%s %s", ("a",), "<a> ?"),
])
def test_percent_parts(template, values, expected) -> None:
    assert "".join(partial.percent_parts(template, values, _text, _unknown)) == expected


def test_parts_are_bounded_before_they_are_made() -> None:
    big = "x" * 1000
    with pytest.raises(budget.OverBudget):
        partial.format_parts("{0}" * 2000, [big], {}, _text, _unknown)
    with pytest.raises(budget.OverBudget):
        partial.join_parts(big, [big] * 2000, _text)
    assert partial.join_parts(",", ["a", "b"], _text) == ["<a>", ",", "<b>"]


# -- the Python launch-file reader --------------------------------------------------------
def _param(model, name: str) -> object:
    return next(p.value for p in model.params if p.name.endswith(name))


def test_launch_format_with_a_substitution_keeps_escaped_braces(write_tree) -> None:
    model, _ = run_launch(write_tree, """
def generate_launch_description():
    ns = LaunchConfiguration('ns')
    return LaunchDescription([
        Node(package='p', executable='e', name='n', parameters=[{
            'pattern': '{{x}}/{}'.format(ns)}])])
""", args={"ns": "robot"})
    assert _param(model, "pattern") == "{x}/robot"


def test_launch_unary_operators_and_subscripts_are_python_s(write_tree) -> None:
    model, _ = run_launch(write_tree, """
def generate_launch_description():
    return LaunchDescription([
        Node(package='p', executable='e', name=f'n{~5}', parameters=[{'s': 'abc'[::0]}])])
""")
    assert [n.name for n in model.nodes] == ["/n-6"]  # ~5 is -6 (it was 5)
    assert any(d.code == "LAUNCH_PY_UNSUPPORTED" and "[::0]" in d.message
               for d in model.diagnostics)  # slice step 0: ValueError, reported


# -- the Python node reader ---------------------------------------------------------------
def _names(write_tree, body: str) -> list[str]:
    folder = write_tree({"pkg/package.xml": package_xml("pkg"),
                         "pkg/scripts/node.py": "import rospy\nfrom std_msgs.msg import String\n"
                                                + body})
    ws = scan([str(folder)])
    found = extract_python([str(folder / "pkg" / "scripts" / "node.py")], ws, package="pkg")
    return [c.name for c in found.calls if c.kind == "publish"]


def test_node_reader_percent_is_exact_when_known(write_tree) -> None:
    names = _names(write_tree, """
rospy.Publisher('/out_%03d' % 5, String, queue_size=1)
rospy.Publisher('/val_%.1f' % 2.25, String, queue_size=1)
rospy.Publisher('/%s/x_%d' % (rospy.get_namespace(), 3), String, queue_size=1)
""")
    assert names == ["/out_005", "/val_2.2", "/?/x_3"]  # were /out_5, /val_2.25


def test_node_reader_format_is_python_s(write_tree) -> None:
    names = _names(write_tree, """
rospy.Publisher('/{}/{{x}}'.format(rospy.get_param('~p')), String, queue_size=1)
rospy.Publisher('/{}/a}'.format(rospy.get_param('~p')), String, queue_size=1)
rospy.Publisher('/'.join(['', rospy.get_param('~p'), 'y']), String, queue_size=1)
""")
    assert names == ["/?/{x}", "?", "/?/y"]  # a lone } raises in Python: was /?/a}


# -- one walk: the launch reader and the one evaluator agree on what only computes ---------
AGREED = ["~5", "-True", "not []", "1 < 2 < 3", "1 < 3 < 2", "'abcdef'[1:5:2]",
          "'abcdef'[::-1]", "[x * 2 for x in [0, 1, 2, 3] if x % 2]",
          "[a + b for a in 'xy' for b in 'z']", "'yes' if 1 > 2 else 'no'",
          "[i for i, j in [(1, 2), (3, 4)] if j > 2]", "0 or 'a'", "1 and []",
          "[] or 2 and 3"]


def test_launch_reader_computes_as_the_one_evaluator(write_tree) -> None:
    from haros_arch.evaluate.python import evaluate

    body = ", ".join(f"'p{i}': {text}" for i, text in enumerate(AGREED))
    model, _ = run_launch(write_tree, f"""
def generate_launch_description():
    return LaunchDescription([Node(package='p', executable='e', name='n',
                                   parameters=[{{{body}}}])])
""")
    for i, text in enumerate(AGREED):
        assert _param(model, f"/p{i}") == evaluate(text), text
