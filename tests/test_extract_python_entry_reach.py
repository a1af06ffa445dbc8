"""A Python node's calls come only from code its entry reaches: the module's own
statements, the function a console_scripts entry point names (``pkg.module:main``), the
classes' code, and every module function any of these calls or names as a value.
sailbot23-24's ``*_vf.py`` define ``trigger_error_transition(node)``, a
``?/change_state`` client, that nothing calls: it is no client of the node. A function
named anywhere (a thread's target, a dict of handlers, a string ``getattr`` looks up) or
decorated stays; so does every function when the code looks names up in a way not read
(``globals()[name]``) or when the entry is not known."""

from __future__ import annotations

import textwrap

from conftest import package_xml

from haros_arch.extract import extract_node
from haros_arch.extract.python import extract_python
from haros_arch.pysetup import parse_package
from haros_arch.workspace import scan

SETUP = """
    from setuptools import setup
    setup(name='sail', packages=['sail'],
          entry_points={'console_scripts': ['follower = sail.follower:main']})
    """

HEAD = """
    import threading
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import String
    from lifecycle_msgs.srv import ChangeState


    class Follower(Node):
        def __init__(self):
            super().__init__('follower')
            self.create_publisher(String, 'heading', 10)

        def on_error(self):
            self.create_publisher(String, 'error', 10)


    def trigger_error_transition(node):
        client = node.create_client(ChangeState, node.get_name() + '/change_state')
        helper(node)


    def helper(node):
        node.create_publisher(String, 'helped', 10)


    def worker(node):
        node.create_publisher(String, 'worked', 10)


    def by_name(node):
        node.create_publisher(String, 'named', 10)


    def main(args=None):
        rclpy.init(args=args)
        node = Follower()
    """


def _calls(write_tree, main: str = "", extra: str = "") -> set[tuple[str, str]]:
    root = write_tree({
        "src/sail/package.xml": package_xml("sail", build_type="ament_python"),
        "src/sail/setup.py": SETUP,
        "src/sail/resource/sail": "",
        "src/sail/sail/__init__.py": "",
        "src/sail/sail/follower.py": textwrap.dedent(HEAD) + main + extra,
    })
    workspace = scan([str(root / "src")])
    nodes, said = parse_package(workspace.packages["sail"], workspace)
    assert not said and len(nodes) == 1
    extract_node(nodes[0], workspace)
    return {(c.kind, c.name) for c in nodes[0].calls}


def _clients(calls: set[tuple[str, str]]) -> list[str]:
    return [name for kind, name in calls if kind == "client" and "change_state" in name]


SPIN = "    rclpy.spin(node)\n"


def test_an_entry_point_names_the_function_the_program_starts_in(write_tree):
    root = write_tree({
        "src/sail/package.xml": package_xml("sail", build_type="ament_python"),
        "src/sail/setup.py": SETUP.replace("]}", ", 'whole = sail.whole']}"),
        "src/sail/setup.cfg": "[options.entry_points]\nconsole_scripts =\n"
                              "    cfg = sail.follower:run\n",
        "src/sail/sail/follower.py": "", "src/sail/sail/whole.py": ""})
    workspace = scan([str(root / "src")])
    nodes, _ = parse_package(workspace.packages["sail"], workspace)
    assert {n.executable: n.entry for n in nodes} == {"follower": "main", "whole": "",
                                                      "cfg": "run"}


def test_a_function_nothing_calls_makes_no_call_of_the_node(write_tree):
    calls = _calls(write_tree, SPIN)
    assert calls == {("publish", "heading"), ("publish", "error")}


def test_a_function_the_entry_calls_or_hands_on_makes_its_calls(write_tree):
    calls = _calls(write_tree, "    threading.Thread(target=worker, args=(node,)).start()\n"
                               "    trigger_error_transition(node)\n" + SPIN)
    assert {c for c in calls if c[0] == "publish"} == {
        ("publish", "heading"), ("publish", "error"), ("publish", "worked"),
        ("publish", "helped")}
    assert _clients(calls)


def test_a_function_named_in_a_table_or_a_string_stays(write_tree):
    calls = _calls(write_tree, "    getattr(HANDLERS['x'], 'y', None)\n" + SPIN,
                   "\n\nHANDLERS = {'w': worker}\nCALLED = 'by_name'\n")
    assert ("publish", "worked") in calls and ("publish", "named") in calls
    assert ("publish", "helped") not in calls


def test_a_decorated_function_stays(write_tree):
    calls = _calls(write_tree, SPIN, "\n\n@some.register\ndef hook(node):\n"
                                     "    node.create_publisher(String, 'hooked', 10)\n")
    assert ("publish", "hooked") in calls and ("publish", "helped") not in calls


def test_names_looked_up_at_run_time_keep_every_function(write_tree):
    calls = _calls(write_tree, "    globals()[node.get_name()](node)\n" + SPIN)
    assert _clients(calls)
    assert ("publish", "helped") in calls and ("publish", "worked") in calls


SCRIPT = """import rospy
from std_msgs.msg import String


def unused():
    rospy.Publisher('unused', String, queue_size=1)


def start():
    rospy.Publisher('used', String, queue_size=1)


if __name__ == '__main__':
    rospy.init_node('talker')
    start()
"""


def _script_calls(tmp_path, entry: str | None) -> set[tuple[str, str]]:
    pkg = tmp_path / "src" / "talk"
    (pkg / "scripts").mkdir(parents=True)
    (pkg / "package.xml").write_text(package_xml("talk"))
    (pkg / "scripts" / "talker.py").write_text(SCRIPT)
    result = extract_python([str(pkg / "scripts" / "talker.py")], scan([str(tmp_path)]),
                            package="talk", entry=entry)
    return {(c.kind, c.name) for c in result.calls}


def test_a_script_runs_its_module_whole(tmp_path):
    assert _script_calls(tmp_path, "") == {("publish", "used")}


def test_an_entry_not_known_keeps_every_function(tmp_path):
    assert _script_calls(tmp_path, None) == {("publish", "used"), ("publish", "unused")}
