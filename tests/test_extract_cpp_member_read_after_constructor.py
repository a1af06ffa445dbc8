"""A member its constructor gives a text, which a method then reads a parameter into: the
constructor's text is the read's default, not the name the node uses. teb_local_planner
(noetic-devel b68c3288) sets ``odom_topic = "odom"`` in TebConfig's constructor (in its
header), reads ``nh.param("odom_topic", odom_topic, odom_topic)`` in
``loadRosParamFromNodeHandle`` (teb_config.cpp) and subscribes through base_local_planner's
odometry helper to ``cfg_.odom_topic`` after ``cfg_.loadRosParamFromNodeHandle(nh)``: the
subscription was named ``odom`` whatever ``odom_topic`` was set to. Now a read in the
unit names it by that parameter (default ``odom``), and a loader in another source that
is handed a ROS handle leaves it not known (``?``)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

CONFIG_H = """
#include <string>
#include <ros/ros.h>
struct Config {
  std::string odom_topic;
  std::string frame;
  Config() { odom_topic = "odom"; frame = "map"; }
  void load(const ros::NodeHandle& nh);
  void print() const;
};
"""

CONFIG_CPP = """
#include "config.h"
void Config::load(const ros::NodeHandle& nh) {
  nh.param("odom_topic", odom_topic, odom_topic);
}
"""

NODE_CPP = """
#include <ros/ros.h>
#include <nav_msgs/Odometry.h>
#include "config.h"
class Helper {
 public:
  void setTopic(std::string t) {
    ros::NodeHandle gn;
    sub_ = gn.subscribe<nav_msgs::Odometry>(t, 1, &Helper::cb, this);
  }
  void cb(const nav_msgs::Odometry::ConstPtr&) {}
  ros::Subscriber sub_;
};
class Planner {
 public:
  Planner() { odom_topic_ = "odom"; plan_topic_ = "plan"; }
  void init() {
    ros::NodeHandle nh("~");
    LOAD
    nh.param("own_odom_topic", odom_topic_, odom_topic_);
    helper_.setTopic(cfg_.odom_topic);
    mine_.setTopic(odom_topic_);
    plan_ = nh.advertise<nav_msgs::Odometry>(plan_topic_, 1);
  }
  Config cfg_;
  std::string odom_topic_, plan_topic_;
  Helper helper_, mine_;
  ros::Publisher plan_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "planner");
  Planner p;
  p.init();
  ros::spin();
}
"""


def _calls(write_tree, load: str) -> list[tuple]:
    root = write_tree({"pl/package.xml": package_xml("pl"),
                       "pl/src/config.h": CONFIG_H, "pl/src/config.cpp": CONFIG_CPP,
                       "pl/src/node.cpp": NODE_CPP.replace("LOAD", load)})
    result = extract_cpp([str(root / "pl" / "src" / "node.cpp"),
                          str(root / "pl" / "src" / "config.cpp")],
                         scan([str(root)]), cache_dir=None)
    return sorted(((c.kind, c.name, c.name_param, c.name_default) for c in result.calls
                   if c.kind in ("subscribe", "publish")), key=repr)


def test_the_parameter_read_into_a_member_names_it_not_the_constructors_text(
        write_tree) -> None:
    assert _calls(write_tree, "cfg_.load(nh);") == [
        ("publish", "~plan", None, None),  # no read writes plan_topic_: the constructor's
        ("subscribe", "?", "~own_odom_topic", "odom"),
        ("subscribe", "?", None, None),  # cfg_.odom_topic: loaded in config.cpp
    ]


def test_a_settings_object_no_loader_is_handed_a_handle_keeps_its_text(write_tree) -> None:
    assert _calls(write_tree, "cfg_.print();") == [
        ("publish", "~plan", None, None),
        ("subscribe", "?", "~own_odom_topic", "odom"),
        ("subscribe", "odom", None, None),  # a const method: the constructor's text holds
    ]
