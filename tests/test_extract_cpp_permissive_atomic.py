"""A vendor value stored in a ``std::atomic`` with the vendor's headers missing:
fairino-moveit2's command_server.cpp:519-522 reads the robot SDK's state
(``ROBOT_STATE_PKG tmp; ... mainerrcode = tmp.main_code;``) into ``std::atomic<int>``
members. The permissive value converts to ``int`` and to the atomic alike, so
``operator=(T)`` and the atomic's own assignment took it equally: "use of overloaded
operator '=' is ambiguous", here in the function that advertises. Storing a number, or
building an atomic from a vendor value, is valid too."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
#include <atomic>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/int32.hpp>
#include <vendor_sdk/robot.h>

class CommandServer : public rclcpp::Node {
public:
  CommandServer() : Node("command_server"), limit_(vendor::defaultLimit()) {}
  void poll() {
    static ROBOT_STATE_PKG state;
    robot_->GetRobotRealTimeState(&state);
    main_code_ = state.main_code;
    sub_code_ = state.sub_code;
    count_ = 3;
    pub_ = create_publisher<std_msgs::msg::Int32>("robot_error", 10);
  }
private:
  vendor::Robot* robot_;
  std::atomic<int> main_code_;
  std::atomic<int> sub_code_{0};
  std::atomic<int> count_;
  std::atomic<int> limit_;
  rclcpp::Publisher<std_msgs::msg::Int32>::SharedPtr pub_;
};
"""


def test_a_permissive_value_stored_in_an_atomic(write_tree) -> None:
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "ament_cmake"),
        "pkg/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(pkg)\n"
                              "add_executable(server src/server.cpp)\n",
        "pkg/src/server.cpp": SOURCE})
    result = extract_cpp([str(root / "pkg" / "src" / "server.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "robot_error")]
