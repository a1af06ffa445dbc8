"""The Python extractor (rospy, rclpy) on the fixture workspace ``fixtures/python/ws``.

Each script or module is extracted once per module (module-scoped fixture); tests
compare the calls against what a reading of the fixture gives, row by row.
"""

from __future__ import annotations

import os

import pytest

from haros_arch.extract import extract_node
from haros_arch.extract.python import PythonResult, extract_python
from haros_arch.model.source import Node, PrimitiveCall
from haros_arch.workspace import Workspace, scan

HERE = os.path.dirname(os.path.abspath(__file__))
WS = os.path.join(os.path.dirname(HERE), "fixtures", "python", "ws")
ROS1 = os.path.join(WS, "src", "ros1_demo")
ROS2 = os.path.join(WS, "src", "ros2_demo")
DEFAULT_QOS = {"depth": 10, "history": "keep_last", "reliability": "reliable",
               "durability": "volatile"}


def row(call: PrimitiveCall) -> tuple[object, ...]:
    """kind, name, type, queue size, latch, callback, line, conditions."""
    return (call.kind, call.name, call.type, call.queue_size, call.latch, call.callback,
            call.location.line, tuple((c.statement, c.text) for c in call.conditions))


def codes(result: PythonResult) -> list[str]:
    return [d.code for d in result.diagnostics]


@pytest.fixture(scope="module")
def ws() -> Workspace:
    return scan([WS])


@pytest.fixture(scope="module")
def extracted(ws: Workspace) -> dict[str, PythonResult]:
    cache: dict[str, PythonResult] = {}
    return cache


def extract(ws: Workspace, cache: dict[str, PythonResult], path: str) -> PythonResult:
    if path not in cache:
        package = "ros1_demo" if path.startswith(ROS1) else "ros2_demo"
        cache[path] = extract_python([path], ws, package=package)
    return cache[path]


@pytest.fixture
def ros1(ws: Workspace, extracted: dict[str, PythonResult]):
    return lambda name: extract(ws, extracted, os.path.join(ROS1, "scripts", name))


@pytest.fixture
def ros2(ws: Workspace, extracted: dict[str, PythonResult]):
    return lambda name: extract(ws, extracted, os.path.join(ROS2, "ros2_demo", name))


# -- rospy ------------------------------------------------------------------------------

def test_rospy_topics(ros1) -> None:
    result = ros1("topics.py")
    assert result.rosname == "topics"
    assert result.anonymous is True
    wait = ("if", "rospy.get_param('~wait', False)")
    loop = ("while", "not rospy.is_shutdown()")
    assert [row(c) for c in result.calls] == [
        ("publish", "relay_out", "std_msgs/String", 10, True, None, 20, ()),
        ("subscribe", "relay_in", "std_msgs/String", 1, False, "Relay.forward", 21, ()),
        ("publish", "chatter", "std_msgs/String", 10, False, None, 29, ()),
        ("subscribe", "chatter", "std_msgs/Int32", None, False, "on_chatter", 30, ()),
        # a star import from the package's own messages, resolved through msg/
        ("publish", "/status", "ros1_demo/Status", 1, False, None, 31, ()),
        ("subscribe", "camera/image", "sensor_msgs/Image", None, False, None, 32, ()),
        ("read", "~wait", "bool", None, False, None, 34, ()),
        ("subscribe", "odom", "std_msgs/Header", None, False, None, 35, (wait,)),
        ("publish", "fast", "std_msgs/String", 20, False, None, 37,
         (("else", wait[1]), ("if", "RATE > 5"))),
        ("publish", "slow", "std_msgs/String", None, False, None, 39,
         (("else", wait[1]), ("else", "RATE > 5"))),
        # a loop over a known tuple is unrolled: one call per item, each made for sure
        # (the body holds no break, return or raise): no condition
        ("publish", "left/cmd", "std_msgs/Float64", 1, False, None, 41, ()),
        ("publish", "right/cmd", "std_msgs/Float64", 1, False, None, 41, ()),
        ("subscribe", "loop", "std_msgs/String", None, False, "on_chatter", 44,
         (loop, ("try", ""))),
        ("publish", "errors", "std_msgs/String", 1, False, None, 46,
         (loop, ("except", "rospy.ROSException"))),
    ]
    assert codes(result) == []


def test_locations_are_workspace_relative_with_columns(ros1) -> None:
    call = ros1("topics.py").calls[0]
    assert call.location.package == "ros1_demo"
    assert call.location.file == "src/ros1_demo/scripts/topics.py"
    assert (call.location.line, call.location.column) == (20, 20)
    condition = ros1("topics.py").calls[7].conditions[0]
    assert (condition.kind, condition.location.line, condition.location.column) == (
        "source", 34, 5)


def test_rospy_services_and_parameters(ros1) -> None:
    result = ros1("services_params.py")
    assert result.rosname == "services_params"
    assert result.anonymous is False
    assert [row(c) for c in result.calls] == [
        # a helper called twice, each with its own name
        ("server", "reset", "ros1_demo/Reset", None, False, "handle_reset", 14, ()),
        ("server", "arm/reset", "ros1_demo/Reset", None, False, "handle_reset", 14, ()),
        ("read", "~topic", "str", None, False, None, 21, ()),
        ("read", "gain", "double", None, False, None, 23, ()),
        ("subscribe", "?", "ros1_demo/Reset", None, False, "Controller.on_scan", 26, ()),
        # class attribute + module constant, through f-string, % and str.format
        ("client", "arm/elbow/reset", "ros1_demo/Reset", None, False, None, 27, ()),
        ("client", "arm/elbow/stop", "ros1_demo/Reset", None, False, None, 28, ()),
        ("client", "arm/?", "ros1_demo/Reset", None, False, None, 29, ()),
        ("client", "calibrate", None, None, False, None, 39, ()),
        ("write", "/robot/mode", "str", None, False, None, 40, ()),
        ("write", "~count", "int", None, False, None, 41, ()),
        ("read", "~debug", None, None, False, None, 42, ()),
        ("write", "~debug", None, None, False, None, 43,
         (("if", "rospy.has_param('~debug')"),)),
        ("read", "~frame_id", None, None, False, None, 44, ()),
        # get_param(found), found = search_param('frame_id'): the parameter it found
        ("read", "~frame_id", None, None, False, None, 45, ()),
    ]
    assert [c.searched for c in result.calls[-2:]] == [True, True]


def test_parameter_valued_name(ros1) -> None:
    scan_sub = ros1("services_params.py").calls[4]
    assert (scan_sub.name, scan_sub.name_param, scan_sub.name_default) == ("?", "~topic", "scan")
    others = [c for c in ros1("services_params.py").calls if c is not scan_sub]
    assert all(c.name_param is None for c in others)


def test_actionlib_and_tf2(ros1) -> None:
    result = ros1("actions_tf.py")
    assert result.rosname == "actions_tf"
    assert [row(c) for c in result.calls] == [
        ("action-server", "dock", "ros1_demo/Dock", None, False, "Docker.execute", 11, ()),
        ("action-server", "undock", "ros1_demo/Dock", None, False, "goal_cb", 25, ()),
        ("action-client", "/station/dock", "ros1_demo/Dock", None, False, None, 26, ()),
        ("action-client", "undock", "ros1_demo/Dock", None, False, None, 27, ()),
        ("publish", "/tf", "tf2_msgs/TFMessage", None, False, None, 28, ()),
        ("publish", "/tf_static", "tf2_msgs/TFMessage", None, True, None, 29, ()),
        # tf2_ros.Buffer() serves ~tf2_frames (debug=True by default)
        ("server", "~tf2_frames", "tf2_msgs/FrameGraph", None, False, None, 30, ()),
        ("subscribe", "/tf", "tf2_msgs/TFMessage", None, False, None, 31, ()),
        ("subscribe", "/tf_static", "tf2_msgs/TFMessage", None, False, None, 31, ()),
    ]
    assert codes(result) == []


def test_modules_of_the_same_package(ros1) -> None:
    result = ros1("uses_module.py")
    assert result.rosname == "uses_module"
    assert [(c.kind, c.name, c.type, c.queue_size, c.location.file, c.location.line)
            for c in result.calls] == [
        # SCAN_TOPIC = PREFIX + 'scan', PREFIX from a relative import in that module
        ("subscribe", "front_scan", "std_msgs/String", None,
         "src/ros1_demo/scripts/uses_module.py", 8),
        ("publish", "status_a", "std_msgs/String", 5, "src/ros1_demo/src/ros1_demo/names.py", 11),
        ("publish", "front_scan_status", "std_msgs/String", 2,
         "src/ros1_demo/src/ros1_demo/names.py", 11),
    ]


def test_python2_file_is_read_after_repair(ros1) -> None:
    result = ros1("legacy.py")
    assert codes(result) == ["PY_PYTHON2"]
    assert result.diagnostics[0].location.line == 10
    assert result.rosname == "legacy"
    assert [row(c) for c in result.calls] == [
        ("publish", "legacy", "std_msgs/String", 1, False, None, 7, ())]


def test_syntax_error_is_a_diagnostic(ros1) -> None:
    result = ros1("broken.py")
    assert result.calls == []
    assert codes(result) == ["PY_PARSE_ERROR"]
    location = result.diagnostics[0].location
    assert (location.file, location.line, location.column) == (
        "src/ros1_demo/scripts/broken.py", 3, 10)


# -- rclpy ------------------------------------------------------------------------------

def test_rclpy_node_subclass(ros2) -> None:
    result = ros2("talker.py")
    assert (result.rosname, result.namespace) == ("talker", "robot")
    debug = (("if", "self.has_parameter('debug')"),)
    assert [row(c) for c in result.calls] == [
        ("declare", "topic", "str", None, False, None, 16, ()),
        ("declare", "limits.speed", "double", None, False, None, 17, ()),
        ("declare", "limits.enabled", "bool", None, False, None, 17, ()),
        ("read", "topic", None, None, False, None, 18, ()),
        ("publish", "?", "std_msgs/msg/String", 10, False, None, 19, ()),
        ("publish", "~status", "std_msgs/msg/String", 1, False, None, 20, ()),
        ("subscribe", "scan", "std_msgs/msg/String", 5, False, "Talker.on_scan", 22, ()),
        ("subscribe", "imu", "std_msgs/msg/String", 5, False, "Talker.on_scan", 23, ()),
        ("subscribe", "map", "std_msgs/msg/String", None, False, "Talker.on_scan", 24, ()),
        ("server", "add", "example_interfaces/srv/AddTwoInts", None, False, "Talker.add", 26,
         ()),
        ("client", "/calc/add", "example_interfaces/srv/AddTwoInts", None, False, None, 27,
         ()),
        ("read", "limits.speed", None, None, False, None, 28, ()),
        ("read", "limits.enabled", None, None, False, None, 28, ()),
        ("read", "debug", None, None, False, None, 29, ()),
        ("write", "debug", "bool", None, False, None, 30, debug),
    ]
    topic = result.calls[4]
    assert (topic.name_param, topic.name_default) == ("topic", "chatter")


def test_rclpy_qos(ros2) -> None:
    qos = {c.name: c.qos for c in ros2("talker.py").calls if c.kind in ("publish", "subscribe")}
    assert qos["?"] == DEFAULT_QOS
    assert qos["~status"] == {**DEFAULT_QOS, "depth": 1, "durability": "transient_local"}
    assert qos["scan"] == {**DEFAULT_QOS, "depth": 5, "reliability": "best_effort"}
    assert qos["imu"] == {**DEFAULT_QOS, "depth": 5, "reliability": "best_effort"}
    assert qos["map"] == {"depth": None, "history": "system_default",
                          "reliability": "system_default", "durability": "system_default"}
    old = {c.name: c.qos for c in ros2("old_style.py").calls}
    assert old == {"events": {**DEFAULT_QOS, "depth": 0, "history": "keep_all"},
                   "heartbeat": {**DEFAULT_QOS, "depth": 2}}


def test_rclpy_create_node_actions_tf_filters(ros2) -> None:
    result = ros2("actions.py")
    assert result.rosname == "actions"
    loop = ()  # unrolled over a known tuple, the body run whole: each call for sure
    assert [row(c) for c in result.calls] == [
        ("action-server", "fibonacci", "example_interfaces/action/Fibonacci", None, False,
         "execute", 17, ()),
        ("action-client", "other/fibonacci", "example_interfaces/action/Fibonacci", None,
         False, None, 18, ()),
        ("publish", "/tf", "tf2_msgs/msg/TFMessage", 100, False, None, 19, ()),
        ("publish", "/tf_static", "tf2_msgs/msg/TFMessage", 1, False, None, 20, ()),
        ("subscribe", "/tf", "tf2_msgs/msg/TFMessage", 100, False, None, 22, ()),
        ("subscribe", "/tf_static", "tf2_msgs/msg/TFMessage", 1, False, None, 22, ()),
        ("subscribe", "camera/image", "sensor_msgs/msg/Image", None, False, None, 23, ()),
        ("publish", "left/image_raw", "sensor_msgs/msg/Image", 1, False, None, 25, loop),
        ("publish", "right/image_raw", "sensor_msgs/msg/Image", 1, False, None, 25, loop),
    ]
    static = result.calls[3].qos
    assert static is not None and static["durability"] == "transient_local"


def test_rclpy_node_init_and_node_constructor(ros2) -> None:
    result = ros2("old_style.py")
    assert result.rosname == "old_style"
    assert [row(c) for c in result.calls] == [
        ("subscribe", "events", "std_msgs/msg/String", 0, False, "Monitor.on_event", 12, ()),
        ("publish", "heartbeat", "std_msgs/msg/String", 2, False, None, 20, ()),
    ]


def test_class_of_another_module_built_with_arguments(ros2) -> None:
    result = ros2("uses_common.py")
    assert result.rosname == "uses_common"
    assert [(c.kind, c.name, c.queue_size, c.callback, c.location.file, c.location.line)
            for c in result.calls] == [
        ("publish", "shared", 3, None, "src/ros2_demo/ros2_demo/common.py", 10),
        ("subscribe", "shared/echo", 1, "Chatter.on_echo",
         "src/ros2_demo/ros2_demo/common.py", 13),
    ]


def test_module_alone_keeps_unknown_arguments(ros2) -> None:
    result = ros2("common.py")
    assert [(c.kind, c.name) for c in result.calls] == [
        ("publish", "?"), ("subscribe", "?/echo")]


# -- the pipeline's entry --------------------------------------------------------------

def test_extract_node_fills_a_python_node(ws: Workspace) -> None:
    node = Node("ros1_demo", "topics.py", kind="script", language="python",
                sources=["src/ros1_demo/scripts/topics.py"])
    diagnostics = extract_node(node, ws)
    assert node.rosname == "topics"
    assert len(node.calls) == 14
    assert [d.code for d in diagnostics] == []


def test_rclpy_qos_policies_set_after_the_profile_is_made(tmp_path) -> None:
    """``qos = QoSProfile(depth=10); qos.reliability = ReliabilityPolicy.BEST_EFFORT``
    (rclpy's QoSProfile properties, the common way to ask for a latched map or a sensor
    stream): the policy set after the profile was made was ignored, so a best-effort
    subscription counted as reliable and a transient-local one as volatile, both to the
    QoS compatibility check."""
    from haros_arch.extract.python import extract_python
    from haros_arch.workspace import scan

    source = tmp_path / "n.py"
    source.write_text(
        "import rclpy\nfrom rclpy.node import Node\n"
        "from rclpy.qos import QoSProfile, ReliabilityPolicy, DurabilityPolicy\n"
        "from nav_msgs.msg import OccupancyGrid, Odometry\n"
        "class N(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('n')\n"
        "        qos = QoSProfile(depth=10)\n"
        "        qos.reliability = ReliabilityPolicy.BEST_EFFORT\n"
        "        self.create_subscription(Odometry, 'odom', print, qos)\n"
        "        self.latched = QoSProfile(depth=1)\n"
        "        self.latched.durability = DurabilityPolicy.TRANSIENT_LOCAL\n"
        "        self.latched.depth = 5\n"
        "        self.create_subscription(OccupancyGrid, 'map', print, self.latched)\n"
        "        msg = OccupancyGrid()\n"
        "        msg.info.resolution = 0.05\n")
    found = extract_python([str(source)], scan([str(tmp_path)]))
    qos = {c.name: c.qos for c in found.calls if c.kind == "subscribe"}
    assert qos["odom"] == {**DEFAULT_QOS, "depth": 10, "reliability": "best_effort"}
    assert qos["map"] == {**DEFAULT_QOS, "depth": 5, "durability": "transient_local"}


def test_rclpy_qos_policy_set_under_a_condition_is_unknown(tmp_path) -> None:
    """ros2/demos' data_publisher.py:69-89: ``if args.best_effort: qos.reliability =
    BEST_EFFORT else: ... RELIABLE``, and a durability set only under one branch: the
    policy depends on the run, so it is unknown (as a C++ setter that may not run
    leaves its field), not the last branch's nor the default; one set where the profile
    was made, in the same block, holds."""
    from haros_arch.extract.python import extract_python
    from haros_arch.workspace import scan

    source = tmp_path / "n.py"
    source.write_text(
        "import sys\nimport rclpy\nfrom rclpy.node import Node\n"
        "from rclpy.qos import QoSProfile, ReliabilityPolicy, DurabilityPolicy\n"
        "from std_msgs.msg import Header\n"
        "class N(Node):\n"
        "    def __init__(self, best_effort, latched):\n"
        "        super().__init__('n')\n"
        "        qos = QoSProfile(depth=10)\n"
        "        if best_effort:\n"
        "            qos.reliability = ReliabilityPolicy.BEST_EFFORT\n"
        "        else:\n"
        "            qos.reliability = ReliabilityPolicy.RELIABLE\n"
        "        if latched:\n"
        "            qos.durability = DurabilityPolicy.TRANSIENT_LOCAL\n"
        "        self.create_publisher(Header, 'data', qos)\n"
        "        if latched:\n"
        "            other = QoSProfile(depth=1)\n"
        "            other.durability = DurabilityPolicy.TRANSIENT_LOCAL\n"
        "            self.create_publisher(Header, 'other', other)\n")
    found = extract_python([str(source)], scan([str(tmp_path)]))
    qos = {c.name: c.qos for c in found.calls if c.kind == "publish"}
    assert qos["data"] == {**DEFAULT_QOS, "depth": 10, "reliability": None,
                           "durability": None}
    assert qos["other"] == {**DEFAULT_QOS, "depth": 1, "durability": "transient_local"}


def test_rclpy_super_init_runs_a_base_class_of_the_package(tmp_path) -> None:
    """A node class built on another of the package (``class Arm(Base)`` with
    ``super().__init__('arm', 'arm_cmd')``, ``Base.__init__(self, name, topic)`` making
    the node and its publisher): ``super().__init__`` runs the base's ``__init__`` with
    those arguments, as Python does. It was taken for rclpy's ``Node.__init__`` (the
    topic for the namespace) and the base's publisher was ``?``."""
    from haros_arch.extract.python import extract_python
    from haros_arch.workspace import scan

    source = tmp_path / "n.py"
    source.write_text(
        "import rclpy\nfrom rclpy.node import Node\nfrom std_msgs.msg import Float64\n"
        "class Base(Node):\n"
        "    def __init__(self, name, topic):\n"
        "        super().__init__(name, namespace='robot')\n"
        "        self.pub = self.create_publisher(Float64, topic, 10)\n"
        "class Arm(Base):\n"
        "    def __init__(self):\n"
        "        super().__init__('arm', 'arm_cmd')\n"
        "        self.create_subscription(Float64, 'arm_state', print, 10)\n"
        "def main():\n    rclpy.init()\n    rclpy.spin(Arm())\n")
    found = extract_python([str(source)], scan([str(tmp_path)]))
    assert (found.rosname, found.namespace) == ("arm", "robot")
    assert sorted((c.kind, c.name) for c in found.calls) == [
        ("publish", "arm_cmd"), ("subscribe", "arm_state")]


def test_rclpy_a_node_class_nothing_builds_is_no_node_of_the_process(tmp_path) -> None:
    """A module that defines two node classes and whose ``main()`` builds one: the other
    was walked as if it ran, its name a second node of the process (an instance of its
    own in the graph) and its calls made. As a C++ class the node never builds, it makes
    none; a class nothing builds in a module that names no node otherwise keeps its
    calls and name (it may be built out of our sight)."""
    from haros_arch.extract.python import extract_python
    from haros_arch.workspace import scan

    source = tmp_path / "n.py"
    source.write_text(
        "import rclpy\nfrom rclpy.node import Node\nfrom std_msgs.msg import String\n"
        "class Talker(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('talker')\n"
        "        self.create_publisher(String, 'chatter', 10)\n"
        "class Listener(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('listener')\n"
        "        self.create_subscription(String, 'chatter', print, 10)\n"
        "def main():\n    rclpy.init()\n    rclpy.spin(Talker())\n")
    found = extract_python([str(source)], scan([str(tmp_path)]))
    assert (found.rosname, found.names, found.nodes) == ("talker", ["talker"], [])
    assert [(c.kind, c.name) for c in found.calls] == [("publish", "chatter")]
    alone = tmp_path / "alone"
    alone.mkdir()
    (alone / "m.py").write_text(source.read_text().split("def main")[0])
    found = extract_python([str(alone / "m.py")], scan([str(alone)]))
    assert sorted((c.kind, c.name) for c in found.calls) == [
        ("publish", "chatter"), ("subscribe", "chatter")]


def test_rclpy_a_local_the_paths_of_an_if_set_differently(tmp_path) -> None:
    """teleop_twist_keyboard (2.4): ``if stamped: TwistMsg = TwistStamped`` ``else:
    TwistMsg = Twist`` then ``create_publisher(TwistMsg, 'cmd_vel', 10)``: one publisher
    per path, each under its path's condition. The walk in order kept the last branch's
    type for both paths (with ``TwistMsg = Twist; if stamped: TwistMsg = ...`` the
    stamped type everywhere: a false type mismatch where the parameter is not set); the
    else path now starts from what was before the if."""
    from haros_arch.extract.python import extract_python
    from haros_arch.workspace import scan

    source = tmp_path / "n.py"
    source.write_text(
        "import rclpy\nfrom geometry_msgs.msg import Twist, TwistStamped\n"
        "def main():\n"
        "    node = rclpy.create_node('teleop')\n"
        "    stamped = node.declare_parameter('stamped', False).value\n"
        "    TwistMsg = Twist\n"
        "    if stamped:\n"
        "        TwistMsg = TwistStamped\n"
        "    node.create_publisher(TwistMsg, 'cmd_vel', 10)\n"
        "    topic = 'front'\n"
        "    if node.get_parameter('rear').value:\n"
        "        topic = 'rear'\n"
        "    else:\n"
        "        other = topic + '_other'\n"
        "    node.create_subscription(Twist, topic, print, 10)\n")
    found = extract_python([str(source)], scan([str(tmp_path)]))
    made = [(c.kind, c.name, c.type, tuple(f"{x.statement} {x.text}" for x in c.conditions))
            for c in found.calls if c.kind in ("publish", "subscribe")]
    assert made == [
        ("publish", "cmd_vel", "geometry_msgs/msg/TwistStamped", ("if stamped",)),
        ("publish", "cmd_vel", "geometry_msgs/msg/Twist", ("else stamped",)),
        ("subscribe", "rear", "geometry_msgs/msg/Twist",
         ("if node.get_parameter('rear').value",)),
        ("subscribe", "front", "geometry_msgs/msg/Twist",
         ("else node.get_parameter('rear').value",))]


def test_rclpy_a_call_both_paths_of_an_if_make_alike_is_under_neither(tmp_path) -> None:
    """gazebo_ros' spawn_entity.py: ``timeout = self.args.timeout``, ``if
    self.args.spawn_service_timeout is not None: timeout = ...``, then
    ``self._spawn_entity(xml, pose, timeout)``, whose ``create_client(SpawnEntity,
    '%s/spawn_entity' % ...)`` does not use the timeout: one call per value of the local,
    both alike, and the one kept had the ``if`` path's condition, so the spawner's only
    client looked conditional. A call that the paths make differently keeps a call per
    path (the test above)."""
    from haros_arch.extract.python import extract_python
    from haros_arch.workspace import scan

    source = tmp_path / "n.py"
    source.write_text(
        "import rclpy\nfrom std_srvs.srv import Empty\n"
        "def spawn(node, timeout):\n"
        "    node.create_client(Empty, 'spawn').wait_for_service(timeout_sec=timeout)\n"
        "def main():\n"
        "    node = rclpy.create_node('spawner')\n"
        "    timeout = 30.0\n"
        "    if node.get_parameter('old_timeout').value is not None:\n"
        "        timeout = 5.0\n"
        "    spawn(node, timeout)\n")
    found = extract_python([str(source)], scan([str(tmp_path)]))
    assert [(c.kind, c.name, tuple(f"{x.statement} {x.text}" for x in c.conditions))
            for c in found.calls if c.kind == "client"] == [
        ("client", "spawn", ())]


def test_rclpy_names_joined_with_os_path_join(tmp_path) -> None:
    """``os.path.join(NS, 'cmd')`` builds a name as on Linux (one ``/`` between parts,
    a part starting with ``/`` starts over); it was ``?``."""
    from haros_arch.extract.python import extract_python
    from haros_arch.workspace import scan

    source = tmp_path / "n.py"
    source.write_text(
        "import os\nfrom os.path import join\nimport rclpy\nfrom std_msgs.msg import String\n"
        "node = rclpy.create_node('n')\nNS = 'robot'\n"
        "node.create_publisher(String, os.path.join(NS, 'cmd'), 1)\n"
        "node.create_publisher(String, join('/a/', 'b'), 1)\n"
        "node.create_publisher(String, os.path.join('x', '/abs', 'y'), 1)\n"
        "node.create_publisher(String, os.path.join(node.get_namespace(), 'c'), 1)\n")
    found = extract_python([str(source)], scan([str(tmp_path)]))
    assert [c.name for c in found.calls] == ["robot/cmd", "/a/b", "/abs/y", "c"]


def test_python_class_of_an_unread_ros_package_makes_the_node_partial(write_tree) -> None:
    """nav2_simple_commander's ``BasicNavigator()`` (a node with a dozen action clients),
    built by a script that starts rclpy, is code we do not read: the node was complete
    with no call. ``PY_CLASS_UNSEEN`` makes it partial. Not for a package known to make
    no ROS call (tf_transformations), a message, a class the API tables model, nor in a
    script that starts no ROS program (a generator of launch files)."""
    import os

    from conftest import package_xml

    from haros_arch.pipeline import Options, analyse
    from haros_arch.project import load

    manifest = package_xml("nav", build_type="ament_python").replace(
        "</package>", "<exec_depend>nav2_simple_commander</exec_depend>"
                      "<exec_depend>tf_transformations</exec_depend>"
                      "<exec_depend>clearpath_config</exec_depend></package>")
    goto = ("import rclpy\n"
            "from geometry_msgs.msg import PoseStamped\n"
            "from nav2_simple_commander.robot_navigator import BasicNavigator\n"
            "from tf_transformations import Quaternion\n"
            "def main():\n"
            "    rclpy.init()\n"
            "    nav = BasicNavigator()\n"
            "    goal = PoseStamped()\n"
            "    q = Quaternion()\n"
            "    nav.goToPose(goal)\n")
    generate = ("from clearpath_config.clearpath_config import ClearpathConfig\n"
                "def main():\n"
                "    ClearpathConfig('robot.yaml')\n")
    launch = ("from launch import LaunchDescription\n"
              "from launch_ros.actions import Node\n"
              "def generate_launch_description():\n"
              "    return LaunchDescription([Node(package='nav', executable='goto'),\n"
              "                              Node(package='nav', executable='generate')])\n")
    root = write_tree({
        "src/nav/package.xml": manifest,
        "src/nav/setup.py": "from setuptools import setup\n"
                            "setup(name='nav', packages=['nav'], entry_points="
                            "{'console_scripts': ['goto = nav.goto:main', "
                            "'generate = nav.generate:main']})\n",
        "src/nav/resource/nav": "",
        "src/nav/nav/__init__.py": "",
        "src/nav/nav/goto.py": goto,
        "src/nav/nav/generate.py": generate,
        "src/nav/launch/nav.launch.py": launch,
        "project.yaml": "project: p\nconfigurations:\n  c: [nav/launch/nav.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    nodes = {n.executable: n for p in model.packages for n in p.nodes}
    assert nodes["goto"].completeness == "partial"
    assert "BasicNavigator of ROS package nav2_simple_commander" in (
        nodes["goto"].completeness_reasons[0])
    assert nodes["generate"].completeness == "complete"
    said = [d for d in model.diagnostics if d.code == "PY_CLASS_UNSEEN"]
    assert [(d.location.line, d.severity) for d in said] == [(7, "info")]


def test_python_class_derived_from_one_of_an_unread_ros_package(write_tree) -> None:
    """Interbotix's xsarm_robot.py builds ``XSArmRobot``, its own subclass of
    interbotix_xs_modules' ``InterbotixManipulatorXS``, whose ``__init__`` (called as
    ``InterbotixManipulatorXS.__init__(self, ...)``) makes the node with its publishers
    and service clients: the node was 'complete' with one subscription. Building the
    subclass builds the unread base: ``PY_CLASS_UNSEEN``, partial. A subclass of rclpy's
    Node is no such class."""
    import os

    from conftest import package_xml

    from haros_arch.pipeline import Options, analyse
    from haros_arch.project import load

    manifest = package_xml("arm", build_type="ament_python").replace(
        "</package>", "<exec_depend>vendor_modules</exec_depend></package>")
    robot = ("import rclpy\n"
             "from rclpy.node import Node\n"
             "from std_msgs.msg import String\n"
             "from vendor_modules.xs_robot.arm import VendorArm\n"
             "class Robot(VendorArm):\n"
             "    def __init__(self):\n"
             "        VendorArm.__init__(self, robot_model='wx250s')\n"
             "        self.core.get_node().create_subscription(String, 'cmd', None, 10)\n"
             "class Plain(Node):\n"
             "    def __init__(self):\n"
             "        super().__init__('plain')\n"
             "        self.create_subscription(String, 'cmd', None, 10)\n"
             "def main():\n"
             "    Robot()\n")  # the base starts rclpy
    plain = robot.replace("    Robot()\n", "    rclpy.init()\n    Plain()\n")
    launch = ("from launch import LaunchDescription\n"
              "from launch_ros.actions import Node\n"
              "def generate_launch_description():\n"
              "    return LaunchDescription([Node(package='arm', executable='robot'),\n"
              "                              Node(package='arm', executable='plain')])\n")
    root = write_tree({
        "src/arm/package.xml": manifest,
        "src/arm/setup.py": "from setuptools import setup\n"
                            "setup(name='arm', packages=['arm'], entry_points="
                            "{'console_scripts': ['robot = arm.robot:main', "
                            "'plain = arm.plain:main']})\n",
        "src/arm/resource/arm": "",
        "src/arm/arm/__init__.py": "",
        "src/arm/arm/robot.py": robot,
        "src/arm/arm/plain.py": plain,
        "src/arm/launch/arm.launch.py": launch,
        "project.yaml": "project: p\nconfigurations:\n  c: [arm/launch/arm.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    nodes = {n.executable: n for p in model.packages for n in p.nodes}
    assert nodes["robot"].completeness == "partial"
    assert "VendorArm of ROS package vendor_modules" in nodes["robot"].completeness_reasons[0]
    assert nodes["plain"].completeness == "complete"
    said = [d for d in model.diagnostics if d.code == "PY_CLASS_UNSEEN"]
    assert [(d.location.file, d.location.line) for d in said] == [("arm/arm/robot.py", 14)]
