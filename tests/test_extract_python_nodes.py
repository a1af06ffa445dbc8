"""Several nodes in one Python executable, and names built from the node's own name or
namespace (``get_name()``, ``get_fully_qualified_name()``, ``get_namespace()``)."""

from __future__ import annotations

from haros_arch.extract.python import PythonResult, extract_python
from haros_arch.workspace import Workspace


def run(tmp_path, text: str) -> PythonResult:
    source = tmp_path / "node.py"
    source.write_text(text)
    return extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")


TWO_CLASSES = (
    "import rclpy\nfrom rclpy.node import Node\nfrom std_msgs.msg import String\n"
    "class Talker(Node):\n"
    "    def __init__(self):\n"
    "        super().__init__('talker')\n"
    "        self.create_publisher(String, 'chatter', 10)\n"
    "class Listener(Node):\n"
    "    def __init__(self, name='listener'):\n"
    "        super().__init__(name)\n"
    "        self.create_subscription(String, 'chatter', self.on_msg, 10)\n"
    "    def on_msg(self, msg):\n"
    "        pass\n"
    "def main():\n"
    "    rclpy.init()\n"
    "    executor = rclpy.executors.MultiThreadedExecutor()\n"
    "    executor.add_node(Talker())\n"
    "    executor.add_node(Listener())\n"
    "    executor.spin()\n"
    "if __name__ == '__main__':\n"
    "    main()\n")


def test_two_node_classes_are_two_nodes_each_with_its_calls(tmp_path) -> None:
    result = run(tmp_path, TWO_CLASSES)
    assert result.rosname == "talker"
    assert result.names == ["talker", "listener"]
    assert result.nodes == ["talker", "listener"]
    several = [d for d in result.diagnostics if d.code == "PY_SEVERAL_NODES"]
    assert len(several) == 1
    assert "talker, listener" in several[0].message
    assert several[0].severity == "info"
    assert several[0].location.line == 10  # where the second name is given
    assert [(c.kind, c.name, c.node_name) for c in result.calls] == [
        ("publish", "chatter", "talker"), ("subscribe", "chatter", "listener")]


def test_one_class_two_names_keeps_a_call_per_node(tmp_path) -> None:
    result = run(tmp_path,
                 "import rclpy\nfrom rclpy.node import Node\nfrom std_msgs.msg import String\n"
                 "class Wheel(Node):\n"
                 "    def __init__(self, side):\n"
                 "        super().__init__(side + '_wheel')\n"
                 "        self.create_publisher(String, 'speed', 1)\n"
                 "        self.create_timer(0.1, self.tick)\n"
                 "    def tick(self):\n"
                 "        self.create_client(String, 'reset')\n"
                 "left, right = Wheel('left'), Wheel('right')\n")
    assert result.nodes == ["left_wheel", "right_wheel"]
    assert [(c.kind, c.node_name) for c in result.calls] == [
        ("publish", "left_wheel"), ("publish", "right_wheel"),
        ("client", None)]  # a callback of a class with two names: node not known


def test_one_node_has_no_node_names(tmp_path) -> None:
    result = run(tmp_path,
                 "import rclpy\nfrom std_msgs.msg import String\n"
                 "node = rclpy.create_node('solo')\n"
                 "node.create_publisher(String, 'x', 1)\n")
    assert result.nodes == []
    assert [c.node_name for c in result.calls] == [None]


def test_create_node_twice(tmp_path) -> None:
    result = run(tmp_path,
                 "import rclpy\nfrom std_msgs.msg import String\n"
                 "rclpy.init()\n"
                 "a = rclpy.create_node('sender', namespace='robot')\n"
                 "b = rclpy.create_node('receiver')\n"
                 "a.create_publisher(String, 'x', 1)\n"
                 "b.create_subscription(String, 'x', None, 1)\n")
    assert (result.rosname, result.namespace) == ("sender", "robot")
    assert result.names == ["sender", "receiver"]
    assert [d.code for d in result.diagnostics] == ["PY_SEVERAL_NODES"]
    assert [c.node_name for c in result.calls] == ["sender", "receiver"]


def test_one_node_named_in_two_places_is_one_name(tmp_path) -> None:
    # the same name through a base class and its subclass, or an entry walk that does not
    # know a parameter's value: no warning, and the known name wins over '?'
    result = run(tmp_path,
                 "import rclpy\nfrom rclpy.node import Node\n"
                 "class Base(Node):\n"
                 "    def __init__(self, name):\n"
                 "        super().__init__(name)\n"
                 "class Driver(Base):\n"
                 "    def __init__(self):\n"
                 "        super().__init__('driver')\n"
                 "node = Driver()\n"
                 "other = rclpy.create_node('driver')\n")
    assert result.rosname == "driver"
    assert result.names == ["driver"]
    assert "PY_SEVERAL_NODES" not in [d.code for d in result.diagnostics]


def test_a_node_name_loop_gives_each_name(tmp_path) -> None:
    result = run(tmp_path,
                 "import rclpy\n"
                 "nodes = [rclpy.create_node(f'arm_{side}') for side in 'lr']\n"
                 "for side in ['left', 'right']:\n"
                 "    rclpy.create_node(f'wheel_{side}')\n")
    assert result.names == ["wheel_left", "wheel_right"]


NAMES = (
    "import rclpy\nfrom rclpy.node import Node\nfrom std_msgs.msg import String\n"
    "class Cam(Node):\n"
    "    def __init__(self):\n"
    "        super().__init__('cam')\n"
    "        self.create_publisher(String, f'{self.get_name()}/status', 10)\n"
    "        self.create_publisher(String, self.get_fully_qualified_name() + '/info', 10)\n"
    "        self.create_publisher(String, f'{self.get_namespace()}/image', 10)\n"
    "        self.create_service(String, self.get_name() + '/reset', self.reset)\n"
    "    def reset(self, request, response):\n"
    "        return response\n"
    "node = rclpy.create_node('helper')\n"
    "node.create_publisher(String, node.get_name() + '/out', 1)\n"
    "cam = Cam()\n")


def test_rclpy_own_name_and_namespace_in_names(tmp_path) -> None:
    result = run(tmp_path, NAMES)
    assert [(c.kind, c.name) for c in result.calls] == [
        ("publish", "~status"), ("publish", "~info"), ("publish", "image"),
        ("server", "~reset"), ("publish", "~out")]
    assert "PY_DYNAMIC_NAME" not in [d.code for d in result.diagnostics]


def test_rospy_own_name_and_namespace_in_names(tmp_path) -> None:
    result = run(tmp_path,
                 "import rospy\nfrom std_msgs.msg import String\n"
                 "rospy.init_node('cam')\n"
                 "rospy.Publisher(rospy.get_name() + '/status', String, queue_size=1)\n"
                 "rospy.Publisher(rospy.get_namespace() + 'image', String, queue_size=1)\n"
                 "rospy.Publisher('%s/x' % rospy.get_name(), String, queue_size=1)\n"
                 "rospy.Publisher(rospy.get_name(), String, queue_size=1)\n")
    assert [c.name for c in result.calls] == ["~status", "image", "~x", "~"]


def test_rospy_resolve_name_is_the_name_it_resolves(tmp_path) -> None:
    """franka_example_controllers' move_to_start.py: ``rospy.resolve_name('~x')`` gives
    the name rospy resolves (and remaps) as a publisher's or a client's own name would
    be: the name as written, which the graph resolves; it was unknown ('?'), the action
    client, parameter and subscription of the script lost."""
    result = run(tmp_path,
                 "import rospy as ros\nfrom actionlib import SimpleActionClient\n"
                 "from sensor_msgs.msg import JointState\n"
                 "from control_msgs.msg import FollowJointTrajectoryAction\n"
                 "ros.init_node('move_to_start')\n"
                 "action = ros.resolve_name('~follow_joint_trajectory')\n"
                 "client = SimpleActionClient(action, FollowJointTrajectoryAction)\n"
                 "param = ros.resolve_name('~joint_pose')\n"
                 "pose = ros.get_param(param, None)\n"
                 "topic = ros.resolve_name('joint_states')\n"
                 "state = ros.wait_for_message(topic, JointState)\n"
                 "other = ros.resolve_name('x', 'elsewhere')\n"
                 "ros.Publisher(other, JointState, queue_size=1)\n")
    assert [(c.kind, c.name) for c in result.calls] == [
        ("action-client", "~follow_joint_trajectory"), ("read", "~joint_pose"),
        ("subscribe", "joint_states"), ("publish", "?")]


def test_rospy_init_node_on_two_branches(tmp_path) -> None:
    result = run(tmp_path,
                 "import rospy, sys\n"
                 "if len(sys.argv) > 1:\n"
                 "    rospy.init_node('left_driver')\n"
                 "else:\n"
                 "    rospy.init_node('right_driver')\n")
    assert result.rosname == "left_driver"
    assert [d.code for d in result.diagnostics] == ["PY_SEVERAL_NODES"]
    assert result.nodes == []  # rospy: one node per process, whatever its name


def test_own_name_followed_by_other_text_is_not_a_private_name(tmp_path) -> None:
    """strands_executive's AbstractTaskServer: ``rospy.Service('%s_is_interruptible' %
    self.name, ...)`` with ``name=rospy.get_name()`` is ``/wait_node_is_interruptible``,
    a sibling of the node, not its private ``~_is_interruptible`` (which resolves to
    ``/wait_node/_is_interruptible``): unknown there. Followed by ``/`` or by nothing the
    node's name is still ``~``."""
    result = run(tmp_path,
                 "import rospy\nfrom std_srvs.srv import Empty\n"
                 "rospy.init_node('wait_node')\n"
                 "name = rospy.get_name()\n"
                 "rospy.Service('%s_is_interruptible' % name, Empty, None)\n"
                 "rospy.Service(name + '_create', Empty, None)\n"
                 "rospy.Service(f'{name}/reset', Empty, None)\n"
                 "rospy.Service(name, Empty, None)\n"
                 "rospy.get_param(name + '/rate', 1)\n"
                 "rospy.Service('~_literal', Empty, None)\n")
    assert [(c.kind, c.name) for c in result.calls] == [
        ("server", "?_is_interruptible"), ("server", "?_create"), ("server", "~reset"),
        ("server", "~"), ("read", "~rate"), ("server", "~_literal")]


def test_a_read_of_the_name_search_param_found_is_a_searched_read(tmp_path) -> None:
    """naoqi_bridge's naoqi_joint_states.py: ``name = rospy.search_param('tf_prefix')``
    then ``if name: rospy.get_param(name)`` reads the parameter the search found: a
    searched read of ``tf_prefix``, not a read of an unknown name ('?', PY_DYNAMIC_NAME,
    an unresolved-names finding)."""
    result = run(tmp_path,
                 "import rospy\n"
                 "rospy.init_node('joints')\n"
                 "found = rospy.search_param('tf_prefix')\n"
                 "if found:\n"
                 "    prefix = rospy.get_param(found, '')\n")
    assert [(c.kind, c.name, c.searched, c.type, c.location.line) for c in result.calls] == [
        ("read", "~tf_prefix", True, None, 3), ("read", "~tf_prefix", True, "str", 5)]
    assert "PY_DYNAMIC_NAME" not in [d.code for d in result.diagnostics]
