"""A Python parameter whose value is a list is typed as the array of its elements, as
C++'s ``std::vector<T>`` is ``T[]`` and as rclpy types it (``Parameter.Type
.from_parameter_value``): ``declare_parameter('gains', [1.0, 2.0])`` is ``double[]``, a
``Parameter.Type.STRING_ARRAY`` declaration ``str[]``. It was ``list``, which
parameter-type-mismatch takes as any array, so a launch file's ``str[]`` for a node that
declares ``double[]`` was never compared."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import Workspace


def _types(tmp_path, body: str) -> list[tuple[str, str | None]]:
    source = tmp_path / "node.py"
    source.write_text(
        "import rclpy\nfrom rclpy.node import Node\nfrom rclpy.parameter import Parameter\n"
        "class N(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('n')\n" + body)
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    return [(c.name, c.type) for c in result.calls if c.kind == "declare"]


def test_a_list_default_is_the_array_of_its_elements(tmp_path):
    got = _types(tmp_path,
                 "        self.declare_parameter('gains', [1.0, 2.0])\n"
                 "        self.declare_parameter('ids', [1, 2])\n"
                 "        self.declare_parameter('frames', ['a', 'b'])\n"
                 "        self.declare_parameter('flags', [True, False])\n"
                 "        self.declare_parameter('empty', [])\n"
                 "        self.declare_parameter('mixed', [1, 'a'])\n")
    assert got == [("gains", "double[]"), ("ids", "int[]"), ("frames", "str[]"),
                   ("flags", "bool[]"), ("empty", "list"), ("mixed", "list")]


def test_a_declared_array_type_is_that_array(tmp_path):
    got = _types(tmp_path,
                 "        self.declare_parameter('a', Parameter.Type.STRING_ARRAY)\n"
                 "        self.declare_parameter('b', Parameter.Type.DOUBLE_ARRAY)\n"
                 "        self.declare_parameter('c', Parameter.Type.INTEGER_ARRAY)\n"
                 "        self.declare_parameter('d', Parameter.Type.BOOL_ARRAY)\n"
                 "        self.declare_parameter('e', Parameter.Type.BYTE_ARRAY)\n")
    assert got == [("a", "str[]"), ("b", "double[]"), ("c", "int[]"), ("d", "bool[]"),
                   ("e", "byte[]")]


def test_rospy_list_default_is_typed_too(tmp_path):
    source = tmp_path / "node.py"
    source.write_text("import rospy\nrospy.init_node('n')\n"
                      "v = rospy.get_param('~v', [0.1, 0.2])\n")
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    assert [(c.name, c.type) for c in result.calls] == [("~v", "double[]")]
