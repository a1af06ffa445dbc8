"""rclcpp's ParameterEventsFilter (rclcpp/parameter_events_filter.hpp) picks the
parameters of a ParameterEvent by name and kind: ``EventType::NEW``, ``DELETED``,
``CHANGED``, and ``get_events()`` gives (kind, parameter) pairs. metavision_driver
6b7297c's DriverROS2::onParameterEvent builds one with
``{rclcpp::ParameterEventsFilter::EventType::CHANGED}``; the stand-ins lacked the class,
the permissive declaration has no nested enum, and the error left the node partial and
the ``set_parameter`` beside it unread. The filter itself makes no ROS call."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <memory>
#include <string>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp/parameter_events_filter.hpp>
class Biases : public rclcpp::Node {
 public:
  Biases() : Node("biases") {
    events_ = create_subscription<rcl_interfaces::msg::ParameterEvent>(
      "/parameter_events", 10,
      std::bind(&Biases::onParameterEvent, this, std::placeholders::_1));
  }
  void onParameterEvent(std::shared_ptr<const rcl_interfaces::msg::ParameterEvent> event) {
    auto ev = std::make_shared<rcl_interfaces::msg::ParameterEvent>(*event);
    rclcpp::ParameterEventsFilter filter(
      ev, {"bias_diff"}, {rclcpp::ParameterEventsFilter::EventType::CHANGED});
    for (auto & it : filter.get_events()) {
      if (it.first == rclcpp::ParameterEventsFilter::EventType::CHANGED) {
        set_parameter(rclcpp::Parameter("bias_diff_off", it.second->value.integer_value));
      }
    }
  }
  rclcpp::Subscription<rcl_interfaces::msg::ParameterEvent>::SharedPtr events_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Biases>());
}
"""


def test_parameter_events_filter_parses_and_the_write_beside_it_is_read(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("biases"))
    source = tmp_path / "node.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None, distro="humble")
    assert [d.code for d in result.diagnostics] == []
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("subscribe", "/parameter_events", "rcl_interfaces/msg/ParameterEvent"),
        ("write", "bias_diff_off", None)]
