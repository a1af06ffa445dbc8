"""A class of another module that the node builds runs its constructor and the methods
the node's code may call: those whose name the code uses (``rs.enable()``, a callback
``self._state_cb``, ``getattr(x, "reset")``), special ones, and every method of a class
with a base the walk cannot read (whose code may call any). intera_interface's
``RobotEnable``: its ``enable()`` / ``reset()`` / ``stop()`` make the publishers of
``robot/set_super_*``, and the joint trajectory action server builds one only to read
``state()``: it never publishes there (6 false multiple-publishers in intera_sdk)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

LIBRARY = (
    "import threading\n"
    "import rospy\n"
    "from std_msgs.msg import Bool, Empty\n"
    "class RobotEnable(object):\n"
    "    def __init__(self):\n"
    "        self._sub = rospy.Subscriber('robot/state', Bool, self._state_cb)\n"
    "    def _state_cb(self, msg):\n"
    "        self._pub_seen = rospy.Publisher('robot/seen', Empty, queue_size=1)\n"
    "    def state(self):\n"
    "        return None\n"
    "    def enable(self):\n"
    "        self.reset()\n"
    "        rospy.Publisher('robot/set_super_enable', Bool, queue_size=10)\n"
    "    def reset(self):\n"
    "        rospy.Publisher('robot/set_super_reset', Empty, queue_size=10)\n"
    "    def stop(self):\n"
    "        rospy.Publisher('robot/set_super_stop', Empty, queue_size=10)\n"
    "class Worker(threading.Thread):\n"
    "    def __init__(self):\n"
    "        threading.Thread.__init__(self)\n"
    "    def run(self):\n"
    "        rospy.Publisher('work', Empty, queue_size=1)\n"
)
TREE = {
    "src/arm/package.xml": package_xml("arm"),
    "src/arm/src/arm/__init__.py": "from .robot_enable import RobotEnable, Worker\n",
    "src/arm/src/arm/robot_enable.py": LIBRARY,
    "src/arm/scripts/server.py": (
        "import rospy\n"
        "import arm\n"
        "rospy.init_node('server')\n"
        "rs = arm.RobotEnable()\n"
        "if rs.state():\n"
        "    pass\n"
        "arm.Worker().start()\n"),
    "src/arm/scripts/client.py": (
        "import rospy\n"
        "import arm\n"
        "rospy.init_node('client')\n"
        "rs = arm.RobotEnable()\n"
        "handler = getattr(rs, 'stop')\n"
        "def main(robot):\n"
        "    robot.enable()\n"),
}


def names(root, script: str) -> list[str]:
    ws = scan([str(root / "src")], {})
    result = extract_python([str(root / "src" / "arm" / "scripts" / script)], ws,
                            package="arm")
    return sorted(c.name for c in result.calls)


def test_only_the_methods_the_code_names_run(write_tree) -> None:
    root = write_tree(TREE)
    assert names(root, "server.py") == ["robot/seen", "robot/state", "work"]
    assert names(root, "client.py") == [
        "robot/seen", "robot/set_super_enable", "robot/set_super_reset",
        "robot/set_super_stop", "robot/state"]
