"""The builtin ``setattr(self, name, value)`` with a name known statically is the
assignment ``self.<name> = value``: vortex-auv's joystick interface and LQR velocity
controller read their topic names in a loop over a list, ``setattr(self, param +
'_topic', self.get_parameter(f'topics.{param}').value)``, then create their
subscriptions and publishers on ``self.joy_topic``, ``self.pose_topic``, ... All were
``?`` with no parameter behind them; now each names its parameter, which the graph
fills from the launch file. A ``setattr`` whose name is not known assigns nothing the
walk can name (the attribute it might have set stays as it was: ``?`` here)."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import Workspace

SOURCE = '''\
import rclpy
from rclpy.node import Node
from std_msgs.msg import Bool, String


class Joystick(Node):
    def __init__(self):
        super().__init__('joystick')
        for param in ['joy', 'killswitch', 'los']:
            if param == 'los':
                self.declare_parameter('topics.guidance.' + param, '')
                setattr(self, param + '_topic',
                        self.get_parameter('topics.guidance.' + param).value)
                continue
            self.declare_parameter(f'topics.{param}', '')
            setattr(self, f'{param}_topic', self.get_parameter(f'topics.{param}').value)
        setattr(self, self.get_parameter('topics.joy').value, 'x')
        self.create_subscription(String, self.joy_topic, self.on_joy, 1)
        self.create_subscription(String, self.los_topic, self.on_joy, 1)
        self.create_publisher(Bool, self.killswitch_topic, 1)
        self.create_publisher(Bool, self.unset_topic, 1)

    def on_joy(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Joystick())
'''


def test_setattr_with_a_known_name_assigns_the_attribute(tmp_path) -> None:
    source = tmp_path / "joystick.py"
    source.write_text(SOURCE)
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    named = [(c.kind, c.name, c.name_param) for c in result.calls
             if c.kind in ("subscribe", "publish")]
    assert named == [("subscribe", "?", "topics.joy"),
                     ("subscribe", "?", "topics.guidance.los"),
                     ("publish", "?", "topics.killswitch"),
                     ("publish", "?", None)]
