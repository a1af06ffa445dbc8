from __future__ import annotations

import pytest

from haros_arch.model.rosname import RosName, as_namespace, resolve, resolve_remaps
from haros_arch.model.values import Unknown, Value


@pytest.mark.parametrize(("name", "ns", "node", "full"), [
    ("chatter", "/", "/talker", "/chatter"),
    ("chatter", "/robot/", "/robot/talker", "/robot/chatter"),
    ("chatter", "/robot", "/robot/talker", "/robot/chatter"),
    ("/chatter", "/robot/", "/robot/talker", "/chatter"),
    ("~rate", "/robot/", "/robot/talker", "/robot/talker/rate"),
    ("~/rate", "/", "/talker", "/talker/rate"),
    ("a/b", "/x/", "/x/n", "/x/a/b"),
    # a name wholly unknown may be global: no namespace is known to hold it; one
    # partly unknown keeps what is known (relative, private)
    ("?", "/", "/talker", "?"),
    ("?", "/r/", "/r/n", "?"),
    ("a/?", "/r/", "/r/n", "/r/a/?"),
    ("~?", "/r/", "/r/n", "/r/n/?"),
    ("scan_?", "/r/", "/r/n", "/r/scan_?"),
    ("", "/ns/", "/ns/n", "/ns"),
])
def test_resolve_follows_ros1_rules(name, ns, node, full):
    assert resolve(name, ns, node) == full


def test_remaps_resolve_in_the_node_namespace():
    remaps = resolve_remaps([("monologue", "chatter"), ("~in", "/abs")], "/r/", "/r/n")
    assert remaps == {"/r/monologue": "/r/chatter", "/r/n/in": "/abs"}
    name = RosName.make("monologue", "/r/", "/r/n", remaps)
    assert (name.given, name.full, name.own, name.namespace) == (
        "monologue", "/r/chatter", "chatter", "/r/")
    assert name.is_relative and not name.is_global and not name.is_private


def test_patterns_match_candidates():
    name = RosName.make("/robot/?/scan")
    assert name.is_unresolved
    assert name.matches("/robot/left/scan")
    assert name.matches("/robot/a/b/scan")
    # a whole segment may be none: "/robot/" + "" + "/scan" is /robot/scan once roscpp's
    # names::clean (rospy's canonicalize_name) drops the empty segment
    assert name.matches("/robot/scan")
    assert not name.matches("/robotscan")
    assert not RosName.make("/chatter").matches("/chatter2")


def test_an_unknown_part_may_be_empty():
    """joint_state_broadcaster publishes ``prefix + "joint_states"``, its prefix "~/" or
    "" (``use_local_topics``): ``/?joint_states`` may be ``/joint_states`` itself, so a
    subscriber of that topic is not without a publisher."""
    name = RosName.make("?joint_states", "/", "/joint_state_broadcaster")
    assert name.matches("/joint_states")
    assert name.matches("/joint_state_broadcaster/joint_states")
    assert not name.matches("/dynamic_joint_states/x")


def test_namespaces_normalise():
    assert as_namespace("") == "/"
    assert as_namespace("a") == "/a/"
    assert as_namespace("/a//b/") == "/a/b/"


def test_values_keep_known_parts():
    value = Value.of("/", Value.unknown("arg robot"), "/scan")
    assert value.text == "/?/scan"
    assert not value.is_known
    assert value.literal is None
    assert value.origins == ("arg robot",)
    assert Value.of("a", "b").literal == "ab"
    assert (Value.of("x") + Value((Unknown("y"),))).text == "x?"


def test_an_unknown_computed_from_several_keeps_each_cause_and_saves_as_before():
    from haros_arch.model.serialise import to_data

    both = Unknown("${a + b}", causes=("arg a is not set", "arg b is not set"))
    value = Value.of("x_", both, "_", Unknown("arg c is not set"))
    assert value.text == "x_?_?"  # one unknown part for the expression, not one per cause
    assert value.origins == ("arg a is not set", "arg b is not set", "arg c is not set")
    assert to_data(both) == to_data(Unknown("${a + b}")) == {"origin": "${a + b}",
                                                             "kind": "unknown"}
