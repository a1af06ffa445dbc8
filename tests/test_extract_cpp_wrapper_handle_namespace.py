"""A call of a workspace function that is given the handle (or node) its ROS call is made
on is named in that handle's namespace, whatever form the handle parameter takes:

- ROS 1, a ``boost::shared_ptr<ros::NodeHandle>`` / ``ros::NodeHandlePtr`` parameter used
  as ``nh->param(..)``: each call site's handle (``~use_x`` for a private one, ``use_y``
  for the node's), not every caller's namespace at once;
- ROS 1, a topic named by the value such a wrapper returns: the parameter it names is
  the read's, with the handle's namespace (``~topic_name``, as for ``pnh.param``);
- ROS 2, a ``rclcpp::Node::SharedPtr`` given a sub node (``create_sub_node("ns")``):
  the publisher is in the sub node's namespace, as when made on the sub node directly.
  (rclcpp does not put a sub node's parameters under its namespace; neither do we.)
"""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

ROS1 = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <boost/shared_ptr.hpp>
#include <boost/make_shared.hpp>
#include <string>
bool getBoolS(const ros::NodeHandlePtr& nh, const std::string& name, bool def) {
  bool v;
  nh->param(name, v, def);
  return v;
}
ros::Publisher advS(boost::shared_ptr<ros::NodeHandle> nh, const std::string& topic) {
  return nh->advertise<std_msgs::String>(topic, 5);
}
std::string getStr(const ros::NodeHandle& nh, const std::string& name,
                   const std::string& def) {
  std::string v;
  nh.param(name, v, def);
  return v;
}
int main(int argc, char **argv) {
  ros::init(argc, argv, "n");
  ros::NodeHandlePtr pnh = boost::make_shared<ros::NodeHandle>("~");
  ros::NodeHandlePtr nh = boost::make_shared<ros::NodeHandle>();
  ros::NodeHandle plain, priv("~"), rel(plain, "rel");
  bool x = getBoolS(pnh, "use_x", false);
  bool y = getBoolS(nh, "use_y", true);
  ros::Publisher p1 = advS(pnh, "ptopic");
  ros::Publisher p2 = advS(nh, "gtopic");
  std::string t = getStr(priv, "topic_name", "chatter");
  ros::Publisher p3 = plain.advertise<std_msgs::String>(t, 5);
  std::string u = getStr(rel, "other_topic", "other");
  ros::Publisher p4 = plain.advertise<std_msgs::String>(u, 5);
  ros::spin();
}
"""

ROS2 = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <string>
rclcpp::Publisher<std_msgs::msg::String>::SharedPtr adv(rclcpp::Node::SharedPtr node,
                                                        const std::string& t) {
  return node->create_publisher<std_msgs::msg::String>(t, 10);
}
bool flag(rclcpp::Node::SharedPtr node, const std::string& name) {
  return node->declare_parameter(name, false);
}
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("m");
  auto sub = node->create_sub_node("sn");
  auto a = adv(sub, "t1");
  auto b = adv(node, "t2");
  auto c = sub->create_publisher<std_msgs::msg::String>("t3", 10);
  bool f = flag(sub, "f");
  rclcpp::spin(node);
}
"""


def _calls(write_tree, build: str, deps: str, source: str):
    xml = package_xml("pkg", build).replace("</package>", f"{deps}</package>")
    root = write_tree({"pkg/package.xml": xml, "pkg/src/n.cpp": source})
    result = extract_cpp([str(root / "pkg" / "src" / "n.cpp")], scan([str(root)]),
                         cache_dir=None)
    return result.calls


def test_ros1_smart_pointer_handle_parameter(write_tree) -> None:
    calls = _calls(write_tree, "catkin", "<depend>roscpp</depend><depend>std_msgs</depend>",
                   ROS1)
    found = sorted((c.kind, c.name, c.handle_namespace, c.location.line) for c in calls
                   if c.location.line in (25, 26, 27, 28))
    assert found == [
        ("publish", "gtopic", None, 28),
        ("publish", "~ptopic", "~", 27),
        ("read", "use_y", None, 26),
        ("read", "~use_x", "~", 25),
    ]


def test_ros1_name_parameter_of_a_wrapper_keeps_the_handle_namespace(write_tree) -> None:
    calls = _calls(write_tree, "catkin", "<depend>roscpp</depend><depend>std_msgs</depend>",
                   ROS1)
    named = sorted((c.name, c.name_param, c.name_default) for c in calls
                   if c.kind == "publish" and c.name == "?")
    assert named == [("?", "rel/other_topic", "other"), ("?", "~topic_name", "chatter")]
    reads = {c.name for c in calls if c.kind == "read"}
    assert {"~topic_name", "rel/other_topic"} <= reads


def test_ros2_sub_node_given_to_a_wrapper(write_tree) -> None:
    calls = _calls(write_tree, "ament_cmake",
                   "<depend>rclcpp</depend><depend>std_msgs</depend>", ROS2)
    found = sorted((c.kind, c.name) for c in calls)
    assert found == [("declare", "f"), ("publish", "sn/t1"), ("publish", "sn/t3"),
                     ("publish", "t2")]


SETUP = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>
void setup(ros::NodeHandle& nh, ros::NodeHandle& pnh);
static std::string getStr(const ros::NodeHandle& nh, const std::string& name) {
  std::string v;
  nh.getParam(name, v);
  return v;
}
static ros::Publisher pub;
void setup(ros::NodeHandle& nh, ros::NodeHandle& pnh) {
  std::string t = getStr(pnh, "topic");
  pub = nh.advertise<std_msgs::String>(t, 5);
}
"""

MAIN = """\
#include <ros/ros.h>
void setup(ros::NodeHandle& nh, ros::NodeHandle& pnh);
int main(int argc, char **argv) {
  ros::init(argc, argv, "five");
  ros::NodeHandle nh, pnh("~");
  setup(nh, pnh);
  ros::spin();
}
"""


def test_the_handle_given_from_another_file(write_tree) -> None:
    """The handle the wrapper is given is a parameter that main.cpp passes: the name
    parameter is filled with that handle's namespace, as the read's name is."""
    xml = package_xml("pkg", "catkin").replace(
        "</package>", "<depend>roscpp</depend><depend>std_msgs</depend></package>")
    root = write_tree({"pkg/package.xml": xml, "pkg/src/setup.cpp": SETUP,
                       "pkg/src/main.cpp": MAIN})
    result = extract_cpp([str(root / "pkg/src/main.cpp"), str(root / "pkg/src/setup.cpp")],
                         scan([str(root)]), cache_dir=None)
    assert sorted((c.kind, c.name, c.name_param) for c in result.calls) == [
        ("publish", "?", "~topic"), ("read", "~topic", None)]
