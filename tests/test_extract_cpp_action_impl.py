"""A ROS 2 action's generated ``Impl`` names the services and topics the action is made
of: templated node code (aerostack2's ``BehaviorServer<ActionT>``) makes a service of
``typename ActionT::Impl::SendGoalService`` and reads its request's ``goal``. The
synthesised action header declares them as rosidl does (``Name_SendGoal`` with its
Request / Response, ``Name_GetResult``, ``Name_FeedbackMessage``, and action_msgs'
status and cancel types), so the class parses and its calls keep their types."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <functional>
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <fly/action/go_to.hpp>

template<typename ActionT>
class Server : public rclcpp::Node {
 public:
  using start_srv = typename ActionT::Impl::SendGoalService;
  using result_srv = typename ActionT::Impl::GetResultService;
  using feedback_msg = typename ActionT::Impl::FeedbackMessage;
  using status_msg = typename ActionT::Impl::GoalStatusMessage;
  using cancel_srv = typename ActionT::Impl::CancelGoalService;
  explicit Server(const std::string & name) : rclcpp::Node(name) {
    modify_ = this->create_service<start_srv>(
        "~/modify", std::bind(&Server::modify, this, std::placeholders::_1,
                              std::placeholders::_2));
    status_ = this->create_publisher<std_msgs::msg::String>("~/status", 10);
  }
  void modify(const typename start_srv::Request::SharedPtr request,
              typename start_srv::Response::SharedPtr response) {
    auto goal = std::make_shared<typename ActionT::Goal>(request->goal);
    auto feedback = std::make_shared<feedback_msg>();
    feedback->feedback.distance = 1.0;
    response->accepted = goal->speed > 0.0;
  }
  typename rclcpp::Service<start_srv>::SharedPtr modify_;
  typename rclcpp::Publisher<feedback_msg>::SharedPtr feedback_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_;
};

class GoTo : public Server<fly::action::GoTo> {
 public:
  GoTo() : Server<fly::action::GoTo>("go_to") {
    speed_ = this->declare_parameter<double>("speed", 1.0);
    twist_ = this->create_subscription<std_msgs::msg::String>(
        "twist", 10, [this](std_msgs::msg::String::SharedPtr) {});
  }
  double speed_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr twist_;
};

int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<GoTo>());
  return 0;
}
"""


def test_templated_code_uses_an_actions_impl_types(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("fly", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend></package>"))
    (tmp_path / "action").mkdir()
    (tmp_path / "action" / "GoTo.action").write_text(
        "float64 speed\n---\nbool ok\n---\nfloat64 distance\n")
    source = tmp_path / "go_to.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []
    # the derived class sees its base: its own calls are found (the template's service
    # keeps type '?', a dependent type the walk does not instantiate)
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("declare", "speed", "double"), ("publish", "~status", "std_msgs/msg/String"),
        ("server", "~modify", "?"), ("subscribe", "twist", "std_msgs/msg/String")]
