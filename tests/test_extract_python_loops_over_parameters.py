"""rbx1's head_tracker.py (pirobot/rbx1 0a408c1) reads ``~head_pan_joint`` and
``~head_tilt_joint``, puts the two values in ``self.joints`` and, ``for joint in
sorted(self.joints)``, makes a client of ``'/' + joint + '/set_speed'`` and a publisher of
``'/' + joint + '/command'`` for each; its dynamixel_joint_state_publisher.py walks
``sorted(self.joints)``, the list parameter ``/joints``, and subscribes to
``controller + '/state'`` for each (survey surveyB). Three gaps made those names '?':

- the two calls of one site named by different parameters were one: the second's
  parameter was lost (the graph had ``/head_pan_joint/command`` and no tilt topic);
- ``sorted(...)``, ``reversed(...)``, ``list(...)``, ``tuple(...)`` of a known sequence was
  not walked item by item (the loop kept its variable unknown);
- nor was such a call around a list parameter's value (no "for each")."""

from __future__ import annotations

from haros_arch.extract.python import PythonResult, extract_python
from haros_arch.workspace import Workspace

HEAD = ("import rospy\nfrom std_msgs.msg import Float64\n"
        "class Tracker(object):\n"
        "    def __init__(self):\n")


def run(tmp_path, body: str) -> PythonResult:
    source = tmp_path / "node.py"
    source.write_text(HEAD + body + "rospy.init_node('tracker')\nTracker()\n")
    return extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")


def made(result: PythonResult) -> list[tuple[object, ...]]:
    return [(c.kind, c.name, c.name_param, c.name_each,
             tuple(str(x) for x in c.conditions)) for c in result.calls
            if c.kind != "read"]


def test_one_site_named_by_two_parameters_is_two_calls(tmp_path) -> None:
    result = run(tmp_path,
                 "        pan = rospy.get_param('~head_pan_joint', 'head_pan_joint')\n"
                 "        tilt = rospy.get_param('~head_tilt_joint', 'head_tilt_joint')\n"
                 "        for joint in [pan, tilt]:\n"
                 "            rospy.Publisher('/' + joint + '/command', Float64,"
                 " queue_size=5)\n")
    assert made(result) == [("publish", "/?/command", "~head_pan_joint", None, ()),
                            ("publish", "/?/command", "~head_tilt_joint", None, ())]


def test_sorted_and_reversed_known_sequences_are_walked_item_by_item(tmp_path) -> None:
    result = run(tmp_path,
                 "        for side in sorted(['right', 'left']):\n"
                 "            rospy.Publisher(side + '/a', Float64, queue_size=1)\n"
                 "        for side in reversed(('front', 'back')):\n"
                 "            rospy.Publisher(side + '/b', Float64, queue_size=1)\n"
                 "        pan = rospy.get_param('~pan', 'pan')\n"
                 "        for joint in sorted([pan, 'tilt']):\n"
                 "            rospy.Publisher(joint + '/c', Float64, queue_size=1)\n")
    assert made(result) == [
        ("publish", "left/a", None, None, ()), ("publish", "right/a", None, None, ()),
        ("publish", "back/b", None, None, ()), ("publish", "front/b", None, None, ()),
        ("publish", "?/c", "~pan", None, ()), ("publish", "tilt/c", None, None, ())]


def test_sorted_list_parameter_is_walked_element_by_element(tmp_path) -> None:
    result = run(tmp_path,
                 "        self.joints = rospy.get_param('/joints', '')\n"
                 "        for c in sorted(self.joints):\n"
                 "            rospy.Subscriber(c + '/state', Float64, None)\n")
    each = ("for each (c in sorted(self.joints))",)
    assert made(result) == [("subscribe", "?/state", "/joints", ".", each)]


def test_a_parameter_read_in_the_node_namespace_names_its_calls_as_read(tmp_path) -> None:
    """rbx1's relax_all_servos.py reads ``rospy.get_namespace() + '/joints'``, the read
    ``joints`` (relative: in the node's namespace); the calls named by its elements took
    ``?/joints`` for their parameter, a name no launch file sets."""
    result = run(tmp_path,
                 "        namespace = rospy.get_namespace()\n"
                 "        self.joints = rospy.get_param(namespace + '/joints', '')\n"
                 "        for c in sorted(self.joints):\n"
                 "            rospy.Publisher('/' + c + '/command', Float64, queue_size=1)\n")
    each = ("for each (c in sorted(self.joints))",)
    assert [c.name for c in result.calls if c.kind == "read"] == ["joints"]
    assert made(result) == [("publish", "/?/command", "joints", ".", each)]


def test_a_list_made_with_list_is_an_empty_list(tmp_path) -> None:
    """rbx1's dynamixel_joint_state_publisher.py: ``self.controllers = list()``, an
    element appended per joint of the list parameter ``/joints``, then a subscription per
    controller: ``list()`` was an unknown value, so the appends were lost and
    ``?/state`` named by nothing; it is ``[]``, as ``tuple()`` is ``()``, and
    ``list(seq)`` a copy of a known sequence."""
    result = run(tmp_path,
                 "        self.joints = rospy.get_param('/joints', '')\n"
                 "        self.controllers = list()\n"
                 "        for controller in sorted(self.joints):\n"
                 "            self.controllers.append(controller)\n"
                 "        [rospy.Subscriber(c + '/state', Float64, None)"
                 " for c in self.controllers]\n"
                 "        for side in list(('left', 'right')):\n"
                 "            rospy.Publisher(side + '/x', Float64, queue_size=1)\n")
    assert made(result) == [("subscribe", "?/state", "/joints", ".", ()),
                            ("publish", "left/x", None, None, ()),
                            ("publish", "right/x", None, None, ())]
