"""C++20's ``<semaphore>``: elkapod_core's motion manager
(elkapod_motion_manager.hpp:15, :75) holds a ``std::binary_semaphore semaphore_{0};``
member, which its callbacks ``acquire()`` and ``release()``. The std stand-ins had no
``<semaphore>`` (an empty stand-in was used): the member's type was unknown, the class's
definition failed, and its constructor's ``declare_parameter`` / ``create_publisher`` /
``create_timer`` / ``create_service`` calls were each a C++ error, the node partial."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """
#include <chrono>
#include <semaphore>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

class Manager : public rclcpp::Node {
public:
  Manager();

private:
  void tick();
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::TimerBase::SharedPtr timer_;
  std::binary_semaphore semaphore_{0};
  std::counting_semaphore<4> slots_{4};
};
"""

SOURCE = """
#include "manager.hpp"

Manager::Manager() : Node("manager") {
  double rate = declare_parameter<double>("rate");
  pub_ = create_publisher<std_msgs::msg::String>("state", 10);
  timer_ = create_timer(std::chrono::duration<double>(1.0 / rate), [this]() { tick(); });
}

void Manager::tick() {
  if (semaphore_.try_acquire_for(std::chrono::milliseconds(5)) && slots_.try_acquire()) {
    slots_.release();
  }
  semaphore_.release();
}
"""


def test_semaphore_members_leave_the_node_class_whole(write_tree) -> None:
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "ament_cmake"),
        "pkg/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(pkg)\n"
                              "include_directories(include)\n"
                              "add_executable(manager src/manager.cpp)\n",
        "pkg/include/manager.hpp": HEADER,
        "pkg/src/manager.cpp": SOURCE})
    result = extract_cpp([str(root / "pkg" / "src" / "manager.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL",
                          "CPP_INCLUDE_MISSING")] == []
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("declare", "rate"), ("publish", "state")]
