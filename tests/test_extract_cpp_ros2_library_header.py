"""In a ROS 2 distribution messages are ``<pkg/msg/name.hpp>``: a missing ``<pkg/Name.h>``
of a package neither in the workspace nor in the catalogue is a library's header (lanelet2's
``<lanelet2_core/LaneletMap.h>``, ``<lanelet2_routing/RoutingGraph.h>``, which Autoware's
planning nodes include), said missing and its names declared permissively, not synthesised
as a message without fields (``CPP_MESSAGE_UNKNOWN``). For a ROS 1 distribution it stays a
message known by name, as gencpp would generate it."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

ROS2 = """#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <lanelet2_core/LaneletMap.h>
#include <lanelet2_routing/RoutingGraph.h>

class Planner : public rclcpp::Node
{
public:
  Planner() : Node("planner")
  {
    route_pub_ = create_publisher<std_msgs::msg::String>("~/output/route", 1);
    map_ = std::make_shared<lanelet::LaneletMap>();
    graph_ = lanelet::routing::RoutingGraph::build(*map_, *rules_);
    if (graph_) {
      declare_parameter("goal_angle_threshold", 0.5);
    }
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr route_pub_;
  lanelet::LaneletMapPtr map_;
  lanelet::traffic_rules::TrafficRulesPtr rules_;
  lanelet::routing::RoutingGraphPtr graph_;
};
"""

ROS1 = """#include <ros/ros.h>
#include <vendor_msgs/Status.h>

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "status");
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<vendor_msgs::Status>("status", 1);
  ros::spin();
}
"""


def _codes(result, code: str) -> list[str]:
    return [d.message for d in result.diagnostics if d.code == code]


def test_a_capitalised_header_in_a_ros2_distribution_is_a_library(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("planner", "ament_cmake"))
    source = tmp_path / "planner.cpp"
    source.write_text(ROS2)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="humble")
    assert _codes(result, "CPP_MESSAGE_UNKNOWN") == []
    assert len(_codes(result, "CPP_INCLUDE_MISSING")) == 2
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("declare", "goal_angle_threshold"), ("publish", "~output/route")]


def test_the_same_header_in_a_ros1_distribution_is_a_message(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("status", "catkin"))
    source = tmp_path / "status.cpp"
    source.write_text(ROS1)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="noetic")
    assert len(_codes(result, "CPP_MESSAGE_UNKNOWN")) == 1
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("publish", "status", "vendor_msgs/Status")]
