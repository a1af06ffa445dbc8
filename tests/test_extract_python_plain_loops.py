"""A loop in code that cannot reach a ROS call (``Reach``) is walked once, not once per
item, unless it builds a value that outlives the call (an object's list of topic names,
item by item). ethzasl_xsens_driver's MTDevice probes each baud rate of each port and
reads each message in loops: walked per item, in each call, that device code took the
walk's whole budget (PY_TOO_COMPLEX, about 200 s of processor time) before the node
created its publishers, and the node kept 4 of its 23 calls."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.evaluate.operations import Limits
from haros_arch.extract.python import extract_python, values, visitor
from haros_arch.workspace import scan

DRIVER = """\
import rospy
from std_msgs.msg import String

BAUDS = (115200, 460800, 921600, 230400, 57600, 38400, 19200, 9600)


class Device(object):
    def __init__(self, port, baud):
        self.port = port
        self.baud = baud
        self.ready = False
        for attempt in range(30):
            self.configure(attempt)

    def configure(self, attempt):
        for register in range(30):
            self.write(register, attempt)

    def write(self, register, value):
        checksum = 0
        for bit in range(30):
            checksum = (checksum + register * bit + value) & 0xff
        return checksum


def find_device(port):
    for baud in BAUDS:
        device = Device(port, baud)
        if device.ready:
            return device
    return None


class Driver(object):
    def __init__(self):
        port = rospy.get_param('~port', '/dev/ttyUSB0')
        self.device = find_device(port)
        self.topics = []
        self.add_sensors(['imu', 'gps'])
        self.name_cameras(['left', 'right'])
        self.pubs = [rospy.Publisher(t, String, queue_size=10) for t in self.topics]
        self.cams = [rospy.Publisher(t, String, queue_size=1) for t in self.cameras]
        self.status = rospy.Publisher('status', String, queue_size=1)

    def add_sensors(self, names):
        for name in names:
            self.topics.append(name + '/data')

    def name_cameras(self, sides):
        found = []
        for side in sides:
            found.append(side + '/image')
        self.cameras = found


def main():
    rospy.init_node('driver')
    Driver()
    rospy.spin()


main()
"""


def test_device_loops_leave_the_budget_to_the_node(write_tree, monkeypatch) -> None:
    # (a budget small enough that walking the device code per item exhausts it)
    monkeypatch.setattr(values.Evaluator, "limits", Limits(steps=50_000))
    monkeypatch.setattr(visitor, "MAX_STEPS", 20_000)
    folder = write_tree({"pkg/package.xml": package_xml("pkg"),
                         "pkg/scripts/driver.py": DRIVER})
    result = extract_python([str(folder / "pkg" / "scripts" / "driver.py")],
                            scan([str(folder)]), package="pkg")
    assert [d.code for d in result.diagnostics] == []
    # the helper's list, built item by item, still names one publisher per item
    # lists a helper builds item by item, in the object or in a local it then stores
    # there, still name one publisher per item
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "gps/data"), ("publish", "imu/data"), ("publish", "left/image"),
        ("publish", "right/image"), ("publish", "status"), ("read", "~port")]
