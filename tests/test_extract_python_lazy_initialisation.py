"""``if self.pub is None: self.pub = rospy.Publisher(...)`` with ``self.pub = None`` the
member's only other value is a lazy initialisation: its block runs the first time the
code reaches it, so the publisher is made there, under the conditions around the ``if``
and not under ``self.pub is None`` (ethzasl_xsens_driver's mtnode.py makes its eleven
publishers so, each read as a conditional-communication). A member another value may
fill first (a parameter, an argument: interbotix's ``if self.robot_name is None``)
keeps its test."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

NODE = """\
import rospy
from std_msgs.msg import String


class Driver(object):
    def __init__(self, name=None):
        self.imu_pub = None
        self.ready = False
        self.name = name
        self.debug_pub = None
        self.enabled = rospy.get_param('~enabled', True)

    def spin_once(self):
        if self.enabled:
            if self.imu_pub is None:
                self.imu_pub = rospy.Publisher('imu/data', String, queue_size=10)
            self.imu_pub.publish(String())
        if not self.ready:
            rospy.Subscriber('reset', String, self.reset)
            self.ready = True
        if self.name is None:
            self.name = 'driver'
            rospy.Publisher('named', String, queue_size=1)
        if self.debug_pub is None:
            self.debug_pub = rospy.Publisher('debug', String, queue_size=1)
        else:
            rospy.logdebug('again')

    def reset(self, msg):
        self.debug_pub = 'x'


def main():
    rospy.init_node('driver')
    driver = Driver()
    while not rospy.is_shutdown():
        driver.spin_once()


main()
"""


def test_a_lazy_initialisation_is_no_condition(write_tree) -> None:
    folder = write_tree({"pkg/package.xml": package_xml("pkg"),
                         "pkg/scripts/driver.py": NODE})
    result = extract_python([str(folder / "pkg" / "scripts" / "driver.py")],
                            scan([str(folder)]), package="pkg")
    conditions = {call.name: [c.text for c in call.conditions if c.statement == "if"]
                  for call in result.calls}
    assert conditions == {
        "~enabled": [],
        "imu/data": ["self.enabled"],  # the enclosing test stays, not the lazy one
        "reset": [],  # ``not self.ready``, set True in the block
        # a member an argument may fill first; and a test with an else, whose member
        # another method sets otherwise: conditions kept
        "named": ["self.name is None"],
        "debug": ["self.debug_pub is None"],
    }
