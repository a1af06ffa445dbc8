"""rclcpp's ``declare_parameter(name, default)`` gives ``get<T>()`` of the value: for a
default ``std::vector<int>`` a ``std::vector<int64_t>``, for ``std::vector<float>`` a
``std::vector<double>`` (spot_ros2's wiggle_arm sets its ``std::vector<int64_t>`` member
from ``declare_parameter("joints_to_wiggle", std::vector<int>{16, 18})``). The stand-in
gave the default's own type: a C++ error in the constructor that makes the node's calls
"maybe incomplete" (CPP_NODE_PARTIAL)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <cstdint>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64_multi_array.hpp>

class Wiggle : public rclcpp::Node {
 public:
  Wiggle() : Node("wiggle") {
    joints_ = declare_parameter("joints", std::vector<int>{16, 18});
    offsets_ = declare_parameter("offsets", std::vector<float>{1.0f, -0.5f});
    const int rate = declare_parameter("rate", 50);
    pub_ = create_publisher<std_msgs::msg::Float64MultiArray>("commands", rate);
  }

 private:
  std::vector<int64_t> joints_;
  std::vector<double> offsets_;
  rclcpp::Publisher<std_msgs::msg::Float64MultiArray>::SharedPtr pub_;
};

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Wiggle>());
  return 0;
}
"""


def test_a_vector_default_declares_a_vector_of_the_parameter_type(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("wiggle", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"))
    source = tmp_path / "wiggle.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [
        ("declare", "joints"), ("declare", "offsets"), ("declare", "rate"),
        ("publish", "commands")]
    assert [d.code for d in result.diagnostics if d.code.startswith("CPP_")
            and d.code not in ("CPP_NAMES_DECLARED", "CPP_MESSAGE_UNKNOWN")] == []
