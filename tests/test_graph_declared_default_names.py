"""A ROS 2 name taken from a parameter that the code declares with a default in one place
and reads without one in another (nav2's behavior server declares
``local_costmap_topic`` with ``local_costmap/costmap_raw``, reads it with
``get_parameter(name, value)`` and hands the value to its costmap subscriber): when
nothing sets the parameter, the name is the declared default, as the node runs; set, the
value set. ROS 1 keeps its ``?``: a read without a default leaves the variable as it was."""

from __future__ import annotations

import os
from typing import Any

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

LISTENER_HPP = """
    #include <memory>
    #include <string>
    #include <rclcpp/rclcpp.hpp>
    #include <std_msgs/msg/string.hpp>

    class Listener {
     public:
      Listener(rclcpp::Node::SharedPtr node, const std::string& topic);
     private:
      std::string topic_;
      rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
    };
    """

LISTENER = """
    #include "demo/listener.hpp"

    Listener::Listener(rclcpp::Node::SharedPtr node, const std::string& topic)
    : topic_(topic) {
      sub_ = node->create_subscription<std_msgs::msg::String>(
          topic_, 10, [](std_msgs::msg::String::SharedPtr) {});
    }
    """

NODE = """
    #include <memory>
    #include <string>
    #include <rclcpp/rclcpp.hpp>
    #include "demo/listener.hpp"

    class Server : public rclcpp::Node {
     public:
      Server() : rclcpp::Node("server") {
        declare_parameter("costmap_topic", std::string("local_costmap/costmap_raw"));
      }
      void configure() {
        get_parameter("costmap_topic", topic_);
        listener_ = std::make_unique<Listener>(shared_from_this(), topic_);
      }
     private:
      std::string topic_;
      std::unique_ptr<Listener> listener_;
    };

    int main(int argc, char** argv) {
      rclcpp::init(argc, argv);
      auto node = std::make_shared<Server>();
      node->configure();
      rclcpp::spin(node);
    }
    """

LAUNCH = """
    <launch>
      <node pkg="demo" exec="server" name="server">{params}</node>
    </launch>
    """


def _subscriptions(write_tree: Any, params: str) -> set[str]:
    root = write_tree({
        "src/demo/package.xml": package_xml("demo", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"),
        "src/demo/CMakeLists.txt": (
            "project(demo)\nfind_package(ament_cmake REQUIRED)\n"
            "include_directories(include)\n"
            "add_executable(server src/server.cpp src/listener.cpp)\n"
            "install(TARGETS server DESTINATION lib/${PROJECT_NAME})\n"),
        "src/demo/src/server.cpp": NODE,
        "src/demo/src/listener.cpp": LISTENER,
        "src/demo/include/demo/listener.hpp": LISTENER_HPP,
        "src/demo/launch/demo.launch.xml": LAUNCH.format(params=params),
        "project.yaml": ("project: p\nworkspace: [src]\nconfigurations:\n"
                         "  c: [demo/launch/demo.launch.xml]\n")})
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    (config,) = model.configurations
    return {link.resource.name for link in config.links
            if link.node.name == "/server" and link.kind == "subscribe"}


def test_an_unset_parameter_names_the_topic_with_its_declared_default(write_tree) -> None:
    assert _subscriptions(write_tree, "") == {"/local_costmap/costmap_raw"}


def test_a_set_parameter_names_the_topic_with_its_value(write_tree) -> None:
    params = '<param name="costmap_topic" value="/other/costmap"/>'
    assert _subscriptions(write_tree, params) == {"/other/costmap"}
