"""The C++ API rows beyond roscpp's NodeHandle: actionlib, image_transport,
message_filters, tf2_ros, nodelet, ros::topic, rclcpp (QoS, parameters, sub nodes),
rclcpp_action, and names that are the values of parameters.

Each fixture source is parsed once per module; tests read the result.
"""

from __future__ import annotations

import os

import pytest
from conftest import package_xml

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.model.source import PrimitiveCall
from haros_arch.workspace import Workspace, scan

HERE = os.path.dirname(os.path.abspath(__file__))
FIXTURES = os.path.join(os.path.dirname(HERE), "fixtures", "cpp")
ROS1 = os.path.join(FIXTURES, "features")
ROS1_SRC = os.path.join(ROS1, "src", "demo", "src")
ROS2 = os.path.join(FIXTURES, "ros2")
ROS2_SRC = os.path.join(ROS2, "src", "demo2", "src")
HAVE_ROS = os.path.isfile("/usr/include/ros/ros.h")
KEEP_LAST_10 = {"history": "keep_last", "depth": 10, "reliability": "reliable",
                "durability": "volatile"}
SENSOR_DATA = {"history": "keep_last", "depth": 5, "reliability": "best_effort",
               "durability": "volatile"}


def row(call: PrimitiveCall) -> tuple[object, ...]:
    return (call.kind, call.name, call.type, call.queue_size, call.latch, call.location.line)


def codes(result: CppResult) -> list[str]:
    return [d.code for d in result.diagnostics]


@pytest.fixture(scope="module")
def ros1_ws() -> Workspace:
    return scan([ROS1])


@pytest.fixture(scope="module")
def ros2_ws() -> Workspace:
    return scan([ROS2])


@pytest.fixture(scope="module")
def libraries(ros1_ws: Workspace) -> CppResult:
    return extract_cpp([os.path.join(ROS1_SRC, "libraries.cpp")], ros1_ws, cache_dir=None)


@pytest.fixture(scope="module")
def camera(ros1_ws: Workspace) -> CppResult:
    """The nodelet libraries.cpp exports, as its manager runs it."""
    return extract_cpp([os.path.join(ROS1_SRC, "libraries.cpp")], ros1_ws, cache_dir=None,
                       entry="demo::Camera")


@pytest.fixture(scope="module")
def talker(ros2_ws: Workspace) -> CppResult:
    return extract_cpp([os.path.join(ROS2_SRC, "talker.cpp")], ros2_ws, cache_dir=None)


@pytest.fixture(scope="module")
def mover(ros2_ws: Workspace) -> CppResult:
    return extract_cpp([os.path.join(ROS2_SRC, "mover.cpp")], ros2_ws, cache_dir=None)


# -- ROS 1 libraries -------------------------------------------------------------------

CAMERA = [
    ("read", "~input_topic", "str", None, False, 27),            # nodelet private handle
    ("subscribe", "?", "std_msgs/String", 1, False, 28),          # name from a parameter
    ("publish", "~status", "std_msgs/String", 1, False, 29),
    ("read", "~rate", "double", None, False, 30),                 # getMTPrivateNodeHandle
    ("read", "output_topic", "str", None, False, 31),
    ("publish", "?", "std_msgs/String", 1, False, 32),
    ("publish", "/tf", "tf2_msgs/TFMessage", None, False, 43),    # a broadcaster member
]
LIBRARIES = [
    ("action-server", "do", "demo/Do", None, False, 59),
    ("action-client", "delegate", "demo/Do", None, False, 60),
    ("publish", "vision/raw", "sensor_msgs/Image", 1, False, 63),
    ("publish", "vision/camera/image", "sensor_msgs/Image", 2, False, 64),
    ("publish", "vision/camera/camera_info", "sensor_msgs/CameraInfo", 2, False, 64),
    ("subscribe", "vision/input", "sensor_msgs/Image", 3, False, 65),
    ("subscribe", "left/image", "sensor_msgs/Image", 4, False, 67),
    ("publish", "/tf_static", "tf2_msgs/TFMessage", None, True, 69),
    ("subscribe", "/tf", "tf2_msgs/TFMessage", None, False, 71),
    ("subscribe", "/tf_static", "tf2_msgs/TFMessage", None, False, 71),
    ("subscribe", "~once", "std_msgs/String", None, False, 74),   # waitForMessage(.., priv)
    ("publish", "~image_raw", "sensor_msgs/Image", 1, False, 77),
    ("publish", "~camera_info", "sensor_msgs/CameraInfo", 1, False, 77),  # beside it
]


def test_ros1_libraries(libraries: CppResult, camera: CppResult) -> None:
    assert [row(c) for c in libraries.calls] == LIBRARIES
    assert libraries.rosname == "libraries"
    assert "CPP_PARSE_ERROR" not in codes(libraries)
    assert "CPP_INCLUDE_MISSING" not in codes(libraries)
    # (the file's main() too: a library holds no main(), this fixture's file both)
    assert [row(c) for c in camera.calls if c.location.line < 45] == CAMERA


def test_an_exported_class_main_never_builds_runs_in_its_host_only(
        libraries: CppResult, camera: CppResult) -> None:
    """The file's main() never builds the nodelet it exports: a manager that loads it
    runs its onInit(), in the manager's process, not this executable."""
    assert not [c for c in libraries.calls if c.location.line < 45]
    assert {c.location.line for c in camera.calls if c.location.line < 45} == {
        27, 28, 29, 30, 31, 32, 43}


def test_names_from_parameters(camera: CppResult) -> None:
    params = [(c.name, c.name_param, c.name_default) for c in camera.calls
              if c.name_param is not None]
    assert params == [("?", "~input_topic", "scan"), ("?", "output_topic", "out")]


def test_callbacks_of_library_calls(libraries: CppResult, camera: CppResult) -> None:
    by_line = {(c.location.line, c.kind): c for c in [*libraries.calls, *camera.calls]}
    assert by_line[(28, "subscribe")].callback == "Camera::onString"
    assert by_line[(65, "subscribe")].callback == "onImage"


# every system header libraries.cpp includes (demo/DoAction.h is made from the fixture)
LIBRARY_HEADERS = ("ros/ros.h", "boost/bind.hpp", "actionlib/server/simple_action_server.h",
                   "image_transport/image_transport.h", "message_filters/subscriber.h",
                   "tf2_ros/transform_broadcaster.h", "nodelet/nodelet.h",
                   "pluginlib/class_list_macros.h", "sensor_msgs/Image.h",
                   "std_msgs/String.h")
MISSING_HEADERS = [h for h in LIBRARY_HEADERS if not os.path.isfile(f"/usr/include/{h}")]


@pytest.mark.skipif(bool(MISSING_HEADERS),
                    reason=f"needs the ROS 1 headers in /usr/include: {MISSING_HEADERS}")
def test_ros1_libraries_with_system_headers(ros1_ws: Workspace, camera: CppResult) -> None:
    real = extract_cpp([os.path.join(ROS1_SRC, "libraries.cpp")], ros1_ws,
                       system_headers=True, cache_dir=None, entry="demo::Camera")
    assert [row(c) for c in real.calls] == [row(c) for c in camera.calls]
    assert [(c.name_param, c.name_default) for c in real.calls] == [
        (c.name_param, c.name_default) for c in camera.calls]


# -- rclcpp ----------------------------------------------------------------------------

TALKER = [
    ("publish", "chatter", "std_msgs/msg/String", 10, KEEP_LAST_10),
    ("publish", "status", "demo2/msg/Status", 5,                      # const char* constant
     {**KEEP_LAST_10, "depth": 5, "reliability": "best_effort"}),
    ("publish", "~latched", "std_msgs/msg/String", 1,
     {**KEEP_LAST_10, "depth": 1, "durability": "transient_local"}),
    ("publish", "all", "std_msgs/msg/String", None,                   # through a variable
     {"history": "keep_all", "reliability": "reliable", "durability": "volatile"}),
    ("publish", "defaults", "std_msgs/msg/String", 0,
     {"history": "system_default", "depth": 0, "reliability": "system_default",
      "durability": "system_default"}),
    ("subscribe", "input", "std_msgs/msg/String", 10, KEEP_LAST_10),
    ("subscribe", "scan", "sensor_msgs/msg/LaserScan", 5, SENSOR_DATA),
    ("subscribe", "raw", "std_msgs/msg/String", 5, SENSOR_DATA),      # rmw profile
    ("server", "set_mode", "demo2/srv/SetMode", None, None),
    ("client", "~reset", "std_srvs/srv/Trigger", None, None),
    ("declare", "rate", "double", None, None),
    ("declare", "frame_id", "str", None, None),
    ("read", "rate", "double", None, None),
    ("write", "ready", None, None, None),
    ("write", "left", None, None, None),
    ("write", "right", None, None, None),
    ("declare", "topic", "str", None, None),
    ("read", "topic", "str", None, None),  # get_parameter("topic").as_string()
    ("publish", "?", "std_msgs/msg/String", 1, {**KEEP_LAST_10, "depth": 1}),
    ("publish", "arm/joint", "std_msgs/msg/String", 3, {**KEEP_LAST_10, "depth": 3}),
]


def test_rclcpp_node(talker: CppResult) -> None:
    assert [(c.kind, c.name, c.type, c.queue_size, c.qos) for c in talker.calls] == TALKER
    assert talker.rosname == "/robot/talker"
    assert "CPP_PARSE_ERROR" not in codes(talker)


def test_rclcpp_callbacks_and_parameter_names(talker: CppResult) -> None:
    calls = {(c.kind, c.name): c for c in talker.calls}
    assert calls[("subscribe", "input")].callback == "Talker::onInput"
    assert calls[("server", "set_mode")].callback == "Talker::onSetMode"
    dynamic = calls[("publish", "?")]
    assert (dynamic.name_param, dynamic.name_default) == ("topic", "cmd")


def test_image_transport_calls_say_how_their_transports_are_chosen(
        libraries: CppResult, mover: CppResult) -> None:
    # publishers publish through every transport, subscribers through the one the node's
    # parameter (TransportHints) or their ROS 2 code names; camera_info has none
    assert [(c.name, c.transport) for c in libraries.calls if c.name.startswith("vision/")] == [
        ("vision/raw", "*"), ("vision/camera/image", "*"), ("vision/camera/camera_info", None),
        ("vision/input", "?/")]
    assert [c.transport for c in libraries.calls if c.name.startswith("~image")] == ["*"]
    assert [(c.name, c.transport) for c in mover.calls if c.type == "sensor_msgs/msg/Image"] == [
        ("camera/image", "*"), ("debug", "*"), ("seen", "compressed"), ("hinted", "?"),
        ("left/image", None)]


def test_ros2_libraries(mover: CppResult) -> None:
    assert [(c.kind, c.name, c.type, c.queue_size, c.latch) for c in mover.calls] == [
        ("action-server", "move", "demo2/action/Move", None, False),
        ("action-client", "follow", "demo2/action/Move", None, False),
        ("publish", "/tf", "tf2_msgs/msg/TFMessage", None, False),          # make_shared
        ("publish", "/tf_static", "tf2_msgs/msg/TFMessage", None, True),    # make_unique
        ("subscribe", "/tf", "tf2_msgs/msg/TFMessage", None, False),
        ("subscribe", "/tf_static", "tf2_msgs/msg/TFMessage", None, False),
        ("publish", "camera/image", "sensor_msgs/msg/Image", 1, False),
        ("publish", "camera/camera_info", "sensor_msgs/msg/CameraInfo", 1, False),
        ("publish", "debug", "sensor_msgs/msg/Image", None, False),
        ("subscribe", "seen", "sensor_msgs/msg/Image", None, False),
        ("subscribe", "hinted", "sensor_msgs/msg/Image", None, False),
        ("subscribe", "left/image", "sensor_msgs/msg/Image", 5, False),
        ("declare", "verbose", "bool", None, False),
    ]
    assert mover.rosname == "/base/mover"
    assert mover.calls[-1].conditions[0].text == "argc > 1"
    assert mover.calls[-2].qos == SENSOR_DATA
    assert "CPP_PARSE_ERROR" not in codes(mover)


def _extract_ros2(tmp_path, text: str) -> CppResult:
    """``text`` as the one source of a ROS 2 package in ``tmp_path``, extracted without a
    cache."""
    (tmp_path / "package.xml").write_text(package_xml("pipe", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend></package>"))
    source = tmp_path / "pipe.cpp"
    source.write_text(text)
    return extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)


RESOLVED_NAMES = """\
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include <image_transport/image_transport.hpp>
#include <sensor_msgs/msg/image.hpp>
#include <std_msgs/msg/string.hpp>

class Rectify : public rclcpp::Node {
public:
  Rectify() : Node("rectify") {
    auto node_base = this->get_node_base_interface();
    std::string topic = node_base->resolve_topic_or_service_name("image", false);
    sub_ = image_transport::create_subscription(
        this, topic, [](const sensor_msgs::msg::Image::ConstSharedPtr &) {}, "raw");
    pub_ = create_publisher<std_msgs::msg::String>(
        get_node_topics_interface()->resolve_topic_name("status"), 1);
  }
  image_transport::Subscriber sub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};

class Crop : public rclcpp_lifecycle::LifecycleNode {
public:
  Crop() : LifecycleNode("crop") {
    const std::string out = this->get_node_base_interface()->resolve_topic_or_service_name(
        std::string("out") + "/image", false, true);
    pub_ = image_transport::create_publisher(this, out);
  }
  image_transport::Publisher pub_;
};
"""


def test_a_name_the_node_resolves_is_the_name_it_resolves(tmp_path) -> None:
    # the graph expands and remaps the name where it links the call, as rclcpp's
    # resolve_topic_or_service_name / resolve_topic_name do in the code
    result = _extract_ros2(tmp_path, RESOLVED_NAMES)
    assert [(c.kind, c.name, c.type) for c in result.calls
            if c.type is not None and c.type.startswith(("sensor_msgs", "std_msgs"))] == [
        ("subscribe", "image", "sensor_msgs/msg/Image"),
        ("publish", "status", "std_msgs/msg/String"),
        ("publish", "out/image", "sensor_msgs/msg/Image"),
    ]
    assert not {"CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_DYNAMIC_NAME"} & set(
        codes(result))
    # image_transport names its transports' topics below a base resolved and remapped,
    # not only expanded (only_expand), as the graph does for a base as written
    assert [c.transport for c in result.calls if c.type == "sensor_msgs/msg/Image"] == [
        "raw=", "*"]


SUBSCRIBER_FILTERS_ROS2 = """\
#include <rclcpp/rclcpp.hpp>
#include <image_transport/image_transport.hpp>
#include <image_transport/subscriber_filter.hpp>
#include <message_filters/subscriber.h>
#include <sensor_msgs/msg/camera_info.hpp>

class Disparity : public rclcpp::Node {
public:
  Disparity() : Node("disparity"), right_(this, "right/image", "compressed") {
    auto node_base = this->get_node_base_interface();
    std::string left_topic = node_base->resolve_topic_or_service_name("left/image_rect", false);
    std::string left_info_topic = node_base->resolve_topic_or_service_name(
        image_transport::getCameraInfoTopic(left_topic), false);
    const auto sensor_data_qos = rmw_qos_profile_sensor_data;
    image_transport::TransportHints hints(this);
    if (!left_.getSubscriber()) {
      left_.subscribe(this, left_topic, hints.getTransport(), sensor_data_qos);
      left_info_.subscribe(this, left_info_topic, sensor_data_qos);
    }
  }
  image_transport::SubscriberFilter left_;
  image_transport::SubscriberFilter right_;
  message_filters::Subscriber<sensor_msgs::msg::CameraInfo> left_info_;
};
"""


def test_image_transport_subscriber_filters_subscribe(tmp_path) -> None:
    result = _extract_ros2(tmp_path, SUBSCRIBER_FILTERS_ROS2)
    assert [(c.kind, c.name, c.type, c.transport, c.queue_size, c.location.line)
            for c in result.calls] == [
        ("subscribe", "right/image", "sensor_msgs/msg/Image", "compressed", None, 9),
        ("subscribe", "left/image_rect", "sensor_msgs/msg/Image", "?=", 5, 17),
        ("subscribe", "left/camera_info", "sensor_msgs/msg/CameraInfo", None, 5, 18),
    ]
    assert result.calls[1].conditions[0].text == "!left_.getSubscriber()"
    assert not {"CPP_PARSE_ERROR", "CPP_NODE_TO_UNKNOWN", "CPP_CALL_MISSED"} & set(
        codes(result))


SUBSCRIBER_FILTERS_ROS1 = """\
#include <ros/ros.h>
#include <image_transport/image_transport.h>
#include <image_transport/subscriber_filter.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "stereo");
  ros::NodeHandle nh("stereo");
  image_transport::ImageTransport it(nh);
  image_transport::SubscriberFilter left(it, "left/image", 3);
  image_transport::SubscriberFilter right;
  right.subscribe(it, "right/image", 4, image_transport::TransportHints("compressed"));
  ros::spin();
}
"""


def test_ros1_image_transport_subscriber_filters_subscribe(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("stereo").replace(
        "</package>", "<depend>roscpp</depend></package>"))
    (tmp_path / "stereo.cpp").write_text(SUBSCRIBER_FILTERS_ROS1)
    result = extract_cpp([str(tmp_path / "stereo.cpp")], scan([str(tmp_path)]),
                         cache_dir=None)
    # the transport its hints name is not read: as ImageTransport::subscribe's
    assert [(c.kind, c.name, c.type, c.transport, c.queue_size) for c in result.calls] == [
        ("subscribe", "stereo/left/image", "sensor_msgs/Image", "?/", 3),
        ("subscribe", "stereo/right/image", "sensor_msgs/Image", "?/", 4),
    ]
    assert "CPP_PARSE_ERROR" not in codes(result)


CAMERA_ENDS_ROS2 = """\
#include <rclcpp/rclcpp.hpp>
#include <image_transport/camera_subscriber.hpp>
#include <image_transport/camera_publisher.hpp>
#include <sensor_msgs/msg/camera_info.hpp>
#include <sensor_msgs/msg/image.hpp>

class Tags : public rclcpp::Node {
public:
  Tags() : Node("tags"),
    sub_{this, "image_rect",
         std::bind(&Tags::on_camera, this, std::placeholders::_1, std::placeholders::_2),
         declare_parameter("image_transport", "raw"), rmw_qos_profile_sensor_data},
    pub_(this, "overlay") {}
  void on_camera(const sensor_msgs::msg::Image::ConstSharedPtr &,
                 const sensor_msgs::msg::CameraInfo::ConstSharedPtr &) {}
  const image_transport::CameraSubscriber sub_;
  image_transport::CameraPublisher pub_;
};
"""


def test_ros2_camera_subscriber_and_publisher_constructors(tmp_path) -> None:
    # ROS 2's image_transport constructs its camera ends from a node (apriltag_ros'
    # AprilTagNode: CameraSubscriber{node, topic, callback, transport, qos}): an image
    # and its camera_info, as create_camera_subscription / create_camera_publisher
    result = _extract_ros2(tmp_path, CAMERA_ENDS_ROS2)
    assert [(c.kind, c.name, c.type) for c in result.calls
            if c.kind in ("subscribe", "publish")] == [
        ("subscribe", "image_rect", "sensor_msgs/msg/Image"),
        ("subscribe", "camera_info", "sensor_msgs/msg/CameraInfo"),
        ("publish", "overlay", "sensor_msgs/msg/Image"),
        ("publish", "camera_info", "sensor_msgs/msg/CameraInfo"),
    ]
    assert not {"CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED"} & set(
        codes(result))
