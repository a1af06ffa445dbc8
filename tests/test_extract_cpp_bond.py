"""bondcpp's Bond exchanges its heartbeat on the topic it is given, of bond's Status:
it publishes and subscribes there (ROS 1 on a NodeHandle of its own, in the node's
namespace; ROS 2 on the node given). urg_node's driver bonds with the diagnostic
aggregator so; nav2's lifecycle nodes with their manager."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

ROS1 = {
    "laser/package.xml": package_xml("laser", "catkin").replace(
        "<export>", "<depend>roscpp</depend><depend>bondcpp</depend><export>"),
    "laser/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(laser)
        find_package(catkin REQUIRED COMPONENTS roscpp bondcpp)
        add_executable(laser src/laser.cpp)
        """,
    "laser/src/laser.cpp": """
        #include <ros/ros.h>
        #include <bondcpp/bond.h>
        int main(int argc, char ** argv)
        {
          ros::init(argc, argv, "laser");
          bond::Bond bond("/aggregator/bond", "laser");
          bond.start();
          ros::spin();
        }
        """,
}

ROS2 = {
    "worker/package.xml": package_xml("worker", "ament_cmake").replace(
        "<export>", "<depend>rclcpp</depend><depend>bondcpp</depend><export>"),
    "worker/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.8)
        project(worker)
        find_package(rclcpp REQUIRED)
        find_package(bondcpp REQUIRED)
        add_executable(worker src/worker.cpp)
        ament_package()
        """,
    "worker/src/worker.cpp": """
        #include "rclcpp/rclcpp.hpp"
        #include "bondcpp/bond.hpp"
        class Worker : public rclcpp::Node {
        public:
          Worker() : rclcpp::Node("worker") {}
          void connect()
          {
            bond_ = std::make_shared<bond::Bond>("heartbeat", get_name(), shared_from_this());
            bond_->start();
          }
          std::shared_ptr<bond::Bond> bond_;
        };
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          auto node = std::make_shared<Worker>();
          node->connect();
          rclcpp::spin(node);
        }
        """,
}

# urg_node's form: a boost::shared_ptr member initialised with nullptr (a stand-in without
# that constructor made the class invalid and lost the bond made in a method)
ROS1_MEMBER = dict(ROS1)
ROS1_MEMBER["laser/src/laser.cpp"] = """
    #include <ros/ros.h>
    #include <bondcpp/bond.h>
    #include <boost/shared_ptr.hpp>
    class Laser {
    public:
      void connect();
      boost::shared_ptr<bond::Bond> bond_ = nullptr;
    };
    void Laser::connect()
    {
      std::string ns = ros::this_node::getNamespace();
      if (bond_ == nullptr) {
        bond_ = boost::shared_ptr<bond::Bond>(new bond::Bond("/aggregator/bond", ns));
      }
      bond_->start();
    }
    int main(int argc, char ** argv)
    {
      ros::init(argc, argv, "laser");
      Laser laser;
      laser.connect();
      ros::spin();
    }
    """


def _calls(write_tree, files: dict[str, str], package: str) -> list[tuple[str, str, str]]:
    ws = scan([str(write_tree(files))])
    pkg = ws.packages[package]
    pkg.nodes, _ = cmake.parse_package(pkg, ws)
    extract_nodes(pkg.nodes, ws, cache_dir=None, jobs=1)
    return sorted((c.kind, c.name, c.type or "") for c in pkg.nodes[0].calls)


def test_ros1_bond_publishes_and_subscribes_its_topic(write_tree) -> None:
    calls = _calls(write_tree, ROS1, "laser")
    assert ("publish", "/aggregator/bond", "bond/Status") in calls
    assert ("subscribe", "/aggregator/bond", "bond/Status") in calls


def test_ros2_bond_publishes_and_subscribes_on_the_node(write_tree) -> None:
    calls = _calls(write_tree, ROS2, "worker")
    assert ("publish", "heartbeat", "bond/msg/Status") in calls
    assert ("subscribe", "heartbeat", "bond/msg/Status") in calls


def test_ros1_bond_in_a_shared_ptr_member_initialised_with_nullptr(write_tree) -> None:
    calls = _calls(write_tree, ROS1_MEMBER, "laser")
    assert ("publish", "/aggregator/bond", "bond/Status") in calls
    assert ("subscribe", "/aggregator/bond", "bond/Status") in calls


# wato_monorepo's lifecycle manager: the broken callback set after construction, and
# the getters of the timeouts (bondcpp's bond.hpp): the stand-in had neither, a parse
# error in the function that makes the bond (CPP_NODE_PARTIAL)
ROS2_SETTERS = dict(ROS2)
ROS2_SETTERS["worker/src/worker.cpp"] = ROS2["worker/src/worker.cpp"].replace(
    "bond_->start();", """bond_->setBrokenCallback([this]() { broken_ = true; });
            bond_->setFormedCallback(std::bind(&Worker::formed, this));
            bond_->setDeadPublishPeriod(bond_->getHeartbeatPeriod() + bond_->getHeartbeatTimeout()
                                        + bond_->getConnectTimeout() + bond_->getDisconnectTimeout()
                                        + bond_->getDeadPublishPeriod());
            if (bond_->getTopic() != bond_->getId() + bond_->getInstanceId()) {
              bond_->start();
            }""").replace(
    "std::shared_ptr<bond::Bond> bond_;", """void formed() {}
          bool broken_ = false;
          std::shared_ptr<bond::Bond> bond_;""")


def test_ros2_bond_callbacks_set_after_construction(write_tree) -> None:
    ws = scan([str(write_tree(ROS2_SETTERS))])
    pkg = ws.packages["worker"]
    pkg.nodes, _ = cmake.parse_package(pkg, ws)
    said = extract_nodes(pkg.nodes, ws, cache_dir=None, jobs=1)
    node = pkg.nodes[0]
    assert [d.message for d in said if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NODE_PARTIAL")] == []
    calls = sorted((c.kind, c.name, c.type or "") for c in node.calls)
    assert ("publish", "heartbeat", "bond/msg/Status") in calls
