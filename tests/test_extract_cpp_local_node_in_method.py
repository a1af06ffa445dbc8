"""A node a method constructs in a local variable is a node of its own, not its class's:
the class's other calls, on the node reference it was given, are made on the node given.
sbg_ros2_driver's SbgDevice reads its parameters through ``rclcpp::Node
n_private("npv", "", node_opt)`` in ``loadParameters()`` and subscribes and serves on the
``rclcpp::Node&`` main() gives it (``sbg_device``): every SbgDevice call was taken for
``/npv``'s."""

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
        class Device {
        public:
          explicit Device(rclcpp::Node & node);
          void start();
        private:
          void loadParameters();
          rclcpp::Node & node_;
          int rate_ = 0;
          rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
        };
        """,
    "dev/src/device.cpp": """
        #include "device.hpp"
        Device::Device(rclcpp::Node & node) : node_(node)
        {
          loadParameters();
        }
        void Device::loadParameters()
        {
          rclcpp::NodeOptions options;
          options.automatically_declare_parameters_from_overrides(true);
          rclcpp::Node parameters("params", "", options);
          parameters.get_parameter_or<int>("rate", rate_, 10);
        }
        void Device::start()
        {
          pub_ = node_.create_publisher<std_msgs::msg::String>("out", 10);
        }
        """,
    "dev/src/main.cpp": """
        #include "device.hpp"
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          auto node = std::make_shared<rclcpp::Node>("dev");
          Device device(*node);
          device.start();
          rclcpp::spin(node);
        }
        """,
}


def test_a_methods_local_node_is_not_its_classs_node(write_tree) -> None:
    ws = scan([str(write_tree(FILES))])
    package = ws.packages["dev"]
    package.nodes, _ = cmake.parse_package(package, ws)
    extract_nodes(package.nodes, ws, cache_dir=None, jobs=1)
    node = package.nodes[0]
    made = {(c.kind, c.name): c.node_name for c in node.calls if c.kind in ("publish", "read")}
    assert made == {("publish", "out"): "dev", ("read", "rate"): "params"}, made
