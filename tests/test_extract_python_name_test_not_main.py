"""``if __name__ == "main": main()`` (drone_autonomous_landing_on_ugv cdfdd52: ten
nodes of ros2_px4_control, ros2_px4_estimation and ros2_px4_swarming, each a
console_scripts entry point ``pkg.module:main``). ``__name__`` is ``"__main__"`` when
the file runs as a script and the module's import name (``pkg.module``) when it is
imported, as an entry point's module is before its function is called: never
``"main"`` for a module whose file is not ``main.py``. The test was kept as a condition
not known, and every call of ``main`` existed "only under if (__name__ == "main")"
(101 conditional-communication infos); the test is false, so the block never runs, and
``main``, which the entry point calls, makes its calls unconditionally. A module named
``main`` may be the one imported as ``main``: its test stays undecided."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

NODE = '''import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Controller(Node):
    def __init__(self):
        super().__init__("controller")
        self.pub = self.create_publisher(String, "command", 10)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Controller())


if __name__ == "main":
    main()
'''

SCRIPT_ONLY = '''import rclpy
from rclpy.node import Node
from std_msgs.msg import String

if __name__ != "main":
    rclpy.init()
    node = Node("talker")
    node.create_publisher(String, "chatter", 10)
'''


def _calls(tmp_path, files):
    pkg = tmp_path / "src" / "ctl"
    (pkg / "ctl").mkdir(parents=True)
    (pkg / "package.xml").write_text(
        '<?xml version="1.0"?><package format="2"><name>ctl</name><version>0.1.0</version>'
        '<description>d</description><maintainer email="a@b.c">m</maintainer>'
        '<license>MIT</license><depend>rclpy</depend>'
        '<export><build_type>ament_python</build_type></export></package>')
    paths = []
    for name, text in files.items():
        (pkg / "ctl" / name).write_text(text)
        paths.append(str(pkg / "ctl" / name))
    result = extract_python(paths, scan([str(tmp_path)]), package="ctl")
    return {(c.kind, c.name): [(k.statement, k.text) for k in c.conditions]
            for c in result.calls}


def test_a_name_test_no_module_name_matches_is_false(tmp_path):
    assert _calls(tmp_path, {"controller.py": NODE}) == {("publish", "command"): []}


def test_its_negation_is_true(tmp_path):
    assert _calls(tmp_path, {"talker.py": SCRIPT_ONLY}) == {("publish", "chatter"): []}


def test_a_module_named_main_keeps_the_test(tmp_path):
    calls = _calls(tmp_path, {"main.py": NODE})
    assert calls == {("publish", "command"): [("if", '__name__ == "main"')]}
