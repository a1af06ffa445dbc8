"""pal_statistics (PAL Robotics): a registry made for a node and a topic T publishes
pal_statistics_msgs' Statistics on T/full, StatisticsNames on T/names and StatisticsValues
on T/values. ros2_control's controller_manager makes two (``INITIALIZE_REGISTRY(this,
"~/introspection_data", key)``, then ``START_PUBLISH_THREAD(key)``); with no stand-in the
macros were undeclared identifiers near ROS calls and the node was partial."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.model.source import Node
from haros_arch.workspace import scan
from tests.conftest import package_xml

FILES = {
    "manager/package.xml": package_xml("manager", "ament_cmake").replace(
        "<export>", "<depend>rclcpp</depend><depend>pal_statistics</depend><export>"),
    "manager/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.8)
        project(manager)
        find_package(rclcpp REQUIRED)
        find_package(pal_statistics REQUIRED)
        add_executable(manager src/manager.cpp)
        add_executable(legacy src/legacy.cpp)
        ament_package()
        """,
    "manager/src/manager.cpp": """
        #include <atomic>
        #include "rclcpp/rclcpp.hpp"
        #include "pal_statistics/pal_statistics_macros.hpp"
        #include "pal_statistics/pal_statistics_utils.hpp"
        namespace stats
        {
        constexpr char KEY[] = "manager_key";
        constexpr char TOPIC[] = "~/introspection_data";
        }
        class Manager : public rclcpp::Node {
        public:
          Manager() : rclcpp::Node("manager")
          {
            INITIALIZE_REGISTRY(this, stats::TOPIC, stats::KEY);
            START_PUBLISH_THREAD(stats::KEY);
            REGISTER_ENTITY(stats::KEY, "manager.period", &period_);
            REGISTER_ENTITY(stats::KEY, "manager.load", &load_, &registrations_, false);
            auto context = get_node_base_interface()->get_context();
            (void)context;
            if (get_node_base_interface()->get_associated_with_executor_atomic().load()) {
              RCLCPP_INFO(get_logger(), "in an executor");
            }
          }
          void update()
          {
            PUBLISH_ASYNC_STATISTICS(stats::KEY);
          }
          ~Manager() { UNREGISTER_ENTITY(stats::KEY, "manager.period"); }
        private:
          double period_ = 0.0;
          double load_ = 0.0;
          pal_statistics::RegistrationsRAII registrations_;
        };
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          auto node = std::make_shared<Manager>();
          rclcpp::spin(node);
        }
        """,
    # the older API: the registry of a node's topic, made by its first use
    "manager/src/legacy.cpp": """
        #include "rclcpp/rclcpp.hpp"
        #include "pal_statistics/pal_statistics_macros.hpp"
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          auto node = std::make_shared<rclcpp::Node>("legacy");
          double value = 0.0;
          REGISTER_VARIABLE(node, "legacy_stats", "value", &value);
          PUBLISH_STATISTICS(node, "legacy_stats");
          INITIALIZE_REGISTRY(node, "/global_stats");
          rclcpp::spin(node);
        }
        """,
}

_MSGS = "pal_statistics_msgs/msg/"


def _nodes(write_tree) -> dict[str, Node]:
    ws = scan([str(write_tree(FILES))])
    pkg = ws.packages["manager"]
    pkg.nodes, _ = cmake.parse_package(pkg, ws)
    extract_nodes(pkg.nodes, ws, cache_dir=None, jobs=1)
    return {node.executable: node for node in pkg.nodes}


def _publishers(node: Node) -> set[tuple[str, str]]:
    return {(c.name, c.type or "") for c in node.calls if c.kind == "publish"}


def test_a_registry_initialised_for_a_key_publishes_its_three_topics(write_tree) -> None:
    node = _nodes(write_tree)["manager"]
    assert _publishers(node) == {
        ("~introspection_data/full", _MSGS + "Statistics"),
        ("~introspection_data/names", _MSGS + "StatisticsNames"),
        ("~introspection_data/values", _MSGS + "StatisticsValues")}
    # the macros are known: nothing left undeclared near the node's ROS calls
    assert node.completeness == "complete", node.completeness_reasons


def test_the_registry_of_a_nodes_topic_publishes_there(write_tree) -> None:
    node = _nodes(write_tree)["legacy"]
    assert _publishers(node) == {
        (f"legacy_stats/{part}", _MSGS + kind) for part, kind in (
            ("full", "Statistics"), ("names", "StatisticsNames"),
            ("values", "StatisticsValues"))} | {
        (f"/global_stats/{part}", _MSGS + kind) for part, kind in (
            ("full", "Statistics"), ("names", "StatisticsNames"),
            ("values", "StatisticsValues"))}
    assert node.completeness == "complete", node.completeness_reasons
