"""A static method of an API class template called on a template parameter
(``InterProcessPollingSubscriber<MessageT>::create_subscription(node, topic, qos)``), in
a class template a workspace factory builds: Autoware's agnocast_wrapper makes every
polling subscriber so (``create_polling_subscriber<Odometry>(this, topic)`` ->
``make_shared<ROS2PollingSubscriber<M>>(...)`` -> the static call in its member
initialiser). The dependent call named no row, so autoware_core's velocity smoother
had none of its four polling subscriptions, and three remaps of autoware_launch's
planning simulator to them were said unused."""

from __future__ import annotations

import pytest

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

WRAPPER = """
#include <rclcpp/rclcpp.hpp>
#include <autoware_utils_rclcpp/polling_subscriber.hpp>
namespace wrap {
using autoware_utils_rclcpp::polling_policy::Latest;
class Node {
 public:
  Node(const std::string & name, const rclcpp::NodeOptions & options)
  : node_(std::make_shared<rclcpp::Node>(name, options)) {}
  rclcpp::Node::SharedPtr get_rclcpp_node() const { return node_; }
 private:
  rclcpp::Node::SharedPtr node_;
};
template <typename MessageT, template <typename> class Policy = Latest>
class Subscriber { public: using SharedPtr = std::shared_ptr<Subscriber>;
                   virtual ~Subscriber() = default; };
template <typename MessageT, template <typename> class Policy = Latest>
class Ros2Subscriber : public Subscriber<MessageT, Policy> {
  typename autoware_utils_rclcpp::InterProcessPollingSubscriber<MessageT, Policy>::SharedPtr
    subscriber_;
 public:
  Ros2Subscriber(rclcpp::Node * node, const std::string & topic, const rclcpp::QoS & qos)
  : subscriber_(autoware_utils_rclcpp::InterProcessPollingSubscriber<MessageT, Policy>::
                  create_subscription(node, topic, qos)) {}
};
template <typename MessageT, template <typename> class Policy = Latest>
typename Subscriber<MessageT, Policy>::SharedPtr create_polling_subscriber(
  Node * node, const std::string & topic, const rclcpp::QoS & qos = rclcpp::QoS{1})
{
  return std::make_shared<Ros2Subscriber<MessageT, Policy>>(
    node->get_rclcpp_node().get(), topic, qos);
}
}
"""

NODE = """
#include "wrap.hpp"
#include <nav_msgs/msg/odometry.hpp>
#include <std_msgs/msg/string.hpp>
class Smoother : public wrap::Node {
 public:
  explicit Smoother(const rclcpp::NodeOptions & options) : wrap::Node("smoother", options) {}
  wrap::Subscriber<nav_msgs::msg::Odometry>::SharedPtr odometry_ =
    wrap::create_polling_subscriber<nav_msgs::msg::Odometry>(this, "/localization/odometry");
  wrap::Subscriber<std_msgs::msg::String>::SharedPtr mode_ =
    wrap::create_polling_subscriber<std_msgs::msg::String>(this, "~/input/mode");
};
"""


@pytest.fixture(scope="module")
def calls(tmp_path_factory) -> list[tuple[str, str, str | None]]:
    root = tmp_path_factory.mktemp("ws")
    (root / "demo/src").mkdir(parents=True)
    (root / "demo/package.xml").write_text(package_xml("demo", "ament_cmake"))
    (root / "demo/src/wrap.hpp").write_text(WRAPPER)
    (root / "demo/src/smoother.cpp").write_text(NODE)
    result = extract_cpp([str(root / "demo/src/smoother.cpp")], scan([str(root)]),
                         cache_dir=None)
    return sorted((c.kind, c.name, c.type) for c in result.calls)


def test_each_polling_subscriber_the_factory_builds_subscribes(calls) -> None:
    assert calls == [("subscribe", "/localization/odometry", "nav_msgs/msg/Odometry"),
                     ("subscribe", "~input/mode", "std_msgs/msg/String")]
