"""Parameter reads whose result (whether the parameter is there) the code tests are
``tested``: they handle the parameter's absence (teleop_twist_joy's
``if (nh.getParam(..))``, interactive_marker_twist_server's ``if (!nh.getParam(..))``)."""

from __future__ import annotations

import os

import pytest

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.workspace import Workspace, scan

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "tested_reads")


def _extract(package: str) -> CppResult:
    source = os.path.join(ROOT, "src", package, "src", package + ".cpp")
    return extract_cpp([source], scan([ROOT]), cache_dir=None)


@pytest.fixture(scope="module")
def ros1() -> dict[str, bool]:
    return {c.name: c.tested for c in _extract("teleop").calls if c.kind == "read"}


@pytest.fixture(scope="module")
def ros2() -> dict[str, bool]:
    return {c.name: c.tested for c in _extract("teleop2").calls if c.kind == "read"}


def test_ros1_reads(ros1: dict[str, bool]) -> None:
    assert ros1 == {
        "~scale_turbo": True,            # if (nh.getParam(..))
        "~scale_linear": True,           # if (!nh.getParam(..))
        "~scale_linear_default": False,  # a read in the else branch, not tested
        "~max_speed": True,              # bool ok = nh.getParam(..); if (!ok)
        "~gain": True,                   # nh.getParam(..) ? gain : 2.0
        "~angular": True,                # argc > 1 && (ros::param::get(..))
        "~frame": True,                  # if (!nh.hasParam(..))
        "~ready": True,                  # while (!nh.getParam(..))
        "~min_speed": True,              # if (nh.getParam(..) == true)
        "~plain": False,                 # result dropped
        "~kept": False,                  # held in a variable never tested
        "~enabled": False,               # param<bool>(name, default): the value
    }


def test_ros2_reads(ros2: dict[str, bool]) -> None:
    assert ros2 == {
        "scale_turbo": True,   # if (node->get_parameter(name, out))
        "scale_linear": True,  # if (!node->get_parameter_or(..))
        "frame": True,         # if (node->has_parameter(..))
        "plain": False,        # result dropped
        "whole": False,        # get_parameter(name) returns the parameter
    }


OPTIONAL_TOPICS = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>
std::string g_pose_topic;
std::string g_frame;
void cb(const std_msgs::String::ConstPtr&) {}
int main(int argc, char** argv) {
  ros::init(argc, argv, "tf");
  ros::NodeHandle node, priv_nh("~");
  priv_nh.getParam("pose_topic", g_pose_topic);
  priv_nh.getParam("frame", g_frame);
  ros::Subscriber sub;
  if (!g_pose_topic.empty()) {
    sub = node.subscribe(g_pose_topic, 10, &cb);
  }
  std::string publish_topic;
  priv_nh.getParam("publish_topic", publish_topic);
  ros::Publisher pub;
  if (!publish_topic.empty())
    pub = node.advertise<std_msgs::String>(publish_topic, 10);
  ROS_INFO("%s", g_frame.c_str());
  ros::spin();
  return 0;
}
"""


def test_a_string_a_read_wrote_tested_for_being_empty_is_a_tested_read(tmp_path):
    """uuv_assistants' message_to_tf reads optional topics into strings and subscribes
    or advertises only when they are not empty: the absence is handled (6 false
    parameter-read-not-set); a string read and used as it is stays untested."""
    source = tmp_path / "n.cpp"
    source.write_text(OPTIONAL_TOPICS)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    assert {c.name: c.tested for c in result.calls if c.kind == "read"} == {
        "~pose_topic": True, "~frame": False, "~publish_topic": True}


DEPRECATED_NAME = r"""
#include <ros/ros.h>
class Chain {
 public:
  Chain() : private_nh_("~") {
    deprecated_ = private_nh_.hasParam("old_name");
    kept_ = private_nh_.hasParam("other");
    if (deprecated_)
      private_nh_.getParam("old_name", value_);
    ROS_INFO("%d", kept_);
  }
 private:
  ros::NodeHandle private_nh_;
  bool deprecated_;
  bool kept_;
  int value_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "chain");
  Chain chain;
  ros::spin();
}
"""


def test_a_member_a_status_read_wrote_then_tested_is_a_tested_read(tmp_path):
    """laser_filters' scan_to_scan_filter_chain stores ``hasParam("filter_chain")`` in a
    member and tests it in the same constructor (the deprecated name, read only when
    set): 15 false parameter-read-not-set. A member held and never tested stays
    untested."""
    source = tmp_path / "n.cpp"
    source.write_text(DEPRECATED_NAME)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    reads = {(c.name, c.location.line): c.tested for c in result.calls if c.kind == "read"}
    assert reads == {("~old_name", 6): True, ("~other", 7): False, ("~old_name", 9): False}


LASTING_STRINGS = r"""
#include <string>
#include <ros/ros.h>
#include <std_msgs/String.h>
std::string g_position_frame;
std::string g_frame;
void send(const std::string& child) {
  if (!g_position_frame.empty() && child != g_position_frame) ROS_INFO("%s", child.c_str());
  ROS_INFO("%s", g_frame.c_str());
}
class Relay {
 public:
  Relay() : pnh_("~") {
    pnh_.getParam("output", output_);
    pnh_.getParam("label", label_);
    sub_ = pnh_.subscribe("in", 1, &Relay::cb, this);
  }
  void cb(const std_msgs::String::ConstPtr& msg) {
    if (output_.empty()) return;
    ROS_INFO("%s %s", label_.c_str(), msg->data.c_str());
  }
 private:
  ros::NodeHandle pnh_;
  ros::Subscriber sub_;
  std::string output_;
  std::string label_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  ros::NodeHandle priv_nh("~");
  priv_nh.getParam("position_frame_id", g_position_frame);
  priv_nh.getParam("frame_id", g_frame);
  send("x");
  Relay relay;
  ros::spin();
}
"""


def test_a_global_or_member_string_tested_for_being_empty_in_another_function(tmp_path):
    """uuv_assistants' message_to_tf reads ``position_frame_id`` into a global in main
    (message_to_tf.cc:247) and tests it for being empty in the function that sends the
    transforms (:89): the absence is handled, a false parameter-read-not-set. So is a
    member read in a constructor and tested in a callback. A global or member read and
    used as it is stays untested."""
    source = tmp_path / "n.cpp"
    source.write_text(LASTING_STRINGS)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    assert {c.name: c.tested for c in result.calls if c.kind == "read"} == {
        "~position_frame_id": True, "~frame_id": False, "~output": True, "~label": False}
