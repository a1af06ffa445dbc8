"""An attribute of ``self`` that the paths of an ``if`` set differently holds both values
after it, each under its path's condition, as a local does: interbotix_xs_modules' core
writes ``self.robot_name = robot_name``, then ``if self.robot_name is None:
self.robot_name = robot_model``, and names every topic and service after
``self.robot_name``. The walk kept the ``if`` path's value as if it always ran: with the
xslocobot_robot.py script (``--robot_model locobot_wx250s --robot_name locobot``) its
arm's topics were ``/locobot_wx250s/commands/joint_group`` and so on, a name the program
never uses (its robot_name defaults to ``locobot``, never None)."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """import sys
import argparse
import rclpy
from rclpy.node import Node
from std_msgs.msg import String

class Core(Node):
    def __init__(self, mode, robot_model, robot_name=None):
        super().__init__('core')
        self.topic = 'slow_cmd'
        if mode == 'fast':
            self.topic = 'fast_cmd'
        self.pub = self.create_publisher(String, self.topic, 10)
        self.robot_name = robot_name
        if self.robot_name is None:
            self.robot_name = robot_model
        self.group = self.create_publisher(String, f'/{self.robot_name}/commands/group', 10)
        self.same = 'state'
        if mode == 'fast':
            self.same = 'state'
        self.state = self.create_subscription(String, self.same, print, 10)

def main():
    p = argparse.ArgumentParser()
    p.add_argument('--robot_model')
    p.add_argument('--robot_name', default='locobot')
    args = p.parse_args()
    rclpy.init()
    Core(sys.argv[1], robot_model=args.robot_model, robot_name=args.robot_name)
"""


def test_an_attribute_set_on_one_path_of_an_if_holds_both_values(write_tree) -> None:
    root = write_tree({"src/arm/package.xml": package_xml("arm", "ament_python"),
                       "src/arm/arm/core.py": NODE})
    result = extract_python([str(root / "src" / "arm" / "arm" / "core.py")],
                            scan([str(root / "src")], {}), package="arm")
    calls = sorted((c.kind, c.name, c.name_option, tuple(x.statement for x in c.conditions))
                   for c in result.calls if c.kind in ("publish", "subscribe"))
    assert calls == [
        # the name option's value, or the model option's where it is None: not the
        # model's for sure
        ("publish", "/?/commands/group", "--robot_model", ("if",)),
        ("publish", "/?/commands/group", "--robot_name", ("else",)),
        ("publish", "fast_cmd", None, ("if",)), ("publish", "slow_cmd", None, ("else",)),
        # both paths leave it alike: one call, no condition
        ("subscribe", "state", None, ())]
