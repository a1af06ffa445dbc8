"""diagnostic_updater's Updater publishes /diagnostics and takes its period from a
parameter: ROS 1 reads ``~diagnostic_period``, ROS 2 declares ``diagnostic_updater.period``
and ``diagnostic_updater.use_fqn`` on the node (Autoware's launch files set them)."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

ROS2 = {
    "router/package.xml": package_xml("router", "ament_cmake").replace(
        "<export>", "<depend>rclcpp</depend><export>"),
    "router/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.8)
        project(router)
        find_package(rclcpp REQUIRED)
        add_executable(router src/router.cpp)
        ament_package()
        """,
    "router/src/router.cpp": """
        #include "rclcpp/rclcpp.hpp"
        #include "diagnostic_updater/diagnostic_updater.hpp"
        class Router : public rclcpp::Node {
        public:
          Router() : rclcpp::Node("router"), diagnostics_(this) {}
          diagnostic_updater::Updater diagnostics_;
        };
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          rclcpp::spin(std::make_shared<Router>());
        }
        """,
}

ROS1 = {
    "driver/package.xml": package_xml("driver", "catkin").replace(
        "<export>", "<depend>roscpp</depend><export>"),
    "driver/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(driver)
        find_package(catkin REQUIRED COMPONENTS roscpp diagnostic_updater)
        add_executable(driver src/driver.cpp)
        """,
    "driver/src/driver.cpp": """
        #include <ros/ros.h>
        #include <diagnostic_updater/diagnostic_updater.h>
        int main(int argc, char ** argv)
        {
          ros::init(argc, argv, "driver");
          diagnostic_updater::Updater updater;
          ros::spin();
        }
        """,
}


def _calls(write_tree, files: dict[str, str], package: str) -> list[tuple[str, str, str]]:
    ws = scan([str(write_tree(files))])
    pkg = ws.packages[package]
    pkg.nodes, _ = cmake.parse_package(pkg, ws)
    extract_nodes(pkg.nodes, ws, cache_dir=None, jobs=1)
    # the library has its defaults: no launch file needs to set them
    assert all(c.has_default for c in pkg.nodes[0].calls if c.kind in ("declare", "read"))
    return sorted((c.kind, c.name, c.type or "") for c in pkg.nodes[0].calls)


def test_ros2_updater_declares_its_parameters_on_the_node(write_tree) -> None:
    calls = _calls(write_tree, ROS2, "router")
    assert ("publish", "/diagnostics", "diagnostic_msgs/msg/DiagnosticArray") in calls
    assert ("declare", "diagnostic_updater.period", "double") in calls
    assert ("declare", "diagnostic_updater.use_fqn", "bool") in calls


def test_ros1_updater_reads_its_private_period(write_tree) -> None:
    calls = _calls(write_tree, ROS1, "driver")
    assert ("publish", "/diagnostics", "diagnostic_msgs/DiagnosticArray") in calls
    assert ("read", "~diagnostic_period", "double") in calls
