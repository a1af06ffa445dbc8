"""An unknown name a macro's definition writes, not its call: ateam_common's
``SET_ROS_PROTOBUF_LOG_HANDLER(name)`` (protobuf_logging.hpp:40) expands to
``google::protobuf::SetLogHandler(...)``, protobuf's headers missing; clang reports the
error at the call (ssl_simulation_radio_bridge_node.cpp:59), where the permissive
declarations read the macro's own name, so ``google`` stayed undeclared and the
constructor, which makes the node's ROS calls, a C++ error near them (two nodes
partial). The name is read where the workspace header that defines the macro writes
it."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include "pkg/log_handler.hpp"

class Bridge : public rclcpp::Node
{
public:
  Bridge()
  : Node("bridge")
  {
    SET_VENDOR_LOG_HANDLER("bridge.vendor");
    declare_parameter("radio_ip", "127.0.0.1");
    pub_ = create_publisher<std_msgs::msg::String>("status", 10);
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Bridge>());
  return 0;
}
"""

HEADER = r"""#pragma once
#include <string>
#include <vendor/logging.h>
#include <rclcpp/logging.hpp>

#define SET_VENDOR_LOG_HANDLER(logger_name) \
  { \
    vendor::log::SetLogHandler( \
      [](vendor::log::LogLevel level, const char * filename, int line, \
      const std::string & message) { \
        auto ros_logger = rclcpp::get_logger(logger_name); \
        switch (level) { \
          case vendor::log::LogLevel::LOGLEVEL_INFO: \
            RCLCPP_INFO(ros_logger, "[%s:%d] %s", filename, line, message.c_str()); \
            break; \
          case vendor::log::LogLevel::LOGLEVEL_ERROR: \
            RCLCPP_ERROR(ros_logger, "[%s:%d] %s", filename, line, message.c_str()); \
            break; \
        } \
      }); \
    RCLCPP_INFO(rclcpp::get_logger(logger_name), "Routing vendor logs through ROS"); \
  }
"""

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(pkg)
find_package(rclcpp REQUIRED)
include_directories(include)
add_executable(bridge src/bridge.cpp)
"""


def test_a_name_of_a_macro_definition_is_declared(write_tree) -> None:
    root = write_tree({"pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "pkg/CMakeLists.txt": CMAKE,
                       "pkg/include/pkg/log_handler.hpp": HEADER,
                       "pkg/src/bridge.cpp": SOURCE})
    result = extract_cpp([str(root / "pkg" / "src" / "bridge.cpp")], scan([str(root)]),
                         cache_dir=None, distro="jazzy")
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    declared = [d.message for d in result.diagnostics if d.code == "CPP_NAMES_DECLARED"]
    assert len(declared) == 1 and "vendor::log::SetLogHandler" in declared[0]
    assert "SET_VENDOR_LOG_HANDLER" not in declared[0]
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("declare", "radio_ip"), ("publish", "status")]
