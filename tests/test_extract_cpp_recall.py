"""Recall on code shaped like real nodes: classes that use Qt, OpenCV / cv_bridge and
Eigen still parse and keep their ROS calls; subscribe / advertise with SubscribeOptions /
AdvertiseOptions; names, queues and handles passed from call sites in the same file."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from haros_arch.extract.cpp import CppResult, extract_cpp, recall
from haros_arch.workspace import Workspace, scan

FIXTURE = Path(__file__).resolve().parent.parent / "fixtures" / "cpp" / "libraries"
SRC = FIXTURE / "src" / "vision" / "src"


def rows(result: CppResult) -> list[tuple[object, ...]]:
    return [(c.kind, c.name, c.type, c.queue_size, c.callback, c.location.line,
             tuple(x.text for x in c.conditions)) for c in result.calls]


@pytest.fixture(scope="module")
def ws() -> Workspace:
    return scan([str(FIXTURE)])


@pytest.fixture(scope="module")
def results(ws: Workspace) -> dict[str, CppResult]:
    files = ["blob_tracker.cpp", "teleop_panel.cpp", "options.cpp", "helpers.cpp"]
    return {name: extract_cpp([str(SRC / name)], ws, cache_dir=None) for name in files}


def test_opencv_cv_bridge_and_eigen_classes_keep_their_calls(
        results: dict[str, CppResult]) -> None:
    result = results["blob_tracker.cpp"]
    assert result.rosname == "blob_tracker"
    assert rows(result) == [
        ("subscribe", "camera/image_raw", "sensor_msgs/Image", 1, "BlobTracker::onImage", 14,
         ()),
        ("publish", "tracker/debug", "sensor_msgs/Image", 1, None, 15, ()),
        ("publish", "tracker/target", "geometry_msgs/PointStamped", 5, None, 16, ()),
    ]
    assert result.diagnostics == []  # every OpenCV / Eigen / cv_bridge use resolved


def test_qt_widget_keeps_its_calls(results: dict[str, CppResult]) -> None:
    result = results["teleop_panel.cpp"]
    assert result.rosname == "teleop_panel"
    assert rows(result) == [
        ("read", "~max_speed", "double", None, None, 19, ()),
        ("publish", "cmd_vel", "geometry_msgs/Twist", 1, None, 20, ()),
        ("subscribe", "teleop/enable", "std_msgs/Bool", 1, "TeleopPanel::onEnable", 21, ()),
    ]
    assert result.diagnostics == []


def test_subscribe_and_advertise_options(results: dict[str, CppResult]) -> None:
    """The call is where nh.subscribe(ops) is (its handle, line and conditions); topic,
    queue, type and callback come from ops.init<M>(...) or Options::create<M>(...)."""
    assert rows(results["options.cpp"]) == [
        ("subscribe", "~count", "std_msgs/Int32", 3, "onCount", 14, ()),
        ("subscribe", "robot/chatter", "std_msgs/String", 7, "onChat", 28, ()),
        ("publish", "robot/echo", "std_msgs/String", 2, None, 32, ("argc > 1",)),
    ]
    assert results["options.cpp"].diagnostics == []


SERVICE_OPTIONS = """\
#include <ros/ros.h>
#include <ros/callback_queue.h>
#include <std_srvs/Empty.h>
#include <std_srvs/Trigger.h>

bool onReset(std_srvs::Empty::Request& req, std_srvs::Empty::Response& res) { return true; }

class Mapper {
 public:
  explicit Mapper(ros::NodeHandle& nh) : nh_(nh) {
    ros::AdvertiseServiceOptions fuse = ros::AdvertiseServiceOptions::create<std_srvs::Empty>(
        "trigger_fusion", [&](auto& req, auto& res) { return true; }, ros::VoidConstPtr(),
        &queue_);
    fuse_ = nh_.advertiseService(fuse);
  }
 private:
  ros::NodeHandle& nh_;
  ros::CallbackQueue queue_;
  ros::ServiceServer fuse_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "svc_demo");
  ros::NodeHandle nh("~");
  ros::AdvertiseServiceOptions ops;
  ops.init<std_srvs::Trigger>(
      "ready", [](std_srvs::Trigger::Request&, std_srvs::Trigger::Response&) { return true; });
  ros::ServiceServer a = nh.advertiseService(ops);
  ros::AdvertiseServiceOptions two;
  two.init<std_srvs::Empty::Request, std_srvs::Empty::Response>("reset", &onReset);
  if (argc > 1) {
    ros::ServiceServer b = nh.advertiseService(two);
  }
  Mapper mapper(nh);
  ros::spin();
}
"""


def test_advertise_service_options(tmp_path: Path) -> None:
    """nh.advertiseService(ops) serves where it is called (handle, line, conditions),
    the name, type and callback from ops.init<...>(...) or
    AdvertiseServiceOptions::create<Service>(...) (elevation_mapping's services)."""
    package = tmp_path / "src" / "svc"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="2"><name>svc</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>BSD</license><depend>roscpp</depend><depend>std_srvs</depend>'
        '</package>\n')
    source = package / "src" / "svc.cpp"
    source.write_text(SERVICE_OPTIONS)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert rows(result) == [
        ("server", "~trigger_fusion", "std_srvs/Empty", None, None, 14, ()),
        ("server", "~ready", "std_srvs/Trigger", None, None, 28, ()),
        ("server", "~reset", "std_srvs/Empty", None, "onReset", 32, ("argc > 1",)),
    ]
    assert result.diagnostics == []


def test_values_from_call_sites_in_the_same_file(results: dict[str, CppResult]) -> None:
    """Helpers that pass their name parameter to ROS are wrappers (``wrappers``): each
    call site is a call, with its own name, handle and queue, at the call site."""
    assert rows(results["helpers.cpp"]) == [
        ("publish", "ranger/left/range", "std_msgs/Float64", 8, None, 27, ()),
        ("publish", "ranger/right/range", "std_msgs/Float64", 8, None, 28, ()),
        ("subscribe", "~scan", "sensor_msgs/LaserScan", 1, "onScan", 29, ()),
        ("publish", "ranger/log_a", "std_msgs/Float64", 1, None, 30, ()),
        ("publish", "ranger/log_b", "std_msgs/Float64", 1, None, 31, ()),
    ]


def test_a_helper_that_calls_itself_stays_unknown(tmp_path: Path) -> None:
    package = tmp_path / "src" / "loop"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="2"><name>loop</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>BSD</license></package>\n')
    source = package / "src" / "loop.cpp"
    source.write_text(
        "#include <ros/ros.h>\n#include <std_msgs/Empty.h>\n"
        "void chain(ros::NodeHandle& nh, const std::string& t, int n) {\n"
        "  if (n > 0) { chain(nh, t + \"/x\", n - 1); return; }\n"
        "  static ros::Publisher p = nh.advertise<std_msgs::Empty>(t, 1);\n}\n"
        "int main(int argc, char** argv) {\n  ros::init(argc, argv, \"loop\");\n"
        "  ros::NodeHandle nh;\n  chain(nh, \"base\", 3);\n}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    # it ends: main's call gives its value (``n > 0`` is not decided, as for any
    # caller), the helper's call of itself a chain of any length, unknown (it was
    # expanded until the values were too many, which made main's value unknown too)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "?/?"),
                                                        ("publish", "base")]


def test_library_headers_come_from_the_stand_ins_only(ws: Workspace, tmp_path: Path) -> None:
    """A Qt / OpenCV header the machine has is not read: results do not depend on it."""
    fake = tmp_path / "include"
    (fake / "opencv2").mkdir(parents=True)
    (fake / "opencv2" / "opencv.hpp").write_text('#error "system OpenCV must not be read"\n')
    (fake / "QTimer").write_text('#error "system Qt must not be read"\n')
    result = extract_cpp([str(SRC / "teleop_panel.cpp")], ws, cache_dir=None,
                         include_dirs=[str(fake)])
    assert [c.name for c in result.calls] == ["~max_speed", "cmd_vel", "teleop/enable"]
    assert os.path.isfile(fake / "QTimer")


def test_variant_random_and_pthread_in_a_node_class(tmp_path: Path) -> None:
    package = tmp_path / "src" / "noise"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="3"><name>noise</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>BSD</license></package>\n')
    source = package / "src" / "noise.cpp"
    source.write_text(
        "#include <pthread.h>\n#include <random>\n#include <variant>\n"
        "#include \"rclcpp/rclcpp.hpp\"\n#include \"std_msgs/msg/float64.hpp\"\n"
        "class Noise : public rclcpp::Node {\n public:\n"
        "  Noise() : Node(\"noise\"), gen_(rd_()), dist_(0.0, 1.0) {\n"
        "    pub_ = create_publisher<std_msgs::msg::Float64>(\"noise\", 10);\n"
        "    value_ = 1.0;\n    if (std::holds_alternative<double>(value_)) {}\n  }\n"
        " private:\n  std::random_device rd_;\n  std::mt19937 gen_;\n"
        "  std::uniform_real_distribution<double> dist_;\n"
        "  std::variant<int, double> value_;\n  pthread_t thread_;\n"
        "  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr pub_;\n};\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("publish", "noise", "std_msgs/msg/Float64")]
    assert result.rosname == "noise"
    assert [d.code for d in result.diagnostics] == []


def test_yaml_cpp_and_every_rclcpp_log_variant_parse_clean(ws: Workspace) -> None:
    """A node that reads its route with yaml-cpp (a ``convert`` of its own, iteration, the
    emitter, the exceptions), logs with ``RCLCPP_ERROR_EXPRESSION`` /
    ``RCLCPP_WARN_SKIPFIRST_THROTTLE`` and times itself with ``Rate::period()``: no clang
    error is left, so its calls are complete (before: 'YAML' unknown, the macros and
    ``period`` undeclared, each a partial node)."""
    source = FIXTURE / "src" / "waypoints" / "src" / "waypoint_server.cpp"
    result = extract_cpp([str(source)], ws, cache_dir=None)
    assert result.rosname == "waypoint_server"
    assert [(c.kind, c.name, c.type, c.queue_size) for c in result.calls] == [
        ("declare", "route_file", "str", None),
        ("publish", "?", "geometry_msgs/msg/PoseStamped", 10),
        ("publish", "route_status", "std_msgs/msg/String", 1),
    ]
    # the goal topic comes from the file: a dynamic name, and no clang error
    assert [d.code for d in result.diagnostics] == ["CPP_DYNAMIC_NAME"]


def test_cxx17_library_and_message_setters_parse_clean(ws: Workspace) -> None:
    """``<filesystem>``, structured bindings over a map and a tuple, ``tuple_element_t``,
    ``map::insert_or_assign``, a message's ``set__frame_id`` and ``!=``, a publisher's
    ``get_intra_process_subscription_count`` and ``HOST_NAME_MAX`` / ``gethostname``: no
    clang error is left (main left six, each a reason for a partial node)."""
    source = FIXTURE / "src" / "waypoints" / "src" / "route_recorder.cpp"
    result = extract_cpp([str(source)], ws, cache_dir=None)
    assert result.rosname == "route_recorder"
    assert [(c.kind, c.name, c.type, c.queue_size) for c in result.calls] == [
        ("declare", "folder", "str", None),
        ("subscribe", "goal_pose", "geometry_msgs/msg/PoseStamped", 10),
        ("publish", "recorded_goal", "geometry_msgs/msg/PoseStamped", 5),
    ]
    assert [d.code for d in result.diagnostics] == []


def test_a_ros1_unit_calls_no_api_of_ros2_only(tmp_path: Path) -> None:
    """ORK's renderer (sara_commun's copy, ROS 1) calls its own renderer's
    ``set_parameters(width, height, ...)`` in a function with a C++ error: the line was
    taken for a call site of rclcpp's ``Node::set_parameters``, CPP_CALL_MISSED and an
    error near a call, so view_generator was partial. The same line in ROS 2 code is
    still a site."""
    package = tmp_path / "src" / "render"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="2"><name>render</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>BSD</license><depend>roscpp</depend></package>\n')
    source = package / "src" / "render.cpp"
    source.write_text(
        "#include <ros/ros.h>\n#include <std_msgs/String.h>\n"
        "class Renderer {\n public:\n  virtual void render() = 0;\n"
        "  void set_parameters(int width, int height, double fx, double fy);\n};\n"
        "void render(Renderer* renderer) {\n"
        "  renderer->set_parameters(640, 480, 525.0, 525.0);\n"
        "  Renderer copy = *renderer;\n}\n"
        "int main(int argc, char** argv) {\n  ros::init(argc, argv, \"render\");\n"
        "  ros::NodeHandle nh;\n"
        "  ros::Publisher pub = nh.advertise<std_msgs::String>(\"out\", 1);\n}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "out")]
    assert [d.code for d in result.diagnostics] == ["CPP_PARSE_ERROR"]
    line = "  renderer->set_parameters(640, 480, 525.0, 525.0);\n"
    assert recall.call_sites(line, ros2=False) == []
    assert [s.line for s in recall.call_sites(line, ros2=True)] == [1]
    assert [s.line for s in recall.call_sites(line)] == [1]
