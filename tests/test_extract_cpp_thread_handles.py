"""A thread's native handle, its CPU clock and scheduling, and rclcpp's
``ContentFilterOptions`` have stand-ins: ros2/examples' callback-group executor sets its
threads' priorities through ``std::thread::native_handle()`` and ``pthread_getschedparam``
and times them with ``pthread_getcpuclockid`` / ``clock_gettime`` (a ``clockid_t``); its
content-filtering subscriber builds ``rclcpp::ContentFilterOptions``. Each was a parse
error (4 on ros2/examples 4a4082a, calls identical after)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = """
#include <chrono>
#include <memory>
#include <thread>
#include <pthread.h>
#include <time.h>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

std::chrono::nanoseconds cpu_time(std::thread::native_handle_type handle) {
  clockid_t id;
  pthread_getcpuclockid(handle, &id);
  timespec spec;
  clock_gettime(id, &spec);
  return std::chrono::seconds{spec.tv_sec} + std::chrono::nanoseconds{spec.tv_nsec};
}

bool raise_priority(std::thread::native_handle_type handle) {
  sched_param params;
  int policy;
  return pthread_getschedparam(handle, &policy, &params) == 0;
}

class Filtered : public rclcpp::Node {
public:
  Filtered() : Node("filtered") {
    rclcpp::SubscriptionOptions options;
    rclcpp::ContentFilterOptions filter;
    filter.filter_expression = "data = %0";
    filter.expression_parameters = {"'on'"};
    options.content_filter_options = filter;
    sub_ = create_subscription<std_msgs::msg::String>(
      "state", 10, [](std_msgs::msg::String::ConstSharedPtr) {}, options);
  }
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};

int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<Filtered>();
  std::thread spinner([node]() { rclcpp::spin(node); });
  raise_priority(spinner.native_handle());
  cpu_time(spinner.native_handle());
  spinner.join();
}
"""


def test_thread_handles_and_content_filters_parse(write_tree) -> None:
    root = write_tree({
        "filtered/package.xml": package_xml("filtered", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"),
        "filtered/src/filtered.cpp": NODE})
    result = extract_cpp([str(root / "filtered" / "src" / "filtered.cpp")],
                         scan([str(root)]), cache_dir=None)
    errors = [d.message for d in result.diagnostics
              if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED")]
    assert errors == []
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("subscribe", "state", "std_msgs/msg/String")]
