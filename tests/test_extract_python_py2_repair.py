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


TUPLE_PARAMS = (
    "#!/usr/bin/env python\n"
    "import rospy\n"
    "from std_msgs.msg import Float32\n"
    "\n"
    "class Control(object):\n"
    "    def __init__(self, api):\n"
    "        self.api = api\n"
    "        rospy.Subscriber('zoom', Float32, Control._with_data(api.zoom))\n"
    "\n"
    "    @staticmethod\n"
    "    def _with_data(func):\n"
    "        return lambda (msg): func(msg.data)\n"
    "\n"
    "    def best(self, scores):\n"
    "        return max(scores.items(), key=lambda (k, v): v)\n"
    "\n"
    "    def moved(self, (x, y), z=(0, 0)):\n"
    "        return x + y\n"
    "\n"
    "rospy.init_node('ptz')\n"
    "Control(None)\n"
)


def test_python2_tuple_parameters_are_repaired(write_tree) -> None:
    """axis_camera's camera_control.py (``lambda (msg): func(msg.data)``, PEP 3113's
    tuple parameters) was a PY_PARSE_ERROR, so axis_ptz was partial with no call of its
    ``Subscriber``s and every parameter set on it undecided."""
    folder = write_tree({"pkg/package.xml": package_xml("pkg"),
                         "pkg/node.py": TUPLE_PARAMS})
    result = extract_python([str(folder / "pkg" / "node.py")],
                            scan([str(folder)]), package="pkg")
    assert [d.code for d in result.diagnostics] == ["PY_PYTHON2"]
    assert [(c.kind, c.name, c.location.line, c.location.column) for c in result.calls] == [
        ("subscribe", "zoom", 8, 9)]


def test_tuple_parameters_keep_columns_and_leave_other_brackets() -> None:
    from haros_arch.extract.python.modules import _repair_python2
    cases = {
        "f = lambda (msg): g(msg.data)": "f = lambda  msg : g(msg.data)",
        "k = lambda (a, b): b": "k = lambda  a, b : b",
        "def f(self, (x, y), z=(1, 2)):": "def f(self,  x, y , z=(1, 2)):",
        "h = lambda: (1, 2)": "h = lambda: (1, 2)",
        "print_it((1, 2))": "print_it((1, 2))",
    }
    for before, after in cases.items():
        assert _repair_python2(before) == after


def test_an_except_clause_that_unpacks_its_exception() -> None:
    """spencer_diagnostics' ntp_monitor.py (survey Z39) has ``except OSError, (errno,
    msg):``, a Python 2 tuple target: the file stayed PY_PARSE_ERROR and its node
    partial with no call. Python 3 binds one name; the first stands for the tuple."""
    from haros_arch.extract.python.modules import _repair_python2
    cases = {
        "    except OSError, (errno, msg):": "    except OSError as errno:",
        "except (IOError, OSError), ( code , text ):": "except (IOError, OSError) as code:",
        "except OSError, e:": "except OSError as e:",
    }
    for before, after in cases.items():
        assert _repair_python2(before) == after


def test_a_node_whose_except_unpacks_its_exception_is_read(write_tree) -> None:
    node = ("#!/usr/bin/env python\nimport rospy\nfrom std_msgs.msg import String\n"
            "rospy.init_node('ntp')\n"
            "pub = rospy.Publisher('diag', String, queue_size=1)\n"
            "try:\n    pass\nexcept OSError, (errno, msg):\n"
            "    if errno == 4:\n        print 'interrupted'\n")
    folder = write_tree({"pkg/package.xml": package_xml("pkg"), "pkg/ntp.py": node})
    result = extract_python([str(folder / "pkg" / "ntp.py")], scan([str(folder)]),
                            package="pkg")
    assert [d.code for d in result.diagnostics] == ["PY_PYTHON2"]
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "diag")]


# survey R: JUSTINA's ros_pyclips_node.py and mobile base scripts end their print
# statements with a ``;`` (``print "Executing function:" + cmd.name;``); the call's ``)``
# went after it, a syntax error, and six nodes stayed PY_NODE_PARTIAL with no call
SEMICOLON = (
    "#!/usr/bin/env python\n"
    "import rospy\n"
    "from std_msgs.msg import String\n"
    "\n"
    "def callback(data):\n"
    "    print \"heard: \" + data.data;\n"
    "    print 'a;b', data.data; rospy.loginfo('x')  # c; d\n"
    "\n"
    "rospy.init_node('semicolons')\n"
    "rospy.Subscriber('in', String, callback)\n"
)


def test_a_print_statement_ended_by_a_semicolon_is_repaired(write_tree) -> None:
    folder = write_tree({"pkg/package.xml": package_xml("pkg"),
                         "pkg/node.py": SEMICOLON})
    result = extract_python([str(folder / "pkg" / "node.py")],
                            scan([str(folder)]), package="pkg")
    assert [d.code for d in result.diagnostics] == ["PY_PYTHON2"]
    assert result.rosname == "semicolons"
    assert [(c.kind, c.name, c.location.line) for c in result.calls] == [
        ("subscribe", "in", 10)]


def test_the_call_closes_before_the_semicolon_outside_strings_and_brackets() -> None:
    from haros_arch.extract.python.modules import _repair_python2
    assert _repair_python2('    print "a;b" + x; y = 1  # c;d') == \
        '    print("a;b" + x); y = 1  # c;d'
    assert _repair_python2("print f(a, ';');") == "print(f(a, ';'));"
    assert _repair_python2("print a, (b +\n  c);\nz = 1") == "print(a, (b +\n  c));\nz = 1"
