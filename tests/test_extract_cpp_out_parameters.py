"""A local a helper of the node fills through a parameter it takes by non-const
reference holds what the helper assigns it there: nav2's collision monitor declares its
topics in ``getParameters(cmd_vel_in_topic, cmd_vel_out_topic, state_topic)``, which
assigns each ``get_parameter("cmd_vel_out_topic").as_string()``, and publishes on the
local it passed. The name is that parameter's value (filled by the configuration), not a
name nothing can fill. Not when the helper may leave the local as it was (its one
assignment in a branch), assigns it twice, passes it on to another call, or takes it by
const reference or by value."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

NODE = """\
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <geometry_msgs/msg/twist.hpp>
class Monitor : public rclcpp::Node {
 public:
  Monitor() : rclcpp::Node("monitor") {
    std::string in_topic;
    std::string out_topic;
    std::string state_topic;
    std::string twice;
    if (!getParameters(in_topic, out_topic, state_topic, twice)) {
      return;
    }
    out_ = create_publisher<geometry_msgs::msg::Twist>(out_topic, 1);
    in_ = create_subscription<geometry_msgs::msg::Twist>(
      in_topic, 1, [](geometry_msgs::msg::Twist::SharedPtr) {});
    state_ = create_publisher<geometry_msgs::msg::Twist>(state_topic, 1);
    twice_ = create_publisher<geometry_msgs::msg::Twist>(twice, 1);
    std::string copied = "copied";
    byValue(copied);
    copied_ = create_publisher<geometry_msgs::msg::Twist>(copied, 1);
  }

 private:
  bool getParameters(
    std::string & in_topic, std::string & out_topic, std::string & state_topic,
    std::string & twice)
  {
    declare_parameter("cmd_vel_in_topic", rclcpp::ParameterValue("cmd_vel_smoothed"));
    in_topic = get_parameter("cmd_vel_in_topic").as_string();
    declare_parameter("cmd_vel_out_topic", rclcpp::ParameterValue("cmd_vel"));
    out_topic = get_parameter("cmd_vel_out_topic").as_string();
    declare_parameter("state_topic", rclcpp::ParameterValue(""));
    if (get_parameter("use_state").as_bool()) {
      state_topic = get_parameter("state_topic").as_string();
    }
    declare_parameter("first", rclcpp::ParameterValue("a"));
    declare_parameter("second", rclcpp::ParameterValue("b"));
    twice = get_parameter("first").as_string();
    twice = get_parameter("second").as_string();
    return true;
  }
  void byValue(std::string topic) {
    declare_parameter("by_value", rclcpp::ParameterValue("v"));
    topic = get_parameter("by_value").as_string();
  }
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr out_, state_, twice_, copied_;
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr in_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Monitor>());
  return 0;
}
"""


def test_a_local_filled_through_a_reference_parameter(tmp_path: Path) -> None:
    (tmp_path / "monitor.cpp").write_text(NODE)
    result = extract_cpp([str(tmp_path / "monitor.cpp")], Workspace(root=str(tmp_path)),
                         cache_dir=None)
    named = sorted((c.location.line, c.kind, c.name, c.name_param) for c in result.calls
                   if c.kind in ("publish", "subscribe"))
    assert named == [
        (15, "publish", "?", "cmd_vel_out_topic"),
        (16, "subscribe", "?", "cmd_vel_in_topic"),
        # assigned only under a condition, assigned twice: not known
        (18, "publish", "?", None),
        (19, "publish", "?", None),
        # a copy the helper changes: the local keeps its own value
        (22, "publish", "copied", None),
    ]
