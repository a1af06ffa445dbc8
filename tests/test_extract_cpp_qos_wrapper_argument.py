"""A wrapper's QoS parameter with a default: the call site's argument when it passes one
(a value not known there stays unknown), the default only when it passes none.
autoware_utils' ``InterProcessPollingSubscriber{this, "~/input/pointcloud",
autoware_utils::single_depth_sensor_qos()}``: the parameter defaults to ``rclcpp::QoS{1}``
(reliable), and the site's sensor-data profile (best effort), made in a function, was
taken for that default: a false qos-incompatible error against its best-effort
publisher on Autoware's logging simulator."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

FILES = {
    "checker/package.xml": package_xml("checker", "ament_cmake"),
    "checker/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.8)
        project(checker)
        find_package(rclcpp REQUIRED)
        add_executable(checker src/checker.cpp)
        ament_package()
        """,
    "checker/include/checker/polling.hpp": """
        #include <string>
        #include "rclcpp/rclcpp.hpp"
        namespace checker {
        inline rclcpp::SensorDataQoS single_depth_sensor_qos()
        {
          rclcpp::SensorDataQoS qos;
          qos.get_rmw_qos_profile().depth = 1;
          return qos;
        }
        template <typename T>
        class Polling {
        public:
          Polling(rclcpp::Node * node, const std::string & topic,
                  const rclcpp::QoS & qos = rclcpp::QoS{1})
          {
            sub_ = node->create_subscription<T>(topic, qos, [](typename T::ConstSharedPtr) {});
          }
        private:
          typename rclcpp::Subscription<T>::SharedPtr sub_;
        };
        }
        """,
    "checker/src/checker.cpp": """
        #include "rclcpp/rclcpp.hpp"
        #include "std_msgs/msg/string.hpp"
        #include "checker/polling.hpp"
        class Checker : public rclcpp::Node {
        public:
          Checker() : rclcpp::Node("checker") {}
        private:
          checker::Polling<std_msgs::msg::String> cloud_{
            this, "cloud", checker::single_depth_sensor_qos()};
          checker::Polling<std_msgs::msg::String> odometry_{this, "odometry"};
          checker::Polling<std_msgs::msg::String> latched_{
            this, "latched", rclcpp::QoS{1}.transient_local()};
        };
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          rclcpp::spin(std::make_shared<Checker>());
        }
        """,
}


def test_the_qos_a_site_passes_to_a_wrapper_is_its_own(write_tree) -> None:
    ws = scan([str(write_tree(FILES))])
    package = ws.packages["checker"]
    package.nodes, _ = cmake.parse_package(package, ws)
    extract_nodes(package.nodes, ws, cache_dir=None, jobs=1)
    qos = {c.name: c.qos for c in package.nodes[0].calls if c.kind == "subscribe"}
    # made by a function the QoS reader does not follow: not known, never the default
    assert not (qos["cloud"] or {}).get("reliability")
    # no argument: the parameter's default, rclcpp::QoS{1}
    assert qos["odometry"] == {"history": "keep_last", "depth": 1, "reliability": "reliable",
                               "durability": "volatile"}
    assert qos["latched"]["durability"] == "transient_local"
