"""The type of a ROS call written with a class template's own type parameter
(``create_server<ActionT>`` in ``Timed<ActionT>``) is the argument the unit's classes
give that template: nav2's behaviors (``class Spin : public TimedBehavior<SpinAction>``)
and navigators (``BehaviorTreeNavigator<NavigateToPose>``, which holds a
``BtActionServer<ActionT>`` that serves the action) had action servers of type '?'."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp_nodes
from haros_arch.model import PrimitiveCall
from haros_arch.workspace import scan

HEADER = """#include <memory>
#include <string>
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_action/rclcpp_action.hpp"
namespace my_nav {
template<class ActionT, class NodeT = rclcpp::Node>
class Server
{
public:
  Server(std::shared_ptr<NodeT> node, const std::string & name) : node_(node), name_(name) {}
  void on_configure();
  std::shared_ptr<NodeT> node_;
  std::string name_;
  typename rclcpp_action::Server<ActionT>::SharedPtr server_;
};
template<class ActionT, class NodeT>
void Server<ActionT, NodeT>::on_configure()
{
  server_ = rclcpp_action::create_server<ActionT>(node_, name_, nullptr, nullptr, nullptr);
}
template<class ActionT>
class Navigator
{
public:
  void on_configure(rclcpp::Node::SharedPtr node)
  {
    server_ = std::make_unique<Server<ActionT, rclcpp::Node>>(node, "navigate");
    server_->on_configure();
  }
  std::unique_ptr<Server<ActionT, rclcpp::Node>> server_;
};
template<class ActionT>
class Timed
{
public:
  void configure(rclcpp::Node::SharedPtr node)
  {
    timed_ = rclcpp_action::create_server<ActionT>(node, "timed", nullptr, nullptr, nullptr);
  }
  typename rclcpp_action::Server<ActionT>::SharedPtr timed_;
};
}  // namespace my_nav
"""

ONE = """#include "my_nav/navigator.hpp"
#include "my_msgs/action/to_pose.hpp"
#include "my_msgs/action/spin.hpp"
namespace my_nav {
class ToPose : public Navigator<my_msgs::action::ToPose> {};
class Spin : public Timed<my_msgs::action::Spin> {};
}  // namespace my_nav
"""

# two classes give the template different arguments: its calls' type is not known
TWO = ONE + """namespace my_nav {
class Turn : public Timed<my_msgs::action::ToPose> {};
}  // namespace my_nav
"""


# a class template whose parameter's default the plugin export specialises (nav2's
# ``DriveOnHeading<ActionT = DriveOnHeading> : public TimedBehavior<ActionT>``,
# ``PLUGINLIB_EXPORT_CLASS(nav2_behaviors::DriveOnHeading<>, nav2_core::Behavior)``)
EXPORTED = """#include "my_nav/navigator.hpp"
#include "my_msgs/action/spin.hpp"
#include "pluginlib/class_list_macros.hpp"
namespace my_nav {
struct Behavior {};
template<class ActionT = my_msgs::action::Spin>
class Heading : public Timed<ActionT>, public Behavior {};
}  // namespace my_nav
PLUGINLIB_EXPORT_CLASS(my_nav::Heading<>, my_nav::Behavior)
"""


def _calls(tmp_path: Path, source: str) -> list[PrimitiveCall]:
    msgs = tmp_path / "my_msgs"
    (msgs / "action").mkdir(parents=True)
    (msgs / "package.xml").write_text(
        '<package format="3"><name>my_msgs</name><version>1.0.0</version>'
        "<description>x</description><maintainer email='a@b.c'>a</maintainer>"
        "<license>x</license><buildtool_depend>ament_cmake</buildtool_depend>"
        "<member_of_group>rosidl_interface_packages</member_of_group>"
        "<export><build_type>ament_cmake</build_type></export></package>")
    for name in ("ToPose", "Spin"):
        (msgs / "action" / f"{name}.action").write_text("int32 a\n---\nint32 b\n---\nint32 c\n")
    package = tmp_path / "my_nav"
    (package / "src").mkdir(parents=True)
    (package / "include" / "my_nav").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="3"><name>my_nav</name><version>1.0.0</version>'
        "<description>x</description><maintainer email='a@b.c'>a</maintainer>"
        "<license>x</license><buildtool_depend>ament_cmake</buildtool_depend>"
        "<depend>rclcpp</depend><depend>my_msgs</depend>"
        "<export><build_type>ament_cmake</build_type></export></package>")
    (package / "include" / "my_nav" / "navigator.hpp").write_text(HEADER)
    (package / "src" / "nav.cpp").write_text(source)
    ws = scan([str(tmp_path)])
    batch = extract_cpp_nodes([[str(package / "src" / "nav.cpp")]], ws, cache_dir=None,
                              jobs=1)
    return batch.results[0].calls


def _servers(calls: list[PrimitiveCall]) -> list[tuple[str, str | None]]:
    return sorted((c.name, c.type) for c in calls if c.kind == "action-server")


def test_the_argument_the_units_class_gives_the_template(tmp_path: Path) -> None:
    assert _servers(_calls(tmp_path, ONE)) == [
        ("navigate", "my_msgs/action/ToPose"),  # Navigator<ToPose> holds Server<ActionT>
        ("timed", "my_msgs/action/Spin"),  # Spin : Timed<Spin>
    ]


def test_classes_that_give_different_arguments_leave_it_unknown(tmp_path: Path) -> None:
    assert _servers(_calls(tmp_path, TWO)) == [
        ("navigate", "my_msgs/action/ToPose"),
        ("timed", "?"),
    ]


def test_a_template_the_plugin_export_specialises(tmp_path: Path) -> None:
    servers = _servers(_calls(tmp_path, EXPORTED))
    assert ("timed", "my_msgs/action/Spin") in servers
    assert ("navigate", "?") in servers  # Navigator<ActionT>: not specialised here
