"""Source conditions over the value a function of the workspace returns: ublox tests
``if (getRosBoolean(node_, "nmea.set"))``, a helper that reads the parameter and
returns its value. The call stands for that parameter in the condition
(``Condition.parameters``, keyed by the call's text), so the graph decides it from the
configuration's value or the default. A helper that returns whether the parameter is
there (``return nh.getParam(n, v)``) is no parameter's value: its condition stays
undecided, and a local holding such an answer is not the parameter either."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue
from haros_arch.workspace import scan

ROS2_NODE = r"""
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <stdexcept>
#include <string>
static inline bool getRosBoolean(rclcpp::Node* node, const std::string& name)
{
  bool ret;
  if (!node->get_parameter(name, ret)) {
    throw std::runtime_error("not declared: " + name);
  }
  return ret;
}
static inline bool hasBoolean(rclcpp::Node* node, const std::string& name, bool& out)
{
  return node->get_parameter(name, out);
}
class Device
{
public:
  explicit Device(rclcpp::Node* node) : node_(node) {}
  void configure()
  {
    if (getRosBoolean(node_, "nmea.set")) {
      int64_t id = 0;
      node_->get_parameter("nmea.talker_id", id);
      pub_ = node_->create_publisher<std_msgs::msg::String>("nmea", 1);
    }
    if (node_->get_parameter("direct").as_bool()) {
      direct_ = node_->create_publisher<std_msgs::msg::String>("direct", 1);
    }
  }
  rclcpp::Node* node_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_, direct_;
};
class Gps : public rclcpp::Node
{
public:
  Gps() : rclcpp::Node("gps")
  {
    declare_parameter("nmea.set", false);
    declare_parameter("direct", false);
    declare_parameter("publish.fix", false);
    declare_parameter("flag", false);
    if (getRosBoolean(this, "publish.fix")) {
      fix_ = create_publisher<std_msgs::msg::String>("fix", 1);
    }
    bool flag = true;
    if (hasBoolean(this, "flag", flag)) {
      flag_ = create_publisher<std_msgs::msg::String>("flag", 1);
    }
    device_ = std::make_shared<Device>(this);
    device_->configure();
  }
  std::shared_ptr<Device> device_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr fix_, flag_;
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Gps>());
}
"""

ROS2_LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='ex', executable='gps', name='gps',
             parameters=[{'publish.fix': True}]),
    ])
"""

ROS1_NODE = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>
bool getBool(ros::NodeHandle& nh, std::string n) {bool v = false; nh.param(n, v, false); return v;}
bool hasBool(ros::NodeHandle& nh, std::string n) { bool v = false; return nh.getParam(n, v); }
int main(int argc, char** argv) {
  ros::init(argc, argv, "x");
  ros::NodeHandle nh, pnh("~");
  ros::Publisher pub, pub_y, pub_z, pub_w;
  if (getBool(pnh, "use_x")) pub = nh.advertise<std_msgs::String>("x", 1);
  if (getBool(pnh, "use_y")) pub_y = nh.advertise<std_msgs::String>("y", 1);
  if (hasBool(pnh, "use_z")) pub_z = nh.advertise<std_msgs::String>("z", 1);
  bool w = true;
  bool ok = pnh.getParam("use_w", w);
  if (ok) pub_w = nh.advertise<std_msgs::String>("w", 1);
  bool there = hasBool(pnh, "use_z");
  if (there) pub_z = nh.advertise<std_msgs::String>("z2", 1);
  ros::spin();
}
"""

ROS1_LAUNCH = """
<launch>
  <node pkg="ex1" type="x" name="x">
    <param name="use_y" value="true"/>
    <param name="use_z" value="false"/>
    <param name="use_w" value="false"/>
  </node>
</launch>
"""


def _workspace(write_tree):
    return write_tree({
        "src/ex/package.xml": package_xml("ex", "ament_cmake"),
        "src/ex/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(ex)\n"
                                 "add_executable(gps src/node.cpp)\n",
        "src/ex/src/node.cpp": ROS2_NODE,
        "src/ex/launch/ex.launch.py": ROS2_LAUNCH,
        "src/ex1/package.xml": package_xml("ex1"),
        "src/ex1/CMakeLists.txt": "project(ex1)\nadd_executable(x src/x.cpp)\n",
        "src/ex1/src/x.cpp": ROS1_NODE,
        "src/ex1/launch/x.launch": ROS1_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  ros2: [ex/launch/ex.launch.py]\n"
                        "  ros1: [ex1/launch/x.launch]\n"})


def test_a_call_returning_a_parameter_value_is_held_in_the_condition(write_tree) -> None:
    root = _workspace(write_tree)
    held = {}
    for path in ("src/ex/src/node.cpp", "src/ex1/src/x.cpp"):
        found = extract_cpp([str(root / path)], scan([str(root / "src")]), cache_dir=None)
        held.update({c.name: c.conditions[0].parameters for c in found.calls
                     if c.kind == "publish" and c.conditions})
    assert held == {
        "nmea": (('getRosBoolean(node_, "nmea.set")', "nmea.set"),),
        "direct": (('node_->get_parameter("direct").as_bool()', "direct"),),
        "fix": (('getRosBoolean(this, "publish.fix")', "publish.fix"),),
        "flag": None,  # hasBoolean returns whether the parameter is there
        "x": (('getBool(pnh, "use_x")', "~use_x"),),
        "y": (('getBool(pnh, "use_y")', "~use_y"),),
        "z": None,  # hasBool: whether it is there
        "w": None,  # ``ok`` holds getParam's answer, not use_w's value
        "z2": None,  # ``there`` holds hasBool's answer
    }


def test_a_condition_on_a_helper_value_is_decided(write_tree) -> None:
    """ublox_firmware7.cpp:65 reads the NMEA talker ids only ``if
    (getRosBoolean(node_, "nmea.set"))``, declared false (node.cpp:392) and not set:
    those reads are not made (they were three parameter-read-not-set warnings)."""
    root = _workspace(write_tree)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))

    def published(config):
        return {link.rosname.own: [c.text for c in link.conditions]
                for link in config.links if link.kind == "publish"
                and "rosout" not in link.rosname.full}
    ros2 = model.configuration("ros2")
    assert published(ros2) == {
        "fix": [],  # set true by the launch file
        "flag": ['hasBoolean(this, "flag", flag)'],  # presence: not decided
    }
    assert not [link for link in ros2.links if "talker_id" in link.rosname.full]
    said = [d.message for d in ros2.diagnostics if d.code == "CONDITION_FALSE"]
    assert any("/gps/nmea.talker_id" in m and "getRosBoolean" in m for m in said)
    ros1 = model.configuration("ros1")
    assert published(ros1) == {
        "y": [],  # set true
        "z": ['hasBool(pnh, "use_z")'],  # whether use_z is there: not its value
        "w": ["ok"],  # getParam finds use_w (set false): not decided false
        "z2": ["there"],
    }  # x: not set, getBool's own default false
    findings = [f for f in run_catalogue(model) if f.rule == "parameter-read-not-set"]
    assert findings == []


def test_a_helper_returning_the_value_does_not_test_for_presence(write_tree) -> None:
    """A read through a helper that returns the parameter's value is not prepared for
    the parameter being absent because the helper's result is a condition (it was
    marked ``tested``); a helper that returns whether the parameter is there is. The
    ROS 1 helper's own default (``nh.param(n, v, false)``) is each call's default."""
    root = _workspace(write_tree)
    reads = {}
    for path in ("src/ex/src/node.cpp", "src/ex1/src/x.cpp"):
        found = extract_cpp([str(root / path)], scan([str(root / "src")]), cache_dir=None)
        reads.update({(c.name, c.location.line): (c.tested, c.has_default, c.default)
                      for c in found.calls if c.kind == "read"})
    assert reads[("nmea.set", 23)] == (False, False, None)
    assert reads[("publish.fix", 44)][0] is False
    assert reads[("flag", 48)][0] is True
    assert reads[("~use_x", 10)] == (False, True, False)
    assert reads[("~use_z", 12)][0] is True
