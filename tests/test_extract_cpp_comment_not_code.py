"""The names the permissive declarations spread over whole files (``synthesis.Names``:
the qualified uses of an unknown scope, the calls of a missing C library's functions,
the value arguments of a declared template) are read in code only, not in comments or
string literals. mqtt_client's header for <mqtt/async_client.h> was missing, so
``mqtt_*(`` names a C library's function; a comment in its node's setup reads ``See
https://github.com/.../mqtt_client (v2.4.1)``, which declared ``mqtt_client`` a global
value: its own namespace ``mqtt_client`` was then a redefinition, the node's class was
invalid, and 20 parameter declarations were lost (CPP_NODE_PARTIAL)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp, synthesis
from haros_arch.workspace import scan

SOURCE = """\
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <vendorlink/async_client.h>

namespace vendorlink_bridge {

class Bridge : public rclcpp::Node, public virtual vendorlink::callback {
 public:
  Bridge();

 private:
  void setup();
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};

}  // namespace vendorlink_bridge

namespace vendorlink_bridge {

Bridge::Bridge() : Node("bridge") {
  declare_parameter("broker.host", rclcpp::ParameterType::PARAMETER_STRING);
  setup();
}

void Bridge::setup() {
  // publishers first: see https://example.org/vendorlink_bridge (v2.4.1) for the race
  pub_ = create_publisher<std_msgs::msg::String>("~/out", 10);
  RCLCPP_INFO(get_logger(), "vendorlink_version (%s)", "1");
}

}  // namespace vendorlink_bridge
"""


def test_a_word_in_a_comment_is_not_declared(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("bridge", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"))
    source = tmp_path / "bridge.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("declare", "broker.host", "str"), ("publish", "~out", "std_msgs/msg/String")]
    assert [d.code for d in result.diagnostics if d.code.startswith("CPP_")
            and d.code not in ("CPP_NAMES_DECLARED", "CPP_INCLUDE_MISSING")] == []


def test_code_only_blanks_comments_and_literals_in_place() -> None:
    text = (b'f("a // b"); // c (d)\r\n/* e\n f */ g(\'"\', "h\\"i");\n'
            b"x = 1; /* open")
    code = synthesis.code_only(text)
    assert len(code) == len(text)
    assert code == (b'f("      ");         \r\n    \n      g(\' \', "    ");\n'
                    b"x = 1;        ")
