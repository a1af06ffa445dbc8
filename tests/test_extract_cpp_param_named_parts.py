"""A name built around a parameter's value (``"/" + robot_name + "/base_feedback"`` with
``robot_name`` read from ``~robot_name``) keeps its text, and the graph puts the
parameter's value in its one ``?``. ros_kortex's examples pass ``robot_name`` to helper
functions (example_full_arm_movement.cpp:155-161): their 10 service clients and a
subscription were all named ``/my_gen3``, the parameter's value alone."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Node
from haros_arch.workspace import Workspace, scan
from tests.conftest import package_xml

NODE = """
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <std_srvs/Empty.h>
void cb(const std_msgs::String::ConstPtr & m) {}
bool helper(ros::NodeHandle n, const std::string & robot_name)
{
  ros::ServiceClient c = n.serviceClient<std_srvs::Empty>("/" + robot_name + "/base/clear");
  ros::Subscriber s = n.subscribe(robot_name + "/feedback", 1, &cb);
  return true;
}
int main(int argc, char ** argv)
{
  ros::init(argc, argv, "ex");
  ros::NodeHandle n;
  std::string robot_name = "my_gen3";
  ros::param::get("~robot_name", robot_name);
  ros::ServiceClient c = n.serviceClient<std_srvs::Empty>("/" + robot_name + "/direct");
  helper(n, robot_name);
  std::string first, second;
  ros::param::get("~first", first);
  ros::param::get("~second", second);
  ros::Publisher p = n.advertise<std_msgs::String>("/" + first + "/" + second, 1);
}
"""


def test_a_name_around_a_parameter_value_keeps_its_text(write_tree) -> None:
    root = write_tree({"ex/package.xml": package_xml("ex"), "ex/src/node.cpp": NODE})
    result = extract_cpp([str(root / "ex" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    calls = sorted((c.kind, c.name, c.name_param) for c in result.calls if c.kind != "read")
    assert calls == [
        ("client", "/?/base/clear", "~robot_name"),
        ("client", "/?/direct", "~robot_name"),
        # two parameters: which '?' is which is not said
        ("publish", "/?/?", None),
        ("subscribe", "?/feedback", "~robot_name"),
    ]
    node = Node("ex", "ex", calls=list(result.calls))
    config = build(Configuration("c"), LaunchModel(
        nodes=[NodeDecl("/ex", "ex", "ex")],
        params=[ParamDecl("/ex/robot_name", "arm", "str")]), Workspace(root="/nowhere"),
        {node.name: node})
    assert sorted((link.kind, link.rosname.full) for link in config.links
                  if link.kind in ("client", "subscribe")) == [
        ("client", "/arm/base/clear"), ("client", "/arm/direct"),
        ("subscribe", "/arm/feedback")]


MEMBER_NODE = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
class Hazards : public rclcpp::Node
{
public:
  Hazards() : rclcpp::Node("hazards")
  {
    topic_ =
      this->declare_parameter("publisher_topic", "hazard_detection");
    pub_ = create_publisher<std_msgs::msg::String>(topic_, rclcpp::SensorDataQoS());
    later_ = this->declare_parameter("later_topic", std::string("later"));
  }
  void start() { sub_ = create_subscription<std_msgs::msg::String>(later_, 10, cb); }
  static void cb(const std_msgs::msg::String::SharedPtr) {}
  std::string topic_, later_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};
"""


def test_a_name_held_by_a_member_the_parameter_was_assigned_to(write_tree) -> None:
    """``topic_ = declare_parameter("publisher_topic", "x")`` then ``create_publisher(
    topic_, ..)``, in the constructor or in another method: the name is the parameter's
    value, as it is through a local variable (create3_sim's hazards_vector_publisher.cpp:18-29
    and seven more of its nodes named their topics '?')."""
    root = write_tree({"ex/package.xml": package_xml("ex", "ament_cmake"),
                       "ex/src/node.cpp": MEMBER_NODE})
    result = extract_cpp([str(root / "ex" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    calls = sorted((c.kind, c.name, c.name_param, c.name_default) for c in result.calls
                   if c.kind in ("publish", "subscribe"))
    assert calls == [("publish", "?", "publisher_topic", "hazard_detection"),
                     ("subscribe", "?", "later_topic", "later")]


LOOP_NODE = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
class Hazards : public rclcpp::Node
{
public:
  Hazards() : rclcpp::Node("hazards")
  {
    topics_ = this->declare_parameter("subscription_topics", std::vector<std::string>());
    for (std::string topic : topics_) {
      subs_.push_back(create_subscription<std_msgs::msg::String>(topic, 10, cb));
    }
    auto outs = this->declare_parameter("publish_topics", std::vector<std::string>());
    for (const std::string & out : outs) {
      for (const std::string & side : sides_) {
        if (out.find(side) != std::string::npos) {
          pubs_.push_back(create_publisher<std_msgs::msg::String>(out, 10));
        }
      }
    }
  }
  static void cb(const std_msgs::msg::String::SharedPtr) {}
  std::vector<std::string> topics_;
  std::vector<std::string> sides_{"left", "right"};
  std::vector<rclcpp::Subscription<std_msgs::msg::String>::SharedPtr> subs_;
  std::vector<rclcpp::Publisher<std_msgs::msg::String>::SharedPtr> pubs_;
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Hazards>());
}
"""

LOOP_LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='ex', executable='hazards', name='hazards',
             parameters=[{'subscription_topics': ['bumper', '/cliff/left']}]),
    ])
"""


def test_a_call_in_a_loop_over_a_list_parameter_is_one_call_per_element(write_tree) -> None:
    """``for (std::string topic : topics_) create_subscription(topic, ..)`` with
    ``topics_`` a list parameter: one subscription per element the configuration gives
    the list (create3_sim's hazards_vector_publisher.cpp:51-58 subscribes its eight
    hazard topics so, its sensors_node its cliff and IR topics: all were '?'); the loop is
    then no condition of each. A list the configuration does not set keeps the one call,
    named '?', under its loop ("for each")."""
    import os

    from haros_arch.pipeline import Options, analyse
    from haros_arch.project import load

    root = write_tree({
        "src/ex/package.xml": package_xml("ex", "ament_cmake"),
        "src/ex/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(ex)\n"
                                 "add_executable(hazards src/node.cpp)\n",
        "src/ex/src/node.cpp": LOOP_NODE,
        "src/ex/launch/ex.launch.py": LOOP_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [ex/launch/ex.launch.py]\n"})
    result = extract_cpp([str(root / "src/ex/src/node.cpp")], scan([str(root / "src")]),
                         cache_dir=None)
    made = [(c.kind, c.name, c.name_param, c.name_each, [str(x) for x in c.conditions])
            for c in result.calls if c.kind in ("publish", "subscribe")]
    assert made == [
        ("subscribe", "?", "subscription_topics", ".",
         ["for each (std::string topic : topics_)"]),
        ("publish", "?", "publish_topics", ".",
         ["for each (const std::string & out : outs)",
          "for (const std::string & side : sides_)",
          "if (out.find(side) != std::string::npos)"])]
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    links = sorted((link.kind, link.rosname.full, tuple(str(c) for c in link.conditions))
                   for link in model.configuration("c").links
                   if link.kind in ("publish", "subscribe"))
    assert links == [
        ("publish", "/?", ("for each (const std::string & out : outs)",
                           "for (const std::string & side : sides_)",
                           "if (out.find(side) != std::string::npos)")),
        ("subscribe", "/bumper", ()), ("subscribe", "/cliff/left", ())]


MAP_NODE = """
#include <map>
#include <rclcpp/rclcpp.hpp>
class Teleop : public rclcpp::Node
{
public:
  Teleop() : rclcpp::Node("teleop")
  {
    std::map<std::string, int64_t> default_linear_map{
      {"x", 5L},
      {"y", -1L},
    };
    this->declare_parameters("axis_linear", default_linear_map);
    this->get_parameters("axis_linear", linear_);
    std::map<std::string, double> changed{{"a", 1.0}};
    changed["b"] = 2.0;
    this->declare_parameters("changed", changed);
  }
  std::map<std::string, int64_t> linear_;
};
"""


def test_declare_parameters_of_a_local_map_declares_its_keys(write_tree) -> None:
    """teleop_twist_joy.cpp:89-94: ``declare_parameters("axis_linear", m)`` with ``m`` a
    local map initialised with string keys declares ``axis_linear.x`` ... each with the
    map's value as its default; it was ``axis_linear.?`` (5 settings of its launch files
    undecided). A map the body also changes keeps '?'; ``get_parameters(prefix, out)``
    reads whatever is declared under the prefix: '?'."""
    root = write_tree({"ex/package.xml": package_xml("ex", "ament_cmake"),
                       "ex/src/node.cpp": MAP_NODE})
    result = extract_cpp([str(root / "ex" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name, c.has_default) for c in result.calls] == [
        ("declare", "axis_linear.x", True), ("declare", "axis_linear.y", True),
        ("read", "axis_linear.?", False), ("declare", "changed.?", True)]
