"""``str.format`` with keyword arguments, as Python formats it: ``'/camera/{camera}/rgb'
.format(camera=self.camera)`` (robosub-ros2's depthai streams, a class constant formatted
with a parameter) names ``/camera/?/rgb``, the known parts kept; a template and keywords
all known give the exact text. A field no keyword names when the call also unpacks a
mapping (``**names``) is not known; the rest of the text is. Before, keyword arguments were
dropped and every such name was ``?``."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

NODE = """\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Streams(Node):
    TOPIC = '/camera/{camera}/rgb/compressed'

    def __init__(self, extra):
        super().__init__('streams')
        self.camera = self.declare_parameter('camera', 'front').value
        self.create_publisher(String, self.TOPIC.format(camera=self.camera), 10)
        self.create_publisher(String, '/{robot}/{part}/state'.format(part='arm', robot='r1'), 10)
        self.create_publisher(String, '{0}/{side}'.format('wheels', side='left'), 10)
        self.create_publisher(String, '/{a}/{b}/x'.format(a='known', **extra), 10)
        self.create_publisher(String, 'up/{name}'.format(name='Cam').lower(), 10)


def main():
    rclpy.init()
    rclpy.spin(Streams({}))
"""


def test_format_reads_keyword_arguments(write_tree) -> None:
    folder = write_tree({"pkg/package.xml": package_xml("pkg"),
                         "pkg/pkg/streams.py": NODE})
    result = extract_python([str(folder / "pkg" / "pkg" / "streams.py")],
                            scan([str(folder)]), package="pkg")
    published = [call.name for call in result.calls if call.kind == "publish"]
    assert published == ["/camera/?/rgb/compressed", "/r1/arm/state", "wheels/left",
                         "/known/?/x", "up/cam"]
