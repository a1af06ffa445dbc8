"""A name a node resolves itself before it gives it to a call: roscpp's
``NodeHandle::resolveName(name)`` (image_view's nodelets: ``std::string topic =
nh.resolveName("image")``, then ``it.subscribe(topic, ...)``) is ``name`` resolved in
that handle's namespace and remapped; rclcpp's ``expand_topic_or_service_name(name,
get_name(), get_namespace())`` expands it in the node's namespace. A call named by either
is named, not ``?``."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

VIEWER = """\
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <std_msgs/String.h>

void onImage(const sensor_msgs::Image::ConstPtr& msg) {}

int main(int argc, char** argv) {
  ros::init(argc, argv, "viewer");
  ros::NodeHandle nh, pnh("~"), motors(nh, "motors");
  std::string topic = nh.resolveName("image");
  ros::Subscriber sub = nh.subscribe(topic, 1, onImage);
  // each resolved on its own handle, given to another one
  ros::Publisher out = nh.advertise<std_msgs::String>(pnh.resolveName("output"), 1);
  ros::Publisher status = pnh.advertise<std_msgs::String>(
      motors.resolveName("status") + "/text", 1);
  ros::spin();
}
"""

CMAKE = """\
cmake_minimum_required(VERSION 3.0.2)
project(view)
find_package(catkin REQUIRED COMPONENTS roscpp sensor_msgs std_msgs)
catkin_package()
add_executable(viewer src/viewer.cpp)
"""

ROS2_NODE = """\
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp/expand_topic_or_service_name.hpp>
#include <sensor_msgs/msg/laser_scan.hpp>

class Scanner : public rclcpp::Node {
 public:
  Scanner() : Node("scanner") {
    std::string topic = rclcpp::expand_topic_or_service_name(
        "scan", this->get_name(), this->get_namespace());
    sub_ = create_subscription<sensor_msgs::msg::LaserScan>(
        topic, 10, [](sensor_msgs::msg::LaserScan::SharedPtr) {});
    // an expanded name after other text holds the node's namespace there (image_view's
    // stereo_view_node: stereo_ns + "/left" + expand(image, ...))
    std::string back = "rear" + rclcpp::expand_topic_or_service_name(
        "scan", this->get_name(), this->get_namespace());
    // an expanded name expanded again is as it was (humble's stereo_view_node)
    back = rclcpp::expand_topic_or_service_name(rclcpp::expand_topic_or_service_name(
        back, this->get_name(), this->get_namespace()), get_name(), get_namespace());
    rear_ = create_subscription<sensor_msgs::msg::LaserScan>(
        back, 10, [](sensor_msgs::msg::LaserScan::SharedPtr) {});
  }
 private:
  rclcpp::Subscription<sensor_msgs::msg::LaserScan>::SharedPtr sub_, rear_;
};

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Scanner>());
}
"""

ROS2_LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package='scan', executable='scanner', namespace='robot',
                                   remappings=[('scan', 'front/scan')])])
"""


def _links(root, name: str) -> list[tuple[str, str]]:
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    (node,) = [n for n in config.nodes if n.name == name]
    assert node.node is not None and node.node.completeness == "complete", node.node
    return sorted((link.kind, link.rosname.full) for link in node.links
                  if link.kind in ("publish", "subscribe"))


def _ros1(write_tree, remaps: str):
    return write_tree({
        "src/view/package.xml": package_xml("view"),
        "src/view/CMakeLists.txt": CMAKE,
        "src/view/src/viewer.cpp": VIEWER,
        "src/view/launch/view.launch": (
            '<launch><group ns="cam"><node pkg="view" type="viewer" name="viewer">'
            f"{remaps}</node></group></launch>\n"),
        "project.yaml": "project: p\nconfigurations:\n  c: [view/launch/view.launch]\n",
    })


def test_a_resolved_name_is_in_its_handles_namespace(write_tree):
    # the public handle's image, the private handle's output, the motors handle's
    # status: each where its own handle puts it, whatever handle the call is made on
    assert _links(_ros1(write_tree, ""), "/cam/viewer") == [
        ("publish", "/cam/motors/status/text"), ("publish", "/cam/viewer/output"),
        ("subscribe", "/cam/image")]


def test_a_resolved_name_takes_the_nodes_remaps(write_tree):
    root = _ros1(write_tree, '<remap from="image" to="/camera/image_raw"/>'
                             '<remap from="~output" to="shown"/>'
                             '<remap from="motors/status" to="/state"/>')
    assert _links(root, "/cam/viewer") == [
        ("publish", "/cam/shown"), ("publish", "/state/text"),
        ("subscribe", "/camera/image_raw")]


def test_an_expanded_name_is_in_the_nodes_namespace(write_tree):
    root = write_tree({
        "src/scan/package.xml": package_xml("scan", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend></package>"),
        "src/scan/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(scan)\n"
                                   "add_executable(scanner src/scanner.cpp)\n",
        "src/scan/src/scanner.cpp": ROS2_NODE,
        "src/scan/launch/scan.launch.py": ROS2_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [scan/launch/scan.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (node,) = [n for p in model.packages for n in p.nodes if n.name == "scan/scanner"]
    assert sorted(c.name for c in node.calls) == ["rear?/scan", "scan"]
    assert ("subscribe", "/robot/front/scan") in _links(root, "/robot/scanner")
