"""A name that begins with an unknown part may be global: C++ ``prefix + "/cmd_vel"``
with the prefix not known is ``/robot1/cmd_vel`` when the prefix is ``/robot1``, which
roscpp, rospy and rcl take as it is on any handle. It was resolved into the node's
namespace (``/r/?/cmd_vel``), so a global topic it may be was never among its candidates;
and a wholly unknown name given on a ROS 2 sub node (``create_sub_node("cam")``) was put
under the sub node (``/r/cam/?``), which rclcpp does only for a relative name. Both stay
as written (``?/cmd_vel``, ``?``): their patterns match the names of every namespace, so
the links they may make are still found as possible."""

from __future__ import annotations

from conftest import package_xml
from test_graph import call, graph, node

from haros_arch.extract.cpp import extract_cpp
from haros_arch.graph import find_candidates
from haros_arch.launch.model import NodeDecl
from haros_arch.model.rosname import RosName, resolve
from haros_arch.workspace import scan


def test_a_name_that_begins_unknown_stays_as_written():
    assert resolve("?/cmd_vel", "/r/", "/r/n") == "?/cmd_vel"
    assert resolve("?_cmd", "/r/", "/r/n") == "?_cmd"
    assert resolve("?", "/r/", "/r/n") == "?"
    # known first: relative, in the namespace, as before
    assert resolve("cmd_?", "/r/", "/r/n") == "/r/cmd_?"
    assert resolve("a/?/b", "/r/", "/r/n") == "/r/a/?/b"
    name = RosName.make("?/cmd_vel", "/r/", "/r/n")
    assert name.is_unresolved
    assert all(name.matches(n) for n in ("/robot1/cmd_vel", "/r/cmd_vel", "/cmd_vel",
                                         "/r/base/cmd_vel"))
    assert not name.matches("/robot1/cmd_vel_safe")


def test_a_global_topic_is_a_candidate_of_a_name_that_begins_unknown():
    base = node("p", "base", call("subscribe", "?/cmd_vel", "geometry_msgs/Twist"))
    teleop = node("p", "teleop", call("publish", "/robot1/cmd_vel", "geometry_msgs/Twist"))
    config = graph([NodeDecl("/r/base", "p", "base", "/r/"),
                    NodeDecl("/teleop", "p", "teleop", "/")], nodes=[base, teleop])
    (link,) = [link for link in config.links if link.node.name == "/r/base"]
    assert (link.rosname.given, link.rosname.full) == ("?/cmd_vel", "?/cmd_vel")
    find_candidates(config)
    assert [c.name for c in link.resource.candidates] == ["/robot1/cmd_vel"]


ROS2 = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <iostream>
#include <string>
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("m");
  std::string topic, prefix;
  std::cin >> topic >> prefix;  // from a file the tool does not read
  auto sub = node->create_sub_node("cam");
  auto a = sub->create_publisher<std_msgs::msg::String>(topic, 10);
  auto b = sub->create_publisher<std_msgs::msg::String>("image", 10);
  auto c = node->create_publisher<std_msgs::msg::String>(prefix + "/cmd_vel", 10);
  auto d = sub->create_publisher<std_msgs::msg::String>("raw_" + topic, 10);
  rclcpp::spin(node);
}
"""


def test_a_sub_node_does_not_extend_a_name_that_begins_unknown(write_tree):
    xml = package_xml("pkg", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>")
    root = write_tree({"pkg/package.xml": xml, "pkg/src/n.cpp": ROS2})
    result = extract_cpp([str(root / "pkg" / "src" / "n.cpp")], scan([str(root)]),
                         cache_dir=None)
    names = sorted((c.location.line, c.name) for c in result.calls if c.kind == "publish")
    assert names == [(11, "?"), (12, "cam/image"), (13, "?/cmd_vel"), (14, "cam/raw_?")]
