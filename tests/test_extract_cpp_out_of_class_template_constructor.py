"""A class template whose constructor is defined out of the class, in its header
(depthai_bridge's ``template <class RosMsg, class SimMsg>
BridgePublisher<RosMsg, SimMsg>::BridgePublisher(node, topic, ...) { ... }``), built
with the node by another package (depthai_examples' nodes):

- its code is in the unit: no ``CPP_NODE_PASSED`` (the check looked only for a
  constructor defined in the class), which made rgb_stereo_node ``partial``;
- it is a wrapper as an in-class one is: its publisher is named and typed at each
  construction (the out-of-class definition's template header declares the class's
  parameters again, and the body's ``RosMsg`` is that header's, not the class's): it
  was ``?`` of type ``?``."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HEADER = """\
#pragma once
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
namespace bridge {
template <class RosMsg, class SimMsg>
class BridgePublisher {
public:
  BridgePublisher(std::shared_ptr<rclcpp::Node> node, const std::string& topic);
private:
  std::shared_ptr<rclcpp::Node> node_;
  typename rclcpp::Publisher<RosMsg>::SharedPtr pub_;
};
template <class RosMsg, class SimMsg>
BridgePublisher<RosMsg, SimMsg>::BridgePublisher(std::shared_ptr<rclcpp::Node> node,
                                                 const std::string& topic)
    : node_(node) {
  pub_ = node_->create_publisher<RosMsg>(topic, 10);
}
}  // namespace bridge
"""

NODE = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <bridge/bridge_publisher.hpp>
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("example");
  auto depth = std::make_unique<bridge::BridgePublisher<std_msgs::msg::String, int>>(
      node, std::string("stereo/depth"));
  rclcpp::spin(node);
}
"""


def test_an_out_of_class_template_constructor_is_read_with_the_node(tmp_path) -> None:
    depends = "<depend>rclcpp</depend><depend>std_msgs</depend>"
    (tmp_path / "bridge" / "include" / "bridge").mkdir(parents=True)
    (tmp_path / "bridge" / "package.xml").write_text(package_xml(
        "bridge", "ament_cmake").replace("</package>", depends + "</package>"))
    (tmp_path / "bridge" / "include" / "bridge" / "bridge_publisher.hpp").write_text(HEADER)
    (tmp_path / "example" / "src").mkdir(parents=True)
    (tmp_path / "example" / "package.xml").write_text(package_xml(
        "example", "ament_cmake").replace(
            "</package>", depends + "<depend>bridge</depend></package>"))
    source = tmp_path / "example" / "src" / "node.cpp"
    source.write_text(NODE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert not [d.message for d in result.diagnostics if d.code == "CPP_NODE_PASSED"]
    calls = [(c.kind, c.name, c.type) for c in result.calls]
    assert calls == [("publish", "stereo/depth", "std_msgs/msg/String")], calls


GREPPED = """\
template <class RosMsg, class SimMsg>
class BridgePublisher {
public:
  BridgePublisher(std::shared_ptr<Queue> queue,
                  std::shared_ptr<rclcpp::Node> node, const std::string& topic);
  BridgePublisher(const BridgePublisher& other);
  void start();
};
template <class RosMsg, class SimMsg>
BridgePublisher<RosMsg, SimMsg>::BridgePublisher(std::shared_ptr<Queue> queue,
                                                 std::shared_ptr<rclcpp::Node> node,
                                                 const std::string& topic) {
  pub_ = node->create_publisher<RosMsg>(topic, 10);
}
template <class RosMsg, class SimMsg>
void BridgePublisher<RosMsg, SimMsg>::start() {
}
void make(std::shared_ptr<rclcpp::Node> node) {
  auto a = std::make_unique<BridgePublisher<A, B>>(queue, node, "a");
  auto b = BridgePublisher<A, B>::create(queue, node, "b");
  BridgePublisher<A, B> c(queue, node, "c");
}
"""


def test_the_grep_for_a_class_templates_calls_skips_its_own_declarations() -> None:
    """Once the constructor is a wrapper, the grep for call sites (``recall``) looks
    for its class's name: its declarations in the class and the definitions of its
    members out of it (``void BridgePublisher<R, S>::start() {``) are no calls of it,
    which made every node that includes the header ``partial`` (CPP_CALL_MISSED at
    each); constructions are."""
    from haros_arch.extract.cpp import recall

    lines = [site.line for site in recall.call_sites(GREPPED, ["BridgePublisher"], [], True)]
    assert lines == [13, 19, 20, 21], lines
