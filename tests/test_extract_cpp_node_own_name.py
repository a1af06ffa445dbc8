"""A name built from the node's own name: rclcpp's ``get_name()`` (on the node, through a
node pointer or its base interface) and ``get_fully_qualified_name()`` at the start of a
name are the node's private namespace, as roscpp's ``ros::this_node::getName()`` is.
navigation2's lifecycle manager serves ``get_name() + std::string("/manage_nodes")``
(lifecycle_manager.cpp:219) and its map server ``get_name() + std::string("/")`` +
the service's name (map_server.cpp:107): their names were ``?/manage_nodes``."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl
from haros_arch.model import Configuration, Node
from haros_arch.workspace import Workspace, scan
from tests.conftest import package_xml

NODE = """
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include <std_msgs/msg/bool.hpp>
#include <std_srvs/srv/trigger.hpp>
class Manager : public rclcpp_lifecycle::LifecycleNode
{
public:
  Manager() : rclcpp_lifecycle::LifecycleNode("manager")
  {
    const std::string prefix = get_name() + std::string("/");
    srv_ = create_service<std_srvs::srv::Trigger>(
      get_name() + std::string("/manage_nodes"), &Manager::cb);
    load_ = create_service<std_srvs::srv::Trigger>(prefix + "load_map", &Manager::cb);
    pub_ = create_publisher<std_msgs::msg::Bool>(
      std::string(this->get_fully_qualified_name()) + "/active", 1);
    mid_ = create_publisher<std_msgs::msg::Bool>(
      std::string("status/") + get_name(), 1);
    node_name_ = get_name();
    declare_parameter(node_name_ + ".verbose", false);  // named after the node
    declare_parameter(node_name_ + "/private", false);
  }
  void plugin(rclcpp::Node::SharedPtr node,
              rclcpp::node_interfaces::NodeBaseInterface::SharedPtr base)
  {
    other_ = node->create_publisher<std_msgs::msg::Bool>(
      std::string(node->get_name()) + "/plugin_out", 1);
    third_ = node->create_publisher<std_msgs::msg::Bool>(
      std::string(base->get_name()) + "/base_out", 1);
  }
  static void cb(const std::shared_ptr<std_srvs::srv::Trigger::Request>,
                 std::shared_ptr<std_srvs::srv::Trigger::Response>) {}
  rclcpp::Service<std_srvs::srv::Trigger>::SharedPtr srv_, load_;
  rclcpp::Publisher<std_msgs::msg::Bool>::SharedPtr pub_, mid_, other_, third_;
  std::string node_name_;
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<Manager>();
  auto handed = &Manager::plugin;  // (handed on: what plugin() makes may be made)
  (void)handed;
  rclcpp::spin(node->get_node_base_interface());
}
"""


def test_the_node_name_starts_a_private_name(write_tree) -> None:
    root = write_tree({"mgr/package.xml": package_xml("mgr", "ament_cmake"),
                       "mgr/src/node.cpp": NODE})
    result = extract_cpp([str(root / "mgr" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    calls = sorted((c.kind, c.name) for c in result.calls if c.kind in ("publish", "server")
                   and "state" not in c.name and "transition" not in c.name)  # lifecycle
    assert calls == [
        ("publish", "status/?"),  # not at the start: no namespace
        ("publish", "~active"),
        ("publish", "~base_out"),
        ("publish", "~plugin_out"),
        ("server", "~load_map"),
        ("server", "~manage_nodes"),
    ]
    declared = sorted(c.name for c in result.calls if c.kind == "declare")
    assert "?.verbose" in declared and "~private" in declared
    node = Node("mgr", "mgr", calls=list(result.calls))
    config = build(Configuration("c"), LaunchModel(
        nodes=[NodeDecl("/robot/lifecycle_manager", "mgr", "mgr")]),
        Workspace(root="/nowhere"), {node.name: node})
    names = sorted(link.rosname.full for link in config.links
                   if link.kind == "server")
    assert "/robot/lifecycle_manager/load_map" in names
    assert "/robot/lifecycle_manager/manage_nodes" in names


def test_the_node_name_inside_a_name_is_the_instance_name(write_tree) -> None:
    """navigation2's costmap serves ``std::string("get_cost_") + get_name()``: the node's
    name without its namespace, which each instance gives (``/global_costmap/
    get_cost_global_costmap``); it was ``get_cost_?``. The fully qualified name inside a
    name stays unknown."""
    root = write_tree({"mgr/package.xml": package_xml("mgr", "ament_cmake"),
                       "mgr/src/node.cpp": NODE})
    result = extract_cpp([str(root / "mgr" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    selves = sorted(c.name for c in result.calls if c.name_self)
    assert "status/?" in selves and "?.verbose" in selves
    node = Node("mgr", "mgr", calls=list(result.calls))
    config = build(Configuration("c"), LaunchModel(
        nodes=[NodeDecl("/robot/lifecycle_manager", "mgr", "mgr")]),
        Workspace(root="/nowhere"), {node.name: node})
    topics = sorted(link.rosname.full for link in config.links if link.kind == "publish")
    assert "/status/lifecycle_manager" in topics  # (the instance is in "/")
    params = {link.rosname.full for link in config.links if link.kind == "read"}
    assert "/lifecycle_manager.verbose" in params  # (resolved as ROS 1 here)
