"""A QoS held in a local variable is what the setters called on it before its use make
it (Autoware's pointcloud map loader: ``rclcpp::QoS qos{1}; qos.transient_local();``);
a setter that may not run leaves what it sets unknown."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

FILES = {
    "maps/package.xml": package_xml("maps", "ament_cmake"),
    "maps/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.8)
        project(maps)
        find_package(rclcpp REQUIRED)
        add_executable(loader src/loader.cpp)
        ament_package()
        """,
    "maps/src/loader.cpp": """
        #include "rclcpp/rclcpp.hpp"
        #include "std_msgs/msg/string.hpp"
        class Loader : public rclcpp::Node {
        public:
          explicit Loader(bool fast) : rclcpp::Node("loader") {
            rclcpp::QoS durable{1};
            durable.transient_local();
            map_ = create_publisher<std_msgs::msg::String>("map", durable);
            rclcpp::QoS maybe{5};
            if (fast) {
              maybe.best_effort();
            }
            maybe.keep_last(3);
            scan_ = create_publisher<std_msgs::msg::String>("scan", maybe);
            rclcpp::QoS later{2};
            late_ = create_publisher<std_msgs::msg::String>("late", later);
            later.transient_local();
          }
          rclcpp::Publisher<std_msgs::msg::String>::SharedPtr map_, scan_, late_;
        };
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          rclcpp::spin(std::make_shared<Loader>(true));
        }
        """,
}


def test_setters_called_on_a_qos_variable_before_its_use(write_tree) -> None:
    ws = scan([str(write_tree(FILES))])
    package = ws.packages["maps"]
    package.nodes, _ = cmake.parse_package(package, ws)
    extract_nodes(package.nodes, ws, cache_dir=None, jobs=1)
    qos = {c.name: c.qos for c in package.nodes[0].calls if c.kind == "publish"}
    assert qos["map"] == {"history": "keep_last", "depth": 1, "reliability": "reliable",
                          "durability": "transient_local"}
    # best_effort only when ``fast``: the reliability is not known; keep_last runs
    assert qos["scan"] == {"history": "keep_last", "depth": 3, "durability": "volatile"}
    # a setter after the use does not change what the publisher was made with
    assert qos["late"]["durability"] == "volatile"
