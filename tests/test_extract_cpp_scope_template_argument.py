"""An unknown name the code uses as a scope (``FalconFeedback::Integrated``) and whole as
a template's argument (``MotorNode<vendor::can::Falcon, FalconConfiguration,
FalconFeedback, FalconMode>``), its vendor header missing: ros_phoenix_humble's
(2023Rover) TalonFXNode, TalonSRXNode and VictorSPXNode (phoenix_nodes.hpp:9, 21, 33).
clang reports the first unknown name of an argument list and skips the rest, so the
permissive declarations knew the name only as a scope and made it a namespace; the
base class stayed invalid ("unexpected namespace name ... expected expression") and
every parameter read of the derived nodes' methods was a C++ error near a ROS call."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include "vendor/Motor.h"

namespace drv
{
template<class Controller, class Configuration, class Feedback, class Mode>
class MotorNode : public rclcpp::Node
{
public:
  explicit MotorNode(const std::string & name)
  : Node(name)
  {
    controller_ = std::make_shared<Controller>(0);
  }

protected:
  std::shared_ptr<Controller> controller_;
};

class FalconNode
  : public MotorNode<vendor::can::Falcon, FalconConfiguration, FalconFeedback, FalconMode>
{
public:
  explicit FalconNode(const std::string & name)
  : MotorNode(name) {}

  void configure(FalconConfiguration & config)
  {
    config.limit = get_parameter("max_current").as_double();
    if (!get_parameter("analog_input").as_bool()) {
      controller_->ConfigSensor(FalconFeedback::Integrated);
    }
  }
};
}  // namespace drv

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<drv::FalconNode>("falcon");
  FalconConfiguration config;
  node->configure(config);
  rclcpp::spin(node);
  return 0;
}
"""

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(pkg)
find_package(rclcpp REQUIRED)
add_executable(falcon src/falcon.cpp)
"""


def test_a_scope_given_as_a_template_argument_is_a_class(write_tree) -> None:
    root = write_tree({"pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "pkg/CMakeLists.txt": CMAKE,
                       "pkg/src/falcon.cpp": SOURCE})
    result = extract_cpp([str(root / "pkg" / "src" / "falcon.cpp")], scan([str(root)]),
                         cache_dir=None, distro="humble")
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("read", "analog_input"), ("read", "max_current")]


HEADER_ONLY_LIST = """
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include "vendor/Motor.h"

namespace drv
{
template<class Controller, class Configuration, class Feedback, class Mode>
class MotorNode : public rclcpp::Node
{
public:
  explicit MotorNode(const std::string & name)
  : Node(name) {}
};

class FalconNode
  : public MotorNode<vendor::can::Falcon, FalconConfiguration, FalconFeedback, FalconMode>
{
public:
  explicit FalconNode(const std::string & name)
  : MotorNode(name)
  {
    limit_ = get_parameter("max_current").as_double();
  }

private:
  double limit_;
};
}  // namespace drv

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<drv::FalconNode>("falcon"));
  return 0;
}
"""


def test_the_arguments_after_an_unknown_one_are_declared_at_once(write_tree) -> None:
    """Each argument after the first unknown name of a list would be the error of one
    more parse (there are two): the three names given only there, and none else, are
    declared from the first."""
    root = write_tree({"pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "pkg/CMakeLists.txt": CMAKE,
                       "pkg/src/falcon.cpp": HEADER_ONLY_LIST})
    result = extract_cpp([str(root / "pkg" / "src" / "falcon.cpp")], scan([str(root)]),
                         cache_dir=None, distro="humble")
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name) for c in result.calls] == [("read", "max_current")]


KNOWN_BESIDE = """
#include <map>
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include "pkg/pose.hpp"
#include "vendor/Key.h"

using namespace geo;

class Mapper : public rclcpp::Node
{
public:
  Mapper()
  : Node("mapper")
  {
    std::map<vendor::Key, Pose> poses;
    std::map<vendor::Key, Frame> frames;
    pub_ = create_publisher<std_msgs::msg::String>("out", 10);
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
"""


def test_a_known_type_after_an_unknown_one_is_not_declared_again(write_tree) -> None:
    """``Pose`` (global) and ``Frame`` (a ``using namespace``'s) come from a header the
    parse read without an error: declared again they were a redefinition, or an
    ambiguity."""
    root = write_tree({"pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "pkg/CMakeLists.txt": CMAKE.replace(
                           "add_executable(falcon src/falcon.cpp)",
                           "include_directories(include)\nadd_library(mapper src/mapper.cpp)"),
                       "pkg/include/pkg/pose.hpp": "#pragma once\nstruct Pose { double x; };\n"
                                                   "namespace geo { struct Frame { int id; }; }\n",
                       "pkg/src/mapper.cpp": KNOWN_BESIDE})
    result = extract_cpp([str(root / "pkg" / "src" / "mapper.cpp")], scan([str(root)]),
                         cache_dir=None, distro="humble")
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []
    declared = [d.message for d in result.diagnostics if d.code == "CPP_NAMES_DECLARED"]
    assert declared and all("Pose" not in m and "Frame" not in m for m in declared)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "out")]
