"""A node handed to a class of another package whose code the node's own sources hold (a
library it links) hides nothing there: navigation2's behavior server (2023) gives
itself to costmap_2d's ``CostmapSubscriber``, read from costmap_subscriber.cpp, and its
base class ``nav2_util::LifecycleNode`` defines ``add_parameter(name, ...)`` helpers that
no file of the node calls. With the node counted as handed to unseen code, any of its
functions might run, so the helpers' ``declare_parameter(descriptor.name, ...)`` were
three reads named ``~/?``, and every "set but never read" of the server undecided (a
misspelt ``global_flame`` unreported)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SUBSCRIBER_HPP = """
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
namespace maps {
class MapSubscriber {
public:
  MapSubscriber(const rclcpp::Node::WeakPtr & parent, const std::string & topic);
private:
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};
}
"""

SUBSCRIBER_CPP = """
#include "maps/map_subscriber.hpp"
namespace maps {
MapSubscriber::MapSubscriber(const rclcpp::Node::WeakPtr & parent, const std::string & topic)
{
  auto node = parent.lock();
  sub_ = node->create_subscription<std_msgs::msg::String>(
    topic, 1, [](std_msgs::msg::String::ConstSharedPtr) {});
}
}
"""

NODE = """
#include <rclcpp/rclcpp.hpp>
#include <rcl_interfaces/msg/parameter_descriptor.hpp>
#include "maps/map_subscriber.hpp"
class Base : public rclcpp::Node {
public:
  explicit Base(const std::string & name) : rclcpp::Node(name) {}
  void add_parameter(const std::string & name, const rclcpp::ParameterValue & value)
  {
    auto descriptor = rcl_interfaces::msg::ParameterDescriptor();
    descriptor.name = name;
    declare_parameter(descriptor.name, value, descriptor);
  }
};
class Server : public Base, public std::enable_shared_from_this<Server> {
public:
  Server() : Base("server") { declare_parameter("global_frame", std::string("map")); }
  void setup() {
    sub_ = std::make_unique<maps::MapSubscriber>(
      rclcpp::Node::WeakPtr(std::static_pointer_cast<rclcpp::Node>(
        std::enable_shared_from_this<Server>::shared_from_this())), "costmap");
  }
  std::unique_ptr<maps::MapSubscriber> sub_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto server = std::make_shared<Server>();
  server->setup();
  rclcpp::spin(server);
}
"""


def test_a_node_handed_to_code_it_reads_hides_no_call(write_tree) -> None:
    root = write_tree({"maps/package.xml": package_xml("maps", "ament_cmake"),
                       "maps/include/maps/map_subscriber.hpp": SUBSCRIBER_HPP,
                       "maps/src/map_subscriber.cpp": SUBSCRIBER_CPP,
                       "server/package.xml": package_xml("server", "ament_cmake"),
                       "server/src/server.cpp": NODE})
    result = extract_cpp([str(root / "server" / "src" / "server.cpp"),
                          str(root / "maps" / "src" / "map_subscriber.cpp")],
                         scan([str(root)]), cache_dir=None, distro="jazzy")
    made = sorted((c.kind, c.name) for c in result.calls)
    assert ("declare", "?") not in made, made
    assert ("declare", "global_frame") in made
    assert ("subscribe", "costmap") in made
