"""A class no code constructs by a call (a member object, built with the class that
holds it) makes its calls on the node its methods are handed. sbg_ros2_driver's
SbgDevice holds a MessagePublisher and a ConfigStore: ``message_publisher_.
initPublishers(ref_node_, ...)`` publishes on the node main() gives SbgDevice,
``config_store_.loadFromRosNodeHandle(n_private)`` reads through the local node
``rclcpp::Node n_private("npv", ...)``; both classes' calls were made on a node not
known ('?')."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

FILES = {
    "dev/package.xml": package_xml("dev", "ament_cmake"),
    "dev/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.8)
        project(dev)
        find_package(rclcpp REQUIRED)
        add_executable(dev src/main.cpp src/device.cpp)
        ament_package()
        """,
    "dev/src/device.hpp": """
        #include "rclcpp/rclcpp.hpp"
        #include "std_msgs/msg/string.hpp"
        class Store {
        public:
          void loadFrom(const rclcpp::Node & node);
          int rate() const { return rate_; }
        private:
          int rate_ = 0;
        };
        class Publishers {
        public:
          void init(rclcpp::Node & node);
        private:
          rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
        };
        class Device {
        public:
          explicit Device(rclcpp::Node & node);
        private:
          rclcpp::Node & node_;
          Store store_;
          Publishers publishers_;
        };
        """,
    "dev/src/device.cpp": """
        #include "device.hpp"
        void Store::loadFrom(const rclcpp::Node & node)
        {
          node.get_parameter_or<int>("rate", rate_, 10);
        }
        void Publishers::init(rclcpp::Node & node)
        {
          pub_ = node.create_publisher<std_msgs::msg::String>("out", 10);
        }
        Device::Device(rclcpp::Node & node) : node_(node)
        {
          rclcpp::Node parameters("params");
          store_.loadFrom(parameters);
          if (store_.rate() > 0) {
            publishers_.init(node_);
          }
        }
        """,
    "dev/src/main.cpp": """
        #include "device.hpp"
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          auto node = std::make_shared<rclcpp::Node>("dev");
          Device device(*node);
          rclcpp::spin(node);
        }
        """,
}


def test_a_member_objects_calls_are_on_the_node_its_methods_are_handed(write_tree) -> None:
    ws = scan([str(write_tree(FILES))])
    package = ws.packages["dev"]
    package.nodes, _ = cmake.parse_package(package, ws)
    extract_nodes(package.nodes, ws, cache_dir=None, jobs=1)
    node = package.nodes[0]
    made = {(c.kind, c.name): c.node_name for c in node.calls if c.kind in ("publish", "read")}
    assert made == {("publish", "out"): "dev", ("read", "rate"): "params"}, made
