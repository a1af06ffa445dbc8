"""A class template whose constructor initialises a base class template with its own
template parameter, whose constructor makes the ROS call (turtlebot4_node's
``Turtlebot4Service<ServiceT>(nh, service, timeout) : Turtlebot4BaseService<ServiceT>(
nh, service, timeout)``, whose body calls ``nh_->create_client<ServiceT>(service)``):
the construction's name and type reach the call. The node's six service clients were
missed (``call_sites.base_initialisers``, ``wrappers``)."""

from __future__ import annotations

import pytest
from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

WRAPPER = """\
#pragma once
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
namespace tb {
template<typename ServiceT>
class BaseService {
public:
  BaseService(std::shared_ptr<rclcpp::Node> & nh, std::string service, uint32_t timeout)
  : nh_(nh), service_(service), timeout_(timeout) {
    client_ = nh_->create_client<ServiceT>(service);
  }
  virtual ~BaseService() {}
protected:
  std::shared_ptr<rclcpp::Node> nh_;
  std::string service_;
  uint32_t timeout_;
  typename rclcpp::Client<ServiceT>::SharedPtr client_;
};
template<typename %s>
class Service : public BaseService<ServiceT> {
public:
  Service(std::shared_ptr<rclcpp::Node> & nh, std::string service, uint32_t timeout = 30)
  : BaseService<ServiceT>(nh, service, timeout) {}
};
}  // namespace tb
"""
NODE = """\
#include <memory>
#include <std_srvs/srv/trigger.hpp>
#include "tb/service.hpp"
class Robot : public rclcpp::Node {
public:
  Robot() : Node("robot") {}
  void init() {
    %s
  }
  std::shared_ptr<rclcpp::Node> node_handle_;
  std::unique_ptr<tb::Service<%s>> client_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto robot = std::make_shared<Robot>();
  robot->init();
  rclcpp::spin(robot);
}
"""
TRIGGER = "std_srvs::srv::Trigger"


def _calls(write_tree, parameters: str, arguments: str, body: str):
    root = write_tree({
        "tb/package.xml": package_xml("tb", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend><depend>std_srvs</depend></package>"),
        "tb/include/tb/service.hpp": WRAPPER % parameters,
        "tb/src/robot.cpp": NODE % (body, arguments)})
    result = extract_cpp([str(root / "tb" / "src" / "robot.cpp")],
                         scan([str(root)], {"ROS_VERSION": "2"}), cache_dir=None,
                         distro="humble")
    return [(c.kind, c.name, c.type) for c in result.calls]


@pytest.mark.parametrize("body", [
    f'client_ = std::make_unique<tb::Service<{TRIGGER}>>(node_handle_, "e_stop");',
    f'tb::Service<{TRIGGER}> once(node_handle_, "e_stop");',
])
def test_the_base_template_s_call_has_the_construction_s_name_and_type(
        write_tree, body) -> None:
    assert _calls(write_tree, "ServiceT", TRIGGER, body) == [
        ("client", "e_stop", "std_srvs/srv/Trigger")]


def test_a_base_named_with_other_arguments_gives_no_type_of_the_construction(
        write_tree) -> None:
    # ``Service<Extra, ServiceT> : BaseService<ServiceT>``: the construction's first
    # argument is not the base's; no call typed ``int`` (not lifted, as before)
    body = f'client_ = std::make_unique<tb::Service<int, {TRIGGER}>>(node_handle_, "e_stop");'
    assert not [c for c in _calls(write_tree, "Extra, typename ServiceT", f"int, {TRIGGER}",
                                  body) if c[2] == "int"]
