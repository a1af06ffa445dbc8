"""``set_parameters`` of a Parameter the code built earlier and kept in a variable
(rmf_demos' ``param = Parameter('use_sim_time', Parameter.Type.BOOL, True)`` then
``self.set_parameters([param])``): the write names that parameter, not '?'."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import Workspace


def _writes(tmp_path, body: str):
    source = tmp_path / "node.py"
    source.write_text(
        "import rclpy\nfrom rclpy.node import Node\nfrom rclpy.parameter import Parameter\n"
        "class N(Node):\n"
        "    def __init__(self, on):\n"
        "        super().__init__('n')\n" + body)
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    return [(c.name, c.type) for c in result.calls if c.kind == "write"]


def test_a_parameter_kept_in_a_variable(tmp_path) -> None:
    body = ("        if on:\n"
            "            param = Parameter('use_sim_time', Parameter.Type.BOOL, True)\n"
            "            self.set_parameters([param])\n")
    assert _writes(tmp_path, body) == [("use_sim_time", "bool")]


def test_keywords_and_a_mix_with_a_direct_one(tmp_path) -> None:
    body = ("        rate = Parameter(name='rate', value=2.5)\n"
            "        self.set_parameters([rate, Parameter('mode', value='fast')])\n")
    assert _writes(tmp_path, body) == [("rate", "double"), ("mode", "str")]


def test_a_variable_of_unknown_value_stays_unknown(tmp_path) -> None:
    body = "        self.set_parameters([make()])\n"
    assert _writes(tmp_path, body) == [("?", None)]


def test_an_unknown_one_beside_known_ones_is_kept(tmp_path) -> None:
    body = "        self.set_parameters([make(), Parameter('a', value=1)])\n"
    assert _writes(tmp_path, body) == [("?", None), ("a", "int")]
