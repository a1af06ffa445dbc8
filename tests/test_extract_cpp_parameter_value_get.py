"""A topic named by ``rclcpp::ParameterValue::get<T>()`` of a parameter's value: the
ROS 2 ``declare_parameter(name, rclcpp::PARAMETER_STRING)`` returns the value as a
``ParameterValue``, whose ``get<std::string>()`` vortex-auv's thrust allocator gives
``create_subscription`` (thrust_allocator_ros.cpp: ``declare_parameter(
"topics.wrench_input", PARAMETER_STRING).get<std::string>()``), as does
``get_parameter(name).get_parameter_value().get<T>()``. Both names were ``?`` with no
parameter behind them, which the graph cannot fill from the launch file's value; a
``get()`` of any other class (a smart pointer's) names nothing."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
using rclcpp::ParameterType::PARAMETER_STRING;

class Relay : public rclcpp::Node {
 public:
  Relay() : Node("relay") {
    std::string in_topic =
        this->declare_parameter("topics.in", PARAMETER_STRING).get<std::string>();
    this->declare_parameter<std::string>("topics.out");
    std::string out_topic =
        this->get_parameter("topics.out").get_parameter_value().get<std::string>();
    auto other = std::make_shared<std::string>("other");
    sub_ = create_subscription<std_msgs::msg::String>(
        in_topic, 10, [](std_msgs::msg::String::SharedPtr) {});
    pub_ = create_publisher<std_msgs::msg::String>(out_topic, 10);
    other_ = create_publisher<std_msgs::msg::String>(*other.get(), 10);
  }

 private:
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_, other_;
};
"""


def test_a_name_from_parameter_value_get_names_its_parameter(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("relay", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"))
    source = tmp_path / "relay.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    named = [(c.kind, c.name_param) for c in result.calls
             if c.kind in ("subscribe", "publish")]
    assert named == [("subscribe", "topics.in"), ("publish", "topics.out"),
                     ("publish", None)]
    assert [d.code for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []
