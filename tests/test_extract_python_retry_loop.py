"""``loaded = False`` then ``while not loaded:``: a loop whose test holds when the code
reaches it, over locals of known value, runs its first turn whenever it is reached, so
what that turn makes is under no condition of the loop (rosbridge_suite's rosbridge_tcp
builds its node, which declares every parameter, in such a retry loop: its parameters'
type mismatches against the launch file were undecided, "exists only under while (not
loaded)"). A test not known at entry, or false there, keeps the loop as a condition."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

NODE = """\
import rospy
from std_msgs.msg import String


def connect():
    return rospy.get_param('~connect', True)


def main():
    rospy.init_node('bridge')
    loaded = False
    tries = 0
    while not loaded and tries < 3:
        rospy.Publisher('status', String, queue_size=1)
        loaded = True
    done = connect()
    while not done:
        rospy.Subscriber('retry', String, None)
        done = True
    quiet = True
    while not quiet:
        rospy.Publisher('never', String, queue_size=1)


main()
"""


def test_the_first_turn_of_a_loop_entered_for_certain_is_no_condition(write_tree) -> None:
    folder = write_tree({"pkg/package.xml": package_xml("pkg"),
                         "pkg/scripts/bridge.py": NODE})
    result = extract_python([str(folder / "pkg" / "scripts" / "bridge.py")],
                            scan([str(folder)]), package="pkg")
    loops = {call.name: [c.text for c in call.conditions if c.statement == "while"]
             for call in result.calls}
    assert loops["status"] == [], loops
    assert loops["retry"] == ["not done"], loops  # its test not known at entry
    assert loops["never"] == ["not quiet"], loops  # false at entry: kept as written
