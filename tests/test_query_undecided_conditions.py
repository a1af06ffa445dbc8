"""A finding whose premise exists only under a condition the configuration does not
decide is undecided, not a warning or an error: sick_scan_xd subscribes /odom and
/nav_odom_velocity only ``if (getScannerName().compare(SICK_SCANNER_NAV_350_NAME) == 0)``
(sick_scan_common.cpp:634), a scanner type read at run time; subscriber-without-publisher
reported both as warnings in its 25 other scanners' configurations, reading "unknown" as
"true". Each rule that rests on links, node instances or parameters existing now counts
such a match in its ``<id>-undecided`` info, which names the condition; a rule that rests
on an absence (no publisher, nobody reads it) counts one whose only partners exist under
undecided conditions there too, where it used to say nothing. A condition that the
entities of a finding share (a launch ``if`` of both, the same ``if`` of one node) is
no reason: the one exists wherever the other does. A ``try`` block is no condition, nor
a ``do ... while`` loop, whose body runs at least once."""

from __future__ import annotations

import pytest
import yaml
from test_query_catalogue import RULES, configuration

from haros_arch.query.catalogue import UNDECIDED, run_rule

NAV350 = ("{text: 'getScannerName().compare(NAV_350) == 0', kind: source, statement: if, "
          "location: {package: s, file: src/sick_scan_common.cpp, line: 634}}")
JOY = ("{text: '$(arg joy)', kind: launch, statement: if, "
       "location: {file: launch/a.launch, line: 3}}")
TRY = "{text: '', kind: source, statement: try}"
DO = "{text: 'more', kind: source, statement: do}"


def findings(rule_id: str, text: str) -> dict[str, list[str]]:
    found: dict[str, list[str]] = {}
    for f in run_rule(RULES[rule_id], configuration(yaml.safe_load(text))):
        found.setdefault(f.rule, []).append(f.message)
    return found


# rule, model where the premise exists only under an undecided condition, the condition's
# text named in the info
CASES = {
    # the subscription itself is conditional (sick_scan_xd's NAV350 one)
    "subscriber-without-publisher": (f"""
links:
  - {{kind: subscribe, node: /sick_scan, name: /odom, type: nav_msgs/Odometry,
     conditions: [{NAV350}]}}
""", "compare(NAV_350) == 0) at src/sick_scan_common.cpp:634"),
    # its only publisher is conditional: no longer no finding at all
    "subscriber-without-publisher#partner": (f"""
links:
  - {{kind: subscribe, node: /base, name: /cmd_vel, type: geometry_msgs/Twist}}
  - {{kind: publish, node: /teleop, name: /cmd_vel, type: geometry_msgs/Twist,
     conditions: [{JOY}]}}
""", "if ($(arg joy)) at launch/a.launch:3"),
    "publisher-without-subscriber": (f"""
links:
  - {{kind: publish, node: /sick_scan, name: /nav_pose, type: geometry_msgs/Pose,
     conditions: [{NAV350}]}}
""", "compare(NAV_350) == 0)"),
    "publisher-without-subscriber#partner": (f"""
links:
  - {{kind: publish, node: /base, name: /odom, type: nav_msgs/Odometry}}
  - {{kind: subscribe, node: /teleop, name: /odom, type: nav_msgs/Odometry,
     conditions: [{JOY}]}}
""", "if ($(arg joy))"),
    "rviz-display-without-data#partner": (f"""
links:
  - {{kind: subscribe, node: /rviz, name: /scan, type: sensor_msgs/LaserScan,
     origin: config}}
  - {{kind: publish, node: /sick_scan, name: /scan, type: sensor_msgs/LaserScan,
     conditions: [{NAV350}]}}
""", "compare(NAV_350) == 0)"),
    "similar-disconnected-topics": (f"""
links:
  - {{kind: publish, node: /driver, name: /front/scan, type: sensor_msgs/LaserScan,
     conditions: [{NAV350}]}}
  - {{kind: subscribe, node: /slam, name: /scan, type: sensor_msgs/LaserScan}}
""", "compare(NAV_350) == 0)"),
    "similar-disconnected-topics#partner": (f"""
links:
  - {{kind: publish, node: /driver, name: /front/scan, type: sensor_msgs/LaserScan}}
  - {{kind: subscribe, node: /slam, name: /scan, type: sensor_msgs/LaserScan}}
  - {{kind: subscribe, node: /logger, name: /front/scan, type: sensor_msgs/LaserScan,
     conditions: [{JOY}]}}
""", "if ($(arg joy))"),
    "topic-type-mismatch": (f"""
links:
  - {{kind: publish, node: /sick_scan, name: /odom, type: std_msgs/String,
     conditions: [{NAV350}]}}
  - {{kind: subscribe, node: /base, name: /odom, type: nav_msgs/Odometry}}
""", "compare(NAV_350) == 0) at src/sick_scan_common.cpp:634"),
    "service-type-mismatch": (f"""
links:
  - {{kind: server, node: /arm, name: /arm/home, type: std_srvs/Trigger,
     conditions: [{NAV350}]}}
  - {{kind: client, node: /ui, name: /arm/home, type: std_srvs/Empty}}
""", "compare(NAV_350) == 0)"),
    "action-type-mismatch": (f"""
links:
  - {{kind: action-server, node: /arm, name: /arm/move, type: arm_msgs/Move}}
  - {{kind: action-client, node: /ui, name: /arm/move, type: arm_msgs/Go,
     conditions: [{JOY}]}}
""", "if ($(arg joy))"),
    "qos-incompatible": (f"""
links:
  - {{kind: publish, node: /cam, name: /image, type: sensor_msgs/Image,
     qos: {{reliability: best_effort}}, conditions: [{NAV350}]}}
  - {{kind: subscribe, node: /viewer, name: /image, type: sensor_msgs/Image,
     qos: {{reliability: reliable}}}}
""", "compare(NAV_350) == 0)"),
    # two publishers, one of them only under a condition of its code
    "multiple-publishers": (f"""
links:
  - {{kind: publish, node: /a, name: /cmd, type: geometry_msgs/Twist}}
  - {{kind: publish, node: /b, name: /cmd, type: geometry_msgs/Twist,
     conditions: [{NAV350}]}}
""", "compare(NAV_350) == 0)"),
    # two servers of one service, one of them only under a condition of its code
    "multiple-service-servers": (f"""
links:
  - {{kind: server, node: /map_a, name: /static_map, type: nav_msgs/GetMap}}
  - {{kind: server, node: /map_b, name: /static_map, type: nav_msgs/GetMap,
     conditions: [{NAV350}]}}
""", "compare(NAV_350) == 0)"),
    # the call itself is conditional, then its only server is
    "client-without-server": (f"""
links:
  - {{kind: client, node: /ui, name: /arm/home, type: std_srvs/Trigger,
     conditions: [{NAV350}]}}
""", "compare(NAV_350) == 0)"),
    "client-without-server#action#partner": (f"""
links:
  - {{kind: action-client, node: /ui, name: /arm/move, type: arm_msgs/Move}}
  - {{kind: action-server, node: /arm, name: /arm/move, type: arm_msgs/Move,
     conditions: [{NAV350}]}}
""", "compare(NAV_350) == 0)"),
    "client-without-server#partner": (f"""
links:
  - {{kind: client, node: /ui, name: /arm/home, type: std_srvs/Trigger}}
  - {{kind: server, node: /arm, name: /arm/home, type: std_srvs/Trigger,
     conditions: [{JOY}]}}
""", "if ($(arg joy)) at launch/a.launch:3"),
    "parameter-type-mismatch": (f"""
parameters:
  - {{name: /base/rate, type: str, value: fast, writers: ["<launch>"], conditions: [{JOY}]}}
links:
  - {{kind: read, node: /base, name: /base/rate, given: ~rate, type: double}}
""", "if ($(arg joy))"),
    "parameter-set-not-read": (f"""
parameters:
  - {{name: /base/rate, type: double, value: 1.0, writers: ["<launch>"], conditions: [{JOY}]}}
links:
  - {{kind: read, node: /base, name: /base/speed, given: ~speed, type: double}}
""", "if ($(arg joy))"),
    # its only reader reads it only under a condition: no longer no finding at all
    "parameter-set-not-read#partner": (f"""
parameters:
  - {{name: /base/rate, type: double, value: 1.0, writers: ["<launch>"]}}
links:
  - {{kind: read, node: /base, name: /base/rate, given: ~rate, type: double,
     conditions: [{NAV350}]}}
""", "compare(NAV_350) == 0)"),
    "parameter-read-not-set": (f"""
links:
  - {{kind: read, node: /base, name: /base/rate, given: ~rate, type: double,
     conditions: [{NAV350}]}}
""", "compare(NAV_350) == 0)"),
    # read without a default only under a condition; another read has a default
    "parameter-read-not-set#default": (f"""
packages:
  - {{name: base, nodes: [{{name: base/base, package: base, executable: base,
     calls: [{{kind: read, name: ~rate, type: double, default: 10.0, has_default: true,
               location: {{file: base/src/base.cpp, line: 20}}}}]}}]}}
nodes:
  - {{name: /base, node: base/base}}
links:
  - {{kind: read, node: /base, name: /base/rate, given: ~rate, type: double,
     location: {{file: base/src/base.cpp, line: 20}}}}
  - {{kind: read, node: /base, name: /base/rate, given: ~rate, type: double,
     location: {{file: base/src/base.cpp, line: 30}}, conditions: [{NAV350}]}}
""", "compare(NAV_350) == 0)"),
    # set only under a launch condition the reader does not have
    "parameter-read-not-set#partner": (f"""
parameters:
  - {{name: /base/rate, type: double, value: 1.0, writers: ["<launch>"], conditions: [{JOY}]}}
links:
  - {{kind: read, node: /base, name: /base/rate, given: ~rate, type: double}}
""", "if ($(arg joy))"),
    # the only use of the remap's name is a call under a condition of the node's code
    "remap-unused#partner": (f"""
nodes:
  - {{name: /teleop, node: known_teleop/node, remaps: [[cmd_vel, /base/cmd_vel]],
     remaps_applied: [/cmd_vel]}}
links:
  - {{kind: publish, node: /teleop, name: /base/cmd_vel, given: cmd_vel,
     type: geometry_msgs/Twist, conditions: [{NAV350}]}}
""", "compare(NAV_350) == 0)"),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_premise_under_an_undecided_condition_is_one_info_naming_it(case) -> None:
    rule_id = case.split("#")[0]
    model, condition = CASES[case]
    found = findings(rule_id, model)
    assert list(found) == [rule_id + UNDECIDED], found
    (message,) = found[rule_id + UNDECIDED]
    assert message.startswith("1 possible finding(s) not reported"), message
    assert condition in message, message
    assert "exists only under a condition not decided" in message


# the same models with the conditions taken off (decided true) or written as a try
@pytest.mark.parametrize("case", sorted(CASES))
def test_the_same_premise_decided_or_under_a_try_is_the_finding(case) -> None:
    rule_id = case.split("#")[0]
    model, _ = CASES[case]
    if case.endswith("#partner"):  # a partner that certainly exists: nothing to say
        assert findings(rule_id, model.replace(JOY, TRY).replace(NAV350, TRY)) == {}
        return
    for text in (model.replace(f"conditions: [{JOY}]", "conditions: []").replace(
            f"conditions: [{NAV350}]", "conditions: []"),
            model.replace(JOY, TRY).replace(NAV350, TRY),
            model.replace(JOY, DO).replace(NAV350, DO)):
        found = findings(rule_id, text)
        assert list(found) == [rule_id], found


def test_a_condition_the_partners_share_is_no_reason() -> None:
    """A subscriber and its publisher under one launch condition exist together: no
    finding; the same source condition of two nodes (each its own value) is a reason."""
    shared = f"""
links:
  - {{kind: subscribe, node: /base, name: /cmd_vel, type: geometry_msgs/Twist,
     conditions: [{JOY}]}}
  - {{kind: publish, node: /teleop, name: /cmd_vel, type: geometry_msgs/Twist,
     conditions: [{JOY}]}}
"""
    assert findings("subscriber-without-publisher", shared) == {}
    own = shared.replace(JOY, NAV350)
    assert list(findings("subscriber-without-publisher", own)) == [
        "subscriber-without-publisher" + UNDECIDED]
    mismatch = shared.replace("/teleop, name: /cmd_vel, type: geometry_msgs/Twist",
                              "/teleop, name: /cmd_vel, type: std_msgs/String")
    # a type mismatch of two that exist only together is still under the condition
    assert list(findings("topic-type-mismatch", mismatch)) == [
        "topic-type-mismatch" + UNDECIDED]


def test_two_publishers_that_certainly_run_are_the_warning_whatever_a_third() -> None:
    model = f"""
links:
  - {{kind: publish, node: /a, name: /cmd, type: geometry_msgs/Twist}}
  - {{kind: publish, node: /b, name: /cmd, type: geometry_msgs/Twist}}
  - {{kind: publish, node: /c, name: /cmd, type: geometry_msgs/Twist,
     conditions: [{NAV350}]}}
"""
    assert list(findings("multiple-publishers", model)) == ["multiple-publishers"]


def test_a_call_in_the_body_of_a_do_loop_is_not_conditional() -> None:
    model = f"""
links:
  - {{kind: publish, node: /ekf, name: /odometry/filtered, type: nav_msgs/Odometry,
     conditions: [{DO}]}}
  - {{kind: publish, node: /ekf, name: /odometry/twist, type: nav_msgs/Odometry,
     conditions: [{DO}, {NAV350}]}}
"""
    found = findings("conditional-communication", model)
    assert len(found["conditional-communication"]) == 1
    assert "/odometry/twist" in found["conditional-communication"][0]


def test_a_node_a_timer_action_starts_exists() -> None:
    """A ROS 2 TimerAction starts what it holds once its period has passed: no condition
    of its existing (its launch condition is ``timer``)."""
    timer = ("{text: 'after timer period=2.0', kind: launch, statement: timer, "
             "location: {file: launch/a.launch.py, line: 9}}")
    model = f"""
links:
  - {{kind: subscribe, node: /late, name: /odom, type: nav_msgs/Odometry,
     conditions: [{timer}]}}
"""
    assert list(findings("subscriber-without-publisher", model)) == [
        "subscriber-without-publisher"]
    assert findings("conditional-communication", model) == {}


def test_a_call_in_a_loop_over_the_node_running_is_not_conditional() -> None:
    """kinova_arm_driver builds its arm (which advertises out/joint_angles and the rest)
    in the body of ``while (ros::ok())``, to build it again after a failure: its first
    turn runs whenever the node does. Its publishers were "conditional", and every
    absence they could fill undecided. A loop over anything else stays a condition."""
    def loop(text: str) -> str:
        return f"{{text: '{text}', kind: source, statement: while}}"

    running = ["ros::ok()", "!ros::isShuttingDown()", "rclcpp::ok()",
               "not rospy.is_shutdown()", "rclpy.ok() and not rospy.is_shutdown()",
               # a literal truth: rosboard's ``while True:`` around its subscriptions
               "True", "true", "(1)"]
    for text in running:
        model = f"""
links:
  - {{kind: publish, node: /driver, name: /driver/out/joint_angles, type: a/JointAngles,
     conditions: [{loop(text)}, {TRY}]}}
  - {{kind: subscribe, node: /tf_updater, name: /arm_driver/out/joint_angles,
     type: a/JointAngles}}
"""
        assert findings("conditional-communication", model) == {}, text
        found = findings("subscriber-without-publisher", model)
        assert list(found) == ["subscriber-without-publisher"], (text, found)
    for text in ("running_", "ros::ok() && running_", "nh.ok()", "True_", "10"):
        model = f"""
links:
  - {{kind: publish, node: /driver, name: /joint_angles, type: a/JointAngles,
     conditions: [{loop(text)}]}}
"""
        assert list(findings("conditional-communication", model)) == [
            "conditional-communication"], text


def test_a_call_after_leaving_when_the_node_stops_is_not_conditional() -> None:
    """ros_whill a03988c opens its serial port in ``while (ros::ok())``, leaves the outer
    loop ``if(!ros::ok())break;`` and then reads its nine ``init_speed/*`` parameters:
    they exist under ``else (!ros::ok())``, which holds whenever the node runs, yet the
    parameters its launch file sets were "not decided". So is an ``if`` over the node's
    running. The ``else`` of any other test stays a condition, and so does a test that
    holds only while the node runs (``else (ros::ok())``)."""
    def side(statement: str, text: str) -> str:
        return f"{{text: '{text}', kind: source, statement: {statement}}}"

    running = [side("else", t) for t in (
        "!ros::ok()", "! ::ros::ok()", "ros::isShuttingDown()", "!rclcpp::ok()",
        "rospy.is_shutdown()", "rospy.core.is_shutdown()", "not rclpy.ok()",
        "(!ros::ok() || ros::isShuttingDown())")] + [
        side("if", t) for t in ("ros::ok()", "rclcpp::ok() && ros::ok()")]
    for condition in running:
        model = f"""
links:
  - {{kind: subscribe, node: /whill, name: /whill/controller/joy, type: sensor_msgs/Joy,
     conditions: [{condition}]}}
"""
        assert findings("conditional-communication", model) == {}, condition
        found = findings("subscriber-without-publisher", model)
        assert list(found) == ["subscriber-without-publisher"], (condition, found)
    for condition in (side("else", "ros::ok()"), side("else", "!ros::ok() && ready_"),
                      side("else", "!running_"), side("if", "!ros::ok()"),
                      side("else", "!nh.ok()"), side("if", "ros::ok() || other")):
        model = f"""
links:
  - {{kind: subscribe, node: /whill, name: /whill/controller/joy, type: sensor_msgs/Joy,
     conditions: [{condition}]}}
"""
        assert list(findings("conditional-communication", model)) == [
            "conditional-communication"], condition
