"""A ROS 2 node of the workspace that makes ros2_control's controller manager itself
(KUKA's kuka_drivers_core control_node: ``std::make_shared<controller_manager::
ControllerManager>(executor, "controller_manager")``, then its own subscription and
parameter reads on it), with ros2_control installed, not as sources. Before, the missing
header left the class unknown: the node was partial by the parse error and unnamed
(``/?``), and the spawners' controllers were loaded into nothing."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
#include "controller_manager/controller_manager.hpp"
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/bool.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto executor = std::make_shared<rclcpp::executors::MultiThreadedExecutor>();
  auto manager = std::make_shared<controller_manager::ControllerManager>(executor, NAME);
  auto sub = manager->create_subscription<std_msgs::msg::Bool>(
    "robot_manager/is_configured", 1, [](std_msgs::msg::Bool::SharedPtr) {});
  bool lock = manager->get_parameter_or<bool>("lock_memory", true);
  executor->add_node(manager);
  executor->spin();
  return 0;
}
"""


def extract(write_tree, name: str):
    root = write_tree({
        "src/robot/package.xml": package_xml("robot", "ament_cmake"),
        "src/robot/src/control_node.cpp": SOURCE.replace(", NAME", name)})
    return extract_cpp([str(root / "src/robot/src/control_node.cpp")], scan([str(root)]),
                       cache_dir=None)


def test_the_manager_is_the_node_named_by_its_constructor(write_tree) -> None:
    result = extract(write_tree, ', "cm"')
    assert result.rosname == "cm"
    servers = [(c.name, c.type) for c in result.calls if c.kind == "server"]
    assert ("~load_controller", "controller_manager_msgs/srv/LoadController") in servers
    assert ("~switch_controller", "controller_manager_msgs/srv/SwitchController") in servers
    assert len(servers) == 10
    assert [(c.kind, c.name) for c in result.calls if c.kind != "server"] == [
        ("subscribe", "robot_manager/is_configured"), ("read", "lock_memory")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_PARSE_ERROR" not in codes and "CPP_INCLUDE_MISSING" not in codes
    # what the manager makes beyond its services is not read: the node is partial
    (unread,) = [d for d in result.diagnostics if d.code == "CPP_NODE_UNREAD"]
    assert "controller_manager::ControllerManager" in unread.message
    assert unread.location.line == 9


def test_a_manager_left_at_its_default_name_is_named_by_the_launch(write_tree) -> None:
    result = extract(write_tree, "")
    assert result.rosname is None  # "controller_manager" by default: not written here
    assert any(c.name == "~load_controller" for c in result.calls)


SIMULATED = """
#include "controller_manager/controller_manager.hpp"
#include "hardware_interface/resource_manager.hpp"
#include "rclcpp/rclcpp.hpp"

void start(std::shared_ptr<rclcpp::Executor> executor, const std::string & urdf)
{
  MAKE;
  executor->add_node(manager);
}
"""


def extract_made(write_tree, make: str):
    root = write_tree({
        "src/sim/package.xml": package_xml("sim", "ament_cmake"),
        "src/sim/src/plugin.cpp": SIMULATED.replace("MAKE", make)})
    return extract_cpp([str(root / "src/sim/src/plugin.cpp")], scan([str(root)]),
                       cache_dir=None)


def test_a_manager_given_a_resource_manager_is_named_by_its_third_argument(
        write_tree) -> None:
    """gazebo_ros2_control's plugin: ``ControllerManager(std::move(resource_manager),
    executor, "controller_manager", namespace)``; the stand-in's one constructor took
    the name from the second argument (it did not parse, so the node was partial)."""
    result = extract_made(write_tree, (
        "auto resources = std::make_unique<hardware_interface::ResourceManager>();\n"
        "  std::shared_ptr<controller_manager::ControllerManager> manager(\n"
        "    new controller_manager::ControllerManager(std::move(resources), executor,\n"
        "      \"sim_manager\", \"robot\"))"))
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []
    assert result.rosname == "/robot/sim_manager"
    assert any(c.name == "~load_controller" for c in result.calls)


def test_a_manager_given_the_urdf_is_named_by_its_fourth_argument(write_tree) -> None:
    """Jazzy's ``ControllerManager(executor, urdf, activate_all_hw_components, name)``,
    made by ``std::make_shared``: ros2_control_node's constructor's places would name
    the node by the URDF and put it in the namespace ``true``."""
    result = extract_made(write_tree, (
        "auto manager = std::make_shared<controller_manager::ControllerManager>(\n"
        "    executor, urdf, true, \"described_manager\")"))
    assert result.rosname == "described_manager"
    assert any(c.name == "~switch_controller" for c in result.calls)
