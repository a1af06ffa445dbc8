"""A Python 2 script whose blocks mix tabs and spaces (ros2/teleop_twist_keyboard's
master, a catkin package: ``    \\tsettings = ...`` then ``\\tpub = rospy.Publisher(...)``
in one block). Python 2 takes a tab to the next multiple of 8 columns, so both lines
are one level; Python 3 raises TabError, and the node was a PY_PARSE_ERROR (an error)
and PY_NODE_PARTIAL with no call at all."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

MIXED = (
    "#!/usr/bin/env python\n"
    "import rospy\n"
    "from geometry_msgs.msg import Twist\n"
    "\n"
    "if __name__==\"__main__\":\n"
    "    \tspeed = 0.5\n"
    "\tpub = rospy.Publisher('cmd_vel', Twist, queue_size = 1)\n"
    "\trospy.init_node('teleop')\n"
    "\tif speed > 0.1 and \\\n"
    "\t\t\tspeed < 2:\n"
    "\t\tfast = rospy.Publisher('fast', Twist,\n"
    "  \t\t\tqueue_size=2)\n"
    "\ttext = '''usage:\n"
    "\t  keys'''\n"
    "\tprint text\n"
)


def test_python2_indentation_mixing_tabs_and_spaces_is_read(write_tree) -> None:
    folder = write_tree({"pkg/package.xml": package_xml("pkg"),
                         "pkg/teleop.py": MIXED})
    result = extract_python([str(folder / "pkg" / "teleop.py")],
                            scan([str(folder)]), package="pkg")
    assert [d.code for d in result.diagnostics] == ["PY_PYTHON2"]
    assert result.rosname == "teleop"
    # columns are the file's own (a tab is one character), as for any other file
    assert [(c.kind, c.name, c.queue_size, c.location.line, c.location.column,
             tuple(k.text for k in c.conditions))
            for c in result.calls if c.kind == "publish"] == [
        ("publish", "cmd_vel", 1, 7, 8, ()),
        ("publish", "fast", 2, 11, 10, ("speed > 0.1 and \\ speed < 2",)),
    ]
