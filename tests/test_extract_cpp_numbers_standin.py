"""C++20's <numbers>: a ROS 2 node that converts its angle parameters with
``std::numbers::pi`` (kyubic_ros' localization components, their CMakeLists asking for
C++20) had no such header among the std stand-ins: the include was an empty stand-in
(CPP_INCLUDE_MISSING) and the constructor that makes the publishers a C++ error, so
the node was partial."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
#include <numbers>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>

class Turner : public rclcpp::Node
{
public:
  Turner() : Node("turner")
  {
    double degrees = declare_parameter("yaw_offset_deg", 90.0);
    offset_ = degrees * std::numbers::pi / 180.0;
    float half = std::numbers::pi_v<float> / 2.0f + static_cast<float>(std::numbers::sqrt2);
    (void)half;
    pub_ = create_publisher<std_msgs::msg::Float64>("yaw", 10);
  }

private:
  double offset_;
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Turner>());
}
"""


def test_std_numbers_constants_parse(write_tree) -> None:
    root = write_tree({"pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "pkg/src/node.cpp": SOURCE})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    codes = [d.code for d in result.diagnostics]
    assert "CPP_INCLUDE_MISSING" not in codes
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("declare", "yaw_offset_deg"), ("publish", "yaw")]
