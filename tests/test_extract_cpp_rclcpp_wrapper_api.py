"""The rclcpp API a node wrapper forwards (Autoware's agnocast_wrapper::Node, included
by every Autoware node): ``describe_parameter(s)``, ``get_parameter_types``,
``NodeParametersInterface::OnSetParametersCallbackType`` (rclcpp 28's name),
``rclcpp::detail::FutureAndRequestId<F>``, ``Publisher<M>::ROSMessageType`` and rcl's
``rcl_timer_exchange_period``. Each was a clang error in the wrapper's headers, and
those errors marked 28 nodes of autoware_core partial (a ``create_service(`` in the
header without a call)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

WRAPPER = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
namespace wrap {
using OnSet = rclcpp::node_interfaces::NodeParametersInterface::OnSetParametersCallbackType;
template<class FutureT> struct Pending : rclcpp::detail::FutureAndRequestId<FutureT> {
  using rclcpp::detail::FutureAndRequestId<FutureT>::FutureAndRequestId;
};
class Node {
 public:
  explicit Node(rclcpp::Node * node) : node_(node) {}
  rcl_interfaces::msg::ParameterDescriptor describe(const std::string & name) const {
    return node_->describe_parameter(name);
  }
  std::vector<uint8_t> types(const std::vector<std::string> & names) const {
    (void)node_->describe_parameters(names);
    return node_->get_parameter_types(names);
  }
  void on_set(OnSet callback) { node_->add_on_set_parameters_callback(std::move(callback)); }
  void period(rclcpp::TimerBase::SharedPtr timer, int64_t ns) {
    int64_t old = 0;
    rcl_timer_exchange_period(timer->get_timer_handle().get(), ns, &old);
  }
 private:
  rclcpp::Node * node_;
};
}
"""

NODE = """
#include "wrap.hpp"
class Talker : public rclcpp::Node {
 public:
  Talker() : rclcpp::Node("talker"), wrapper_(this) {
    pub_ = create_publisher<std_msgs::msg::String>("chatter", 3);
    auto message = std::make_unique<rclcpp::Publisher<std_msgs::msg::String>::ROSMessageType>();
    pub_->publish(*message);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  wrap::Node wrapper_;
};
"""


def test_the_wrapped_api_parses_without_errors(write_tree) -> None:
    root = write_tree({"talk/package.xml": package_xml("talk", "ament_cmake"),
                       "talk/src/wrap.hpp": WRAPPER, "talk/src/talker.cpp": NODE})
    result = extract_cpp([str(root / "talk/src/talker.cpp")], scan([str(root)]),
                         cache_dir=None)
    errors = [d.message for d in result.diagnostics
              if d.code in ("CPP_PARSE_ERROR", "CPP_CALL_MISSED", "CPP_ERROR_NEAR_CALL")]
    assert errors == []
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("publish", "chatter", "std_msgs/msg/String")]
