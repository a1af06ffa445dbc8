"""A message's class template by its generated name (bench/README, helper surveyP): the
generators make each message struct from a class template named with a trailing ``_``
whose argument is the allocator (rosidl_generator_cpp's ``Name_<ContainerAllocator>``,
gencpp's the same), and code names it so (the Omron AMR's goals_marker.cpp declares a
function taking ``std::shared_ptr<om_aiv_msg::srv::ArclApi_Request_<std::allocator<void>>>&``).
The synthesised headers declared only ``Name``: the parameter's type was unknown, the call
of that function a C++ error in ``main``, which calls the ROS API, and the node partial."""

from __future__ import annotations

import pytest
from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

ERRORS = ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED", "CPP_MESSAGE_UNKNOWN")

ROS2 = """#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <arm/srv/command.hpp>
#include <arm/action/move.hpp>

void ask(std::shared_ptr<arm::srv::Command_Request_<std::allocator<void>>>& request,
         const std_msgs::msg::String_<std::allocator<void>>& text,
         arm::action::Move_Goal_<std::allocator<void>> goal);

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("node");
  auto request = std::make_shared<arm::srv::Command::Request>();
  std_msgs::msg::String text;
  arm::action::Move::Goal goal;
  ask(request, text, goal);
  auto pub = node->create_publisher<std_msgs::msg::String>("out", 10);
  rclcpp::spin(node);
}
"""

ROS1 = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include <arm/Command.h>
#include <arm/MoveAction.h>

void ask(arm::CommandRequest_<std::allocator<void> >& request,
         const std_msgs::String_<std::allocator<void> >::ConstPtr& text,
         const arm::MoveGoal_<std::allocator<void> >& goal);

int main(int argc, char** argv) {
  ros::init(argc, argv, "node");
  ros::NodeHandle nh;
  arm::Command::Request request;
  std_msgs::String::ConstPtr text;
  arm::MoveGoal goal;
  ask(request, text, goal);
  ros::Publisher pub = nh.advertise<std_msgs::String>("out", 1);
}
"""


@pytest.mark.parametrize(("distro", "build", "source"), [
    ("jazzy", "ament_cmake", ROS2), ("noetic", "catkin", ROS1)])
def test_a_message_named_by_its_class_template(tmp_path, distro: str, build: str,
                                               source: str) -> None:
    arm = tmp_path / "arm"
    (arm / "srv").mkdir(parents=True)
    (arm / "action").mkdir()
    (arm / "package.xml").write_text(package_xml("arm", build))
    (arm / "srv" / "Command.srv").write_text("string command\n---\nstring response\n")
    (arm / "action" / "Move.action").write_text("float64 x\n---\nbool ok\n---\nfloat64 left\n")
    node = tmp_path / "node"
    node.mkdir()
    (node / "package.xml").write_text(package_xml("node", build))
    (node / "node.cpp").write_text(source)
    result = extract_cpp([str(node / "node.cpp")], scan([str(tmp_path)]), cache_dir=None,
                         distro=distro)
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ERRORS] == []
    assert [(c.kind, c.name) for c in result.calls if c.name == "out"] == [("publish", "out")]
