"""Dict literals with known keys (``objects.Record``): an entry read with a known key is
its value, so a loop over a list of such dicts names one call per element (crane_x7's
preset_reconfigure.py: ``joint["control"] + "/" + joint["joint"]``)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

SCRIPT = """\
import rospy
from std_msgs.msg import UInt8


class Presets:
    def __init__(self):
        self.joints = [{"control": "/arm/ctl", "joint": "pan"},
                       {"control": "/arm/ctl", "joint": "tilt"}]
        for joint in self.joints:
            rospy.Publisher(joint["control"] + "/" + joint["joint"], UInt8, queue_size=1)
        rospy.Publisher({"a": "known"}["a"], UInt8, queue_size=1)
        rospy.Publisher({"a": "known"}["b"], UInt8, queue_size=1)
        rospy.Publisher({**{"a": "x"}}["a"], UInt8, queue_size=1)


rospy.init_node("presets")
Presets()
"""


def test_entries_of_dict_literals_name_calls(write_tree) -> None:
    root = write_tree({"pkg/package.xml": package_xml("pkg"), "pkg/scripts/presets.py": SCRIPT})
    result = extract_python([str(root / "pkg" / "scripts" / "presets.py")],
                            scan([str(root)]), package="pkg")
    assert [(c.name, c.location.line) for c in result.calls if c.kind == "publish"] == [
        ("/arm/ctl/pan", 10), ("/arm/ctl/tilt", 10),
        ("known", 11),
        ("?", 12),  # no such key: not known
        ("?", 13),  # a dict built from another: not read
    ]
