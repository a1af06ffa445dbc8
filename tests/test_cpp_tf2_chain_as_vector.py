"""tf2's ``BufferCore::_chainAsVector`` (the frames between two, through a fixed frame)
is declared by the stand-in Buffer: ROS 2 tf2_ros' tf2_monitor calls it in the function
that makes its publishers and was partial for "no member named '_chainAsVector'"."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

CMAKE = """
    cmake_minimum_required(VERSION 3.8)
    project(mon)
    find_package(ament_cmake REQUIRED)
    find_package(rclcpp REQUIRED)
    find_package(tf2_ros REQUIRED)
    add_executable(mon src/mon.cpp)
    ament_target_dependencies(mon rclcpp tf2_ros)
    ament_package()
    """

SOURCE = """
    #include <rclcpp/rclcpp.hpp>
    #include <tf2_ros/buffer.h>
    #include <tf2_ros/transform_listener.h>
    #include <std_msgs/msg/string.hpp>
    int main(int argc, char** argv) {
      rclcpp::init(argc, argv);
      auto node = std::make_shared<rclcpp::Node>("mon");
      tf2_ros::Buffer buffer(node->get_clock());
      tf2_ros::TransformListener listener(buffer);
      std::vector<std::string> chain;
      buffer._chainAsVector("b", tf2::TimePointZero, "a", tf2::TimePointZero, "b", chain);
      auto pub = node->create_publisher<std_msgs::msg::String>("chain", 1);
      rclcpp::spin(node);
    }
    """


def test_a_chain_of_frames_asked_of_the_buffer_parses(write_tree) -> None:
    root = write_tree({"mon/package.xml": package_xml("mon", "ament_cmake"),
                       "mon/CMakeLists.txt": CMAKE, "mon/src/mon.cpp": SOURCE})
    ws = scan([str(root)])
    package = ws.packages["mon"]
    package.nodes, _ = cmake.parse_package(package, ws)
    extract_nodes(package.nodes, ws, cache_dir=None, jobs=1)
    (node,) = package.nodes
    assert ("publish", "chain") in [(c.kind, c.name) for c in node.calls]
    assert node.completeness == "complete", node.completeness_reasons
