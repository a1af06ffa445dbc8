"""A member's default initialiser (``std::string camera_name_ = "camera";``) is its value
only while nothing else in the file writes it. OrbbecSDK_ROS2's OBLidarNode sets
``camera_name_`` in getParameters() through a helper that takes it by non-const
reference (``setAndGetNodeParameter<std::string>(camera_name_, "camera_name",
"lidar")``), then publishes ``"/" + camera_name_ + "/lidar_to_imu"``: the topic was
``/camera/lidar_to_imu`` for every camera, and each launch file that starts two cameras
got a false multiple-publishers warning."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
using S = std_msgs::msg::String;
class Cam {
public:
  explicit Cam(rclcpp::Node* node) : node_(node) { setup(); }
  template <class T> void fetch(T& param, const std::string& name, const T& fallback) {
    param = node_->declare_parameter<T>(name, fallback);
  }
  void read() { fetch<std::string>(camera_name_, "camera_name", "lidar"); }
  void rename() { label_ = node_->get_name(); }
  void setup() {
    read();
    rename();
    pub_ = node_->create_publisher<S>("/" + camera_name_ + "/extrinsics", 1);
    other_ = node_->create_publisher<S>("/" + label_ + "/status", 1);
    kept_ = node_->create_publisher<S>(prefix_ + "/info", 1);
  }
  rclcpp::Node* node_;
  std::string camera_name_ = "camera";
  std::string label_ = "label";
  std::string prefix_ = "fixed";
  rclcpp::Publisher<S>::SharedPtr pub_, other_, kept_;
};
"""


def test_a_default_member_initialiser_written_elsewhere_is_not_the_value(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("cam", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"))
    source = tmp_path / "cam.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    names = sorted(c.name for c in result.calls if c.kind == "publish")
    assert "/camera/extrinsics" not in names and "/label/status" not in names, names
    assert "fixed/info" in names, names  # written nowhere: its initialiser holds
    assert len(names) == 3, names


AMCL = """\
#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/laser_scan.hpp>
using Scan = sensor_msgs::msg::LaserScan;
class Amcl : public rclcpp::Node {
public:
  Amcl() : Node("amcl") {
    initParameters();
    handle_ = add_on_set_parameters_callback(
        std::bind(&Amcl::dynamicParametersCallback, this, std::placeholders::_1));
    subscribe();
  }
  void initParameters() {
    scan_topic_ = declare_parameter("scan_topic", std::string{"scan"});
  }
  rcl_interfaces::msg::SetParametersResult dynamicParametersCallback(
      std::vector<rclcpp::Parameter> parameters) {
    for (auto parameter : parameters) {
      if (parameter.get_name() == "scan_topic") { scan_topic_ = parameter.as_string(); }
    }
    return rcl_interfaces::msg::SetParametersResult();
  }
  void subscribe() {
    sub_ = create_subscription<Scan>(scan_topic_, 1, [](Scan::ConstSharedPtr) {});
  }
  std::string scan_topic_{"scan"};
  rclcpp::Subscription<Scan>::SharedPtr sub_;
  rclcpp::node_interfaces::OnSetParametersCallbackHandle::SharedPtr handle_;
};
"""


def test_a_member_set_from_a_parameter_and_in_a_parameter_callback_is_that_parameter(
        tmp_path) -> None:
    """navigation2's amcl: ``scan_topic_{"scan"}``, set in initParameters() from the
    ``scan_topic`` parameter and again in dynamicParametersCallback when a user changes
    it at run time. The subscription's topic is that parameter (launch value, else
    "scan"): the callback's write comes after start-up and is left out."""
    (tmp_path / "package.xml").write_text(package_xml("amcl", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>sensor_msgs</depend></package>"))
    source = tmp_path / "amcl.cpp"
    source.write_text(AMCL)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    subs = [c for c in result.calls if c.kind == "subscribe"]
    assert len(subs) == 1 and subs[0].name_param == "scan_topic", subs


RNAV = """\
#include <rclcpp/rclcpp.hpp>
#include <nav_msgs/msg/odometry.hpp>
using Odom = nav_msgs::msg::Odometry;
class Rnav : public rclcpp::Node {
public:
  Rnav() : Node("rnav") {
    read_parameters();
    sub_ = create_subscription<Odom>(topic_odometry_, 1, [](Odom::ConstSharedPtr) {});
  }
  void read_parameters() {
    declare_parameter<std::string>("topic_odometry", topic_odometry_);
    get_parameter("topic_odometry", topic_odometry_);
  }
  std::string topic_odometry_ = "/odom";
  rclcpp::Subscription<Odom>::SharedPtr sub_;
};
"""


def test_a_member_read_into_keeps_its_initialiser_as_the_names_default(tmp_path) -> None:
    """mrpt_reactivenav2d: ``std::string subTopicOdometry_ = "/odom";`` then
    ``get_parameter("topic_odometry", subTopicOdometry_)``: the subscription is named
    by that parameter, with "/odom" as its default (the variable is left as it was when
    the parameter is not set), not a name wholly unknown."""
    (tmp_path / "package.xml").write_text(package_xml("rnav", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>nav_msgs</depend></package>"))
    source = tmp_path / "rnav.cpp"
    source.write_text(RNAV)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    (sub,) = [c for c in result.calls if c.kind == "subscribe"]
    assert (sub.name_param, sub.name_default) == ("topic_odometry", "/odom"), sub
