"""C++20's ``std::ranges`` algorithms and ``std::array``'s comparison in the stand-in
standard library: vortex-auv's pose filter calls ``std::ranges::for_each(measurements_,
[](auto& m) {...})`` in the callback of its subscription, its thruster interface
``std::ranges::transform(mapping, direction, std::back_inserter(v), f)`` where it reads
its parameters, and its LOS guidance compares ``goal_handle->get_goal_id() ==
preempted_goal_id_`` (an ``rclcpp_action::GoalUUID``, a ``std::array``) in its action's
``execute``. Each was a C++ error in a function that calls the ROS API, and the three
nodes "partial" (CPP_NODE_PARTIAL)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <algorithm>
#include <cstdint>
#include <iterator>
#include <mutex>
#include <string>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_action/rclcpp_action.hpp>
#include <std_msgs/msg/string.hpp>
#include <example_interfaces/action/fibonacci.hpp>
using Fibonacci = example_interfaces::action::Fibonacci;
struct Mark { double x; };
class Filter : public rclcpp::Node {
 public:
  Filter() : Node("filter") {
    std::vector<int64_t> mapping{1, 2}, direction{1, -1};
    std::ranges::transform(mapping, direction, std::back_inserter(out_),
                           [](const int64_t& m, const int64_t& d) { return m * d; });
    sub_ = create_subscription<std_msgs::msg::String>("in", 10,
        [this](std_msgs::msg::String::SharedPtr) {
          std::ranges::for_each(marks_, [](auto& m) { m.x = -m.x; });
          auto it = std::ranges::find_if(marks_, [](const Mark& m) { return m.x > 0; });
          if (it != marks_.end() && std::ranges::any_of(out_, [](int64_t v) { return v > 0; })) {
            pub_->publish(std_msgs::msg::String());
          }
        });
    pub_ = create_publisher<std_msgs::msg::String>("out", 10);
  }
  void execute(const std::shared_ptr<rclcpp_action::ServerGoalHandle<Fibonacci>> goal_handle) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (goal_handle->get_goal_id() == preempted_) {
      done_ = create_publisher<std_msgs::msg::String>("preempted", 10);
    }
  }
 private:
  std::vector<Mark> marks_;
  std::vector<int64_t> out_;
  std::mutex mutex_;
  rclcpp_action::GoalUUID preempted_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_, done_;
};
"""


def test_ranges_algorithms_and_array_comparison_parse(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("filt", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>rclcpp_action</depend>"
        "<depend>std_msgs</depend><depend>example_interfaces</depend></package>"))
    source = tmp_path / "filt.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [
        ("subscribe", "in"), ("publish", "out"), ("publish", "preempted")]
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
