"""A range-for over an object of a library the parse does not have (mrpt_map_server's
``for (const auto& [layerName, layerMap] : theMap_.layers)``, map_server_node.cpp:171)
was an error, "invalid range expression of type 'haros_any'", and the publishers made
in the loop's body were lost (5 create_publisher calls, CPP_CALL_MISSED). A permissive
object is now a range, by argument-dependent begin / end, and its elements bind as a
pair's do."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <vendor/maps.h>
class Server : public rclcpp::Node
{
public:
  Server() : rclcpp::Node("server")
  {
    for (const auto & [name, layer] : map_.layers) {
      pubs_[name] = create_publisher<std_msgs::msg::String>("layer/" + name, 1);
    }
    for (const auto & item : map_.items) {
      (void)item;
      other_ = create_publisher<std_msgs::msg::String>("items", 1);
    }
  }
  vendor::Map map_;
  std::map<std::string, rclcpp::Publisher<std_msgs::msg::String>::SharedPtr> pubs_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr other_;
};
"""


def test_a_range_for_over_an_unknown_library_s_object_keeps_its_calls(write_tree) -> None:
    root = write_tree({"srv/package.xml": package_xml("srv", "ament_cmake"),
                       "srv/src/server.cpp": NODE})
    result = extract_cpp([str(root / "srv" / "src" / "server.cpp")], scan([str(root)]),
                         cache_dir=None)
    # the layer's name is the library's value, unknown; the text before it is the
    # code's (test_extract_cpp_permissive_concatenation)
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "items"), ("publish", "layer/?")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_CALL_MISSED" not in codes and "CPP_ERROR_NEAR_CALL" not in codes


ELEMENT = """
#include <rclcpp/rclcpp.hpp>
#include <std_srvs/srv/trigger.hpp>
#include <variant>
#include <vendor/dashboard.h>
class Dashboard : public rclcpp::Node
{
public:
  Dashboard() : rclcpp::Node("dashboard")
  {
    srv_ = create_service<std_srvs::srv::Trigger>(
      "get_loaded_program",
      [this](const std::shared_ptr<std_srvs::srv::Trigger::Request>,
             std::shared_ptr<std_srvs::srv::Trigger::Response> resp) {
        vendor::Response answer = client_.call();
        resp->message = std::get<std::string>(answer.data.at("program_name"));
        resp->success = std::get<0>(answer.flags);
      });
  }
  vendor::Client client_;
  rclcpp::Service<std_srvs::srv::Trigger>::SharedPtr srv_;
};
"""


def test_an_element_of_an_unknown_library_s_variant_keeps_the_call(write_tree) -> None:
    """ur_robot_driver's dashboard client reads ``std::get<std::string>(...)`` of a
    variant its vendor library returns: no std::get took the permissive object, an error
    in the function that makes the service, so the node was partial."""
    root = write_tree({"srv/package.xml": package_xml("srv", "ament_cmake"),
                       "srv/src/dashboard.cpp": ELEMENT})
    result = extract_cpp([str(root / "srv" / "src" / "dashboard.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("server", "get_loaded_program")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_ERROR_NEAR_CALL" not in codes and "CPP_PARSE_ERROR" not in codes


MATH = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <cmath>
#include <string>
#include <vendor/robot.h>
class Arm : public rclcpp::Node
{
public:
  Arm() : rclcpp::Node("arm")
  {
    vendor::RobotState state = robot_.readOnce();
    if (std::abs(state.q_d[0] - 0.5) > 0.1) {
      pub_ = create_publisher<std_msgs::msg::String>("mode_" + std::to_string(state.mode), 1);
    }
  }
  vendor::Robot robot_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
"""


def test_a_standard_function_of_an_unknown_library_s_value_keeps_the_call(write_tree) -> None:
    """franka's ``std::abs(state.q_d[i] - q_start[i])`` of libfranka's RobotState and
    ouster's ``std::to_string`` of its sensor's mode: every standard overload took the
    permissive value through a conversion, an ambiguous call in the function that makes
    the publisher, so the node was partial. The name keeps its known text."""
    root = write_tree({"arm/package.xml": package_xml("arm", "ament_cmake"),
                       "arm/src/arm.cpp": MATH})
    result = extract_cpp([str(root / "arm" / "src" / "arm.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "mode_?")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_ERROR_NEAR_CALL" not in codes and "CPP_PARSE_ERROR" not in codes
