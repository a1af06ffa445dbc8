"""rclpy shapes of webots_ros2: a preset profile kept in a local whose policy is set
after (lane_follower's ``qos = qos_profile_sensor_data; qos.reliability = RELIABLE``),
and a local chosen by a conditional expression whose test is not known, used inside a
name (``prefix + ('/state' if old else '/controller_state')``)."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import Workspace

HEAD = ("import rclpy\nfrom rclpy.node import Node\n"
        "from rclpy.qos import qos_profile_sensor_data, QoSReliabilityPolicy, QoSPresetProfiles\n"
        "from std_msgs.msg import String\n"
        "class N(Node):\n"
        "    def __init__(self, prefix):\n"
        "        super().__init__('n')\n")


def _calls(tmp_path, body: str):
    source = tmp_path / "node.py"
    source.write_text(HEAD + body)
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    return result.calls


def test_a_policy_set_on_a_preset_kept_in_a_local(tmp_path) -> None:
    calls = _calls(tmp_path, (
        "        q = qos_profile_sensor_data\n"
        "        q.reliability = QoSReliabilityPolicy.RELIABLE\n"
        "        self.create_subscription(String, 'a', self.cb, q)\n"
        "        p = QoSPresetProfiles.SENSOR_DATA.value\n"
        "        p.depth = 20\n"
        "        self.create_subscription(String, 'b', self.cb, p)\n"))
    got = {c.name: (c.qos["reliability"], c.qos["depth"]) for c in calls}
    assert got == {"a": ("reliable", 5), "b": ("best_effort", 20)}


def test_a_policy_set_on_a_preset_under_a_condition_is_unknown(tmp_path) -> None:
    calls = _calls(tmp_path, (
        "        q = qos_profile_sensor_data\n"
        "        if prefix:\n"
        "            q.reliability = QoSReliabilityPolicy.RELIABLE\n"
        "        self.create_subscription(String, 'a', self.cb, q)\n"))
    assert [c.qos["reliability"] for c in calls] == [None]


def test_a_conditional_expression_gives_one_call_per_value(tmp_path) -> None:
    calls = _calls(tmp_path, (
        "        topic = '/state' if self.old() else '/controller_state'\n"
        "        self.create_subscription(String, prefix + topic, self.cb, 1)\n"
        "        self.create_publisher(String, 'ctl' + topic, 1)\n"))
    got = [(c.kind, str(c.name), [k.statement for k in c.conditions]) for c in calls]
    assert ("publish", "ctl/state", ["if"]) in got
    assert ("publish", "ctl/controller_state", ["else"]) in got
    assert len(got) == 4 and not any(name == "ctl?" for _, name, _ in got)


def test_a_test_known_statically_keeps_one_value(tmp_path) -> None:
    calls = _calls(tmp_path, (
        "        topic = 'x' if 1 > 2 else 'y'\n"
        "        self.create_publisher(String, topic, 1)\n"))
    assert [(c.name, list(c.conditions)) for c in calls] == [("y", [])]
