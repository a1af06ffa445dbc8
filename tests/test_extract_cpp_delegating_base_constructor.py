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


# rtabmap_odom's shape whole: the base class also derives from a class of a library not
# here (rtabmap's UThread), the derived class's method gives the node to that library's
# code (CPP_NODE_TO_UNKNOWN: code not read, which may construct what it names), and the
# base class is exported as a component; neither builds a second node in the
# executable, whose main builds the derived class
HEADER_ALL = HEADER.replace('#include <string>\n', '#include <string>\n'
                            '#include <rtabmap/utilite/UThread.h>\n').replace(
    "class OdometryROS : public rclcpp::Node {",
    "class OdometryROS : public rclcpp::Node, public UThread {").replace(
    "  explicit RGBDOdometry(const rclcpp::NodeOptions & options);",
    "  explicit RGBDOdometry(const rclcpp::NodeOptions & options);\n"
    "  void update(ParametersMap & parameters);")
BASE_ALL = BASE + ('#include "rclcpp_components/register_node_macro.hpp"\n'
                   "RCLCPP_COMPONENTS_REGISTER_NODE(odom::OdometryROS)\n")
DERIVED_ALL = DERIVED.replace('#include "odom/odometry.hpp"\n', '#include "odom/odometry.hpp"\n'
                              "#include <rtabmap/core/Parameters.h>\n").replace(
    "}  // namespace odom", """\
void RGBDOdometry::update(ParametersMap & parameters)
{
  rtabmap::Parameters::parse(this, parameters);
}
}  // namespace odom""")


def test_not_with_a_base_of_a_library_not_here_nor_the_base_exported(write_tree) -> None:
    root: Path = write_tree({
        "odom/package.xml": package_xml("odom", "ament_cmake"),
        "odom/include/odom/odometry.hpp": HEADER_ALL,
        "odom/src/odometry.cpp": BASE_ALL,
        "odom/src/rgbd.cpp": DERIVED_ALL,
        "odom/src/main.cpp": MAIN % "RGBDOdometry",
    })
    result = extract_cpp([str(root / "odom/src" / name) for name in
                          ("main.cpp", "rgbd.cpp", "odometry.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert "CPP_NODE_TO_UNKNOWN" in {d.code for d in result.diagnostics}
    assert result.rosname == "rgbd_odometry"
    assert result.rosnames == []
    assert [(c.kind, c.name, c.node_name) for c in result.calls] == [
        ("publish", "odom", None)]
