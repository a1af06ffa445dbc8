"""A public member that main fills from a parameter before it calls the method that names
a topic with it, on a handle the object's constructor takes: Weston Robot's messengers
(agilex hunter_ros, scout_ros, tracer_ros, bunker_ros) advertise the odometry on
``nh_->advertise<nav_msgs::Odometry>(odom_frame_, 50)``, where ``nh_`` is the handle main
passes to the constructor and main reads ``private_node.param("odom_frame",
messenger.odom_frame_, std::string("odom"))``. The publisher is named by that parameter
(with its default), under the handle's namespace; it was ``?`` (the handle's namespace
comes from the callers, which kept the member unnamed)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """
#include <ros/ros.h>
#include <nav_msgs/Odometry.h>
class Messenger {
 public:
  explicit Messenger(ros::NodeHandle *nh) : nh_(nh) {}
  void Setup();
  std::string odom_frame_;
  std::string base_frame_;
  std::string status_topic_;
 private:
  ros::NodeHandle *nh_;
  ros::Publisher odom_, base_, status_;
};
"""

MESSENGER = """
#include "messenger.hpp"
void Messenger::Setup() {
  odom_ = nh_->advertise<nav_msgs::Odometry>(odom_frame_, 50);
  base_ = nh_->advertise<nav_msgs::Odometry>(base_frame_ + "/odom", 50);
  status_ = nh_->advertise<nav_msgs::Odometry>(status_topic_, 5);
}
"""

MAIN = """
#include "messenger.hpp"
int main(int argc, char **argv) {
  ros::init(argc, argv, "base");
  ros::NodeHandle node, private_node("~");
  Messenger messenger(&NODE);
  private_node.param<std::string>("odom_frame", messenger.odom_frame_, std::string("odom"));
  private_node.param<std::string>("base_frame", messenger.base_frame_,
                                  std::string("base_link"));
  // two parameters into one member: which one names the topic is not known
  private_node.param<std::string>("status", messenger.status_topic_, std::string("a"));
  if (argc > 2)
    private_node.param<std::string>("status2", messenger.status_topic_, std::string("b"));
  messenger.Setup();
  ros::spin();
}
"""


def _publishers(write_tree, handle: str) -> list[tuple]:
    root = write_tree({"mb/package.xml": package_xml("mb"),
                       "mb/src/messenger.hpp": HEADER, "mb/src/messenger.cpp": MESSENGER,
                       "mb/src/main.cpp": MAIN.replace("NODE", handle)})
    result = extract_cpp([str(root / "mb" / "src" / "main.cpp"),
                          str(root / "mb" / "src" / "messenger.cpp")],
                         scan([str(root)]), cache_dir=None)
    return sorted(((c.name, c.name_param, c.name_default) for c in result.calls
                   if c.kind == "publish"), key=repr)


def test_a_member_main_reads_a_parameter_into_names_the_topic(write_tree) -> None:
    assert _publishers(write_tree, "node") == [
        ("?", "~odom_frame", "odom"),
        ("?", None, None),  # status_topic_: two parameters may fill it
        ("?/odom", "~base_frame", "base_link"),
    ]


def test_on_the_private_handle_the_name_is_under_it(write_tree) -> None:
    assert _publishers(write_tree, "private_node") == [
        ("~?", "~odom_frame", "odom"),
        ("~?", None, None),
        ("~?/odom", "~base_frame", "base_link"),
    ]
