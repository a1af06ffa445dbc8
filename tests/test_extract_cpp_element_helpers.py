"""A name made of each element of a list parameter in turn, when the element reaches the
ROS call through a helper function, a variable, or a lambda a standard algorithm calls
with each element: raspimouse's lifecycle_node_manager reads ``components``, and for
each component ``std::all_of(names.begin(), names.end(), [&](std::string s) { return
change_state(s, node, ...); })`` makes a client of ``s + "/change_state"`` in
``change_state``. Its four clients were ``?/get_state`` and ``?/change_state``; they are
now one per element of ``components`` (``name_each``), which the graph fills."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Node
from haros_arch.workspace import Workspace, scan
from tests.conftest import package_xml

MANAGER = """
#include <algorithm>
#include <string>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <lifecycle_msgs/srv/change_state.hpp>
#include <lifecycle_msgs/srv/get_state.hpp>
#include <std_srvs/srv/trigger.hpp>
using SrvGetState = lifecycle_msgs::srv::GetState;
using SrvChangeState = lifecycle_msgs::srv::ChangeState;

int state_of(std::string target_node_name, rclcpp::Node::SharedPtr node)
{
  auto service_name = target_node_name + "/get_state";
  auto client = node->create_client<SrvGetState>(service_name);
  return 0;
}

bool change_state(std::string target_node_name, rclcpp::Node::SharedPtr node, int id)
{
  auto service_name = target_node_name + "/change_state";
  auto client = node->create_client<SrvChangeState>(service_name);
  return id > 0;
}

bool all_inactive(rclcpp::Node::SharedPtr node, const std::vector<std::string> & names)
{
  return std::all_of(names.begin(), names.end(), [&](std::string s) {
    return state_of(s, node) == 2;
  });
}

bool all_active(rclcpp::Node::SharedPtr node, const std::vector<std::string> & names)
{
  return std::all_of(names.begin(), names.end(), [&](std::string s) {
    return state_of(s, node) == 3;
  });
}

bool configure_all(rclcpp::Node::SharedPtr node, const std::vector<std::string> & names)
{
  return std::all_of(names.begin(), names.end(), [&](std::string s) {
    return change_state(s, node, 1);
  });
}

int main(int argc, char * argv[])
{
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("lifecycle_node_manager");
  node->declare_parameter("components", std::vector<std::string>());
  auto components = node->get_parameter("components").get_value<std::vector<std::string>>();
  configure_all(node, components);
  all_inactive(node, components);
  all_active(node, components);
  std::vector<std::string> fixed{"a", "b"};
  // a lambda called with each element of a list that is no parameter's, and one whose
  // argument is no element: unknown, as before
  std::for_each(fixed.begin(), fixed.end(), [&](const std::string & f) {
    node->create_client<std_srvs::srv::Trigger>(f + "/reset");
  });
  auto other = [&](const std::string & g) {
    node->create_client<std_srvs::srv::Trigger>(g + "/other");
  };
  other(components.front());
  rclcpp::spin(node);
}
"""


def test_each_element_through_helpers_and_an_algorithm_lambda(write_tree) -> None:
    root = write_tree({"m/package.xml": package_xml("m", "ament_cmake"),
                       "m/src/manager.cpp": MANAGER})
    result = extract_cpp([str(root / "m" / "src" / "manager.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    clients = sorted({(c.name, c.name_param, c.name_each) for c in result.calls
                      if c.kind == "client"})
    assert clients == [
        ("?/change_state", "components", "."), ("?/get_state", "components", "."),
        ("?/other", None, None), ("?/reset", None, None)]
    node = Node("m", "manager", calls=list(result.calls))
    config = build(Configuration("c"), LaunchModel(
        nodes=[NodeDecl("/manager", "m", "manager", ros_version=2)],
        params=[ParamDecl("/manager/components", ["raspimouse", "tracker"])]),
        Workspace(root="/nowhere"), {node.name: node})
    names = {link.rosname.full for link in config.links if link.kind == "client"}
    assert {"/raspimouse/get_state", "/tracker/get_state", "/raspimouse/change_state",
            "/tracker/change_state"} <= names
    assert not any(name.endswith(("/get_state", "/change_state")) and "?" in name
                   for name in names)
