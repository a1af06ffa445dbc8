"""A character literal appended to a name (``ns + '/' + "state"``, ``name + '.' + part``):
std::string's ``operator+(string, char)`` appends that one character, so the name is known
where its other parts are. It was read as an unknown part, `arm?state` for `arm/state`, and
a parameter helper's `ring?.id` swallowed the dot that separates the ring's name from the
sensor's (EduArt's edu_robot: ``SensorTofHardware::get_parameter(name + '.' + sensor_name,
...)``)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HELPER = r"""
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
inline int get_one(const std::string & name, rclcpp::Node & node)
{
  node.declare_parameter<int>(name + ".id", 1);
  return node.get_parameter(name + ".id").as_int();
}
inline void get_ring(const std::string & name, rclcpp::Node & node)
{
  get_one(name + '.' + "front", node);
  node.declare_parameter<int>(name + '.' + "rate", 1);
}
"""

NODE = r"""
#include "helper.hpp"
class Bot : public rclcpp::Node {
public:
  Bot() : rclcpp::Node("bot") {
    std::string ns = "arm";
    pub_ = create_publisher<std_msgs::msg::String>(ns + '/' + "state", 10);
    get_ring("ring", *this);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Bot>());
}
"""


def test_a_character_appended_to_a_name_is_that_character(write_tree) -> None:
    root = write_tree({"bot/package.xml": package_xml("bot", "ament_cmake"),
                       "bot/src/helper.hpp": HELPER, "bot/src/bot.cpp": NODE})
    result = extract_cpp([str(root / "bot" / "src" / "bot.cpp")], scan([str(root)]),
                         cache_dir=None)
    names = sorted({(c.kind, c.name) for c in result.calls})
    assert names == [("declare", "ring.front.id"), ("declare", "ring.rate"),
                     ("publish", "arm/state"), ("read", "ring.front.id")]
    assert not [d for d in result.diagnostics if d.code == "CPP_DYNAMIC_NAME"]


def test_only_a_plain_character_is_known() -> None:
    from haros_arch.extract.cpp.values import char_literal
    assert [char_literal(s) for s in ("'.'", "'/'", "'\\n'", "'\\''")] == [
        ".", "/", "\n", "'"]
    assert [char_literal(s) for s in ("'ab'", "L'x'", "'\\x41'", "''", '"a"')] == [
        None, None, None, None, None]
