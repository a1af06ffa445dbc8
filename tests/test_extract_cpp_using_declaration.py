"""A vendor class the header names qualified and the source through a using-declaration
(motoman_driver's ``using industrial::smpl_msg_connection::SmplMsgConnection;`` then
``bool JointRelayHandler::init(SmplMsgConnection* connection, ...)``): one class, so the
out-of-line definition matches its declaration and the function is not partial."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HEADER = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
#include "vendor/connection.h"
namespace relay {
class Relay {
 public:
  bool init(vendor::conn::Connection* connection, int type);
  ros::NodeHandle node_;
  ros::Publisher pub_;
};
}
"""

SOURCE = """\
#include "pkg/relay.h"
using vendor::conn::Connection;
namespace relay {
bool Relay::init(Connection* connection, int type) {
  pub_ = node_.advertise<std_msgs::String>("state", 1);
  return connection != nullptr;
}
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "relay");
  relay::Relay r;
  r.init(nullptr, 1);
}
"""


def test_a_using_declaration_names_the_qualified_vendor_class(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("pkg").replace(
        "</package>", "<depend>roscpp</depend><depend>std_msgs</depend></package>"))
    (tmp_path / "include" / "pkg").mkdir(parents=True)
    (tmp_path / "include" / "pkg" / "relay.h").write_text(HEADER)
    (tmp_path / "src").mkdir()
    source = tmp_path / "src" / "relay.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "state")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_NAMES_DECLARED" in codes
    assert "CPP_PARSE_ERROR" not in codes and "CPP_ERROR_NEAR_CALL" not in codes


def _one_source(tmp_path, client: str, name: str, text: str):
    """What a package of one source file, depending on ``client`` and std_msgs, gives."""
    (tmp_path / "package.xml").write_text(package_xml("pkg").replace(
        "</package>", f"<depend>{client}</depend><depend>std_msgs</depend></package>"))
    source = tmp_path / name
    source.write_text(text)
    return extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)


CONSTANT = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
#include "vendor/limits.h"
using vendor::limits::MAX_SPEED;
int main(int argc, char** argv) {
  ros::init(argc, argv, "limiter");
  ros::NodeHandle nh;
  double scale = (MAX_SPEED - 1) * 2.0;
  ros::Publisher pub = nh.advertise<std_msgs::String>("limited", 1);
  return scale > 0 ? 0 : 1;
}
"""


def test_a_using_declaration_of_a_constant_the_code_reads_as_a_value(tmp_path) -> None:
    """nav2's gradient_layer tutorial: ``using nav2_costmap_2d::LETHAL_OBSTACLE;`` then
    ``(LETHAL_OBSTACLE - gradient_index * GRADIENT_FACTOR)``: a value, not a type."""
    result = _one_source(tmp_path, "roscpp", "limiter.cpp", CONSTANT)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "limited")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_PARSE_ERROR" not in codes and "CPP_ERROR_NEAR_CALL" not in codes


INHERITED = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <vendor/fiber_driver.hpp>
class Bridge : public FiberDriver {
 public:
  using FiberDriver::FiberDriver;
  void start(rclcpp::Node::SharedPtr node) {
    pub_ = node->create_publisher<std_msgs::msg::String>("state", 10);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("bridge");
  Bridge bridge(nullptr, 1);
  bridge.start(node);
}
"""


def test_an_inherited_constructor_of_an_unknown_base_ends(tmp_path) -> None:
    """ros2_canopen's ``using FiberDriver::FiberDriver;`` (the base's constructors, the
    base a vendor class whose header is missing) was taken for a name brought from a
    namespace ``FiberDriver``: the class was merged into itself and the names' tree
    became a cycle that every later round walked for ever."""
    result = _one_source(tmp_path, "rclcpp", "bridge.cpp", INHERITED)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "state")]
    assert "CPP_ERROR_NEAR_CALL" not in [d.code for d in result.diagnostics]
