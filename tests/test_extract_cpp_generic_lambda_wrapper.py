"""A generic lambda that wraps a ROS call (MoveIt's planning scene monitor declares its
parameters through ``[this](const std::string& name, auto value, const std::string&
description) { ...; return pnode_->declare_parameter(name, value, desc); }``): its calls
are made where the lambda is called, and the call in its body, which clang leaves
dependent, is no ROS call the parse missed. With another error in the unit, the body's
site was ``CPP_CALL_MISSED`` and every node building the monitor was partial."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <rclcpp/rclcpp.hpp>
#include <rcl_interfaces/msg/parameter_descriptor.hpp>
#include <string>

class Monitor
{
public:
  explicit Monitor(const rclcpp::Node::SharedPtr & node) : pnode_(node)
  {
    auto declare_parameter = [this](const std::string & name, %s value,
                                    const std::string & description) -> auto
    {
      rcl_interfaces::msg::ParameterDescriptor desc;
      desc.set__description(description);
      return pnode_->declare_parameter(name, value, desc);
    };
    bool publish_scene = false;
    publish_scene = declare_parameter("publish_planning_scene", publish_scene, "Publish");
    double hz = 4.0;
    hz = declare_parameter("publish_planning_scene_hz", hz, "Rate");
  }

private:
  rclcpp::Node::SharedPtr pnode_;
};

int helper() { return undeclared_function(3); }

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("monitor");
  Monitor monitor(node);
  rclcpp::spin(node);
}
"""


def _extract(tmp_path, parameter_type: str):
    (tmp_path / "package.xml").write_text(package_xml("monitor", "ament_cmake"))
    source = tmp_path / "monitor.cpp"
    source.write_text(SOURCE % parameter_type)
    return extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None, distro="jazzy")


def test_a_generic_lambda_wrapper_hides_no_call(tmp_path) -> None:
    result = _extract(tmp_path, "auto")
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("declare", "publish_planning_scene", "bool"),
        ("declare", "publish_planning_scene_hz", "double")]
    assert [d.message for d in result.diagnostics if d.code == "CPP_CALL_MISSED"] == []


def test_the_same_lambda_with_a_plain_parameter(tmp_path) -> None:
    result = _extract(tmp_path, "double")
    assert sorted(c.name for c in result.calls) == ["publish_planning_scene",
                                                    "publish_planning_scene_hz"]
    assert [d.message for d in result.diagnostics if d.code == "CPP_CALL_MISSED"] == []
