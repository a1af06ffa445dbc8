"""Two parameters' values next to each other in a Python name: doosan-robot's example
nodes (dsr_example/py/scripts, ab24968e) name their topics ``'/' + ROBOT_ID +
ROBOT_MODEL + '/stop'``, the C++ driver the same names from its ``name`` and ``model``
parameters; here the two are read from parameters, as kortex's ``prefix + arm`` is. The
run of two values is one ``?`` (it was ``/??/stop``), its second parameter a JOINED
``name_more`` entry as the C++ side makes it (test_extract_cpp_param_joined_segment);
the graph fills it with both values joined where the configuration sets both."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Node
from haros_arch.workspace import Workspace, scan
from tests.conftest import package_xml

ROS1 = """#!/usr/bin/env python
import rospy
from std_msgs.msg import String

rospy.init_node('ex')
ROBOT_ID = rospy.get_param('~robot_id', 'dsr01')
ROBOT_MODEL = rospy.get_param('~robot_model')
ARM = rospy.get_param('~arm')
pub_stop = rospy.Publisher('/' + ROBOT_ID + ROBOT_MODEL + '/stop', String, queue_size=10)
pub_state = rospy.Publisher(f'{ROBOT_ID}{ROBOT_MODEL}{ARM}', String, queue_size=10)
pub_two = rospy.Publisher('/%s/%s%s_cmd' % (ROBOT_ID, ROBOT_MODEL, ARM), String,
                          queue_size=10)
rospy.spin()
"""

ROS2 = """import rclpy
from rclpy.node import Node
from std_msgs.msg import String

class Ex(Node):
    def __init__(self):
        super().__init__('ex')
        robot_id = self.declare_parameter('robot_id', 'dsr01').value
        model = self.declare_parameter('robot_model', '').value
        self.pub = self.create_publisher(String, f'/{robot_id}{model}/stop', 10)

def main():
    rclpy.init()
    rclpy.spin(Ex())
"""


def _calls(root, name: str):
    result = extract_python([str(root / "ex" / "scripts" / name)], scan([str(root)]))
    return result, sorted((c.name, c.name_param, c.name_default, c.name_more)
                          for c in result.calls if c.kind == "publish")


def _publishers(calls, given: dict[str, str], version: int = 1) -> list[str]:
    node = Node("ex", "ex", calls=list(calls))
    config = build(Configuration("c"), LaunchModel(
        nodes=[NodeDecl("/ex", "ex", "ex", ros_version=version)],
        params=[ParamDecl(f"/ex/{key}", value, "str") for key, value in given.items()]),
        Workspace(root="/nowhere"), {node.name: node})
    return sorted(link.rosname.full for link in config.links if link.kind == "publish")


def test_two_parameters_next_to_each_other_are_one_unknown(write_tree) -> None:
    root = write_tree({"ex/package.xml": package_xml("ex"), "ex/scripts/ex.py": ROS1})
    result, named = _calls(root, "ex.py")
    assert named == [
        ("/?/?_cmd", "~robot_id", "dsr01", [["~robot_model", None], ["~arm", None, "+"]]),
        ("/?/stop", "~robot_id", "dsr01", [["~robot_model", None, "+"]]),
        ("?", "~robot_id", "dsr01", [["~robot_model", None, "+"], ["~arm", None, "+"]]),
    ]
    calls = result.calls
    assert _publishers(calls, {"robot_id": "dsr01", "robot_model": "m1013", "arm": "a"}
                       ) == ["/dsr01/m1013a_cmd", "/dsr01m1013/stop", "/dsr01m1013a"]
    # the model not set: the runs it is in stay unknown (the id's default alone is not
    # the run's value)
    assert _publishers(calls, {"robot_id": "dsr01", "arm": "a"}) == [
        "/?/stop", "/dsr01/?_cmd", "?"]


def test_ros2_declared_parameters_in_one_segment(write_tree) -> None:
    root = write_tree({"ex/package.xml": package_xml("ex", "ament_python").replace(
        "</package>", "<depend>rclpy</depend></package>"), "ex/scripts/ex.py": ROS2})
    result, named = _calls(root, "ex.py")
    assert named == [("/?/stop", "robot_id", "dsr01", [["robot_model", "", "+"]])]
    assert _publishers(result.calls, {"robot_id": "dsr02", "robot_model": "m0609"},
                       version=2) == ["/dsr02m0609/stop"]
