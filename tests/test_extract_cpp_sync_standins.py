"""C++20's ``<latch>``, ``<barrier>`` and ``<stop_token>`` (with ``<thread>``'s
``std::jthread``), which a node class may hold as members as elkapod_core's motion
manager holds ``<semaphore>``'s (elkapod_motion_manager.hpp:15, :75). The std stand-ins
had none of them (an empty stand-in was used): each member's type was unknown, the
class's definition failed, and its constructor's calls were C++ errors, the node
partial (surveyX's "Seen, not done")."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """
#include <barrier>
#include <chrono>
#include <latch>
#include <stop_token>
#include <thread>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

class Worker : public rclcpp::Node {
public:
  Worker();
  ~Worker() { stop_.request_stop(); }

private:
  void tick();
  void run(std::stop_token token);
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::TimerBase::SharedPtr timer_;
  std::latch ready_{1};
  std::barrier<> phase_{2};
  std::stop_source stop_;
  std::jthread loop_;
};
"""

SOURCE = """
#include "worker.hpp"

Worker::Worker() : Node("worker") {
  double rate = declare_parameter<double>("rate");
  pub_ = create_publisher<std_msgs::msg::String>("state", 10);
  timer_ = create_timer(std::chrono::duration<double>(1.0 / rate), [this]() { tick(); });
  loop_ = std::jthread([this](std::stop_token token) { run(token); });
  ready_.count_down();
}

void Worker::run(std::stop_token token) {
  std::stop_callback on_stop(token, [this]() { ready_.count_down(); });
  while (!token.stop_requested() && !stop_.stop_requested()) {
    phase_.arrive_and_wait();
  }
}

void Worker::tick() {
  if (ready_.try_wait()) {
    auto arrived = phase_.arrive();
    phase_.wait(std::move(arrived));
  }
  if (loop_.get_stop_token().stop_possible()) {
    loop_.request_stop();
  }
}
"""


def test_cxx20_synchronisation_members_leave_the_node_class_whole(write_tree) -> None:
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "ament_cmake"),
        "pkg/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(pkg)\n"
                              "include_directories(include)\n"
                              "add_executable(worker src/worker.cpp)\n",
        "pkg/include/worker.hpp": HEADER,
        "pkg/src/worker.cpp": SOURCE})
    result = extract_cpp([str(root / "pkg" / "src" / "worker.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL",
                          "CPP_INCLUDE_MISSING")] == []
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("declare", "rate"), ("publish", "state")]
