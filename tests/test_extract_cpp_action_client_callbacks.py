"""rclcpp_action's client as Jazzy declares it: ``async_get_result(handle, callback)``,
``async_cancel_goal(handle, callback)`` whose future holds the CancelGoal response, the
goal handle's callback types. With a one-argument ``async_get_result`` stand-in, MoveIt's
simple controller manager's ``waitForExecution`` (``async_get_result(current_goal_,
[this, done](const auto& wrapped_result) {...})``) was an error in a function that makes
ROS calls, and the plugin was partial."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <rclcpp/rclcpp.hpp>
#include <rclcpp_action/rclcpp_action.hpp>
#include <control_msgs/action/follow_joint_trajectory.hpp>
#include <std_msgs/msg/bool.hpp>
#include <future>

using Action = control_msgs::action::FollowJointTrajectory;

class Handle
{
public:
  explicit Handle(const rclcpp::Node::SharedPtr & node) : node_(node)
  {
    client_ = rclcpp_action::create_client<Action>(node_, "arm_controller/follow_joint_trajectory");
  }

  bool waitForExecution()
  {
    auto done = std::make_shared<std::promise<bool>>();
    auto result_future = client_->async_get_result(
      goal_, [this, done](const auto & wrapped_result) {
        finished(wrapped_result);
        done->set_value(true);
      });
    auto status = result_future.wait_for(std::chrono::milliseconds(50));
    auto done_pub = node_->create_publisher<std_msgs::msg::Bool>("execution_done", 1);
    return status == std::future_status::ready && done_pub != nullptr;
  }

  void cancel()
  {
    auto cancelled = client_->async_cancel_goal(
      goal_, [](rclcpp_action::Client<Action>::CancelResponse::SharedPtr response) {
        (void)response->return_code;
      });
    const auto & response = cancelled.get();
    if (response->return_code != rclcpp_action::Client<Action>::CancelResponse::ERROR_NONE) {
      auto failed = node_->create_publisher<std_msgs::msg::Bool>("cancel_failed", 1);
      (void)failed;
    }
  }

private:
  void finished(const rclcpp_action::ClientGoalHandle<Action>::WrappedResult & result)
  {
    (void)result.code;
  }

  rclcpp::Node::SharedPtr node_;
  rclcpp_action::Client<Action>::SharedPtr client_;
  rclcpp_action::ClientGoalHandle<Action>::SharedPtr goal_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("handle");
  Handle handle(node);
  handle.waitForExecution();
  handle.cancel();
}
"""


def test_action_client_result_and_cancel_callbacks_parse(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("handle", "ament_cmake"))
    source = tmp_path / "handle.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="jazzy")
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("action-client", "arm_controller/follow_joint_trajectory"),
        ("publish", "cancel_failed"), ("publish", "execution_done")]
    assert [d.message for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED")] == []
