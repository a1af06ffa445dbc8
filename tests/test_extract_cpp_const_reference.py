"""A variable that is a reference to const holds what it is bound to: f1tenth_ws' scan
matching node names its topics ``const string &TOPIC_SCAN = "/scan";`` at namespace
scope, a temporary string the reference keeps alive; its subscriber and publishers were
``?`` (CPP_DYNAMIC_NAME)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

const std::string &TOPIC_SCAN = "/scan";
const std::string BASE = "/scan_match";
const std::string &TOPIC_POS = BASE;

class ScanMatch : public rclcpp::Node {
public:
  ScanMatch() : Node("scanmatch_node") {
    const std::string &debug = "debug";
    sub_ = create_subscription<std_msgs::msg::String>(
        TOPIC_SCAN, 1, [](std_msgs::msg::String::SharedPtr) {});
    pos_ = create_publisher<std_msgs::msg::String>(TOPIC_POS, 1);
    dbg_ = create_publisher<std_msgs::msg::String>(debug, 1);
  }
private:
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pos_, dbg_;
};
"""


def test_a_reference_to_const_holds_what_it_is_bound_to(write_tree) -> None:
    root = write_tree({"pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "pkg/src/node.cpp": SOURCE})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [
        ("subscribe", "/scan"), ("publish", "/scan_match"), ("publish", "debug")]
    assert "CPP_DYNAMIC_NAME" not in [d.code for d in result.diagnostics]
