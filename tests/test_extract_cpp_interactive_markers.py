"""interactive_markers' server, when the workspace has no interactive_markers (a
fallback stand-in and an API row): ROS 1 publishes ``<ns>/update`` and the latched
``<ns>/update_full`` and subscribes ``<ns>/feedback``; ROS 2 publishes and subscribes the
first and last on the node given and serves ``<ns>/get_interactive_markers``. Before, the
class was unknown: ROS 1 nodes building one were partial (CPP_CLASS_UNSEEN), and its
topics were missing from both."""

from __future__ import annotations

import os
from typing import Any

from haros_arch.extract.cpp import extract_cpp
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import scan
from tests.conftest import package_xml

ROS1 = """
#include <ros/ros.h>
#include <geometry_msgs/Twist.h>
#include <interactive_markers/interactive_marker_server.h>
#include <interactive_markers/menu_handler.h>
#include <interactive_markers/tools.h>
class Teleop {
 public:
  Teleop() : server_("twist_marker_server") {
    pub_ = nh_.advertise<geometry_msgs::Twist>("cmd_vel", 1);
    visualization_msgs::InteractiveMarker marker;
    marker.name = "base";
    interactive_markers::autoComplete(marker);
    server_.insert(marker, boost::bind(&Teleop::feedback, this, _1));
    menu_.insert("reset", boost::bind(&Teleop::feedback, this, _1));
    menu_.apply(server_, marker.name);
    server_.applyChanges();
  }
  void feedback(const visualization_msgs::InteractiveMarkerFeedbackConstPtr& f) {}
 private:
  ros::NodeHandle nh_;
  ros::Publisher pub_;
  interactive_markers::InteractiveMarkerServer server_;
  interactive_markers::MenuHandler menu_;
};
int main(int argc, char** argv) { ros::init(argc, argv, "teleop"); Teleop t; ros::spin(); }
"""

ROS2 = """
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <interactive_markers/interactive_marker_server.hpp>
#include <interactive_markers/menu_handler.hpp>
class Tool : public rclcpp::Node {
 public:
  Tool() : rclcpp::Node("tool") {
    server_ = std::make_unique<interactive_markers::InteractiveMarkerServer>(
      "slam_toolbox", get_node_base_interface(), get_node_clock_interface(),
      get_node_logging_interface(), get_node_topics_interface(),
      get_node_services_interface());
    visualization_msgs::msg::InteractiveMarker marker;
    server_->insert(marker, std::bind(&Tool::feedback, this, std::placeholders::_1));
    menu_.apply(*server_, marker.name);
    server_->applyChanges();
  }
  void feedback(interactive_markers::InteractiveMarkerServer::FeedbackConstSharedPtr f) {}
 private:
  std::unique_ptr<interactive_markers::InteractiveMarkerServer> server_;
  interactive_markers::MenuHandler menu_;
};
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<Tool>();
  interactive_markers::InteractiveMarkerServer other("markers", node);
  rclcpp::spin(node);
}
"""


def _depends(name: str, *deps: str, build_type: str | None = None) -> str:
    return package_xml(name, build_type).replace(
        "</package>", "".join(f"<depend>{d}</depend>" for d in deps) + "</package>")


def test_a_ros1_server_s_topics_and_the_node_complete(write_tree: Any) -> None:
    root = write_tree({
        "src/teleop/package.xml": _depends("teleop", "roscpp", "interactive_markers",
                                           "visualization_msgs", "geometry_msgs"),
        "src/teleop/CMakeLists.txt": "project(teleop)\nadd_executable(teleop src/a.cpp)\n",
        "src/teleop/src/a.cpp": ROS1,
        "project.yaml": "project: p\nworkspace: [src]\nconfigurations: {}\n"})
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    node = next(n for p in model.packages for n in p.nodes if n.name == "teleop/teleop")
    assert node.completeness == "complete", node.completeness_reasons
    assert sorted((c.kind, c.name, c.type) for c in node.calls) == [
        ("publish", "cmd_vel", "geometry_msgs/Twist"),
        ("publish", "twist_marker_server/update",
         "visualization_msgs/InteractiveMarkerUpdate"),
        ("publish", "twist_marker_server/update_full",
         "visualization_msgs/InteractiveMarkerInit"),
        ("subscribe", "twist_marker_server/feedback",
         "visualization_msgs/InteractiveMarkerFeedback")]


def test_a_ros2_server_on_the_node_given(write_tree: Any) -> None:
    root = write_tree({
        "ws/src/tool/package.xml": _depends("tool", "rclcpp", "interactive_markers",
                                            build_type="ament_cmake"),
        "ws/src/tool/src/a.cpp": ROS2})
    result = extract_cpp([str(root / "ws/src/tool/src/a.cpp")], scan([str(root / "ws")]),
                         cache_dir=None, distro="jazzy")
    assert [d.code for d in result.diagnostics if d.code.startswith("CPP_")
            and d.code not in ("CPP_DYNAMIC_NAME",)] == []
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == sorted(
        (kind, f"{ns}/{name}", f"visualization_msgs/{kind_type}")
        for ns in ("slam_toolbox", "markers") for kind, name, kind_type in (
            ("publish", "update", "msg/InteractiveMarkerUpdate"),
            ("subscribe", "feedback", "msg/InteractiveMarkerFeedback"),
            ("server", "get_interactive_markers", "srv/GetInteractiveMarkers")))
