"""A node handle member set once outside its class's constructor list takes that value,
as depth_image_proc's disparity nodelet (ROS 1 image_pipeline) sets
``right_nh_.reset(new ros::NodeHandle(nh, "right"))`` in ``onInit`` and subscribes
``camera_info`` on ``*right_nh_`` in its connection callback: ``right/camera_info``,
not ``?/camera_info``. The value is read where it is written (a local handle of that
method), and a member the file's functions set to different values is unknown."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODELET = """
#include <ros/ros.h>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include <boost/shared_ptr.hpp>
#include <message_filters/subscriber.h>
#include <sensor_msgs/CameraInfo.h>
#include <std_msgs/String.h>

namespace demo {
class Disparity : public nodelet::Nodelet {
  ros::NodeHandlePtr right_nh_;
  ros::NodeHandle left_nh_;
  ros::NodeHandle sub_nh_;
  boost::shared_ptr<ros::NodeHandle> either_nh_;
  message_filters::Subscriber<sensor_msgs::CameraInfo> sub_info_;
  ros::Publisher a_, b_, c_, d_, e_;
  void onInit() override;
  void connectCb();
  void setup(ros::NodeHandle& pnh);
  void other();
};

void Disparity::onInit() {
  ros::NodeHandle& nh = getNodeHandle();
  right_nh_.reset(new ros::NodeHandle(nh, "right"));
  ros::NodeHandle left(nh, "left");
  left_nh_ = left;
  either_nh_.reset(new ros::NodeHandle(nh, "one"));
  ros::NodeHandle& pnh = getPrivateNodeHandle();
  setup(pnh);
}

void Disparity::setup(ros::NodeHandle& pnh) {
  sub_nh_ = ros::NodeHandle(pnh, "sub");
}

void Disparity::other() {
  either_nh_.reset(new ros::NodeHandle(getNodeHandle(), "two"));
}

void Disparity::connectCb() {
  sub_info_.subscribe(*right_nh_, "camera_info", 1);
  a_ = right_nh_->advertise<std_msgs::String>("right_out", 1);
  b_ = left_nh_.advertise<std_msgs::String>("left_out", 1);
  c_ = sub_nh_.advertise<std_msgs::String>("sub_out", 1);
  d_ = either_nh_->advertise<std_msgs::String>("either_out", 1);
}
}  // namespace demo

PLUGINLIB_EXPORT_CLASS(demo::Disparity, nodelet::Nodelet)
"""

NODE = """
#include <ros/ros.h>
#include <boost/shared_ptr.hpp>
#include <std_msgs/String.h>

int main(int argc, char ** argv) {
  ros::init(argc, argv, "talker");
  boost::shared_ptr<ros::NodeHandle> nh;
  nh.reset(new ros::NodeHandle("ns"));
  ros::Publisher p = nh->advertise<std_msgs::String>("chatter", 1);
  ros::spin();
}
"""


def _calls(write_tree, name: str, text: str) -> list[tuple[str, str]]:
    root = write_tree({"demo/package.xml": package_xml("demo"), f"demo/src/{name}": text})
    result = extract_cpp([str(root / "demo" / "src" / name)], scan([str(root)]),
                         cache_dir=None)
    return sorted((c.kind, c.name) for c in result.calls)


def test_a_handle_member_set_once_outside_the_constructor(write_tree) -> None:
    assert _calls(write_tree, "disparity.cpp", NODELET) == [
        ("publish", "?/either_out"),  # set to ``one`` in onInit and ``two`` in other()
        ("publish", "left/left_out"),  # a local handle of onInit, assigned
        ("publish", "right/right_out"),  # reset(new NodeHandle(nh, "right"))
        ("publish", "~sub/sub_out"),  # ``= ros::NodeHandle(pnh, "sub")`` in a method
        ("subscribe", "right/camera_info"),  # through ``*right_nh_``
    ]


def test_a_local_handle_pointer_reset_once(write_tree) -> None:
    assert _calls(write_tree, "talker.cpp", NODE) == [("publish", "ns/chatter")]
