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
