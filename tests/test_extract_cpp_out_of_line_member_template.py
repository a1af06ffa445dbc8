"""A member function template declared in its class and defined outside it, which calls
the ROS API with its template parameter as the type (OrbbecSDK_ROS2's
``FrameLatencyNode::createListener<MsgType>(topic_name, qos)``, called once per message
type under a test of the ``topic_type`` parameter). Its specialisations are specialised
from the definition, whose place was taken for a function of its own: the template was
no wrapper of its call sites, and its call was one subscription of type ``?`` under no
condition, where an in-class definition gave one per call site, typed and conditioned."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

CLASS = """
    #include "rclcpp/rclcpp.hpp"
    #include "sensor_msgs/msg/image.hpp"
    #include "sensor_msgs/msg/imu.hpp"
    class Latency : public rclcpp::Node {
    public:
      Latency();
      template <typename M> void listen(const std::string & name);
      rclcpp::SubscriptionBase::SharedPtr sub_;
    };
    """
DEFINITION = """
    template <typename M> void Latency::listen(const std::string & name) {
      sub_ = this->create_subscription<M>(name, 10, [](const std::shared_ptr<M>) {});
    }
    """
CONSTRUCTOR = """
    Latency::Latency() : Node("latency") {
      std::string type = this->declare_parameter("topic_type", std::string("image"));
      if (type == "image") {
        listen<sensor_msgs::msg::Image>("/camera/image");
      } else if (type == "imu") {
        listen<sensor_msgs::msg::Imu>("/camera/imu");
      }
    }
    int main(int argc, char ** argv) {
      rclcpp::init(argc, argv);
      rclcpp::spin(std::make_shared<Latency>());
    }
    """


def files(source: str) -> dict[str, str]:
    return {
        "lat/package.xml": package_xml("lat", "ament_cmake").replace(
            "<export>", "<depend>rclcpp</depend><depend>sensor_msgs</depend><export>"),
        "lat/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.8)
            project(lat)
            find_package(rclcpp REQUIRED)
            add_executable(lat src/lat.cpp)
            ament_package()
            """,
        "lat/src/lat.cpp": source,
    }


def subscriptions(write_tree, source: str) -> list[tuple[str, str | None, int]]:
    ws = scan([str(write_tree(files(source)))])
    pkg = ws.packages["lat"]
    pkg.nodes, _ = cmake.parse_package(pkg, ws)
    extract_nodes(pkg.nodes, ws, cache_dir=None, jobs=1)
    return sorted((c.name, c.type, len(c.conditions)) for c in pkg.nodes[0].calls
                  if c.kind == "subscribe")


def test_a_member_template_defined_outside_its_class_is_made_at_each_call_site(
        write_tree) -> None:
    expected = [("/camera/image", "sensor_msgs/msg/Image", 1),
                ("/camera/imu", "sensor_msgs/msg/Imu", 2)]
    # defined before its callers, and after them
    assert subscriptions(write_tree, CLASS + DEFINITION + CONSTRUCTOR) == expected
    assert subscriptions(write_tree, CLASS + CONSTRUCTOR + DEFINITION) == expected


def test_a_member_template_defined_in_its_class_as_before(write_tree) -> None:
    inline = CLASS.replace(
        "template <typename M> void listen(const std::string & name);",
        DEFINITION.replace("Latency::listen", "listen"))
    assert subscriptions(write_tree, inline + CONSTRUCTOR) == [
        ("/camera/image", "sensor_msgs/msg/Image", 1),
        ("/camera/imu", "sensor_msgs/msg/Imu", 2)]
