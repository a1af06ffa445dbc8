"""``std::make_unique<T>(args)`` / ``make_shared`` where ``T`` has several constructors
of as many parameters: the one C++ calls is the one whose smart pointer parameter the
argument converts to. navigation2's behavior server (2023) builds
``CostmapSubscriber(shared_from_this(), topic)``, whose class has one constructor on a
``rclcpp_lifecycle::LifecycleNode::WeakPtr`` and one on a ``rclcpp::Node::WeakPtr``;
``shared_from_this()`` of its ``nav2_util::LifecycleNode`` (a class derived from
rclcpp_lifecycle's) converts only to the first. Neither takes the argument's very type,
so the site named no constructor: the topic it passes never reached
costmap_subscriber.cpp, whose subscription stayed ``?``."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include <std_msgs/msg/string.hpp>
class Lifecycle : public rclcpp_lifecycle::LifecycleNode {
public:
  explicit Lifecycle(const std::string & name) : rclcpp_lifecycle::LifecycleNode(name) {}
  std::shared_ptr<Lifecycle> shared_from_this() {
    return std::static_pointer_cast<Lifecycle>(
      rclcpp_lifecycle::LifecycleNode::shared_from_this());
  }
};
class MapSubscriber {
public:
  MapSubscriber(const rclcpp_lifecycle::LifecycleNode::WeakPtr & parent,
                const std::string & topic_name);
  MapSubscriber(const rclcpp::Node::WeakPtr & parent, const std::string & topic_name);
private:
  std::string topic_name_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};
"""

SUBSCRIBER = """
#include "map.hpp"
MapSubscriber::MapSubscriber(const rclcpp_lifecycle::LifecycleNode::WeakPtr & parent,
                             const std::string & topic_name)
: topic_name_(topic_name)
{
  auto node = parent.lock();
  sub_ = node->create_subscription<std_msgs::msg::String>(
    topic_name_, 1, [](std_msgs::msg::String::ConstSharedPtr) {});
}
MapSubscriber::MapSubscriber(const rclcpp::Node::WeakPtr & parent,
                             const std::string & topic_name)
: topic_name_(topic_name)
{
  auto node = parent.lock();
  sub_ = node->create_subscription<std_msgs::msg::String>(
    topic_name_, 1, [](std_msgs::msg::String::ConstSharedPtr) {});
}
"""

NODE = """
#include "map.hpp"
class Server : public Lifecycle {
public:
  Server() : Lifecycle("server") {
    declare_parameter("map_topic", std::string("map_raw"));
  }
  void setup() {
    std::string topic;
    get_parameter("map_topic", topic);
    map_sub_ = std::make_unique<MapSubscriber>(shared_from_this(), topic);
    other_ = std::make_shared<MapSubscriber>(shared_from_this(), "fixed_map");
  }
  std::unique_ptr<MapSubscriber> map_sub_;
  std::shared_ptr<MapSubscriber> other_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto server = std::make_shared<Server>();
  server->setup();
  rclcpp::spin(server->get_node_base_interface());
}
"""


def test_the_constructor_the_argument_converts_to_is_called(write_tree) -> None:
    root = write_tree({"srv/package.xml": package_xml("srv", "ament_cmake"),
                       "srv/src/map.hpp": HEADER, "srv/src/map.cpp": SUBSCRIBER,
                       "srv/src/node.cpp": NODE})
    result = extract_cpp([str(root / "srv" / "src" / name) for name in ("node.cpp", "map.cpp")],
                         scan([str(root)]), cache_dir=None, distro="humble")
    subs = sorted((c.name, c.name_param, c.location.line) for c in result.calls
                  if c.kind == "subscribe")
    # both sites call the first constructor (line 7), the one on rclcpp::Node's pointer
    # none (its subscription, line 15, is never made); the topic is the value of the
    # parameter map_topic, which the graph fills in
    assert subs == [("?", "map_topic", 7), ("fixed_map", None, 7)], subs
