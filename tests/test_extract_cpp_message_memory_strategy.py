"""rclcpp's ``create_subscription`` takes a fifth argument, the message memory strategy
(``rclcpp/strategies/message_pool_memory_strategy.hpp``): aws-deepracer's servo_node and
ctrl_node hand it a ``MessagePoolMemoryStrategy``. The stand-ins had neither the
argument nor the class: each such subscription was kept by its name only, its function
in error, and both nodes partial."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

FILES = {
    "servo/package.xml": package_xml("servo", "ament_cmake").replace(
        "<export>", "<depend>rclcpp</depend><depend>std_msgs</depend><export>"),
    "servo/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.8)
        project(servo)
        find_package(rclcpp REQUIRED)
        add_executable(servo src/servo.cpp)
        ament_package()
        """,
    "servo/src/servo.cpp": """
        #include "rclcpp/rclcpp.hpp"
        #include <rclcpp/strategies/message_pool_memory_strategy.hpp>
        #include "std_msgs/msg/float32.hpp"
        using Float32 = std_msgs::msg::Float32;
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          auto node = rclcpp::Node::make_shared("servo");
          auto qos = rclcpp::QoS(rclcpp::KeepLast(1));
          auto pool = std::make_shared<rclcpp::strategies::message_pool_memory_strategy::
              MessagePoolMemoryStrategy<Float32, 1>>();
          auto sub = node->create_subscription<Float32>(
              "/ctrl/servo", qos, [](const Float32::SharedPtr) {},
              rclcpp::SubscriptionOptions(), pool);
          rclcpp::spin(node);
        }
        """,
}


def test_a_subscription_given_a_memory_strategy_is_read(write_tree) -> None:
    ws = scan([str(write_tree(FILES))])
    pkg = ws.packages["servo"]
    pkg.nodes, _ = cmake.parse_package(pkg, ws)
    found = extract_nodes(pkg.nodes, ws, cache_dir=None, jobs=1)
    node = pkg.nodes[0]
    assert [(c.kind, c.name, c.type, c.queue_size) for c in node.calls] == [
        ("subscribe", "/ctrl/servo", "std_msgs/msg/Float32", 1)]
    codes = [d.code for d in found]
    assert "CPP_CALL_UNRESOLVED" not in codes
    assert "CPP_NODE_PARTIAL" not in codes
    assert node.completeness == "complete"
