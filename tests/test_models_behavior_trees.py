"""An interface model may hold a package's BehaviorTree.CPP libraries and a tree host's
default trees (``bt_libraries``, ``bt_trees``): nav2_behavior_tree's and
nav2_bt_navigator's, which a navigator of an installed navigation2 runs."""

from __future__ import annotations

import json

import pytest

from haros_arch.model.location import Location
from haros_arch.models.format import ModelFileError, dumps, from_document
from haros_arch.models.library import Library
from haros_arch.plugins.behavior_trees import (
    Registered,
    Tag,
    Tree,
    registered_data,
    registered_from_data,
    tree_data,
    tree_from_data,
)


def test_registrations_and_trees_round_trip_through_a_model_document() -> None:
    each = Registered("Watch", "my_bt::Watch", "my_bt_nodes",
                      Location("my_bt", "my_bt/src/nodes.cpp", 12, 0), None, None, None,
                      [("subscribe", "std_msgs/msg/Bool", ("port", "watch_topic"))],
                      {"watch_topic": "/watched"})
    tree = Tree([Tag("Spin", {"spin_dist": "1.57"}, Location("p", "p/t.xml", 7, 0))],
                {"Main"}, [], ["a reason"])
    data = {"schema": "haros-arch-model/2", "package": "my_bt", "distro": "jazzy",
            "nodes": [], "bt_libraries": {"my_bt_nodes": [registered_data(each)]},
            "bt_trees": {"trees/main.xml": tree_data(tree)}}
    model = from_document(json.loads(dumps(from_document(data))))
    (back,) = [registered_from_data(e, "my_bt_nodes", "my_bt")
               for e in model.bt_libraries["my_bt_nodes"]]
    assert back == each
    assert tree_from_data(model.bt_trees["trees/main.xml"], "p") == tree


@pytest.mark.parametrize("field, value", [("bt_libraries", []), ("bt_trees", {"x": 1}),
                                          ("bt_libraries", {"lib": "not a list"})])
def test_a_model_with_a_malformed_tree_field_is_refused(field: str, value: object) -> None:
    data = {"schema": "haros-arch-model/2", "package": "p", "distro": "jazzy", "nodes": [],
            field: value}
    with pytest.raises(ModelFileError):
        from_document(data)


def test_malformed_entries_are_skipped_not_fatal() -> None:
    assert registered_from_data({"class": "no id"}, "lib", "p") is None
    odd = registered_from_data({"id": "X", "location": {"line": "7"}, "calls": [[1, 2]],
                                "ports": {"a": 1}}, "lib", "p")
    assert odd is not None and odd.location.line == 0 and odd.calls == []
    assert odd.ports == {"a": "1"}
    assert tree_from_data([], "p") is None


def test_the_shipped_nav2_models_hold_the_libraries_and_default_trees() -> None:
    library = Library()
    for distro in ("jazzy", "humble"):
        tree_nodes = library.find("nav2_behavior_tree", distro)
        navigator = library.find("nav2_bt_navigator", distro)
        assert tree_nodes is not None and navigator is not None
        ids = {e["id"] for entries in tree_nodes.bt_libraries.values() for e in entries}
        assert {"ComputePathToPose", "FollowPath", "Spin", "ClearEntireCostmap"} <= ids
        assert "nav2_compute_path_to_pose_action_bt_node" in tree_nodes.bt_libraries
        assert "behavior_trees/navigate_to_pose_w_replanning_and_recovery.xml" in (
            navigator.bt_trees)
        assert not library.diagnostics

