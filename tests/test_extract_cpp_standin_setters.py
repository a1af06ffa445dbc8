"""What rosidl generates for rcl_interfaces' and builtin_interfaces' messages (the
``set__<field>`` setters, ``_<field>_type`` aliases, ``SharedPtr``) and what the
standard library gives for an allocator (``std::allocator_traits``), in the stand-ins: a
parameter callback that answers ``result.set__successful(true)``, or a header that
rebinds an allocator (metavision_driver's resize_hack.h), was a C++ error beside the
node's calls."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = """\
#include <memory>
#include <string>
#include <vector>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"
template<class V> using rebound = std::vector<
    typename V::value_type,
    typename std::allocator_traits<typename V::allocator_type>::template rebind_alloc<
      typename V::value_type>>;
class Tuned : public rclcpp::Node {
 public:
  Tuned() : Node("tuned") {
    declare_parameter("gain", 1.0);
    callback_ = add_on_set_parameters_callback(
      [this](const std::vector<rclcpp::Parameter> & params) {
        rcl_interfaces::msg::SetParametersResult result;
        result.set__successful(true).set__reason("");
        builtin_interfaces::msg::Time stamp;
        stamp.set__sec(0).set__nanosec(0);
        rcl_interfaces::msg::SetParametersResult::SharedPtr kept;
        for (const auto & p : params) {
          if (p.get_name() == "gain") {
            pub_->publish(std_msgs::msg::String());
          }
        }
        return result;
      });
    pub_ = create_publisher<std_msgs::msg::String>("gain_changed", 10);
    rebound<std::vector<int>> values;
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::node_interfaces::OnSetParametersCallbackHandle::SharedPtr callback_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Tuned>());
}
"""


def test_generated_setters_and_allocator_traits_parse(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("tuned"))
    source = tmp_path / "node.cpp"
    source.write_text(NODE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="jazzy")
    assert [(d.code, d.message) for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED")] == []
    assert sorted((c.kind, c.name) for c in result.calls if not c.name.startswith("~")) == [
        ("declare", "gain"), ("publish", "gain_changed")]
