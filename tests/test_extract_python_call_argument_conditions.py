"""A test over a parameter of a function walked at its call is decided when the call
gives it a literal and the function never assigns it: fetch_gazebo 19c5ec4's
fetchit_challenge builds ``SchunkMachineServer(is_simulated=True)``
(schunk_machine_server.py:101), whose ``__init__`` makes the simulated machine's
command publishers ``if is_simulated:`` and the real machine's otherwise. Both were
made, each "conditional", and the infos that count undecided absences named the test.
A parameter the body assigns, one a call gives no literal, and a function walked
without a caller keep their tests."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """import rospy
from std_msgs.msg import String


class Machine(object):
    def __init__(self, is_simulated=True, prefix="lathe"):
        if is_simulated:
            self.pub = rospy.Publisher(prefix + "/sim", String, queue_size=1)
        else:
            self.pub = rospy.Publisher(prefix + "/real", String, queue_size=1)
        if prefix == "door" and not is_simulated:
            self.door = rospy.Publisher("door", String, queue_size=1)


def changed(flag):
    if flag:
        rospy.Publisher("changed_on", String, queue_size=1)
    flag = not flag


def entry(flag=True):
    if flag:
        rospy.Publisher("entry_on", String, queue_size=1)


if __name__ == "__main__":
    rospy.init_node("machine")
    Machine(is_simulated=True)
    Machine(False, "door")
    Machine(is_simulated=rospy.get_param("~simulated", True), prefix="param")
    changed(True)
    rospy.Subscriber("entry", String, entry)
    rospy.spin()
"""


def test_a_literal_argument_decides_the_tests_over_its_parameter(write_tree) -> None:
    root = write_tree({"src/sch/package.xml": package_xml("sch"),
                       "src/sch/scripts/machine.py": NODE})
    result = extract_python([str(root / "src" / "sch" / "scripts" / "machine.py")],
                            scan([str(root / "src")], {}), package="sch")
    calls = sorted((c.name, tuple(f"{x.statement} {x.text}" for x in c.conditions))
                   for c in result.calls if c.kind == "publish")
    assert calls == [
        ("changed_on", ("if flag",)),  # assigned after the test
        ("door", ()), ("door/real", ()),
        ("entry_on", ("if flag",)),  # a callback: walked without a caller
        ("lathe/sim", ()),
        # a parameter's value: the graph decides it
        ("param/real", ("else is_simulated",)), ("param/sim", ("if is_simulated",)),
    ]
