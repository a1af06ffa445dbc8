"""A helper of the unit that reads a ROS parameter into the variable its caller gives it
by non-const reference: the variable then holds that parameter, named by the caller's
argument. rm_engineer's config loaders call a generic lambda ``declare_get(name,
value)`` that declares and gets the parameter into ``value``, once per member of a
config struct the node publishes on (``config_.hfsm_intent_topic``): every topic of its
five nodes was ``?`` (unresolved-names), though the parameter and its default (the
member's initialiser) name it."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HEAD = """#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

struct Config {
  std::string out_topic{"/out_default"};
  std::string in_topic{"in_default"};
  int period{20};
  static Config Load(rclcpp::Node& node);
};
"""

TAIL = """
class Relay : public rclcpp::Node {
public:
  Relay() : rclcpp::Node("relay"), config_(Config::Load(*this)) {
    pub_ = create_publisher<std_msgs::msg::String>(config_.out_topic, 10);
    sub_ = create_subscription<std_msgs::msg::String>(
        config_.in_topic, 10, [](std_msgs::msg::String::SharedPtr) {});
  }
  Config config_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Relay>());
}
"""

HELPERS = {
    "generic lambda": """
inline Config Config::Load(rclcpp::Node& node) {
  Config cfg;
  auto declare_get = [&](const std::string& name, auto& value) {
    node.declare_parameter(name, value);
    node.get_parameter(name, value);
  };
  declare_get("out_topic", cfg.out_topic);
  declare_get("in_topic", cfg.in_topic);
  declare_get("period", cfg.period);
  return cfg;
}
""",
    "function": """
void declare_get(rclcpp::Node& node, const std::string& name, std::string& value) {
  node.declare_parameter(name, value);
  node.get_parameter(name, value);
}

inline Config Config::Load(rclcpp::Node& node) {
  Config cfg;
  declare_get(node, "out_topic", cfg.out_topic);
  declare_get(node, "in_topic", cfg.in_topic);
  return cfg;
}
""",
}


def test_a_member_a_helper_reads_a_parameter_into_names_the_topic(tmp_path) -> None:
    for kind, helper in HELPERS.items():
        folder = tmp_path / kind.replace(" ", "_")
        folder.mkdir()
        (folder / "package.xml").write_text(package_xml("node", "ament_cmake"))
        source = folder / "node.cpp"
        source.write_text(HEAD + helper + TAIL)
        result = extract_cpp([str(source)], scan([str(folder)]), cache_dir=None,
                             distro="jazzy")
        links = sorted((c.kind, c.name_param, c.name_default) for c in result.calls
                       if c.kind in ("publish", "subscribe"))
        assert links == [("publish", "out_topic", "/out_default"),
                         ("subscribe", "in_topic", "in_default")], kind
