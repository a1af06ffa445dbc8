"""Python 2 repairs seen on real nodes (survey T): strands_navigation's monitored_nav.py
has ``except (ImportError, AttributeError, ValueError), e:`` (a tuple of exception
types before the comma), and naoqi_bridge's generate_urdf.py a float ``2e-06`` whose
exponent the octal repair turned into ``2e-0o6``. Both files stayed PY_PARSE_ERROR
(an error) and their nodes PY_NODE_PARTIAL with no call."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

NODE = (
    "#!/usr/bin/env python\n"
    "import rospy\n"
    "from std_msgs.msg import String\n"
    "\n"
    "def load():\n"
    "    try:\n"
    "        import yaml\n"
    "    except (ImportError, AttributeError), e:\n"
    "        print 'no yaml', e\n"
    "    eps = [1.1e-9, 2e-06, 3.E+07, 010]\n"
    "    return eps\n"
    "\n"
    "rospy.init_node('repaired')\n"
    "pub = rospy.Publisher('out', String, queue_size=3)\n"
)


def test_python2_tuple_except_and_float_exponent_are_repaired(write_tree) -> None:
    folder = write_tree({"pkg/package.xml": package_xml("pkg"),
                         "pkg/node.py": NODE})
    result = extract_python([str(folder / "pkg" / "node.py")],
                            scan([str(folder)]), package="pkg")
    assert [d.code for d in result.diagnostics] == ["PY_PYTHON2"]
    assert result.rosname == "repaired"
    assert [(c.kind, c.name, c.queue_size, c.location.line) for c in result.calls] == [
        ("publish", "out", 3, 14)]


def test_float_exponents_keep_their_value() -> None:
    from haros_arch.extract.python.modules import _repair_python2
    assert _repair_python2("x = [2e-06, 1.E+07, 5e07, 0e0, 07]") == \
        "x = [2e-06, 1.E+07, 5e07, 0e0, 0o7]"
