"""A name from a getter (a method without parameters whose body is one ``return``), and
a base class template's call of a pure virtual getter that the unit's class overrides
(nav2's BehaviorTreeNavigator<ActionT>::on_configure makes its BtActionServer with
``getName()``, which NavigateToPoseNavigator defines); the class template that the
dependent ``std::make_unique<Server<ActionT>>(...)`` constructs is read as made there."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp_nodes
from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Location, Node, PrimitiveCall
from haros_arch.workspace import Workspace, scan

HEADER = """#include <memory>
#include <string>
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_action/rclcpp_action.hpp"
#include "geometry_msgs/msg/twist.hpp"
namespace my_nav {
template<class ActionT>
class Server
{
public:
  Server(rclcpp::Node::SharedPtr node, const std::string & action_name)
  : node_(node), action_name_(action_name) {}
  void on_configure()
  {
    server_ = rclcpp_action::create_server<ActionT>(
      node_, action_name_, nullptr, nullptr, nullptr);
  }
  rclcpp::Node::SharedPtr node_;
  std::string action_name_;
  typename rclcpp_action::Server<ActionT>::SharedPtr server_;
};
template<class ActionT>
class Navigator
{
public:
  virtual ~Navigator() = default;
  bool on_configure(rclcpp::Node::SharedPtr node)
  {
    server_ = std::make_unique<Server<ActionT>>(node, getName());
    server_->on_configure();
    pub_ = node->create_publisher<geometry_msgs::msg::Twist>(topic(), 10);
    return true;
  }
  virtual std::string getName() = 0;
  std::string topic()
  {
    std::string t = "state";
    t += "_out";
    return t;
  }
  std::unique_ptr<Server<ActionT>> server_;
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr pub_;
};
}  // namespace my_nav
"""

SOURCE = """#include "my_nav/navigator.hpp"
namespace my_nav {
class ToPose : public Navigator<my_msgs::action::ToPose>
{
public:
  std::string getName() override {return std::string("to_pose");}
  void more(rclcpp::Node::SharedPtr node)
  {
    sub_ = node->create_subscription<geometry_msgs::msg::Twist>(
      getName() + "/cmd", 10, nullptr);
  }
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr sub_;
};
}  // namespace my_nav
"""

# a unit that defines two navigators: the base's getName() is either
TWO = SOURCE + """namespace my_nav {
class ThroughPoses : public Navigator<my_msgs::action::ThroughPoses>
{
public:
  std::string getName() override {return "through_poses";}
};
}  // namespace my_nav
"""


def _calls(tmp_path: Path, source: str) -> list[PrimitiveCall]:
    package = tmp_path / "my_nav"
    (package / "src").mkdir(parents=True)
    (package / "include" / "my_nav").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="3"><name>my_nav</name><version>1.0.0</version>'
        "<description>x</description><maintainer email='a@b.c'>a</maintainer>"
        "<license>x</license><buildtool_depend>ament_cmake</buildtool_depend>"
        "<depend>rclcpp</depend><export><build_type>ament_cmake</build_type>"
        "</export></package>")
    (package / "include" / "my_nav" / "navigator.hpp").write_text(HEADER)
    (package / "src" / "nav.cpp").write_text(source)
    ws = scan([str(tmp_path)])
    batch = extract_cpp_nodes([[str(package / "src" / "nav.cpp")]], ws, cache_dir=None,
                              jobs=1)
    return batch.results[0].calls


def _names(calls: list[PrimitiveCall]) -> list[tuple[str, str]]:
    return sorted((c.kind, c.name) for c in calls)


def test_a_getter_and_the_override_of_a_base_templates_pure_getter_name_calls(tmp_path):
    assert _names(_calls(tmp_path, SOURCE)) == [
        ("action-server", "to_pose"),  # the base template's, through the override
        ("publish", "?"),  # a getter of more than one statement: not read
        ("subscribe", "to_pose/cmd"),  # the class's own getter
    ]


def test_overrides_that_disagree_leave_the_base_getter_unknown(tmp_path):
    assert ("action-server", "?") in _names(_calls(tmp_path, TWO))


def _where(line: int) -> Location:
    return Location("nav2_bt_navigator", "nav2_bt_navigator/src/x.cpp", line, 3)


def test_bt_navigator_makes_the_calls_of_its_navigators():
    to_pose = Node("nav2_bt_navigator", "nav2_bt_navigator::NavigateToPoseNavigator",
                   "plugin", plugin_class="nav2_bt_navigator::NavigateToPoseNavigator",
                   calls=[PrimitiveCall("action-server", "navigate_to_pose",
                                        "nav2_msgs/action/NavigateToPose",
                                        location=_where(1)),
                          PrimitiveCall("read", "navigate_to_pose.goal_blackboard_id",
                                        location=_where(2))])
    through = Node("nav2_bt_navigator", "nav2_bt_navigator::NavigateThroughPosesNavigator",
                   "plugin",
                   plugin_class="nav2_bt_navigator::NavigateThroughPosesNavigator",
                   calls=[PrimitiveCall("action-server", "navigate_through_poses",
                                        "nav2_msgs/action/NavigateThroughPoses",
                                        location=_where(3))])
    navigator = Node("nav2_bt_navigator", "bt_navigator")
    decl = NodeDecl("/bt_navigator", "nav2_bt_navigator", "bt_navigator")
    decl.ros_version = 2
    nodes = {n.name: n for n in (to_pose, through, navigator)}

    def served(params: list[ParamDecl]) -> list[str]:
        config = build(Configuration("c"), LaunchModel(nodes=[decl], params=params),
                       Workspace(root="/nowhere"), dict(nodes))
        return sorted(link.resource.name for link in config.links
                      if link.node.name == "/bt_navigator" and link.kind == "action-server")

    # not set: bt_navigator's two defaults
    assert served([]) == ["/navigate_through_poses", "/navigate_to_pose"]
    assert served([ParamDecl("/bt_navigator/navigators", ["only"]),
                   ParamDecl("/bt_navigator/only.plugin",
                             "nav2_bt_navigator::NavigateToPoseNavigator")]) == [
        "/navigate_to_pose"]


def test_a_humble_bt_navigator_loads_no_navigator_plugins():
    """navigation2 1.1.x (Humble) builds NavigateToPoseNavigator and
    NavigateThroughPosesNavigator in bt_navigator.cpp itself (its model has their calls);
    from Iron (1.2) on it loads them by their ``<id>.plugin``. articubot_one's Humble
    navigation had two false PLUGIN_NOT_FOUND and its bt_navigator partial."""
    def warned(version: str) -> list[str]:
        own = Node("nav2_bt_navigator", "bt_navigator", model=f"x/nav2_bt_navigator {version}",
                   calls=[PrimitiveCall("action-server", "navigate_to_pose",
                                        "nav2_msgs/action/NavigateToPose",
                                        location=_where(1))])
        decl = NodeDecl("/bt_navigator", "nav2_bt_navigator", "bt_navigator")
        decl.ros_version = 2
        config = build(Configuration("c"), LaunchModel(nodes=[decl]),
                       Workspace(root="/nowhere"), {own.name: own})
        assert [link.resource.name for link in config.links
                if link.kind == "action-server"] == ["/navigate_to_pose"]
        return sorted(d.message.split()[2] for d in config.diagnostics
                      if d.code == "PLUGIN_NOT_FOUND")

    assert warned("1.1.20") == []
    assert warned("1.2.10") == ["nav2_bt_navigator::NavigateThroughPosesNavigator",
                                "nav2_bt_navigator::NavigateToPoseNavigator"]
