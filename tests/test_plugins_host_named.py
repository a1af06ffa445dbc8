"""A plugin whose call is named wholly by the string its host passes it (nav2's
TimedBehavior: ``behavior_name_ = name`` in ``configure``, then an action server under
``behavior_name_``) makes that call under its plugin name on the host."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp_nodes
from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Node, PrimitiveCall
from haros_arch.workspace import Workspace, scan

HEADER = """#include <string>
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_action/rclcpp_action.hpp"
#include "geometry_msgs/msg/twist.hpp"
namespace nav2_core {
// the base class the host loads its plugins by
class Behavior
{
public:
  virtual ~Behavior() = default;
  virtual void configure(
    const rclcpp::Node::WeakPtr & parent, const std::string & name, int tf) = 0;
  virtual void relabel(const std::string & from, const std::string & to) = 0;
  // the base's own code calls it: its string is not the host's
  virtual void follow(const std::string & topic) = 0;
  void start() {follow(followed_);}
  std::string followed_;
};
}  // namespace nav2_core
namespace my_beh {
// a base that calls its own virtual method in the file that defines it (shape.cpp), a
// subclass of another file overriding it (nav2's Polygon::createSubscription, Circle)
class Shape
{
public:
  virtual ~Shape() = default;
  void begin(const rclcpp::Node::WeakPtr & parent);
  virtual void listen(const std::string & topic);
  rclcpp::Node::WeakPtr node_;
  std::string heard_;
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr sub_;
};
template<class ActionT>
class Timed : public nav2_core::Behavior
{
public:
  void configure(
    const rclcpp::Node::WeakPtr & parent, const std::string & name, int tf) override
  {
    node_ = parent;
    auto node = node_.lock();
    behavior_name_ = name;
    server_ = rclcpp_action::create_server<ActionT>(
      node, behavior_name_, nullptr, nullptr, nullptr);
  }
  void relabel(const std::string & from, const std::string & to) override
  {
    auto node = node_.lock();
    label_ = to;
    pub_ = node->create_publisher<geometry_msgs::msg::Twist>(label_, 10);
  }
  void follow(const std::string & topic) override
  {
    auto node = node_.lock();
    following_ = topic;
    pub_ = node->create_publisher<geometry_msgs::msg::Twist>(following_, 10);
  }
  // declared here, not by the class the host loads: the host never calls it
  virtual void relay(const std::string & topic) {}
  void watch(const std::string & topic)
  {
    auto node = node_.lock();
    topic_ = topic;
    sub_ = node->create_subscription<geometry_msgs::msg::Twist>(topic_, 10, nullptr);
  }

protected:
  rclcpp::Node::WeakPtr node_;
  std::string behavior_name_;
  std::string label_;
  std::string following_;
  std::string topic_;
  typename rclcpp_action::Server<ActionT>::SharedPtr server_;
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr pub_;
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr sub_;
};
}  // namespace my_beh
"""

SOURCE = """#include "my_beh/timed.hpp"
namespace my_beh {
class Spin : public Timed<my_msgs::action::Spin>
{
public:
  void relay(const std::string & topic) override
  {
    auto node = node_.lock();
    relayed_ = topic;
    relay_pub_ = node->create_publisher<geometry_msgs::msg::Twist>(relayed_, 10);
  }
  std::string relayed_;
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr relay_pub_;
};
class Ring : public Shape
{
public:
  void listen(const std::string & topic) override
  {
    auto node = node_.lock();
    heard_ = topic;
    sub_ = node->create_subscription<geometry_msgs::msg::Twist>(heard_, 10, nullptr);
  }
};
}  // namespace my_beh
"""

SHAPE = """#include "my_beh/timed.hpp"
namespace my_beh {
void Shape::begin(const rclcpp::Node::WeakPtr & parent)
{
  node_ = parent;
  std::string topic;
  topic = pick();
  listen(topic);
}
void Shape::listen(const std::string & topic) {}
}  // namespace my_beh
"""


def _calls(tmp_path: Path):
    package = tmp_path / "my_beh"
    (package / "src").mkdir(parents=True)
    (package / "include" / "my_beh").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="3"><name>my_beh</name><version>1.0.0</version>'
        "<description>x</description><maintainer email='a@b.c'>a</maintainer>"
        "<license>x</license><buildtool_depend>ament_cmake</buildtool_depend>"
        "<depend>rclcpp</depend><export><build_type>ament_cmake</build_type>"
        "</export></package>")
    (package / "include" / "my_beh" / "timed.hpp").write_text(HEADER)
    (package / "src" / "spin.cpp").write_text(SOURCE)
    (package / "src" / "shape.cpp").write_text(SHAPE)
    ws = scan([str(tmp_path)])
    batch = extract_cpp_nodes([[str(package / "src" / "spin.cpp"),
                                str(package / "src" / "shape.cpp")]], ws, cache_dir=None,
                              jobs=1)
    return batch.results[0].calls


def test_a_name_wholly_from_the_one_string_of_a_virtual_method_is_the_hosts(tmp_path):
    calls = sorted((c.kind, c.name, c.host_named or "", c.location.line)
                   for c in _calls(tmp_path))
    # a virtual method with two strings, one its plugin's own code calls (through the
    # base, or in the file that defines it), and a method no base class declares: their
    # strings are not the host's, nor that of an override of a virtual method no base
    # class the host loads by declares (Spin::relay); ``Timed::watch``, a method of a
    # class template that is not virtual and that nothing calls, is never instantiated:
    # no call
    assert [c[:3] for c in calls] == [
        ("action-server", "?", "nav2_core::Behavior"), ("publish", "?", ""),
        ("publish", "?", ""), ("publish", "?", ""), ("subscribe", "?", "")]


def test_the_host_names_such_a_call_by_the_plugin_name(tmp_path):
    # and one named by a method of a class the host does not load plugins by (nav2's
    # filters' ``initializeFilter(topic)``, which their base CostmapFilter calls from
    # the costmap's core library, code outside the plugin's own)
    other = PrimitiveCall("subscribe", "?", "geometry_msgs/msg/Twist",
                          host_named="my_beh::Filter")
    spin = Node("my_beh", "my_beh::Spin", "plugin", calls=[*_calls(tmp_path), other],
                plugin_class="my_beh::Spin")
    decl = NodeDecl("/behavior_server", "nav2_behaviors", "behavior_server")
    decl.ros_version = 2
    params = [ParamDecl("/behavior_server/behavior_plugins", ["spin"]),
              ParamDecl("/behavior_server/spin.plugin", "my_beh::Spin")]
    config = build(Configuration("c"), LaunchModel(nodes=[decl], params=params),
                   Workspace(root="/nowhere"), {spin.name: spin})
    served = sorted(link.resource.name for link in config.links
                    if link.node.name == "/behavior_server" and link.kind == "action-server")
    assert served == ["/spin"]
    # the others stay unknown: not named by the plugin (``Timed::watch``, called
    # nowhere, makes none)
    assert sorted((link.kind, link.resource.name) for link in config.links
                  if link.kind in ("publish", "subscribe") and link.origin != "action"
                  ) == [("publish", "?"), ("publish", "?"), ("publish", "?"),
                        ("subscribe", "?"), ("subscribe", "?")]


def test_an_interface_model_keeps_what_names_a_call():
    # a plugin node read back from its model (a package without source) keeps the mark
    from haros_arch.model.load import node_from_data
    from haros_arch.model.serialise import to_data

    node = Node("p", "p::A", "plugin", calls=[
        PrimitiveCall("action-server", "?", host_named="nav2_core::Behavior")])
    assert node_from_data(to_data(node), "p").calls[0].host_named == "nav2_core::Behavior"
