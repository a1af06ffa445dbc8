"""Calls the regenerated interface models lost (issue 15), each on a small fixture:
fixtures/cpp/model_regressions."""

from __future__ import annotations

import os

from haros_arch.extract.cpp import CppResult, extract_cpp, recall
from haros_arch.workspace import scan

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "model_regressions")


def extract(package: str, name: str) -> CppResult:
    path = os.path.join(ROOT, "src", package, "src", name)
    return extract_cpp([path], scan([ROOT]), cache_dir=None, jobs=1)


def rows(result: CppResult) -> list[tuple[str, str, str | None, int, bool]]:
    return [(c.kind, c.name, c.type, c.location.line, c.latch) for c in result.calls]


def test_camera_publisher_with_connect_callbacks() -> None:
    # image_proc crop_decimate.cpp:103; the plain overload's latch is its third argument
    assert rows(extract("ros1_fixes", "camera_cb.cpp")) == [
        ("publish", "image_raw", "sensor_msgs/Image", 12, False),
        ("publish", "camera_info", "sensor_msgs/CameraInfo", 12, False),
        ("publish", "still", "sensor_msgs/Image", 13, True),
        ("publish", "camera_info", "sensor_msgs/CameraInfo", 13, True),
        ("subscribe", "image_in", "sensor_msgs/Image", 15, False),
        ("subscribe", "camera_info", "sensor_msgs/CameraInfo", 15, False),
    ]


def test_tf_listener_reads_tf_prefix_where_it_resolves() -> None:
    # tf/transform_listener.h: resolve and tf::remap search ~tf_prefix
    result = extract("ros1_fixes", "remap.cpp")
    assert rows(result) == [("read", "~tf_prefix", None, 6, False)]
    assert result.calls[0].searched


def test_gtest_bodies_are_read() -> None:
    # tf's transform_listener_unittest lost all six calls to TEST's parse errors
    result = extract("ros1_fixes", "listener_test.cpp")
    assert rows(result) == [
        ("subscribe", "/tf", "tf2_msgs/TFMessage", 8, False),
        ("subscribe", "/tf_static", "tf2_msgs/TFMessage", 8, False),
        ("write", "~tf_prefix", "str", 9, False),
        ("read", "~tf_prefix", None, 10, False),
        ("read", "rate", None, 19, False),
        ("write", "gain", "double", 20, False),
        ("read", "rate", "double", 21, False),
    ]
    assert not [d for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"]


def test_class_template_client_built_as_member_and_local() -> None:
    # nav2_util lifecycle_service_client.cpp:35-36: ServiceClient<T> members built in the
    # constructor's initialiser list, as make_shared already was
    assert rows(extract("ros2_fixes", "lifecycle_client.cpp")) == [
        ("client", "map_server/change_state", "lifecycle_msgs/srv/ChangeState", 15, False),
        ("client", "map_server/get_state", "lifecycle_msgs/srv/GetState", 16, False),
        ("client", "probe", "lifecycle_msgs/srv/GetState", 18, False),
        ("client", "shared", "lifecycle_msgs/srv/GetState", 19, False),
    ]


def test_private_prefix_kept_when_the_rest_is_unknown() -> None:
    # fetch_depth_layer depth_layer.cpp:61: NodeHandle("~/" + name_), name_ of a base class
    # whose header is missing: clang drops the initialiser
    assert rows(extract("ros1_fixes", "layer_ns.cpp")) == [
        ("publish", "~?/clearing", "std_msgs/String", 10, False)]


def test_factory_of_a_class_template_with_two_arguments() -> None:
    # nav2_amcl amcl_node.cpp:1535: make_unique<message_filters::Subscriber<M, Node>>(...)
    # was read as a make_unique of M, its first written type
    result = extract("ros2_fixes", "scan_filter.cpp")
    assert ("subscribe", "scan", "sensor_msgs/msg/LaserScan", 19, False) in rows(result)


def test_ros2_wrapper_without_callers_in_its_unit_keeps_its_calls() -> None:
    # realsense2_camera dynamic_params.cpp:104, 179: setParamT's callers are in the
    # node's other files; its calls were dropped as a wrapper's, emitted nowhere
    found = {(kind, name, line) for kind, name, _, line, _ in
             rows(extract("ros2_fixes", "set_param.cpp"))}
    assert {("read", "?", 25), ("declare", "?", 25)} <= found


def test_recall_grep_sees_constructions_of_api_classes() -> None:
    # the recall check did not flag amcl_node.cpp:1535 when its subscription was missed
    text = ("  sub_ = std::make_unique<message_filters::Subscriber<sensor_msgs::msg::LaserScan,\n"
            "  auto l = std::make_shared<tf2_ros::TransformListener>(*buffer);\n"
            "  raw_ = new message_filters::Subscriber<M>(nh, \"x\", 1);\n"
            "  auto s = std::make_shared<ros::Subscriber>();\n")
    assert [site.line for site in recall.call_sites(text)] == [1, 2, 3]
