"""A constructor that another class's registration alone calls runs in that class's node,
not in this one. ouster_ros' OusterSensorNodeBase makes the client ``name +
"/change_state"`` of the node name its constructor is given; OusterDriver (a component)
is built by ``OusterSensor("os_driver", options)``, and its files register OusterSensor
too, whose ``OusterSensor(options) : OusterSensor("os_sensor", options)`` only a
container that loads OusterSensor calls, as a node of its own. The jazzy interface
model's OusterDriver was a client of ``os_sensor/change_state`` beside its own
``os_driver/change_state``: lexus_bringup's os_driver had a client with no server."""

from __future__ import annotations

import pytest

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """
#pragma once
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include <lifecycle_msgs/srv/change_state.hpp>
namespace os {
class Base : public rclcpp_lifecycle::LifecycleNode {
 public:
  Base(const std::string& name, const rclcpp::NodeOptions& options);
 protected:
  std::shared_ptr<rclcpp::Client<lifecycle_msgs::srv::ChangeState>> client_;
};
class Sensor : public Base {
 public:
  Sensor(const std::string& name, const rclcpp::NodeOptions& options);
  explicit Sensor(const rclcpp::NodeOptions& options);
};
}
"""

BASE = """
#include "os/base.h"
using namespace std::string_literals;
namespace os {
Base::Base(const std::string& name, const rclcpp::NodeOptions& options)
: rclcpp_lifecycle::LifecycleNode(name, options),
  client_{create_client<lifecycle_msgs::srv::ChangeState>(name + "/change_state"s)} {}
}
"""

SENSOR = """
#include "os/base.h"
#include <rclcpp_components/register_node_macro.hpp>
namespace os {
Sensor::Sensor(const std::string& name, const rclcpp::NodeOptions& options)
: Base(name, options) {}
Sensor::Sensor(const rclcpp::NodeOptions& options) : Sensor("os_sensor", options) {}
}
RCLCPP_COMPONENTS_REGISTER_NODE(os::Sensor)
"""

DRIVER = """
#include "os/base.h"
#include <rclcpp_components/register_node_macro.hpp>
namespace os {
class Driver : public Sensor {
 public:
  explicit Driver(const rclcpp::NodeOptions& options) : Sensor("os_driver", options) {}
};
}
RCLCPP_COMPONENTS_REGISTER_NODE(os::Driver)
"""


@pytest.mark.parametrize(("entry", "clients"), [
    ("os::Driver", ["os_driver/change_state"]),
    # no class it runs as: what a loader builds is not known, both stay
    (None, ["os_driver/change_state", "os_sensor/change_state"]),
])
def test_a_registered_class_builds_its_own_node(write_tree, entry: str | None,
                                               clients: list[str]) -> None:
    root = write_tree({"os/package.xml": package_xml("os", "ament_cmake"),
                       "os/include/os/base.h": HEADER, "os/src/base.cpp": BASE,
                       "os/src/sensor.cpp": SENSOR, "os/src/driver.cpp": DRIVER})
    sources = [str(root / "os" / "src" / name) for name in ("driver.cpp", "sensor.cpp", "base.cpp")]
    result = extract_cpp(sources, scan([str(root)]), cache_dir=None,
                         include_dirs=[str(root / "os" / "include")], entry=entry)
    assert sorted(c.name for c in result.calls if c.kind == "client") == clients
