"""A name of a missing header in capitals given as a template's argument is a constant,
and a size: lbr_fri_ros2_stack's controllers hold ``std::array<std::string,
KUKA::FRI::LBRState::NUMBER_OF_JOINTS> joint_names_ = {"A1", ..., "A7"}`` (the FRI
client SDK ships as an archive the build unpacks, so ``friLBRState.h`` is missing). The
name was declared a class (a type where a template argument may be one), the member's
declaration an error, the controller's class invalid, and ``get_node()`` in ``on_init``
"no matching member function": every controller's publisher or subscription was
unresolved and the controller partial. Now it is an enumerator with a value an
initialiser of a few elements fits (an array's bound too)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <array>
#include <memory>
#include <string>
#include "controller_interface/controller_interface.hpp"
#include "rclcpp/rclcpp.hpp"
#include "friLBRState.h"
#include "std_msgs/msg/float64_multi_array.hpp"
namespace lbr {
class StateBroadcaster : public controller_interface::ControllerInterface {
public:
  using Configuration = controller_interface::InterfaceConfiguration;
  Configuration command_interface_configuration() const override {
    return Configuration{controller_interface::interface_configuration_type::NONE}; }
  Configuration state_interface_configuration() const override {
    return Configuration{controller_interface::interface_configuration_type::ALL}; }
  controller_interface::return_type update(const rclcpp::Time &,
                                           const rclcpp::Duration &) override {
    return controller_interface::return_type::OK; }
  controller_interface::CallbackReturn on_init() override {
    pub_ = this->get_node()->create_publisher<std_msgs::msg::Float64MultiArray>(
        "state", 1);
    if (joint_names_.size() != KUKA::FRI::LBRState::NUMBER_OF_JOINTS) {
      RCLCPP_ERROR(this->get_node()->get_logger(), "joints %d",
                   KUKA::FRI::LBRState::NUMBER_OF_JOINTS);
      return controller_interface::CallbackReturn::ERROR;
    }
    return controller_interface::CallbackReturn::SUCCESS;
  }
protected:
  std::array<std::string, KUKA::FRI::LBRState::NUMBER_OF_JOINTS> joint_names_ = {"A1", "A2"};
  std::array<double, KUKA::FRI::LBRState::NUMBER_OF_JOINTS> positions_;
  rclcpp::Publisher<std_msgs::msg::Float64MultiArray>::SharedPtr pub_;
};
}
"""


def test_a_capitals_template_argument_of_a_missing_header_is_a_size(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("lbrc", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>controller_interface</depend>"
        "<depend>std_msgs</depend></package>"))
    source = tmp_path / "c.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "state")]
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL",
                          "CPP_CALL_UNRESOLVED")] == []
