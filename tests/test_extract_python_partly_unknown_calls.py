"""A call site of the node's own wrapper reached from several callers keeps every name
they give it: one partly unknown (``get_param("zeros/" + joint_name)``, joint_state_publisher's
read of ``~zeros/<joint>``) is a read of its own, not a copy of a known one. Only a '?'
name that a known name of the same site fits (the wrapper's body read with its argument
unbound) is dropped as that one."""

from __future__ import annotations

from haros_arch.extract.python import PythonResult, extract_python
from haros_arch.workspace import Workspace

WRAPPER = (
    "import rospy\n"
    "def get_param(name, value=None):\n"
    "    private = '~%s' % name\n"
    "    if rospy.has_param(private):\n"
    "        return rospy.get_param(private)\n"
    "    return value\n"
)


def run(tmp_path, text: str) -> PythonResult:
    source = tmp_path / "node.py"
    source.write_text(text)
    return extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")


def test_a_partly_unknown_name_beside_known_ones_is_kept(tmp_path) -> None:
    result = run(tmp_path, WRAPPER + (
        "class Publisher(object):\n"
        "    def __init__(self):\n"
        "        self.rate = get_param('rate', 10)\n"
        "        self.init_urdf(rospy.get_param('robot_description'))\n"
        "    def init_urdf(self, robot):\n"
        "        for child in robot.childNodes:\n"
        "            name = child.getAttribute('name')\n"
        "            zero = get_param('zeros/' + name)\n"
        "rospy.init_node('jsp')\n"
        "Publisher()\n"))
    reads = {c.name for c in result.calls if c.kind == "read" and c.location.line == 5}
    assert reads == {"~rate", "~zeros/?"}


def test_an_unknown_name_a_known_one_fits_is_that_one(tmp_path) -> None:
    """The wrapper reached from a callback with a name not known (``~?``) beside the same
    site reached with ``rate``: ``~?`` may be ``~rate``, so one read, ``~rate``, as before."""
    result = run(tmp_path, WRAPPER + (
        "from std_msgs.msg import String\n"
        "def on_msg(msg):\n    get_param(msg.data)\n"
        "rospy.init_node('n')\n"
        "rospy.Subscriber('t', String, on_msg)\n"
        "rate = get_param('rate', 10)\n"))
    reads = {c.name for c in result.calls if c.kind == "read" and c.location.line == 5}
    assert reads == {"~rate"}
