"""Survey C's cases of loops a node's walk unrolls. ethzasl_xsens_driver (8abe90f) reads
its device through ``waitfor``, ``for _ in range(100): buf.extend(self.device.read(size
- len(buf)))``, which every message read calls, in methods that retry ``for _ in
range(n_resend)``: each call walked the loop a hundred times, the node's walk ran out of
evaluation steps (PY_TOO_COMPLEX in mtdevice.py) and its publishers and parameter reads
past that point were lost. main's c63cb12d walks a loop of code that cannot reach a ROS
call once (this survey's own rule, dropped in favour of it, walked once any loop whose
body reads neither its variable nor a counter); these cases hold with it: the retries
do not exhaust the walk, a counter (``i += 1``) still names each turn's publisher, and a
container a loop fills is not taken for one turn's."""

from __future__ import annotations

from haros_arch.extract.python import PythonResult, extract_python
from haros_arch.workspace import Workspace

HEAD = ("import rospy\nfrom std_msgs.msg import String\n"
        "class Device(object):\n"
        "    def __init__(self):\n"
        "        self.port = None\n"
        "    def waitfor(self, size=1):\n"
        "        buf = bytearray()\n"
        "        for _ in range(30):\n"
        "            buf.extend(self.port.read(size - len(buf)))\n"
        "            if len(buf) == size:\n"
        "                return buf\n"
        "        raise IOError('timeout')\n"
        "    def read_msg(self):\n"
        "        for _ in range(30):\n"
        "            a = self.waitfor()\n"
        "            b = self.waitfor(2)\n"
        "            c = self.waitfor(a[0])\n"
        "        return c\n"
        "    def configure(self):\n"
        "        for _ in range(250):\n"
        "            self.read_msg()\n"
        "            self.read_msg()\n")


def run(tmp_path, body: str) -> PythonResult:
    source = tmp_path / "node.py"
    source.write_text(HEAD + body)
    return extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")


def test_retries_of_a_helper_do_not_exhaust_the_walk(tmp_path) -> None:
    result = run(tmp_path,
                 "rospy.init_node('imu')\n"
                 "device = Device()\n"
                 "device.configure()\n"
                 "device.configure()\n"
                 "pub = rospy.Publisher('imu/data', String, queue_size=10)\n"
                 "frame = rospy.get_param('~frame_id', 'imu')\n")
    assert [d.code for d in result.diagnostics] == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("publish", "imu/data"), ("read", "~frame_id")]


def test_a_counter_still_names_each_turn(tmp_path) -> None:
    result = run(tmp_path,
                 "rospy.init_node('imu')\n"
                 "i = 0\n"
                 "for _ in range(3):\n"
                 "    i += 1\n"
                 "    rospy.Publisher('imu%d' % i, String, queue_size=10)\n")
    assert [c.name for c in result.calls] == ["imu1", "imu2", "imu3"]


def test_a_container_the_body_fills_is_unknown_after_one_walk(tmp_path) -> None:
    result = run(tmp_path,
                 "rospy.init_node('imu')\n"
                 "names = []\n"
                 "for _ in range(3):\n"
                 "    names.append('imu%d' % len(names))\n"
                 "for name in names:\n"
                 "    rospy.Publisher(name, String, queue_size=10)\n")
    assert [c.name for c in result.calls] != ["imu0"]


# quadruped_ctrl (6e1093c)'s walking_simulation.py resets its robot with ``for _ in
# range(200): self.run()``, and ``run`` steps the simulation, publishing: a function
# that reaches ROS calls, so the loop was unrolled 200 times, which exhausted the walk
# (PY_TOO_COMPLEX) before the node's later subscription
SIMULATOR = """import rospy
from sensor_msgs.msg import JointState
class Simulator(object):
    def __init__(self):
        rospy.init_node('simulator')
        self.pub = rospy.Publisher('joint_states', JointState, queue_size=1)
        self.reset()
        self.sub = rospy.Subscriber('cmd', JointState, self.command)
    def reset(self):
        for _ in range(200):
            self.run()
    def run(self):
        while not rospy.is_shutdown():
            self.step()
    def step(self):
        msg = JointState()
        for j in range(12):
            msg.position.append(self.read(j))
            msg.velocity.append(self.read(j + 12))
        self.pub.publish(msg)
    def read(self, j):
        total = rospy.get_param('~gain', 1.0)
        for k in range(8):
            total += j * k * self.scale(k)
        return total
    def scale(self, k):
        if rospy.has_param('~scale_%d' % k):
            return rospy.get_param('~scale_%d' % k)
        return 1.0
    def command(self, msg):
        pass
Simulator()
"""


def test_a_loop_that_stores_nothing_stops_when_its_turns_repeat(tmp_path) -> None:
    source = tmp_path / "simulator.py"
    source.write_text(SIMULATOR)
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    assert [d.code for d in result.diagnostics] == []
    calls = {(c.kind, c.name) for c in result.calls}
    assert {("publish", "joint_states"), ("subscribe", "cmd"), ("read", "~gain"),
            ("read", "~scale_0"), ("read", "~scale_7")} <= calls


def test_a_counter_a_called_method_advances_still_names_each_turn(tmp_path) -> None:
    """The loop stores nothing itself, but each turn's call names another topic: the
    turns differ, so each is walked."""
    result = run(tmp_path,
                 "class Bank(object):\n"
                 "    def __init__(self):\n"
                 "        self.count = 0\n"
                 "    def add(self):\n"
                 "        self.count += 1\n"
                 "        rospy.Publisher('imu%d' % self.count, String, queue_size=10)\n"
                 "rospy.init_node('imu')\n"
                 "bank = Bank()\n"
                 "for _ in range(3):\n"
                 "    bank.add()\n")
    assert [c.name for c in result.calls if c.kind == "publish"] == ["imu1", "imu2", "imu3"]
