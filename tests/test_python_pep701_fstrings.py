"""Python 3.12's f-strings (PEP 701) read with an older interpreter: kyubic_ros (Jazzy)
writes a single-quoted f-string whose replacement field runs over several lines
(``self.get_logger().info(f'... {\\n len(sats)} ...')``, gnss_driver.py, the dashboard,
trdi_toolz); the 3.11 parser refused the whole file (a PY_PARSE_ERROR error, each node
partial, its publishers lost). Such an f-string, and one holding a string in its own
quotes (``f"{d["key"]}"``), is now read as the triple-quoted string it equals, with the
columns of the file's own lines. A string with escapes in a field (nova's terminal
colours) is read with the characters they stand for; one whose escape is a line break
(``{'\\n'.join(...)}``) still fails."""

from __future__ import annotations

import ast
from pathlib import Path

from conftest import package_xml

from haros_arch.evaluate import syntax
from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

NODE = '''import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Gnss(Node):
    def __init__(self):
        super().__init__('gnss')
        sats = {"gps": [1, 2]}
        self.get_logger().info(f'satellites ({len(sats["gps"])}): {
            ", ".join(str(s) for s in sats["gps"])}')
        topic = f"fix/{sats["gps"][0]}"
        self.pub = self.create_publisher(String, topic, 10)
        self.sub = self.create_subscription(String, 'rtcm', self.on_rtcm, 10)

    def on_rtcm(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Gnss())
'''


def run(folder: Path):
    ws = scan([str(folder)])
    return extract_python([str(folder / "pkg" / "scripts" / "gnss.py")], ws, package="pkg")


def test_a_jazzy_node_with_nested_f_strings_is_read(write_tree) -> None:
    folder = write_tree({"pkg/package.xml": package_xml("pkg", "ament_python"),
                         "pkg/scripts/gnss.py": NODE})
    result = run(folder)
    assert [d.code for d in result.diagnostics if d.code == "PY_PARSE_ERROR"] == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("publish", "fix/1"), ("subscribe", "rtcm")]
    subscribe = result.calls[1]
    assert (subscribe.location.line, subscribe.location.column) == (14, 20)


def test_columns_are_those_of_the_file() -> None:
    text = 'd = {"k": 1}\ns = f"v={d["k"]}" + f"{d["k"]}"; t = len(d)\n'
    tree = syntax.parse(text)
    second = tree.body[1]
    names = [n for n in ast.walk(second) if isinstance(n, ast.Name) and n.id == "d"]
    assert sorted(n.col_offset for n in names) == [9, 23]
    # after both rewritten strings on the line: four quotes less each
    call = next(n for n in ast.walk(tree.body[2]) if isinstance(n, ast.Call))
    assert (call.col_offset, call.end_col_offset) == (37, 43)


def test_a_backslash_in_a_field_is_still_an_error(write_tree) -> None:
    text = "import rclpy\nx = f'{\"\\n\".join(\n  [\"a\"])}'\n"
    folder = write_tree({"pkg/package.xml": package_xml("pkg", "ament_python"),
                         "pkg/scripts/gnss.py": text})
    assert [d.code for d in run(folder).diagnostics] == ["PY_PARSE_ERROR"]


COLOURED = '''import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Controller(Node):
    def __init__(self):
        super().__init__('controller')
        self.get_logger().info(f"{'\\033[1;32m'}{self.get_name()} started{'\\x1b[0m'}")
        tab = f"{'\\t'.join(['a', 'b'])}"
        self.pub = self.create_publisher(String, f"{'\\u0073tatus'}", 10)
        self.sub = self.create_subscription(String, 'command', self.on_command, 10)

    def on_command(self, msg):
        pass
'''


def test_escapes_in_a_field_are_read_as_the_characters_they_stand_for(write_tree) -> None:
    # nova's python_control2 (Jazzy): a terminal colour written as a string with an
    # escape in a field; the whole file was a PY_PARSE_ERROR, and every node of the
    # workspace that imports it partial
    folder = write_tree({"pkg/package.xml": package_xml("pkg", "ament_python"),
                         "pkg/scripts/gnss.py": COLOURED})
    result = run(folder)
    assert [d.code for d in result.diagnostics if d.code == "PY_PARSE_ERROR"] == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("publish", "status"), ("subscribe", "command")]
    subscribe = result.calls[1]
    assert (subscribe.location.line, subscribe.location.column) == (12, 20)


def test_a_field_escape_keeps_its_value_and_the_columns() -> None:
    text = "a = f\"{'\\033[0m'}\"; b = f'{\"\\x41\\t\"!r:>6}'; c = 1\n"
    tree = syntax.parse(text)
    assert ast.literal_eval(tree.body[0].value.values[0].value) == "\x1b[0m"
    assert tree.body[1].value.values[0].value.value == "A\t"
    assert tree.body[2].col_offset == text.index("c = 1")
