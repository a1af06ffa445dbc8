"""Classes a module defines under a module-level ``if`` on the ROS version, which the
node's process has from the distribution's setup (carla ros-bridge's ros_compatibility:
``ROS_VERSION = get_ros_version()``, ``int(os.environ.get("ROS_VERSION", 0))``, then
``if ROS_VERSION == 1: class CompatibleNode(object)`` with rospy's calls ``elif
ROS_VERSION == 2: class CompatibleNode(Node)`` with rclpy's, its ``Node`` imported in
the ``elif``). Each bridge node derives from ``CompatibleNode``: the class was not
defined for the walk (only imports were read under an ``if``, and not those of an
``elif``), so every node was "complete" with no calls at all. Now the branch the tests
choose defines it, ``os.environ`` gives the distribution's variables (ROS_VERSION,
ROS_DISTRO, ROS_PYTHON_VERSION; any other is not known), ``int()`` reads a known text,
and a module importing both rospy and rclpy is of the node's version."""

from __future__ import annotations

import pytest
from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.pipeline import distro_variables
from haros_arch.workspace import scan

CORE = """\
import os


def get_ros_version():
    ros_version = int(os.environ.get("ROS_VERSION", 0))
    if ros_version not in (1, 2):
        raise RuntimeError("no ROS_VERSION")
    return ros_version
"""
NODE = """\
from compat.core import get_ros_version

ROS_VERSION = get_ros_version()

if ROS_VERSION == 1:
    import rospy

    class CompatibleNode(object):
        def __init__(self, name, **kwargs):
            pass

        def new_publisher(self, msg_type, topic, depth):
            return rospy.Publisher(topic, msg_type, queue_size=depth)

elif ROS_VERSION == 2:
    from rclpy.node import Node

    class CompatibleNode(Node):
        def __init__(self, name, **kwargs):
            super(CompatibleNode, self).__init__(name, **kwargs)

        def new_publisher(self, msg_type, topic, depth):
            return self.create_publisher(msg_type, topic, depth)
"""
TALKER = """\
from std_msgs.msg import String
from compat.node import CompatibleNode


class Talker(CompatibleNode):
    def __init__(self):
        super(Talker, self).__init__("talker")
        self.pub = self.new_publisher(String, "chatter", 10)


def main():
    Talker()


if __name__ == "__main__":
    main()
"""


def _manifest(name: str) -> str:
    return package_xml(name).replace(
        "</package>", '<export><build_type condition="$ROS_VERSION == 1">catkin</build_type>'
        '<build_type condition="$ROS_VERSION == 2">ament_python</build_type></export>'
        "</package>")


@pytest.mark.parametrize("distro", ["noetic", "humble"])
def test_a_class_defined_in_the_branch_of_the_ros_version(write_tree, distro) -> None:
    root = write_tree({"compat/package.xml": _manifest("compat"),
                       "compat/src/compat/__init__.py": "",
                       "compat/src/compat/core.py": CORE,
                       "compat/src/compat/node.py": NODE,
                       "talker/package.xml": _manifest("talker"),
                       "talker/src/talker/__init__.py": "",
                       "talker/src/talker/talker.py": TALKER})
    workspace = scan([str(root)], {"ROS_DISTRO": distro, **distro_variables(distro)})
    result = extract_python([str(root / "talker/src/talker/talker.py")], workspace,
                            package="talker")
    assert result.rosname == ("talker" if distro == "humble" else None)
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("publish", "chatter", "std_msgs/String" if distro == "noetic"
         else "std_msgs/msg/String")]


def test_an_environment_variable_the_distribution_does_not_set_is_not_known(
        write_tree) -> None:
    root = write_tree({"talker/package.xml": package_xml("talker", "ament_python"),
                       "talker/talker.py": "import os\nimport rclpy\n"
                       "from std_msgs.msg import String\n"
                       "node = rclpy.create_node('talker')\n"
                       "node.create_publisher(String, os.environ.get('ROBOT', 'r1') + '/out', 1)\n"
                       "node.create_publisher(String, os.environ['ROS_DISTRO'] + '/out', 1)\n"})
    workspace = scan([str(root)], {"ROBOT": "r2", "ROS_DISTRO": "humble",
                                   **distro_variables("humble")})
    result = extract_python([str(root / "talker/talker.py")], workspace, package="talker")
    assert [c.name for c in result.calls] == ["?/out", "humble/out"]


SHIM = """\
import rclpy

_node = None


def init_node(name):
    global _node
    _node = rclpy.create_node(name)


def get_param(name, default=None):
    name = name.strip("~")
    _node.declare_parameter(name, default)
    return _node.get_parameter(name).value
"""
BOARD = """\
import os

if os.environ.get("ROS_VERSION") == "1":
    import rospy
elif os.environ.get("ROS_VERSION") == "2":
    import board.shim as rospy
else:
    raise SystemExit(1)


def main():
    rospy.init_node("board")
    port = rospy.get_param("~port", 8888)
"""


@pytest.mark.parametrize("distro", ["noetic", "humble"])
def test_an_import_chosen_by_the_environment_is_the_branch_s(write_tree, distro) -> None:
    """rosboard imports rospy as ``rospy`` under ``os.environ.get("ROS_VERSION") ==
    "1"`` and its own rclpy shim as ``rospy`` under ``== "2"``: the shim, imported last,
    was taken for rospy in ROS 1 too, and its ``declare_parameter(name.strip("~"))``
    read ``/port`` where rospy reads ``~port`` (a false parameter-set-not-read of the
    launch file's ``port``). A module-level branch whose test over the distribution's
    variables does not hold imports nothing."""
    root = write_tree({"board/package.xml": package_xml("board"),
                       "board/src/board/__init__.py": "",
                       "board/src/board/shim.py": SHIM,
                       "board/src/board/board.py": BOARD})
    workspace = scan([str(root)], {"ROS_DISTRO": distro, **distro_variables(distro)})
    result = extract_python([str(root / "board/src/board/board.py")], workspace,
                            package="board")
    calls = [(c.kind, c.name) for c in result.calls]
    assert calls == ([("read", "~port")] if distro == "noetic"
                     else [("declare", "port"), ("read", "port")])


TALKER_BY_VERSION = """\
from std_msgs.msg import String
from compat.core import get_ros_version
from compat.node import CompatibleNode

ROS_VERSION = get_ros_version()
DEBUG = False


class Talker(CompatibleNode):
    def __init__(self):
        super(Talker, self).__init__("talker")
        self.pub = self.new_publisher(String, "chatter", 10)
        if ROS_VERSION == 1:
            self.descriptions = self.new_publisher(String, "descriptions", 1)
        if ROS_VERSION == 2:
            self.events = self.new_publisher(String, "events", 1)
        if DEBUG:
            self.debug = self.new_publisher(String, "debug", 1)


def main():
    Talker()


if __name__ == "__main__":
    main()
"""


@pytest.mark.parametrize("distro", ["noetic", "humble"])
def test_a_method_s_branch_on_a_module_global_of_the_ros_version(write_tree, distro) -> None:
    """carla ros-bridge's ackermann controller: ``ROS_VERSION =
    roscomp.get_ros_version()`` at module level, then in ``__init__`` ``if ROS_VERSION ==
    1:`` a dynamic_reconfigure server (its ``parameter_descriptions`` and
    ``parameter_updates`` publishers) and ``if ROS_VERSION == 2:`` rclpy's parameter
    callback. The test was kept as a condition of the calls, never decided: the ROS 2
    node had the ROS 1 server's publishers "only under if (ROS_VERSION == 1)". A global
    the module computes once (not a literal written there, which is the code's own
    switch) is known in its functions as at module level."""
    root = write_tree({"compat/package.xml": _manifest("compat"),
                       "compat/src/compat/__init__.py": "",
                       "compat/src/compat/core.py": CORE,
                       "compat/src/compat/node.py": NODE,
                       "talker/package.xml": _manifest("talker"),
                       "talker/src/talker/__init__.py": "",
                       "talker/src/talker/talker.py": TALKER_BY_VERSION})
    workspace = scan([str(root)], {"ROS_DISTRO": distro, **distro_variables(distro)})
    result = extract_python([str(root / "talker/src/talker/talker.py")], workspace,
                            package="talker")
    found = [(c.name, [k.text for k in c.conditions]) for c in result.calls
             if c.kind == "publish"]
    assert found == [("chatter", []),
                     ("descriptions" if distro == "noetic" else "events", []),
                     ("debug", ["DEBUG"])]
