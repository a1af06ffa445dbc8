"""A name that is a field of a parameter struct another file fills: navigation2's
servers keep their parameters in a ``Parameters`` struct that a ``ParameterHandler``
fills in parameter_handler.cpp (``params_.odom_topic = declare_or_get_parameter(
"odom_topic", ...)``); the server's file subscribes through ``OdomSmoother(node, ...,
params_->odom_topic)``, a constructor in a header. The subscription is named by the
parameter (controller, docking and following servers: ``?`` before)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """
#include <rclcpp/rclcpp.hpp>
#include <nav_msgs/msg/odometry.hpp>
struct Parameters { std::string odom_topic; std::string other; double duration; };
class Handler {
public:
  explicit Handler(rclcpp::Node * node);
  Parameters * getParams() { return &params_; }
protected:
  Parameters params_;
};
class Smoother {
public:
  template<typename NodeT>
  Smoother(const NodeT & parent, double d = 0.3, const std::string & topic = "odom") {
    sub_ = parent->template create_subscription<nav_msgs::msg::Odometry>(topic, 1,
      [](nav_msgs::msg::Odometry::ConstSharedPtr) {});
  }
  rclcpp::Subscription<nav_msgs::msg::Odometry>::SharedPtr sub_;
};
"""

HANDLER = """
#include "handler.hpp"
Handler::Handler(rclcpp::Node * node) {
  params_.odom_topic = node->declare_parameter("odom_topic", std::string("odom"));
  params_.duration = node->declare_parameter("odom_duration", 0.3);
}
"""

SERVER = """
#include "handler.hpp"
class Server : public rclcpp::Node {
public:
  Server() : rclcpp::Node("server") {
    handler_ = std::make_unique<Handler>(this);
    params_ = handler_->getParams();
    smoother_ = std::make_unique<Smoother>(this, params_->duration, params_->odom_topic);
    pub_ = create_publisher<nav_msgs::msg::Odometry>(params_->odom_topic + "_out", 1);
    other_ = create_publisher<nav_msgs::msg::Odometry>(params_->other + "_x", 1);
  }
  std::unique_ptr<Handler> handler_;
  Parameters * params_;
  std::unique_ptr<Smoother> smoother_;
  rclcpp::Publisher<nav_msgs::msg::Odometry>::SharedPtr pub_, other_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Server>());
}
"""


def test_a_struct_field_filled_in_another_file_names_the_call(write_tree) -> None:
    root = write_tree({"ps/package.xml": package_xml("ps", "ament_cmake"),
                       "ps/src/handler.hpp": HEADER, "ps/src/handler.cpp": HANDLER,
                       "ps/src/server.cpp": SERVER})
    result = extract_cpp([str(root / "ps" / "src" / "server.cpp"),
                          str(root / "ps" / "src" / "handler.cpp")],
                         scan([str(root)]), cache_dir=None)
    named = sorted((c.kind, c.name, c.name_param, c.name_default) for c in result.calls
                   if c.kind in ("subscribe", "publish"))
    assert named == [
        ("publish", "?_out", "odom_topic", "odom"),
        ("publish", "?_x", None, None),  # a field no file fills: unknown
        ("subscribe", "?", "odom_topic", "odom"),
    ]
