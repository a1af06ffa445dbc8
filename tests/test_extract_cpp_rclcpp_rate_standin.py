"""rclcpp's rate stand-in (reachy2_core's gazebo_mimic plugin makes its loop rate with
``rclcpp::Rate::make_shared(1.0 / step)`` and keeps a ``rclcpp::Rate::SharedPtr``): rclcpp
declares the smart pointer aliases on its rates (humble's ``GenericRate``, jazzy's
``Rate``), and jazzy's takes a clock (``rclcpp::Rate rate(10.0, node->get_clock())``);
the stand-in had none of these, so the function that makes the rate was a C++ error
and the node's calls there were taken as possibly missing (CPP_NODE_PARTIAL)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

class Looper {
public:
  void start(rclcpp::Node::SharedPtr node, double step) {
    loop_rate_ = rclcpp::Rate::make_shared(1.0 / step);
    rclcpp::Rate clocked(10.0, node->get_clock());
    rclcpp::Rate periodic(rclcpp::Duration::from_seconds(0.1), node->get_clock());
    rclcpp::GenericRate<std::chrono::steady_clock>::SharedPtr generic =
        std::make_shared<rclcpp::GenericRate<std::chrono::steady_clock>>(5.0);
    pub_ = node->create_publisher<std_msgs::msg::String>("out", 10);
    clocked.sleep();
    generic->sleep();
  }
private:
  rclcpp::Rate::SharedPtr loop_rate_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("node");
  Looper looper;
  looper.start(node, 0.001);
  rclcpp::spin(node);
}
"""


def test_rates_have_their_smart_pointers_and_clocks(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("node", "ament_cmake"))
    source = tmp_path / "node.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="jazzy")
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED",
                          "CPP_NODE_PARTIAL")] == []
    assert [(c.kind, c.name) for c in result.calls if c.name == "out"] == [("publish", "out")]
