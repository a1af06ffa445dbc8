"""Stand-ins that real ROS 2 nodes needed (survey Z45).

- lidarslam_ros2's scan matcher holds a ``std::packaged_task<void()>`` member (it maps in
  a thread of its own): the stand-in ``<future>`` had no ``packaged_task``, the member
  was invalid, so was the class, and every ``declare_parameter`` / ``get_parameter`` of
  its constructor was "no matching member function" (the node partial, its 40
  parameter calls kept by name only).
- stella_vslam_ros subclasses ``message_filters::Subscriber<M>`` (constructors taking
  ``Subscriber<M>::NodePtr``, a callback taking ``Subscriber<M>::MConstPtr`` that calls
  ``signalMessage``) and synchronises two of them with
  ``std::make_shared<ApproximateTimeSyncPolicy::Sync>(10, left, right)``: the
  stand-in's policies had no ``Sync``, the subscriber no ``NodePtr`` / ``MConstPtr``,
  and the stereo and RGB-D constructors were C++ errors (the node partial)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

TASK = """\
#include <future>
#include <thread>
#include <functional>
#include <chrono>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
using namespace std::chrono_literals;
class Matcher : public rclcpp::Node {
 public:
  explicit Matcher(const rclcpp::NodeOptions& options) : Node("matcher", options) {
    declare_parameter("frame", "map");
    get_parameter("frame", frame_);
    pub_ = create_publisher<std_msgs::msg::String>("map", 10);
  }
  void update() {
    if (future_.valid() && future_.wait_for(0s) == std::future_status::ready) {
      thread_.join();
    }
    task_ = std::packaged_task<void()>(std::bind(&Matcher::work, this));
    future_ = task_.get_future();
    thread_ = std::thread(std::move(std::ref(task_)));
  }
  void work() { pub_->publish(std_msgs::msg::String()); }
 private:
  std::string frame_;
  std::thread thread_;
  std::packaged_task<void()> task_;
  std::future<void> future_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
"""

FILTERS = """\
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <message_filters/subscriber.h>
#include <message_filters/synchronizer.h>
#include <message_filters/sync_policies/approximate_time.h>
#include <message_filters/sync_policies/exact_time.h>
#include <sensor_msgs/msg/image.hpp>
template<class M, class NodeType = rclcpp::Node>
class Modified : public message_filters::Subscriber<M> {
 public:
  Modified(typename message_filters::Subscriber<M>::NodePtr node, const std::string& topic,
           const rmw_qos_profile_t qos = rmw_qos_profile_default)
      : message_filters::Subscriber<M>(node, topic, qos) {}
  Modified(NodeType* node, const std::string& topic,
           const rmw_qos_profile_t qos = rmw_qos_profile_default)
      : message_filters::Subscriber<M>(node, topic, qos) {}
  void cb(const typename message_filters::Subscriber<M>::MConstPtr& msg) {
    this->signalMessage(msg);
  }
};
using Image = sensor_msgs::msg::Image;
class Stereo {
 public:
  Stereo(rclcpp::Node* node) : node_(node), left_(node_, "left"), right_(node_, "right") {
    exact_ = node_->declare_parameter("use_exact_time", false);
    if (exact_) {
      exact_sync_ = std::make_shared<Exact::Sync>(2, left_, right_);
      exact_sync_->registerCallback(&Stereo::callback, this);
    } else {
      approx_sync_ = std::make_shared<Approx::Sync>(10, left_, right_);
      approx_sync_->registerCallback(&Stereo::callback, this);
    }
  }
  void callback(const Image::ConstSharedPtr& l, const Image::ConstSharedPtr& r) {}
  rclcpp::Node* node_;
  Modified<Image> left_, right_;
  using Approx = message_filters::sync_policies::ApproximateTime<Image, Image>;
  std::shared_ptr<Approx::Sync> approx_sync_;
  using Exact = message_filters::sync_policies::ExactTime<Image, Image>;
  std::shared_ptr<Exact::Sync> exact_sync_;
  bool exact_;
};
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("stereo");
  auto stereo = std::make_shared<Stereo>(node.get());
  rclcpp::spin(node);
}
"""


def _extract(tmp_path, name: str, text: str, depends: str):
    (tmp_path / "package.xml").write_text(package_xml("z45", "ament_cmake").replace(
        "</package>", "".join(f"<depend>{d}</depend>" for d in depends.split())
        + "</package>"))
    source = tmp_path / name
    source.write_text(text)
    return extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)


def _errors(result) -> list[str]:
    return [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")]


def test_a_packaged_task_member_leaves_the_class_valid(tmp_path) -> None:
    result = _extract(tmp_path, "matcher.cpp", TASK, "rclcpp std_msgs")
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("declare", "frame"), ("publish", "map"), ("read", "frame")]
    assert _errors(result) == []


def test_a_subscriber_subclass_and_a_policys_synchronizer(tmp_path) -> None:
    result = _extract(tmp_path, "stereo.cpp", FILTERS,
                      "rclcpp message_filters sensor_msgs")
    assert sorted((c.kind, c.name, c.type, c.location.line) for c in result.calls
                  if c.kind == "subscribe") == [
        ("subscribe", "left", "sensor_msgs/msg/Image", 24),
        ("subscribe", "right", "sensor_msgs/msg/Image", 24)]
    assert _errors(result) == []


def test_a_subscriber_subclass_of_a_fixed_type_is_untyped_but_kept(tmp_path) -> None:
    # the base named with no template parameter of the class: the subscriptions are
    # made, their type not taken from the construction's template argument
    text = FILTERS.replace(
        "public message_filters::Subscriber<M> {",
        "public message_filters::Subscriber<sensor_msgs::msg::Image> {").replace(
        ": message_filters::Subscriber<M>(",
        ": message_filters::Subscriber<sensor_msgs::msg::Image>(")
    result = _extract(tmp_path, "stereo.cpp", text, "rclcpp message_filters sensor_msgs")
    assert sorted((c.kind, c.name) for c in result.calls if c.kind == "subscribe") == [
        ("subscribe", "left"), ("subscribe", "right")]


CLOUD = """\
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/point_cloud2.hpp>
#include <sensor_msgs/point_cloud2_iterator.hpp>
using sensor_msgs::msg::PointCloud2;
using sensor_msgs::msg::PointField;
namespace odometry {
class Odometry : public rclcpp::Node {
 public:
  Odometry() : Node("odometry") {
    pub_ = create_publisher<PointCloud2>("frame", 10);
    auto cloud = std::make_unique<PointCloud2>();
    sensor_msgs::PointCloud2Modifier modifier(*cloud);
    int offset = 0;
    offset = addPointField(*cloud, "x", 1, PointField::FLOAT32, offset);
    offset += sizeOfPointField(PointField::FLOAT64);
    cloud->point_step = offset;
    pub_->publish(std::move(cloud));
  }
 private:
  rclcpp::Publisher<PointCloud2>::SharedPtr pub_;
};
}  // namespace odometry
"""


def test_the_point_cloud_field_helpers(tmp_path) -> None:
    # kiss-icp's Utils.hpp builds its clouds' fields with sensor_msgs' addPointField and
    # sizeOfPointField, which its implementation header declares in an unnamed namespace
    # of the global one: undeclared in the stand-in
    result = _extract(tmp_path, "odometry.cpp", CLOUD, "rclcpp sensor_msgs")
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "frame")]
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []
