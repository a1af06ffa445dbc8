"""A subscriber whose name is only partly known (``/camera/image/?``: image_view's
transport comes from its nodelet arguments in a loop, not known statically) has no
publisher when nothing in the configuration publishes a name it could be, whatever the
unknown part is: video_stream_opencv's camera.launch (f2984a8's parent) starts image_view
on ``image`` in the camera's namespace, where the stream publishes only ``image_raw``.
A ``?`` that is the last segment may also be none (``raw`` subscribes the base itself),
and another name with ``?`` that could be the same name is a publisher it may meet."""

from __future__ import annotations

import pytest
from test_query_catalogue import RULES, configuration

from haros_arch.graph.candidates import find_candidates
from haros_arch.model.rosname import pattern_for
from haros_arch.query.absence import may_meet
from haros_arch.query.catalogue import UNDECIDED, run_rule

RULE = RULES["subscriber-without-publisher"]


def image_view(*published: str, unknown_node: bool = False) -> object:
    links = [{"kind": "publish", "node": "/camera/stream", "name": name, "given": name,
              "type": "sensor_msgs/Image"} for name in published]
    links.append({"kind": "subscribe", "node": "/camera/view", "name": "/camera/image/?",
                  "given": "image/?", "type": "sensor_msgs/Image"})
    doc: dict = {"links": links}
    if unknown_node:
        doc["nodes"] = [{"name": "/driver", "node": None}]
    model = configuration(doc)
    find_candidates(model.configurations[0])
    return model


def found(model: object) -> list[tuple[str, tuple[str, ...]]]:
    return [(f.rule, f.entities) for f in run_rule(RULE, model)]


def test_a_partly_unknown_name_no_publisher_could_have_is_a_finding():
    model = image_view("/camera/image_raw", "/camera/image_raw/compressed")
    assert found(model) == [("subscriber-without-publisher",
                             ("node:/camera/view", "topic:/camera/image/?"))]
    message = run_rule(RULE, model)[0].message
    assert "/camera/image/?" in message


@pytest.mark.parametrize("published", [
    "/camera/image",             # raw: the base itself
    "/camera/image/compressed",  # a transport's topic
    "/?/image/theora",           # another name with ? that could be the same
    "/camera/?",
])
def test_a_publisher_the_name_could_be_is_its_publisher(published):
    assert found(image_view("/camera/image_raw", published)) == []


def test_a_node_of_unknown_interface_leaves_it_undecided():
    assert [rule for rule, _ in found(image_view("/camera/image_raw", unknown_node=True))] == [
        "subscriber-without-publisher" + UNDECIDED]


@pytest.mark.parametrize("name", ["?", "/?", "?/?"])
def test_a_name_of_which_nothing_is_known_claims_nothing(name):
    # it could be /tf or /clock, which drivers and tools outside the configuration serve
    model = configuration({"links": [{"kind": "subscribe", "node": "/n", "name": name,
                                      "given": name, "type": "std_msgs/String"}]})
    find_candidates(model.configurations[0])
    assert found(model) == []


def test_a_last_unknown_segment_may_be_none():
    import re
    pattern = re.compile(pattern_for("/camera/image/?"))
    assert pattern.match("/camera/image") and pattern.match("/camera/image/compressed")
    assert not pattern.match("/camera/image_raw")
    assert not re.match(pattern_for("/?"), "")  # the root's one segment is still one


@pytest.mark.parametrize(("first", "second", "meet"), [
    ("/camera/image/?", "/camera/image", True),
    ("/a/?/b", "/?/b", True),
    ("/a/?/b", "/?/c", False),
    ("/x/?", "/y/?", False),
    ("?", "/anything", True),
])
def test_two_names_with_unknown_parts_meet_when_some_name_fits_both(first, second, meet):
    assert may_meet(first, second) is meet
    assert may_meet(second, first) is meet


def test_a_partly_unknown_client_name_no_server_could_have_is_a_finding():
    # camera_calibration's cameracalibrator calls <camera>/set_camera_info, its camera
    # named at run time: ``?/set_camera_info``
    def calibrator(*served: str) -> object:
        links = [{"kind": "server", "node": "/driver", "name": name, "given": name,
                  "type": "sensor_msgs/SetCameraInfo"} for name in served]
        links.append({"kind": "client", "node": "/calibrator", "name": "?/set_camera_info",
                      "given": "?/set_camera_info", "type": "sensor_msgs/SetCameraInfo"})
        model = configuration({"links": links})
        find_candidates(model.configurations[0])
        return model

    rule = RULES["client-without-server"]
    assert [(f.rule, f.entities) for f in run_rule(rule, calibrator("/driver/reset"))] == [
        ("client-without-server", ("node:/calibrator", "service:?/set_camera_info"))]
    assert run_rule(rule, calibrator("/camera/set_camera_info")) == []
    assert run_rule(rule, calibrator("/?/set_camera_info")) == []
