"""An action client a class template makes, one per type its constructions give it.

MoveIt 2's ``ActionBasedControllerHandle<T>`` (moveit_simple_controller_manager's
action_based_controller_handle.hpp:88 at moveit2 4d841063) makes its client with
``rclcpp_action::create_client<T>(node, getActionName())``; clang leaves that call
unresolved (``T`` is the template's). The extractor took it for rclcpp's node method
``create_client`` (a service client named by its first argument, the node: an empty
name), typed it ``?``, and kept one call for the three types the constructions give
``T`` (FollowJointTrajectory, GripperCommand, ParallelGripperCommand). A service client
a class template makes with ``node->template create_client<S>(name)`` is typed by its
constructions the same way (it was ``?``)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

HANDLES = r"""#include <memory>
#include <string>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_action/rclcpp_action.hpp>
#include <control_msgs/action/follow_joint_trajectory.hpp>
#include <control_msgs/action/gripper_command.hpp>
#include <example_interfaces/srv/trigger.hpp>

class HandleBase
{
public:
  explicit HandleBase(const std::string& name) : name_(name) {}
  virtual ~HandleBase() = default;
protected:
  std::string name_;
};

template <typename T>
class ActionHandle : public HandleBase
{
public:
  ActionHandle(const rclcpp::Node::SharedPtr& node, const std::string& name,
               const std::string& ns)
    : HandleBase(name), namespace_(ns)
  {
    client_ = rclcpp_action::create_client<T>(node, getActionName());
  }
  std::string getActionName() const { return name_ + "/" + namespace_; }
protected:
  typename rclcpp_action::Client<T>::SharedPtr client_;
  std::string namespace_;
};

class TrajectoryHandle : public ActionHandle<control_msgs::action::FollowJointTrajectory>
{
public:
  TrajectoryHandle(const rclcpp::Node::SharedPtr& node, const std::string& name,
                   const std::string& ns)
    : ActionHandle<control_msgs::action::FollowJointTrajectory>(node, name, ns) {}
};

class GripperHandle : public ActionHandle<control_msgs::action::GripperCommand>
{
public:
  GripperHandle(const rclcpp::Node::SharedPtr& node, const std::string& name,
                const std::string& ns)
    : ActionHandle<control_msgs::action::GripperCommand>(node, name, ns) {}
};

template <typename S>
class ServiceHandle
{
public:
  explicit ServiceHandle(const rclcpp::Node::SharedPtr& node)
  {
    client_ = node->template create_client<S>("reset");
  }
  typename rclcpp::Client<S>::SharedPtr client_;
};
"""

MAIN = r"""#include "handles.hpp"

int main(int argc, char** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("manager");
  std::vector<std::shared_ptr<HandleBase>> handles;
  handles.push_back(std::make_shared<TrajectoryHandle>(node, "arm", "follow_joint_trajectory"));
  handles.push_back(std::make_shared<GripperHandle>(node, "hand", "gripper_cmd"));
  ServiceHandle<example_interfaces::srv::Trigger> reset(node);
  rclcpp::spin(node);
}
"""


def _package_xml() -> str:
    return package_xml("mgr", "ament_cmake").replace(
        "<export>", "<buildtool_depend>ament_cmake</buildtool_depend><depend>rclcpp"
        "</depend><depend>rclcpp_action</depend><depend>control_msgs</depend><depend>"
        "example_interfaces</depend><export>")


def test_a_class_templates_action_client_per_construction(write_tree) -> None:
    """(fails on main: one ``client`` named '' typed '?')"""
    root = write_tree({
        "src/mgr/package.xml": _package_xml(),
        "src/mgr/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.8)\nproject(mgr)\n"
            "find_package(ament_cmake REQUIRED)\nfind_package(rclcpp REQUIRED)\n"
            "find_package(rclcpp_action REQUIRED)\nfind_package(control_msgs REQUIRED)\n"
            "find_package(example_interfaces REQUIRED)\n"
            "add_executable(manager src/main.cpp)\n"
            "target_include_directories(manager PRIVATE include)\n"
            "ament_target_dependencies(manager rclcpp rclcpp_action control_msgs "
            "example_interfaces)\n"
            "install(TARGETS manager DESTINATION lib/${PROJECT_NAME})\nament_package()\n"),
        "src/mgr/include/handles.hpp": HANDLES,
        "src/mgr/src/main.cpp": MAIN,
        "project.yaml": "project: p\nworkspace: src\ndistro: jazzy\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (package,) = [p for p in model.packages if p.name == "mgr"]
    (node,) = package.nodes
    calls = sorted((c.kind, c.name, c.type) for c in node.calls
                   if c.kind in ("client", "action-client"))
    assert calls == [
        ("action-client", "arm/follow_joint_trajectory",
         "control_msgs/action/FollowJointTrajectory"),
        ("action-client", "hand/gripper_cmd", "control_msgs/action/GripperCommand"),
        # a guard: a node method of that name in a class template stays a service client
        ("client", "reset", "example_interfaces/srv/Trigger"),
    ]
