"""A ``try`` that reads a parameter and a handler that sets the same name again: the name
is the parameter's value, the handler's constant its default (the handler runs when the
read fails), not the handler's constant alone."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.python import extract_python
from haros_arch.workspace import Workspace

SOURCE = '''
import rospy
from std_msgs.msg import String


class Controller(object):
    def __init__(self):
        try:
            self._prefix = rospy.get_param("~vehicle_prefix")
            if self._prefix != "":
                self._prefix = "/" + self._prefix
        except:
            rospy.logwarn("no prefix")
            self._prefix = ""
        self.pub = rospy.Publisher(self._prefix + "/wheelSpeeds", String, queue_size=1)


if __name__ == "__main__":
    rospy.init_node("controller")
    try:
        topic = rospy.get_param("~topic")
    except KeyError:
        topic = "chatter"
    out = rospy.Publisher(topic, String, queue_size=1)
    Controller()
    rospy.spin()
'''


def test_a_handler_constant_is_the_parameter_default(tmp_path: Path) -> None:
    """autorally's autorally_controller.py: every car of the multi-car simulation
    published /wheelSpeeds and /chassisState (two false multiple-publishers), as the
    except branch's "" named them; each car's vehicle_prefix names them."""
    source = tmp_path / "n.py"
    source.write_text(SOURCE)
    result = extract_python([str(source)], Workspace(root=str(tmp_path)))
    published = sorted((c.name, c.name_param, c.name_default)
                       for c in result.calls if c.kind == "publish")
    assert published == [("/?/wheelSpeeds", "~vehicle_prefix", None),
                         ("?", "~topic", "chatter")]
