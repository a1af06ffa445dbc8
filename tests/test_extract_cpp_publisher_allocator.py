"""rclcpp's Publisher, Subscription and rclcpp_lifecycle's LifecyclePublisher take the
allocator ``std::allocator<void>`` by default. A workspace's own wrapper of
``create_publisher`` that returns ``std::shared_ptr<LifecyclePublisher<MessageT,
AllocatorT>>`` with ``AllocatorT = std::allocator<void>`` (mocap4r2 078b202's
ControlledLifecycleNode, whose options default to
``rclcpp_lifecycle::create_default_publisher_options<AllocatorT>()``) gives the type of a
``LifecyclePublisher<M>::SharedPtr`` member; the stand-ins' ``void`` default made the
assignment a C++ error beside the call, and the node partial."""

from __future__ import annotations

import pytest
from conftest import package_xml

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.workspace import scan

LIFECYCLE_WRAPPER = """\
#include <memory>
#include <set>
#include <string>
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_lifecycle/lifecycle_node.hpp"
#include "std_msgs/msg/string.hpp"
class Controlled : public rclcpp_lifecycle::LifecycleNode {
 public:
  Controlled() : LifecycleNode("controlled") {
    control_pub_ = create_publisher<std_msgs::msg::String>(
      "control", rclcpp::QoS(100).reliable());
    control_pub_->on_activate();
  }
 protected:
  template<typename MessageT, typename AllocatorT = std::allocator<void>>
  std::shared_ptr<rclcpp_lifecycle::LifecyclePublisher<MessageT, AllocatorT>>
  create_publisher(
    const std::string & topic_name, const rclcpp::QoS & qos,
    const rclcpp::PublisherOptionsWithAllocator<AllocatorT> & options = (
      rclcpp_lifecycle::create_default_publisher_options<AllocatorT>()))
  {
    topics_.insert(topic_name);
    using PublisherT = rclcpp_lifecycle::LifecyclePublisher<MessageT, AllocatorT>;
    return rclcpp::create_publisher<MessageT, AllocatorT, PublisherT>(
      *this, topic_name, qos, options);
  }
  std::set<std::string> topics_;
  rclcpp_lifecycle::LifecyclePublisher<std_msgs::msg::String>::SharedPtr control_pub_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Controlled>()->get_node_base_interface());
}
"""

NODE_WRAPPER = """\
#include <memory>
#include <string>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"
template<typename MessageT, typename AllocatorT = std::allocator<void>>
std::shared_ptr<rclcpp::Publisher<MessageT, AllocatorT>> make_pub(
  rclcpp::Node & node, const std::string & topic)
{
  return node.create_publisher<MessageT, AllocatorT>(topic, 10);
}
template<typename MessageT, typename AllocatorT = std::allocator<void>>
std::shared_ptr<rclcpp::Subscription<MessageT, AllocatorT>> make_sub(
  rclcpp::Node & node, const std::string & topic)
{
  return node.create_subscription<MessageT>(topic, 10, [](typename MessageT::SharedPtr) {});
}
class Plain : public rclcpp::Node {
 public:
  Plain() : Node("plain") {
    pub_ = make_pub<std_msgs::msg::String>(*this, "out");
    sub_ = make_sub<std_msgs::msg::String>(*this, "in");
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Plain>());
}
"""


def _extract(tmp_path, text: str, distro: str) -> CppResult:
    (tmp_path / "package.xml").write_text(package_xml("wrappers"))
    source = tmp_path / "node.cpp"
    source.write_text(text)
    return extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None, distro=distro)


def _errors(result: CppResult) -> list[tuple[str, str]]:
    return [(d.code, d.message) for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED")]


@pytest.mark.parametrize("distro", ["humble", "jazzy"])
def test_lifecycle_wrapper_returns_the_members_publisher_type(tmp_path, distro: str) -> None:
    result = _extract(tmp_path, LIFECYCLE_WRAPPER, distro)
    assert _errors(result) == []
    assert [(c.kind, c.name, c.type) for c in result.calls if not c.name.startswith("~")] == [
        ("publish", "control", "std_msgs/msg/String")]


def test_node_wrappers_with_the_default_allocator(tmp_path) -> None:
    result = _extract(tmp_path, NODE_WRAPPER, "humble")
    assert _errors(result) == []
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("publish", "out", "std_msgs/msg/String"),
        ("subscribe", "in", "std_msgs/msg/String")]
