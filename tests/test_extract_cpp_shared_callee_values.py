"""A string parameter of a function that the node's other files may call too (declared
in a header, external linkage) takes its value from the calls of every file, not from
the calls of the one file that defines it. ouster_ros' ``OusterSensor(name, options)``
is defined in os_sensor_node.cpp, whose other constructor delegates to it with
"os_sensor"; os_driver_node.cpp's ``OusterDriver`` calls it with "os_driver". The
os_driver component was named ``os_sensor``: its own file's one call agreed with itself."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HEADER = """\
#pragma once
#include <string>
#include <rclcpp/rclcpp.hpp>
namespace lidar {
class Sensor : public rclcpp::Node {
public:
  Sensor(const std::string & name, const rclcpp::NodeOptions & options);
  explicit Sensor(const rclcpp::NodeOptions & options);
};
}  // namespace lidar
"""
SENSOR = """\
#include "lidar/sensor.hpp"
namespace lidar {
Sensor::Sensor(const std::string & name, const rclcpp::NodeOptions & options)
: rclcpp::Node(name, options) {}
Sensor::Sensor(const rclcpp::NodeOptions & options) : Sensor("sensor", options) {}
}  // namespace lidar
"""
DRIVER = """\
#include "lidar/sensor.hpp"
namespace lidar {
class Driver : public Sensor {
public:
  explicit Driver(const rclcpp::NodeOptions & options) : Sensor("%s", options) {}
};
}  // namespace lidar
"""
# a helper of one file, not declared in a header: no other file can call it
LOCAL = """\
#include <string>
#include <rclcpp/rclcpp.hpp>
namespace {
std::shared_ptr<rclcpp::Node> make(const std::string & name) {
  return std::make_shared<rclcpp::Node>(name);
}
}  // namespace
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(make("solo"));
}
"""


def _tree(write_tree, driver_name: str = "driver"):
    return write_tree({"lidar/package.xml": package_xml("lidar", "ament_cmake").replace(
                           "</package>", "<depend>rclcpp</depend></package>"),
                       "lidar/include/lidar/sensor.hpp": HEADER,
                       "lidar/src/sensor.cpp": SENSOR,
                       "lidar/src/driver.cpp": DRIVER % driver_name,
                       "lidar/src/local.cpp": LOCAL})


def _rosname(root, *files: str) -> str | None:
    sources = [str(root / "lidar" / "src" / f) for f in files]
    return extract_cpp(sources, scan([str(root)]), cache_dir=None).rosname


def test_the_defining_file_alone_gives_its_own_value(write_tree) -> None:
    assert _rosname(_tree(write_tree), "sensor.cpp") == "sensor"


def test_another_file_calling_it_otherwise_is_not_overruled(write_tree) -> None:
    # the two files pass two names: which one the component runs is not "sensor" alone
    assert _rosname(_tree(write_tree), "sensor.cpp", "driver.cpp") != "sensor"


def test_files_that_agree_still_give_the_value(write_tree) -> None:
    assert _rosname(_tree(write_tree, "sensor"), "sensor.cpp", "driver.cpp") == "sensor"


def test_a_function_only_its_file_can_call_takes_its_calls_value(write_tree) -> None:
    assert _rosname(_tree(write_tree), "local.cpp") == "solo"


ROUTER = """\
#pragma once
#include <string>
#include <rclcpp/rclcpp.hpp>
namespace hub {
class Router : public rclcpp::Node {
public:
  explicit Router(const std::string & name = "router")
  : Router(rclcpp::NodeOptions(), name) {}
  explicit Router(const rclcpp::NodeOptions & options, const std::string & name = "router");
};
}  // namespace hub
"""
ROUTER_SOURCE = """\
#include "hub/router.hpp"
namespace hub {
Router::Router(const rclcpp::NodeOptions & options, const std::string & name)
: rclcpp::Node(name, options) {}
}  // namespace hub
"""
HUB_MAIN = """\
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include "hub/router.hpp"
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::NodeOptions options;
  auto node = std::make_shared<rclcpp::Node>("hub_node", options);
  auto router = std::make_shared<hub::Router>(options, "hub_router");
  rclcpp::executors::MultiThreadedExecutor exec;
  exec.add_node(node);
  exec.add_node(router);
  exec.spin();
}
"""


def test_a_delegating_constructor_nobody_calls_gives_no_name(write_tree) -> None:
    """mavros' node process: ``Router(options, "mavros_router")`` in main, a header's
    ``Router(name) : Router(NodeOptions(), name)`` that nothing calls, and the constructor
    itself defined in the router's file. The router's name was ``?``: the delegation
    passes on its own parameter, which nobody gives a value."""
    root = write_tree({"hub/package.xml": package_xml("hub", "ament_cmake").replace(
                           "</package>", "<depend>rclcpp</depend></package>"),
                       "hub/include/hub/router.hpp": ROUTER,
                       "hub/src/router.cpp": ROUTER_SOURCE,
                       "hub/src/main.cpp": HUB_MAIN})
    sources = [str(root / "hub" / "src" / f) for f in ("main.cpp", "router.cpp")]
    result = extract_cpp(sources, scan([str(root)]), cache_dir=None)
    assert sorted(result.rosnames) == ["hub_node", "hub_router"]


CONFIG_HEADER = """\
#pragma once
#include <string>
#include <ros/ros.h>
namespace cfg {
double readValue(const ros::NodeHandle & nh, const std::string & field);
double readScaled(const ros::NodeHandle & nh, const std::string & field);
}  // namespace cfg
"""
CONFIG_SOURCE = """\
#include "cfg/config.h"
namespace cfg {
double readValue(const ros::NodeHandle & nh, const std::string & field) {
  double value = 0.0;
  nh.getParam(field, value);
  return value;
}
double readScaled(const ros::NodeHandle & nh, const std::string & field) {
  return 2.0 * readValue(nh, field);
}
}  // namespace cfg
"""
CONFIG_MAIN = """\
#include "cfg/config.h"
int main(int argc, char ** argv) {
  ros::init(argc, argv, "tracker");
  ros::NodeHandle nh("~");
  double gain = cfg::readValue(nh, "gain");
  double offset = cfg::readScaled(nh, "offset");
  return 0;
}
"""


def test_a_free_wrapper_its_own_file_calls_takes_every_files_names(write_tree) -> None:
    """msckf_vio's ``utils::getTransformCV(nh, field)``, a wrapper of ``getParam`` defined
    in utils.cpp, is called there by ``getTransformEigen(nh, field)`` and in
    image_processor.cpp with "cam0/T_cam_imu": the image processor's reads of its
    transforms were lost, as the wrapper's calls were named at its own file's call site
    only (named by getTransformEigen's callers: none in that node)."""
    root = write_tree({"cfg/package.xml": package_xml("cfg", "catkin").replace(
                           "</package>", "<depend>roscpp</depend></package>"),
                       "cfg/include/cfg/config.h": CONFIG_HEADER,
                       "cfg/src/config.cpp": CONFIG_SOURCE,
                       "cfg/src/main.cpp": CONFIG_MAIN})
    sources = [str(root / "cfg" / "src" / f) for f in ("main.cpp", "config.cpp")]
    result = extract_cpp(sources, scan([str(root)]), cache_dir=None)
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("read", "~gain"), ("read", "~offset")]
