"""Autoware's node utilities from autoware_utils, when the library is installed rather
than in the workspace (stand-ins, ``standin/fallback/autoware_utils/
haros_node_utilities.h``): the logger level configurator serves ``~/config_logger``,
the diagnostics interface publishes ``/diagnostics``, the transform listener listens to
``/tf`` and ``/tf_static`` (as tf2_ros' listener it holds). They were missing headers, and
the node handed to them made 28 of autoware_core's nodes partial."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
#include <rclcpp/rclcpp.hpp>
#include <autoware_utils_logging/logger_level_configure.hpp>
#include <autoware_utils_diagnostics/diagnostics_interface.hpp>
#include <autoware_utils_tf/transform_listener.hpp>
class Checker : public rclcpp::Node {
 public:
  Checker() : rclcpp::Node("checker") {
    logger_configure_ = std::make_unique<autoware_utils_logging::LoggerLevelConfigure>(this);
    diagnostics_ =
      std::make_unique<autoware_utils_diagnostics::DiagnosticsInterface>(this, "status");
    diagnostics_->add_key_value("ready", true);
    diagnostics_->publish(now());
    transform_listener_ = std::make_shared<autoware_utils_tf::TransformListener>(this);
  }
 private:
  std::unique_ptr<autoware_utils_logging::LoggerLevelConfigure> logger_configure_;
  std::unique_ptr<autoware_utils_diagnostics::DiagnosticsInterface> diagnostics_;
  std::shared_ptr<autoware_utils_tf::TransformListener> transform_listener_;
};
"""


def test_the_utilities_serve_and_publish_on_the_node(write_tree) -> None:
    root = write_tree({"check/package.xml": package_xml("check", "ament_cmake"),
                       "check/src/checker.cpp": SOURCE})
    result = extract_cpp([str(root / "check/src/checker.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("publish", "/diagnostics", "diagnostic_msgs/msg/DiagnosticArray"),
        ("server", "~config_logger", "logging_demo/srv/ConfigLogger"),
        ("subscribe", "/tf", "tf2_msgs/msg/TFMessage"),
        ("subscribe", "/tf_static", "tf2_msgs/msg/TFMessage")]
    assert not [d for d in result.diagnostics
                if d.code in ("CPP_INCLUDE_MISSING", "CPP_PARSE_ERROR", "CPP_NODE_PASSED")]
