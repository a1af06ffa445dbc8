"""diagnostic_updater's ``Updater::getPeriod()`` is seconds (a double) in ROS 1 and an
``rclcpp::Duration`` in ROS 2: a ROS 1 unit dividing it by a number (ros_canopen's
``ros::Duration(diag_updater_.getPeriod() / 2.0)``) parses without error, so the calls of
its function are read; a ROS 2 unit still gets a duration (``.nanoseconds()``)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

ROS1 = r"""
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <diagnostic_updater/diagnostic_updater.h>
class Chain {
 public:
  Chain() : nh_(), nh_priv_("~") {}
  bool setup() {
    diag_timer_ = nh_.createTimer(ros::Duration(diag_updater_.getPeriod() / 2.0),
                                  &Chain::tick, this);
    srv_ = nh_priv_.advertiseService("init", &Chain::handle, this);
    return true;
  }
  void tick(const ros::TimerEvent&) {}
  bool handle(std_srvs::Trigger::Request&, std_srvs::Trigger::Response&) { return true; }
  ros::NodeHandle nh_, nh_priv_;
  diagnostic_updater::Updater diag_updater_;
  ros::Timer diag_timer_;
  ros::ServiceServer srv_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "chain");
  Chain c;
  c.setup();
}
"""

ROS2 = r"""
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <diagnostic_updater/diagnostic_updater.hpp>
class Filter : public rclcpp::Node {
 public:
  Filter() : Node("filter"), updater_(this) {
    long period = updater_.getPeriod().nanoseconds();
    pub_ = create_publisher<std_msgs::msg::String>("status", period > 0 ? 10 : 1);
  }
  diagnostic_updater::Updater updater_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Filter>());
}
"""


def _result(tmp_path, text):
    source = tmp_path / "n.cpp"
    source.write_text(text)
    return extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)


def test_ros1_period_is_seconds_and_the_function_s_calls_are_read(tmp_path):
    result = _result(tmp_path, ROS1)
    assert ("server", "~init") in {(c.kind, c.name) for c in result.calls}
    assert not [d for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"]


def test_ros2_period_is_a_duration(tmp_path):
    result = _result(tmp_path, ROS2)
    assert ("publish", "status") in {(c.kind, c.name) for c in result.calls}
    assert not [d for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"]
