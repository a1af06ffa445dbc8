"""A Gazebo classic plugin registered in its header (survey Z49): audibot_gazebo's
``AudibotInterfacePlugin.hpp`` declares the class and ends with
``GZ_REGISTER_MODEL_PLUGIN(AudibotInterfacePlugin)``; the library's one source includes
it. Only the library's own sources were searched for the macro, so the plugin the
robot description loads was GAZEBO_PLUGIN_UNKNOWN and its topics were missing."""

from __future__ import annotations

from conftest import package_xml

from haros_arch import pipeline
from haros_arch.workspace import scan

HEADER = """\
#pragma once
#include <gazebo/gazebo.hh>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>
namespace gazebo {
class CarPlugin : public ModelPlugin {
 public:
  void Load(physics::ModelPtr model, sdf::ElementPtr sdf) override;
 private:
  std::shared_ptr<rclcpp::Node> node_;
  rclcpp::Subscription<std_msgs::msg::Float64>::SharedPtr sub_;
};
GZ_REGISTER_MODEL_PLUGIN(CarPlugin)
}
"""

SOURCE = """\
#include <car_gazebo/CarPlugin.hpp>
namespace gazebo {
void CarPlugin::Load(physics::ModelPtr model, sdf::ElementPtr sdf) {
  node_ = std::make_shared<rclcpp::Node>("control", "car");
  sub_ = node_->create_subscription<std_msgs::msg::Float64>(
    "throttle_cmd", 1, [](std_msgs::msg::Float64::SharedPtr) {});
}
}
"""

CMAKE = """\
cmake_minimum_required(VERSION 3.5)
project(car_gazebo)
find_package(ament_cmake REQUIRED)
find_package(rclcpp REQUIRED)
find_package(gazebo_ros REQUIRED)
add_library(car_plugin SHARED src/CarPlugin.cpp)
target_include_directories(car_plugin PUBLIC include)
ament_package()
"""


def test_a_plugin_registered_in_the_header_its_source_includes(write_tree) -> None:
    root = write_tree({
        "car_gazebo/package.xml": package_xml("car_gazebo", "ament_cmake"),
        "car_gazebo/CMakeLists.txt": CMAKE,
        "car_gazebo/include/car_gazebo/CarPlugin.hpp": HEADER,
        "car_gazebo/src/CarPlugin.cpp": SOURCE,
    })
    workspace = scan([str(root)], {"ROS_VERSION": "2", "ROS_DISTRO": "humble"})
    package = workspace.packages["car_gazebo"]
    pipeline.read_build_files(package, workspace)
    assert [(n.executable, n.kind, n.plugin_class, n.plugin_base, n.location.file,
             n.location.line) for n in package.nodes] == [
        ("car_plugin", "plugin", "CarPlugin", "gazebo::ModelPlugin",
         "car_gazebo/include/car_gazebo/CarPlugin.hpp", 13)]
    assert "car_gazebo/src/CarPlugin.cpp" in package.nodes[0].sources
