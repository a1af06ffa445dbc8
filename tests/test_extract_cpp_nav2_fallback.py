"""navigation2's plugins and servers outside navigation2 (nav2 installed, not in the
workspace): the stand-ins of ``standin/fallback`` give nav2_util, nav2_ros_common,
nav2_core and nav2_costmap_2d, and their parameter helpers, factories and action servers
are API rows; a workspace with navigation2's own headers is read with those."""

from __future__ import annotations

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

# what a unit the stand-ins parse cleanly has none of
UNCLEAN = ("CPP_PARSE_ERROR", "CPP_MESSAGE_FIELD", "CPP_INCLUDE_MISSING", "CPP_CALL_UNRESOLVED",
           "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED", "CPP_NODE_TO_UNKNOWN")


def _extract(tmp_path, text: str) -> CppResult:
    (tmp_path / "package.xml").write_text(package_xml("plugins", "ament_cmake"))
    source = tmp_path / "a.cpp"
    source.write_text(text)
    return extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)


def _rows(result: CppResult) -> list[tuple[str, str, str | None, bool, int]]:
    return [(c.kind, c.name, c.type, c.has_default, c.location.line) for c in result.calls]


def _unclean(result: CppResult) -> list[tuple[str, str]]:
    return [(d.code, d.message) for d in result.diagnostics if d.code in UNCLEAN]


CONTROLLER = """\
#include <memory>
#include <string>
#include "nav2_core/controller.hpp"
#include "nav2_util/node_utils.hpp"
#include "nav_msgs/msg/path.hpp"
#include "pluginlib/class_list_macros.hpp"
namespace demo {
class Pursuit : public nav2_core::Controller {
 public:
  void configure(const rclcpp_lifecycle::LifecycleNode::WeakPtr & parent, std::string name,
                 std::shared_ptr<tf2_ros::Buffer>,
                 std::shared_ptr<nav2_costmap_2d::Costmap2DROS> costmap) override {
    auto node = parent.lock();
    nav2_util::declare_parameter_if_not_declared(
      node, "lookahead", rclcpp::ParameterValue(0.4));
    nav2_util::declare_parameter_if_not_declared(node, "frame", rclcpp::PARAMETER_STRING);
    node->get_parameter("lookahead", lookahead_);
    std::string type = nav2_util::get_plugin_type_param(node, "checker");
    plan_pub_ = node->create_publisher<nav_msgs::msg::Path>("local_plan", 1);
    frame_ = costmap->getGlobalFrameID();
  }
  void cleanup() override {}
  void activate() override {}
  void deactivate() override {}
  void setPlan(const nav_msgs::msg::Path &) override {}
  geometry_msgs::msg::TwistStamped computeVelocityCommands(
    const geometry_msgs::msg::PoseStamped &, const geometry_msgs::msg::Twist &,
    nav2_core::GoalChecker *) override { return {}; }
  void setSpeedLimit(const double &, const bool &) override {}
 private:
  double lookahead_;
  std::string frame_;
  rclcpp_lifecycle::LifecyclePublisher<nav_msgs::msg::Path>::SharedPtr plan_pub_;
};
}
PLUGINLIB_EXPORT_CLASS(demo::Pursuit, nav2_core::Controller)
"""


def test_controller_plugin_declares_through_nav2_util(tmp_path) -> None:
    """declare_parameter_if_not_declared(node, name, value) declares ``name`` on the node
    (a ParameterType: typed, no default); get_plugin_type_param(node, p) declares
    ``p.plugin``, a string without default; the Jazzy Controller's overrides parse."""
    result = _extract(tmp_path, CONTROLLER)
    assert _rows(result) == [
        ("declare", "lookahead", "double", True, 14),
        ("declare", "frame", "str", False, 16),
        ("read", "lookahead", "double", False, 17),
        ("declare", "checker.plugin", "str", False, 18),
        ("publish", "local_plan", "nav_msgs/msg/Path", False, 19),
    ]
    assert _unclean(result) == []


LAYER = """\
#include "nav2_costmap_2d/costmap_layer.hpp"
#include "nav2_costmap_2d/layered_costmap.hpp"
#include "pluginlib/class_list_macros.hpp"
#include "std_msgs/msg/float32.hpp"
namespace demo {
class Gradient : public nav2_costmap_2d::CostmapLayer {
 public:
  void onInitialize() override {
    auto node = node_.lock();
    declareParameter("enabled", rclcpp::ParameterValue(true));
    node->get_parameter(name_ + "." + "enabled", enabled_);
    auto options = rclcpp::PublisherOptions();
    pub_ = node->create_publisher<std_msgs::msg::Float32>("level", rclcpp::QoS(1), options);
    current_ = true;
  }
  void updateBounds(double, double, double, double *, double *, double *, double *) override {}
  void updateCosts(nav2_costmap_2d::Costmap2D & grid, int, int, int, int) override {
    grid.setCost(0, 0, nav2_costmap_2d::LETHAL_OBSTACLE);
  }
  void reset() override {}
  bool isClearable() override { return false; }
 private:
  rclcpp::Publisher<std_msgs::msg::Float32>::SharedPtr pub_;
};
}
PLUGINLIB_EXPORT_CLASS(demo::Gradient, nav2_costmap_2d::Layer)
"""


def test_costmap_layer_declares_under_its_name(tmp_path) -> None:
    """A layer's declareParameter(name, value) declares ``<layer name>.name`` on its node
    (Layer::getFullName); the layer's name is given at run time: ``?.``. Its node, the
    lifecycle node of the release (rclcpp_lifecycle's for the default, Jazzy; Kilted's
    nav2 node from Kilted on), takes create_publisher(topic, qos, options)."""
    result = _extract(tmp_path, LAYER)
    assert _rows(result) == [
        ("declare", "?.enabled", "bool", True, 10),
        ("read", "?.enabled", "bool", False, 11),
        ("publish", "level", "std_msgs/msg/Float32", False, 13),
    ]
    assert _unclean(result) == []


SERVERS = """\
#include <memory>
#include "nav2_util/lifecycle_node.hpp"
#include "nav2_util/simple_action_server.hpp"
#include "nav2_ros_common/lifecycle_node.hpp"
#include "nav2_ros_common/node_utils.hpp"
#include "nav2_msgs/action/dock_robot.hpp"
#include "nav_msgs/msg/path.hpp"
using DockRobot = nav2_msgs::action::DockRobot;
class Jazzy : public nav2_util::LifecycleNode {
 public:
  explicit Jazzy(const rclcpp::NodeOptions & options)
  : nav2_util::LifecycleNode("jazzy_server", "", options) {
    declare_parameter("rate", 20.0);
  }
  nav2_util::CallbackReturn on_configure(const rclcpp_lifecycle::State &) override {
    server_ = std::make_unique<nav2_util::SimpleActionServer<DockRobot>>(
      shared_from_this(), "dock", std::bind(&Jazzy::run, this), nullptr,
      std::chrono::milliseconds(500), true);
    return nav2_util::CallbackReturn::SUCCESS;
  }
  nav2_util::CallbackReturn on_activate(const rclcpp_lifecycle::State &) override {
    createBond();
    return nav2_util::CallbackReturn::SUCCESS;
  }
  void run() {}
  std::unique_ptr<nav2_util::SimpleActionServer<DockRobot>> server_;
};
class Kilted : public nav2::LifecycleNode {
 public:
  explicit Kilted(const rclcpp::NodeOptions & options)
  : nav2::LifecycleNode("kilted_server", "", options) {}
  nav2::CallbackReturn on_configure(const rclcpp_lifecycle::State &) override {
    auto node = shared_from_this();
    nav2::declare_parameter_if_not_declared(node, "cartesian", rclcpp::ParameterValue(true));
    int port = nav2::declare_or_get_parameter(node, "port", 1667);
    double tolerance = node->declare_or_get_parameter("tolerance", 0.25);
    server_ = node->create_action_server<DockRobot>(
      "follow", std::bind(&Kilted::run, this), nullptr, std::chrono::milliseconds(500), true);
    pub_ = node->create_publisher<nav_msgs::msg::Path>("plan");
    sub_ = node->create_subscription<nav_msgs::msg::Path>(
      "path", [](nav_msgs::msg::Path::ConstSharedPtr) {}, rclcpp::QoS(3));
    (void)tolerance;
    (void)port;
    return nav2::CallbackReturn::SUCCESS;
  }
  void run() {}
  nav2::SimpleActionServer<DockRobot>::SharedPtr server_;
  nav2::Publisher<nav_msgs::msg::Path>::SharedPtr pub_;
  nav2::Subscription<nav_msgs::msg::Path>::SharedPtr sub_;
};
"""

_LIFECYCLE = [
    ("publish", "~transition_event", "lifecycle_msgs/msg/TransitionEvent"),
    ("server", "~change_state", "lifecycle_msgs/srv/ChangeState"),
    ("server", "~get_state", "lifecycle_msgs/srv/GetState"),
    ("server", "~get_available_states", "lifecycle_msgs/srv/GetAvailableStates"),
    ("server", "~get_available_transitions", "lifecycle_msgs/srv/GetAvailableTransitions"),
    ("server", "~get_transition_graph", "lifecycle_msgs/srv/GetAvailableTransitions"),
    ("declare", "bond_heartbeat_period", "double"), ("read", "bond_heartbeat_period", "double"),
    ("declare", "autostart_node", "bool"), ("read", "autostart_node", "bool"),
    ("declare", "/bond_disable_heartbeat_timeout", "bool"),
    ("write", "/bond_disable_heartbeat_timeout", "bool"),
]


def test_nav2_lifecycle_servers(tmp_path) -> None:
    """A server deriving nav2_util's (Jazzy) or nav2's (Kilted) lifecycle node: named by
    its base's constructor, with rclcpp_lifecycle's state machine and the parameters
    the base declares; the base's declare_parameter, its bond, nav2_util's
    SimpleActionServer and the Kilted node's factories (topic, callback, QoS)."""
    result = _extract(tmp_path, SERVERS)
    by_node: dict[str | None, list[tuple[str, str, str | None]]] = {}
    for call in result.calls:
        by_node.setdefault(call.node_name, []).append((call.kind, call.name, call.type))
    assert result.rosnames == ["jazzy_server", "kilted_server"]
    jazzy, kilted = by_node["jazzy_server"], by_node["kilted_server"]
    assert jazzy == [*_LIFECYCLE, ("declare", "rate", "double"),
                     ("action-server", "dock", "nav2_msgs/action/DockRobot"),
                     ("publish", "bond", "bond/msg/Status"),
                     ("subscribe", "bond", "bond/msg/Status")]
    assert kilted == [*_LIFECYCLE, ("declare", "cartesian", "bool"), ("declare", "port", "int"),
                      ("declare", "tolerance", "double"),
                      ("action-server", "follow", "nav2_msgs/action/DockRobot"),
                      ("publish", "plan", "nav_msgs/msg/Path"),
                      ("subscribe", "path", "nav_msgs/msg/Path")]
    assert [d for d in _unclean(result) if "dock_robot" not in d[1]] == []


def test_navigation2_own_headers_win(tmp_path) -> None:
    """With nav2_util's sources in the workspace, its own node_utils.hpp is read (the
    helper's body: has_parameter, then declare_parameter), not the stand-in's row."""
    util = tmp_path / "nav2_util"
    (util / "include" / "nav2_util").mkdir(parents=True)
    (util / "package.xml").write_text(package_xml("nav2_util", "ament_cmake"))
    (util / "include" / "nav2_util" / "node_utils.hpp").write_text(
        "#pragma once\n#include <string>\n#include <rclcpp/rclcpp.hpp>\n"
        "namespace nav2_util {\ntemplate<typename NodeT>\n"
        "void declare_parameter_if_not_declared(NodeT node, const std::string & name,\n"
        "    const rclcpp::ParameterValue & value) {\n"
        "  if (!node->has_parameter(name)) {\n"
        "    node->declare_parameter(name, value);\n  }\n}\n}\n")
    plugin = tmp_path / "plugins"
    plugin.mkdir()
    (plugin / "package.xml").write_text(package_xml("plugins", "ament_cmake"))
    source = plugin / "a.cpp"
    source.write_text(
        "#include <rclcpp/rclcpp.hpp>\n#include \"nav2_util/node_utils.hpp\"\n"
        "class N : public rclcpp::Node {\n public:\n  N() : Node(\"n\") {\n"
        "    nav2_util::declare_parameter_if_not_declared(\n"
        "      this, \"gain\", rclcpp::ParameterValue(2.0));\n  }\n};\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("read", "gain"), ("declare", "gain")]


UNREAD = """\
#include <memory>
#include "nav2_costmap_2d/costmap_subscriber.hpp"
#include "nav2_util/lifecycle_node.hpp"
#include "vendor/helper.hpp"
class Checker : public nav2_util::LifecycleNode {
 public:
  Checker() : nav2_util::LifecycleNode("checker") {}
  nav2_util::CallbackReturn on_configure(const rclcpp_lifecycle::State &) override {
    auto node = shared_from_this();
    costmap_ = std::make_unique<nav2_costmap_2d::CostmapSubscriber>(node, "costmap_raw");
    nav2_costmap_2d::CostmapSubscriber local(node, "local_costmap_raw");
    footprint_ = std::make_unique<nav2_costmap_2d::FootprintSubscriber>(
      node, "footprint", *tf_);
    helper_ = std::make_shared<vendor::Helper>(node, "x");
    return nav2_util::CallbackReturn::SUCCESS;
  }
  std::unique_ptr<nav2_costmap_2d::CostmapSubscriber> costmap_;
  std::shared_ptr<vendor::Helper> helper_;
  std::unique_ptr<nav2_costmap_2d::FootprintSubscriber> footprint_;
  std::shared_ptr<tf2_ros::Buffer> tf_;
};
"""


def test_node_given_to_a_class_not_read(tmp_path) -> None:
    """A class the stand-ins declare only so that code using it parses (``HAROS_UNREAD``:
    nav2_costmap_2d's CostmapSubscriber subscribes to the topic given, and from Jazzy on
    to its ``_updates`` too) or that the parse
    declares permissively (a vendor's), built with the node directly or through
    make_unique / make_shared, makes the node partial: ``CPP_NODE_TO_UNKNOWN``."""
    result = _extract(tmp_path, UNREAD)
    assert sorted((d.location.line, d.message) for d in result.diagnostics
                  if d.code == "CPP_NODE_TO_UNKNOWN") == [
        (10, "the node (node) is given to nav2_costmap_2d::CostmapSubscriber, which the "
             "parse does not know"),
        (11, "the node (node) is given to nav2_costmap_2d::CostmapSubscriber, which the "
             "parse does not know"),
        (14, "the node (node) is given to vendor::Helper, which the parse does not know"),
    ]
    # FootprintSubscriber's subscription is a row: the node given to it is read
    assert [(c.kind, c.name, c.type) for c in result.calls if c.kind == "subscribe"] == [
        ("subscribe", "footprint", "geometry_msgs/msg/PolygonStamped")]


def test_parameter_value_and_type_arguments(tmp_path) -> None:
    """A declaration's default given as ``rclcpp::ParameterValue(v)`` has v's type and
    value; one given an ``rclcpp::ParameterType`` constant is typed by it, without
    default (rclcpp's declare_parameter as nav2's helpers)."""
    result = _extract(tmp_path, """\
#include <string>
#include <rclcpp/rclcpp.hpp>
class N : public rclcpp::Node {
 public:
  N() : Node("n") {
    declare_parameter("gain", rclcpp::ParameterValue(0.5));
    declare_parameter("frame", rclcpp::ParameterValue(std::string("odom")));
    declare_parameter("enabled", rclcpp::ParameterValue{true});
    declare_parameter("ids", rclcpp::PARAMETER_INTEGER_ARRAY);
    declare_parameter("rate", rclcpp::ParameterType::PARAMETER_DOUBLE);
  }
};
""")
    assert [(c.name, c.type, c.has_default, c.default) for c in result.calls] == [
        ("gain", "double", True, 0.5), ("frame", "str", True, "odom"),
        ("enabled", "bool", True, True), ("ids", "int[]", False, None),
        ("rate", "double", False, None)]


def test_helper_called_with_a_node_of_a_template_parameter(tmp_path) -> None:
    """opennav_coverage's generators declare in a constructor template on any node type
    (``template<typename NodeT> explicit Gen(const NodeT & node)``): a call clang cannot
    resolve, kept by its name as a declaration where the name may be the stand-in's."""
    result = _extract(tmp_path, """\
#include <memory>
#include <string>
#include "nav2_ros_common/lifecycle_node.hpp"
#include "nav2_ros_common/node_utils.hpp"
class Gen {
 public:
  template<typename NodeT>
  explicit Gen(const NodeT & node) {
    nav2::declare_parameter_if_not_declared(
      node, "default_type", rclcpp::ParameterValue("CONSTANT"));
    type_ = node->get_parameter("default_type").as_string();
  }
  std::string type_;
};
class Server : public nav2::LifecycleNode {
 public:
  Server() : nav2::LifecycleNode("server", "") {}
  nav2::CallbackReturn on_configure(const rclcpp_lifecycle::State &) override {
    gen_ = std::make_unique<Gen>(shared_from_this());
    return nav2::CallbackReturn::SUCCESS;
  }
  std::unique_ptr<Gen> gen_;
};
""")
    assert [(c.kind, c.name, c.type, c.has_default, c.default) for c in result.calls
            if "default_type" in c.name] == [
        ("declare", "default_type", "str", True, "CONSTANT"),
        ("read", "default_type", None, False, None)]


def test_stand_in_row_inside_a_wrapper_of_the_workspace(tmp_path) -> None:
    """A function of the workspace that passes its parameter on to a stand-in's row (a
    plugin's own helper around declare_parameter_if_not_declared) is a wrapper: the call
    is made at each of its call sites, though those are not the stand-in's."""
    result = _extract(tmp_path, """\
#include <string>
#include "nav2_util/lifecycle_node.hpp"
#include "nav2_util/node_utils.hpp"
void declare(const rclcpp_lifecycle::LifecycleNode::SharedPtr & node,
             const std::string & name, double value) {
  nav2_util::declare_parameter_if_not_declared(node, name, rclcpp::ParameterValue(value));
}
class Server : public nav2_util::LifecycleNode {
 public:
  Server() : nav2_util::LifecycleNode("server") {}
  nav2_util::CallbackReturn on_configure(const rclcpp_lifecycle::State &) override {
    declare(shared_from_this(), "gain", 0.5);
    return nav2_util::CallbackReturn::SUCCESS;
  }
};
""")
    assert [(c.kind, c.name, c.location.line) for c in result.calls if c.name == "gain"] == [
        ("declare", "gain", 12)]


SERVICE_CLIENT = """\
#include <memory>
#include "nav2_util/service_client.hpp"
#include "rclcpp/rclcpp.hpp"
#include "std_srvs/srv/set_bool.hpp"
#include "std_srvs/srv/trigger.hpp"
class Manager : public rclcpp::Node {
 public:
  Manager() : rclcpp::Node("manager") {}
  void start() {
    arm_ = std::make_shared<nav2_util::ServiceClient<std_srvs::srv::SetBool>>(
      "/driver/arm", shared_from_this());
    reset_ = std::make_shared<nav2_util::ServiceClient<std_srvs::srv::Trigger>>(
      "reset", shared_from_this(), true);
    auto request = std::make_shared<std_srvs::srv::SetBool::Request>();
    auto response = std::make_shared<std_srvs::srv::SetBool::Response>();
    if (arm_->invoke(request, response)) { arm_->wait_for_service(); }
  }
  std::shared_ptr<nav2_util::ServiceClient<std_srvs::srv::SetBool>> arm_;
  nav2_util::ServiceClient<std_srvs::srv::Trigger>::SharedPtr reset_;
};
"""


def test_service_client_of_nav2_util_is_a_client(tmp_path) -> None:
    """orca4's manager calls mavros and nav2's lifecycle manager through nav2_util's
    ``ServiceClient<S>(name, node)`` (Humble; Jazzy adds use_internal_executor): a
    name the stand-ins did not declare, so the node was given to an unknown class five
    times (CPP_NODE_TO_UNKNOWN, partial) and had none of its clients."""
    result = _extract(tmp_path, SERVICE_CLIENT)
    assert _unclean(result) == []
    assert [(c.kind, c.name, c.type, c.location.line) for c in result.calls] == [
        ("client", "/driver/arm", "std_srvs/srv/SetBool", 10),
        ("client", "reset", "std_srvs/srv/Trigger", 12)]


def test_line_iterator_of_nav2_util(tmp_path) -> None:
    """neo_local_planner2 walks a costmap's cells with ``nav2_util::LineIterator``
    (nav2_util/line_iterator.hpp, no ROS call): it was no class of the stand-in, five
    parse errors in the planner's unit."""
    result = _extract(tmp_path, """\
#include <utility>
#include <vector>
#include "nav2_util/line_iterator.hpp"
std::vector<std::pair<int, int>> cells(int x0, int y0, int x1, int y1) {
  std::vector<std::pair<int, int>> found;
  for (nav2_util::LineIterator line(x0, y0, x1, y1); line.isValid(); line.advance()) {
    found.push_back(std::make_pair(line.getX(), line.getY()));
  }
  nav2_util::LineIterator last(x0, y0, x1, y1);
  found.push_back({last.getX0() + last.getX1(), last.getY0() + last.getY1()});
  return found;
}
""")
    assert _unclean(result) == []
