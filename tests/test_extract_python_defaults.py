"""Parameter reads record their defaults; search_param is marked as a searched name."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import Workspace


def test_defaults_and_searches(tmp_path):
    source = tmp_path / "node.py"
    source.write_text(
        "import rospy\n"
        "rospy.init_node('n')\n"
        "a = rospy.get_param('~a', 0.5)\n"
        "b = rospy.get_param('b')\n"
        "c = rospy.search_param('global_example')\n"
        "d = rospy.get_param('~d', [1, 2])\n"
        "e = rospy.get_param('~e', some_runtime_value)\n")
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    got = [(c.name, c.has_default, c.default, c.searched) for c in result.calls]
    assert got == [("~a", True, 0.5, False), ("b", False, None, False),
                   # rospy's search starts at the node's own name
                   ("~global_example", False, None, True), ("~d", True, [1, 2], False),
                   ("~e", True, None, False)]


def test_rclpy_declare_gives_the_default(tmp_path):
    source = tmp_path / "node.py"
    source.write_text(
        "import rclpy\nfrom rclpy.node import Node\n"
        "class N(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('n')\n"
        "        self.declare_parameter('rate', 10)\n"
        "        self.declare_parameter('name')\n")
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    got = [(c.kind, c.name, c.has_default, c.default) for c in result.calls]
    # the name alone: rclpy declares it dynamically typed, unset (a get returns None)
    assert got == [("declare", "rate", True, 10), ("declare", "name", True, None)]


def test_a_read_the_code_converts_has_no_type_of_its_own(tmp_path):
    """rosserial's ``int(rospy.get_param('~baud', '500000'))``: the string default does
    not make the parameter a string; any value ``int()`` takes will do (survey C)."""
    source = tmp_path / "node.py"
    source.write_text(
        "import rospy\n"
        "rospy.init_node('serial_node')\n"
        "baud = int(rospy.get_param('~baud', '500000'))\n"
        "port = rospy.get_param('~port', '/dev/ttyUSB0')\n"
        "rate = float(rospy.get_param('~rate'))\n")
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    got = [(c.name, c.type, c.has_default, c.default) for c in result.calls]
    assert got == [("~baud", None, True, "500000"), ("~port", "str", True, "/dev/ttyUSB0"),
                   ("~rate", None, False, None)]


def test_a_read_the_code_uses_as_a_dict_is_read_as_a_dict(tmp_path):
    """AutoRally's autorally_controller.py: ``self.commandPriorities =
    rospy.get_param("~chassisCommandProirities", [])``, then ``sorted(
    self.commandPriorities.items(), ...)``: the launch file loads a dict there, and the
    list default made parameter-type-mismatch say the node reads a list (survey Z30). A
    member used as no dict keeps its default's type."""
    source = tmp_path / "node.py"
    source.write_text(
        "import operator\nimport rospy\n"
        "class Controller(object):\n"
        "    def __init__(self):\n"
        "        self.priorities = rospy.get_param('~priorities', [])\n"
        "        self.priorities = sorted(self.priorities.items(),"
        " key=operator.itemgetter(1))\n"
        "        self.joints = rospy.get_param('~joints', [])\n"
        "        self.count = len(self.joints)\n"
        "rospy.init_node('controller')\n"
        "Controller()\n")
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    got = [(c.name, c.type, c.has_default, c.default) for c in result.calls]
    assert got == [("~priorities", "dict", True, []), ("~joints", "list", True, [])]


def test_an_rclpy_managed_node_serves_its_state_machine(tmp_path):
    """ros2/demos' lifecycle_py talker: a subclass of ``rclpy.lifecycle.Node`` publishes
    its transitions and serves its state machine, as rclcpp_lifecycle's node does; a
    plain ``rclpy.node.Node`` does not (survey C)."""
    source = tmp_path / "talker.py"
    source.write_text(
        "import rclpy\nfrom rclpy.lifecycle import Node\nfrom rclpy.node import Node as Plain\n"
        "from std_msgs.msg import String\n"
        "class Talker(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('lc_talker')\n"
        "    def on_configure(self, state):\n"
        "        self._pub = self.create_lifecycle_publisher(String, 'lifecycle_chatter', 10)\n"
        "class Other(Plain):\n"
        "    def __init__(self):\n"
        "        super().__init__('other')\n")
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    got = sorted((c.kind, c.name, c.node_name) for c in result.calls)
    assert got == [
        ("publish", "lifecycle_chatter", "lc_talker"),
        ("publish", "~/transition_event", "lc_talker"),
        ("server", "~/change_state", "lc_talker"),
        ("server", "~/get_available_states", "lc_talker"),
        ("server", "~/get_available_transitions", "lc_talker"),
        ("server", "~/get_state", "lc_talker"), ("server", "~/get_transition_graph", "lc_talker")]


def test_an_empty_text_default_of_a_value_walked_element_by_element_is_a_list(tmp_path):
    """rbx1's dynamixel_joint_state_publisher.py: ``self.joints = rospy.get_param(
    namespace + '/joints', '')``, then ``for controller in sorted(self.joints)``: the
    launch file loads a list there, and the empty text made parameter-type-mismatch say
    the node reads a string (survey surveyB). A text default that is not empty, or an
    empty one the code does not walk, keeps its type."""
    source = tmp_path / "node.py"
    source.write_text(
        "import rospy\n"
        "class Publisher(object):\n"
        "    def __init__(self):\n"
        "        self.joints = rospy.get_param('/joints', '')\n"
        "        self.names = rospy.get_param('~names', '')\n"
        "        self.frame = rospy.get_param('~frame', '')\n"
        "        self.prefix = rospy.get_param('~prefix', 'arm')\n"
        "        for joint in sorted(self.joints):\n"
        "            rospy.loginfo(joint)\n"
        "        self.upper = [n.upper() for n in self.names]\n"
        "        self.label = self.frame + '/base'\n"
        "        for c in self.prefix:\n"
        "            rospy.loginfo(c)\n"
        "rospy.init_node('publisher')\n"
        "Publisher()\n")
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    got = [(c.name, c.type) for c in result.calls]
    assert got == [("/joints", "list"), ("~names", "list"), ("~frame", "str"),
                   ("~prefix", "str")]


def test_a_read_kept_in_a_local_the_code_only_converts_has_no_type_of_its_own(tmp_path):
    """mbzirc2020's c3_starter.py: ``ground_id = rospy.get_param('~ground_id', '0')``,
    then only ``int(ground_id)`` and ``'{}'.format(ground_id)``: the launch file's
    integer 0 is as good as the string default, so parameter-type-mismatch said a false
    "set as int but read as str". A local used as itself somewhere (``port`` opened as a
    path), or assigned twice, keeps its default's type."""
    source = tmp_path / "node.py"
    source.write_text(
        "import rospy\n"
        "def main():\n"
        "    rospy.init_node('starter')\n"
        "    ground_id = rospy.get_param('~ground_id', '0')\n"
        "    facade_id = rospy.get_param('~facade_id', '0')\n"
        "    srv = rospy.ServiceProxy('start_facade_' + str(facade_id), Empty)\n"
        "    port = rospy.get_param('~port', '/dev/ttyUSB0')\n"
        "    rate = rospy.get_param('~rate', '10')\n"
        "    rate = int(rate)\n"
        "    if int(ground_id) != 0:\n"
        "        rospy.loginfo('Starting ground {}'.format(ground_id))\n"
        "        rospy.loginfo('facade %s' % facade_id)\n"
        "    open(port)\n"
        "main()\n")
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    got = [(c.name, c.type) for c in result.calls if c.kind == "read"]
    assert got == [("~ground_id", None), ("~facade_id", None), ("~port", "str"),
                   ("~rate", "str")]


def test_a_read_kept_in_a_local_never_used_has_no_type_of_its_own(tmp_path):
    """mobiman's plot_ocs2_log.py: ``mpc_flag = rospy.get_param('mpc_flag', 2)`` under its
    ``if __name__ == '__main__':``, and the name is never used; its YAML sets ``mpc_flag:
    false``, and parameter-type-mismatch said "set as bool but read as int" of a value
    nothing reads. A local used as itself keeps its default's type, and so does a
    module's global outside the main guard, which another module may import."""
    source = tmp_path / "node.py"
    source.write_text(
        "import rospy\n"
        "def main():\n"
        "    rospy.init_node('plotter')\n"
        "    mpc_flag = rospy.get_param('mpc_flag', 2)\n"
        "    digits = rospy.get_param('n_round_digit', 2)\n"
        "    print(round(1.2345, digits))\n"
        "main()\n"
        "shared = rospy.get_param('shared', 2)\n"
        "if __name__ == '__main__':\n"
        "    option = rospy.get_param('option', 0)\n")
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    got = [(c.name, c.type) for c in result.calls if c.kind == "read"]
    # (a module's global another module may import keeps its type)
    assert got == [("mpc_flag", None), ("n_round_digit", "int"), ("shared", "int"),
                   ("option", None)]
