"""Python 3.12's type parameter lists (PEP 695) read with an older interpreter:
robosub-ros2's task_planning (Jazzy) declares ``class Task[YieldType, SendType,
ReturnType]:``; the 3.11 parser refused the whole file (a PY_PARSE_ERROR error and the
node partial, its publishers lost). A class's or a function's type parameters are now
blanked (they mean nothing to a ROS call) and a ``type`` statement read as the
assignment it names, every other column in its place."""

from __future__ import annotations

import ast

from conftest import package_xml

from haros_arch.evaluate import syntax
from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

NODE = '''import rclpy
from rclpy.node import Node
from std_msgs.msg import String

type Topics = list[str]
type Pair[T] = tuple[T, T]


class Relay[T, U: int](Node):
    def __init__(self):
        super().__init__('relay')
        self.pub = self.create_publisher(String, first(['status', 'other']), 10)
        self.sub = self.create_subscription(String, 'input', self.on_input, 10)

    def on_input(self, msg):
        pass


def first[
    T,  # what the list holds
](items: list[T]) -> T:
    return items[0]


def main():
    rclpy.init()
    rclpy.spin(Relay())
'''


def test_a_jazzy_node_with_type_parameters_is_read(write_tree) -> None:
    folder = write_tree({"pkg/package.xml": package_xml("pkg", "ament_python"),
                         "pkg/scripts/relay.py": NODE})
    result = extract_python([str(folder / "pkg" / "scripts" / "relay.py")],
                            scan([str(folder)]), package="pkg")
    assert [d.code for d in result.diagnostics if d.code == "PY_PARSE_ERROR"] == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("publish", "status"), ("subscribe", "input")]
    subscribe = result.calls[1]
    assert (subscribe.location.line, subscribe.location.column) == (13, 20)


def test_type_parameters_keep_the_columns_and_the_type_statement_is_an_assignment() -> None:
    tree = syntax.parse(NODE)
    relay = next(n for n in tree.body if isinstance(n, ast.ClassDef))
    assert (relay.name, relay.lineno, [ast.unparse(b) for b in relay.bases]) == (
        "Relay", 9, ["Node"])
    function = next(n for n in tree.body if isinstance(n, ast.FunctionDef) and n.name == "first")
    returned = function.body[0]
    assert (returned.lineno, returned.col_offset) == (22, 4)
    aliases = [ast.unparse(n) for n in tree.body if isinstance(n, ast.Assign)]
    assert aliases == ["Topics = list[str]", "Pair = tuple[T, T]"]


def test_a_file_still_refused_keeps_its_syntax_error() -> None:
    try:
        syntax.parse("class Broken[T](:\n    pass\n")
    except SyntaxError:
        pass
    else:
        raise AssertionError("a class that is no Python parsed")
