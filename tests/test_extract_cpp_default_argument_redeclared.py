"""A constructor declared ``DiffDriveHardwareInterface(std::string node_name)`` and
defined with a default, ``(std::string node_name = "diff_drive_hardware_interface")``
(clearpath_platform 2f04d13): GCC builds it, clang says "addition of default argument on
redeclaration makes this constructor a default constructor" and still reads the body
whole. That error sat beside the constructor's publisher and subscription, and the
hardware plugin was partial (CPP_ERROR_NEAR_CALL) though every call was read. An error
that may drop code beside a call still says so."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HEADER = """\
#include <string>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"
class Bridge : public rclcpp::Node {
public:
  explicit Bridge(std::string node_name);
private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
"""

SOURCE = """\
#include "bridge/bridge.hpp"
Bridge::Bridge(std::string node_name%s)
: Node(node_name)
{
  pub_ = create_publisher<std_msgs::msg::String>("platform/cmd", 10);%s
}
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Bridge>("bridge"));
}
"""


def _extract(write_tree, default: str, extra: str = ""):
    root = write_tree({
        "bridge/package.xml": package_xml("bridge", "ament_cmake"),
        "bridge/include/bridge/bridge.hpp": HEADER,
        "bridge/src/main.cpp": SOURCE % (default, extra),
    })
    return extract_cpp([str(root / "bridge/src/main.cpp")], scan([str(root)]), cache_dir=None)


def test_a_default_argument_added_on_the_definition_hides_no_call(write_tree) -> None:
    result = _extract(write_tree, ' = "bridge_default"')
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "platform/cmd")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_PARSE_ERROR" in codes  # clang's error is still said
    assert "CPP_ERROR_NEAR_CALL" not in codes, result.diagnostics


def test_an_error_that_may_drop_code_beside_a_call_is_said(write_tree) -> None:
    result = _extract(write_tree, "", "\n  undeclared_helper(pub_);")
    assert "CPP_ERROR_NEAR_CALL" in [d.code for d in result.diagnostics]
