"""A subscription to the frame tree in a namespace that nothing publishes, while the
configuration publishes the tree elsewhere: pilz_robots' speed observer, started in
``prbt``, waited on the relative name ``tf`` (``/prbt/tf``) while the transforms go on
``/tf`` (fixed upstream in 79695c1). tf and tf_static were left out of
subscriber-without-publisher wherever they are, as a convention a driver outside the
configuration may serve; where the configuration itself publishes the tree on another
name, the subscriber is cut off from it."""

from __future__ import annotations

from haros_arch.model.load import from_data
from haros_arch.query.catalogue import load_catalogue, run_rule

RULE = next(rule for rule in load_catalogue() if rule.id == "subscriber-without-publisher")


def _run(links: list[dict]) -> list[str]:
    nodes = [{"name": n, "node": f"known{n.replace('/', '_')}/node"}
             for n in dict.fromkeys(link["node"] for link in links)]
    model = from_data({"project": "p", "configurations": [
        {"name": "c", "nodes": nodes, "links": links}]})
    return sorted(f"{f.rule}: {f.message}" for f in run_rule(RULE, model))


TF = "tf2_msgs/TFMessage"
OBSERVER = {"kind": "subscribe", "node": "/prbt/speed_observer", "name": "/prbt/tf",
            "given": "tf", "type": TF}
STATE_PUBLISHER = {"kind": "publish", "node": "/prbt/robot_state_publisher", "name": "/tf",
                   "given": "/tf", "type": TF}


def test_a_namespaced_tree_no_one_publishes_while_the_root_one_is_published() -> None:
    assert _run([OBSERVER, STATE_PUBLISHER]) == [
        "subscriber-without-publisher: /prbt/speed_observer subscribes to /prbt/tf but "
        "nothing publishes it"]


def test_tf_static_too() -> None:
    static = {**OBSERVER, "name": "/prbt/tf_static", "given": "tf_static"}
    published = {**STATE_PUBLISHER, "name": "/tf_static", "given": "/tf_static"}
    assert _run([static, published]) == [
        "subscriber-without-publisher: /prbt/speed_observer subscribes to /prbt/tf_static "
        "but nothing publishes it"]


def test_a_namespaced_tree_that_is_published_is_silent() -> None:
    remapped = {**STATE_PUBLISHER, "name": "/prbt/tf", "given": "tf"}
    assert _run([OBSERVER, remapped, STATE_PUBLISHER]) == []


def test_a_tree_published_nowhere_in_the_configuration_stays_a_convention() -> None:
    # a driver started elsewhere may publish it: as before, not said
    assert _run([OBSERVER]) == []
    assert _run([{**OBSERVER, "name": "/tf", "given": "/tf"}]) == []


def test_other_conventions_in_a_namespace_are_not_concerned() -> None:
    updates = {"kind": "subscribe", "node": "/ui", "name": "/prbt/driver/parameter_updates",
               "given": "parameter_updates", "type": "dynamic_reconfigure/Config"}
    elsewhere = {"kind": "publish", "node": "/x", "name": "/x/parameter_updates",
                 "given": "~parameter_updates", "type": "dynamic_reconfigure/Config"}
    assert _run([updates, elsewhere]) == []


def test_the_global_name_a_remap_moves_into_a_namespace_is_the_launchs_convention() -> None:
    # tf2's listener subscribes /tf; a launch remap /tf:=tf moves it into the node's
    # namespace (navigation2's bringup): not the code's mistake, as before not said
    remapped = {**OBSERVER, "given": "/tf"}
    assert _run([remapped, STATE_PUBLISHER]) == []
