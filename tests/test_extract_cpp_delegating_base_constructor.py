"""A node class with two constructors, one delegating to the other with a name of its
own, and a derived class that main() builds through ``std::make_shared`` with another
name (rtabmap_odom aec4f91f: ``OdometryROS(options) : OdometryROS("odometry",
options)`` beside ``RGBDOdometry(options) : OdometryROS("rgbd_odometry", options)``;
rgbd_odometry's main makes the RGBDOdometry). The delegating constructor never runs in
that process: one node, ``rgbd_odometry``. It was two nodes, ``rgbd_odometry`` and
``odometry``, each with the base class's calls: main's factory call (which may call any
constructor) left the derived class's declaration unseen though another file of the node
defines its one constructor, so the delegating constructor counted as possibly run, and
its name as given; and a name passed only in code the node never runs still counted."""

from __future__ import annotations

from pathlib import Path

from conftest import package_xml

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.workspace import scan

HEADER = """\
#include <string>
#include "rclcpp/rclcpp.hpp"
#include "nav_msgs/msg/odometry.hpp"
namespace odom {
class OdometryROS : public rclcpp::Node {
public:
  explicit OdometryROS(const rclcpp::NodeOptions & options);
  explicit OdometryROS(const std::string & name, const rclcpp::NodeOptions & options);
protected:
  rclcpp::Publisher<nav_msgs::msg::Odometry>::SharedPtr pub_;
};
class RGBDOdometry : public OdometryROS {
public:
  explicit RGBDOdometry(const rclcpp::NodeOptions & options);
};
}  // namespace odom
"""

BASE = """\
#include "odom/odometry.hpp"
namespace odom {
OdometryROS::OdometryROS(const rclcpp::NodeOptions & options)
: OdometryROS("odometry", options) {}
OdometryROS::OdometryROS(const std::string & name, const rclcpp::NodeOptions & options)
: Node(name, options)
{
  pub_ = create_publisher<nav_msgs::msg::Odometry>("odom", 1);
}
}  // namespace odom
"""

DERIVED = """\
#include "odom/odometry.hpp"
namespace odom {
RGBDOdometry::RGBDOdometry(const rclcpp::NodeOptions & options)
: OdometryROS("rgbd_odometry", options) {}
}  // namespace odom
"""

MAIN = """\
#include "odom/odometry.hpp"
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::NodeOptions options;
  auto node = std::make_shared<odom::%s>(options);
  rclcpp::spin(node);
}
"""


def _extract(write_tree, made: str) -> CppResult:
    root: Path = write_tree({
        "odom/package.xml": package_xml("odom", "ament_cmake"),
        "odom/include/odom/odometry.hpp": HEADER,
        "odom/src/odometry.cpp": BASE,
        "odom/src/rgbd.cpp": DERIVED,
        "odom/src/main.cpp": MAIN % made,
    })
    return extract_cpp([str(root / "odom/src" / name) for name in
                        ("main.cpp", "rgbd.cpp", "odometry.cpp")], scan([str(root)]),
                       cache_dir=None)


def test_a_delegating_constructor_the_process_never_runs_names_no_node(write_tree) -> None:
    result = _extract(write_tree, "RGBDOdometry")
    assert result.rosname == "rgbd_odometry"
    assert result.rosnames == []  # one node
    assert [(c.kind, c.name, c.node_name) for c in result.calls] == [
        ("publish", "odom", None)]


def test_a_base_class_main_builds_itself_is_one_node(write_tree) -> None:
    # main's factory may call either constructor (which one is not read: the name stays
    # '?'), and the derived class's constructor, which nothing calls, names no node
    result = _extract(write_tree, "OdometryROS")
    assert result.rosnames == []
    assert [(c.kind, c.name, c.node_name) for c in result.calls] == [
        ("publish", "odom", None)]
