"""Python nodes as C++ ones: what follows ``if test: return`` (``continue``, ``break``)
runs under ``else`` test unless that side fails (``raise``, an exit, an error logged,
``return False``), and a ``has_param`` test whose absent side fails makes the parameter
required: the read under it is under no condition of the test."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

NODE = '''
import sys
import rospy
from std_msgs.msg import String


class Relay(object):
    def __init__(self):
        if rospy.has_param("~target"):
            self.target = rospy.get_param("~target")
        else:
            rospy.logfatal("no target")
            sys.exit(1)
        if rospy.has_param("~rate"):
            self.rate = rospy.get_param("~rate")
        else:
            self.rate = 10
        if not rospy.get_param("~enabled", True):
            return
        self.pub = rospy.Publisher("out", String, queue_size=1)

    def check(self):
        if not rospy.has_param("~frame"):
            rospy.logerr("frame required")
            return False
        self.status = rospy.Publisher("status", String, queue_size=1)
        return True


def main():
    rospy.init_node("relay")
    if not rospy.has_param("~ready"):
        print("not ready")
        return 1
    relay = Relay()
    relay.check()
    rospy.spin()
    return 0


if __name__ == "__main__":
    sys.exit(main())
'''


def _calls(tmp_path):
    pkg = tmp_path / "src" / "relay"
    (pkg / "scripts").mkdir(parents=True)
    (pkg / "package.xml").write_text(
        '<?xml version="1.0"?><package format="2"><name>relay</name><version>0.1.0</version>'
        '<description>d</description><maintainer email="a@b.c">m</maintainer>'
        '<license>MIT</license><depend>rospy</depend></package>')
    script = pkg / "scripts" / "relay.py"
    script.write_text(NODE)
    result = extract_python([str(script)], scan([str(tmp_path)]), package="relay")
    return {(c.kind, c.name, c.location.line): [(k.statement, k.text) for k in c.conditions]
            for c in result.calls}


def test_python_early_returns_and_required_parameters(tmp_path):
    calls = _calls(tmp_path)
    lines = NODE.splitlines()

    def line(text: str) -> int:
        return next(i for i, t in enumerate(lines, 1) if text in t)

    # the else aborts: the read is made whenever the node goes on
    assert calls["read", "~target", line('get_param("~target")')] == []
    # a fallback: the read stays under its test
    assert calls["read", "~rate", line('get_param("~rate")')] == [
        ("if", 'rospy.has_param("~rate")')]
    # a plain return: the publisher exists only when enabled
    assert calls["publish", "out", line('"out"')] == [
        ("else", 'not rospy.get_param("~enabled", True)')]
    # a failure (an error logged, False returned; an exit status): the function's work
    # when it succeeds
    assert calls["publish", "status", line('"status"')] == []
    assert calls["publish", "out", line('"out"')] == [
        ("else", 'not rospy.get_param("~enabled", True)')]
