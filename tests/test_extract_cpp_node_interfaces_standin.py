"""rclcpp's ``node_interfaces::NodeInterfaces<...>`` (Iron and later): nova's arm
kinematics plugins and controllers (Jazzy) take the node as
``NodeInterfaces<NodeBaseInterface, NodeLoggingInterface, NodeParametersInterface>``
(kinematics_base.hpp:31) and read their parameters through its
``get_node_parameters_interface()`` and ``get<...>()``; the rclcpp stand-in had no such
class, so every unit that includes the header was a C++ error near the ROS calls and
eight nodes partial. Humble's rclcpp has no NodeInterfaces: there it stays an error,
as the compiler says."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp/node_interfaces/node_interfaces.hpp>
#include <std_msgs/msg/string.hpp>

namespace arm
{
using Interfaces = rclcpp::node_interfaces::NodeInterfaces<
  rclcpp::node_interfaces::NodeBaseInterface,
  rclcpp::node_interfaces::NodeParametersInterface>;

class Params
{
public:
  explicit Params(Interfaces node)
  {
    auto params = node.get_node_parameters_interface();
    params->declare_parameter("base_link", rclcpp::ParameterValue(std::string("base")));
    node.get<rclcpp::node_interfaces::NodeParametersInterface>()->declare_parameter(
      "tip_link", rclcpp::ParameterValue(std::string("tip")));
  }
};

class Arm : public rclcpp::Node
{
public:
  Arm()
  : Node("arm"), params_(*this)
  {
    pub_ = create_publisher<std_msgs::msg::String>("arm_state", 10);
  }

private:
  Params params_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
}  // namespace arm

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<arm::Arm>());
  return 0;
}
"""

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(pkg)
find_package(rclcpp REQUIRED)
add_executable(arm src/arm.cpp)
"""


def _run(write_tree, distro: str):
    root = write_tree({"pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "pkg/CMakeLists.txt": CMAKE,
                       "pkg/src/arm.cpp": SOURCE})
    return extract_cpp([str(root / "pkg" / "src" / "arm.cpp")], scan([str(root)]),
                       cache_dir=None, distro=distro)


def _errors(result) -> list[str]:
    return [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")]


def test_node_interfaces_in_jazzy(write_tree) -> None:
    result = _run(write_tree, "jazzy")
    assert _errors(result) == []
    assert [d.message for d in result.diagnostics if d.code == "CPP_NODE_TO_UNKNOWN"] == []
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("declare", "base_link"), ("declare", "tip_link"), ("publish", "arm_state")]


def test_no_node_interfaces_in_humble(write_tree) -> None:
    result = _run(write_tree, "humble")
    assert _errors(result) != []
    assert any("rclcpp::node_interfaces::NodeInterfaces" in d.message
               for d in result.diagnostics if d.code == "CPP_NAMES_DECLARED")
