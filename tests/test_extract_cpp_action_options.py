"""rclcpp_action's factories take rcl_action's options: ``create_server<A>(node, name,
goal, cancel, accepted, rcl_action_server_get_default_options(), group)`` (the
Universal Robots driver's trajectory_until_node) and ``create_client<A>(node, name,
group, options)`` resolve against the stand-in, with no C++ error that makes the
function partial."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <functional>
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_action/rclcpp_action.hpp>
#include <example_interfaces/action/fibonacci.hpp>

using Fibonacci = example_interfaces::action::Fibonacci;
using Handle = rclcpp_action::ServerGoalHandle<Fibonacci>;

class Counter : public rclcpp::Node {
 public:
  Counter() : Node("counter") {
    group_ = create_callback_group(rclcpp::CallbackGroupType::Reentrant);
    auto options = rcl_action_server_get_default_options();
    options.result_timeout.nanoseconds = 10;
    server_ = rclcpp_action::create_server<Fibonacci>(
        this, "~/count",
        std::bind(&Counter::goal, this, std::placeholders::_1, std::placeholders::_2),
        std::bind(&Counter::cancel, this, std::placeholders::_1),
        std::bind(&Counter::accepted, this, std::placeholders::_1),
        options, group_);
    client_ = rclcpp_action::create_client<Fibonacci>(
        this, "/other/count", group_, rcl_action_client_get_default_options());
  }

 private:
  rclcpp_action::GoalResponse goal(const rclcpp_action::GoalUUID &,
                                   std::shared_ptr<const Fibonacci::Goal>) {
    return rclcpp_action::GoalResponse::ACCEPT_AND_EXECUTE;
  }
  rclcpp_action::CancelResponse cancel(const std::shared_ptr<Handle>) {
    return rclcpp_action::CancelResponse::ACCEPT;
  }
  void accepted(const std::shared_ptr<Handle>) {}
  rclcpp::CallbackGroup::SharedPtr group_;
  rclcpp_action::Server<Fibonacci>::SharedPtr server_;
  rclcpp_action::Client<Fibonacci>::SharedPtr client_;
};
"""


def test_action_factories_take_rcl_action_options(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("count", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>rclcpp_action</depend>"
        "<depend>example_interfaces</depend></package>"))
    source = tmp_path / "counter.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("action-server", "~count", "example_interfaces/action/Fibonacci"),
        ("action-client", "/other/count", "example_interfaces/action/Fibonacci")]
    assert [d.code for d in result.diagnostics if d.code.startswith("CPP_")
            and d.code not in ("CPP_NAMES_DECLARED", "CPP_MESSAGE_UNKNOWN")] == []
