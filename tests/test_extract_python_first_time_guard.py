"""Python nodes as C++ ones (``ConditionReader._guards_first_time``): ``if
self._initialized: return`` before ``self._initialized = True`` guards what the method
does once, and its first run goes past it: what follows is under no condition of the
test. A test of something the rest does not set, or that the code may first set to a
value of its own, keeps the rest under its ``else``; and
a test of a loop variable whose value the unrolled loop knows is decided there
(``for side in ['left', 'right']: if side == 'skip': continue``), as C++ decides it."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

NODE = '''
import rospy
from std_msgs.msg import String


class Arms(object):
    def __init__(self):
        self._initialized = False
        self._enabled = rospy.get_param("~enabled", True)
        self._matrix = None
        if rospy.has_param("~matrix"):
            self._matrix = rospy.get_param("~matrix")

    def start(self):
        if self._initialized:
            rospy.logwarn("started already")
            return
        self.pub = rospy.Publisher("state", String, queue_size=1)
        self._initialized = True

    def sides(self):
        for side in ["left", "right"]:
            if side == "skip":
                continue
            rospy.Publisher(side + "/cmd", String, queue_size=1)

    def calibrate(self):
        if self._matrix is not None:
            return
        self.tf = rospy.Subscriber("tf", String, self.on_tf)
        self._matrix = [1.0]

    def on_tf(self, msg):
        pass

    def enable(self):
        if not self._enabled:
            return
        self.on = rospy.Publisher("on", String, queue_size=1)


def main():
    rospy.init_node("arms")
    arms = Arms()
    arms.start()
    arms.sides()
    arms.enable()
    arms.calibrate()
    rospy.spin()


if __name__ == "__main__":
    main()
'''


def _calls(tmp_path):
    pkg = tmp_path / "src" / "arms"
    (pkg / "scripts").mkdir(parents=True)
    (pkg / "package.xml").write_text(
        '<?xml version="1.0"?><package format="2"><name>arms</name><version>0.1.0</version>'
        '<description>d</description><maintainer email="a@b.c">m</maintainer>'
        '<license>MIT</license><depend>rospy</depend></package>')
    script = pkg / "scripts" / "arms.py"
    script.write_text(NODE)
    result = extract_python([str(script)], scan([str(tmp_path)]), package="arms")
    return {(c.kind, c.name): [(k.statement, k.text) for k in c.conditions]
            for c in result.calls if c.kind in ("publish", "subscribe")}


def test_a_first_time_guard_makes_no_condition(tmp_path):
    calls = _calls(tmp_path)
    assert calls["publish", "state"] == []
    # a member the rest does not set: the rest is under the test's else
    assert calls["publish", "on"] == [("else", "not self._enabled")]
    # nor a member the code may set to a value of its own (a parameter's) first
    assert calls["subscribe", "tf"] == [("else", "self._matrix is not None")]


def test_a_test_of_an_unrolled_loop_variable_is_decided(tmp_path):
    calls = _calls(tmp_path)
    assert calls["publish", "left/cmd"] == [] and calls["publish", "right/cmd"] == []
