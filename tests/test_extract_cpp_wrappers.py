"""Functions that wrap the ROS API (``extract.cpp.wrappers``): a call of a wrapper is a ROS
call at the call site, with the call site's name, type, QoS, handle and conditions; the
call inside the wrapper is not reported on its own.

``radar`` (ROS 2) is shaped like Nav2: a lifecycle node base class whose member templates
call free factory templates that call rclcpp on a ``NodeT``, a parameter wrapper with a
default, plain functions that make publishers. ``sonar`` (ROS 1): a class whose own
handle makes the publishers, a chain of three wrappers, two functions that call each
other.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.model.source import PrimitiveCall
from haros_arch.workspace import Workspace, scan

FIXTURE = Path(__file__).resolve().parent.parent / "fixtures" / "cpp" / "wrappers"
RADAR = FIXTURE / "src" / "radar" / "src" / "radar_node.cpp"
SONAR = FIXTURE / "src" / "sonar" / "src" / "sonar_node.cpp"
NODE = "src/radar/src/radar_node.cpp"


def row(call: PrimitiveCall) -> tuple[object, ...]:
    return (call.kind, call.name, call.type, call.queue_size, call.location.file,
            call.location.line, tuple(c.text for c in call.conditions))


@pytest.fixture(scope="module")
def ws() -> Workspace:
    return scan([str(FIXTURE)])


@pytest.fixture(scope="module")
def radar(ws: Workspace) -> CppResult:
    return extract_cpp([str(RADAR)], ws, cache_dir=None)


@pytest.fixture(scope="module")
def sonar(ws: Workspace) -> CppResult:
    return extract_cpp([str(SONAR)], ws, cache_dir=None)


def topics(result: CppResult) -> list[tuple[object, ...]]:
    return [row(c) for c in result.calls if c.kind in ("publish", "subscribe")]


def test_base_class_member_templates_are_calls_at_the_call_site(radar: CppResult) -> None:
    """ManagedNode::create_publisher<MessageT> -> factory::create_publisher<MessageT>
    (NodeT) -> node->create_publisher<MessageT>: the type is the call site's template
    argument, the QoS the call site's (or the wrapper's default, 10), the condition the
    call site's."""
    found = topics(radar)
    assert (("publish", "points", "sensor_msgs/msg/PointCloud2", 10, NODE, 48, ())
            in found)
    assert (("publish", "far", "sensor_msgs/msg/Range", 1, NODE, 50, ("range_ > 10.0",))
            in found)
    assert ("subscribe", "command", "std_msgs/msg/String", 10, NODE, 52, ()) in found


def test_parameter_wrapper_with_a_default(radar: CppResult) -> None:
    declared = {c.name: (c.type, c.has_default, c.default, c.location.line)
                for c in radar.calls if c.kind == "declare"}
    assert declared["range"] == ("double", True, 40.0, 46)
    assert declared["frame_id"] == ("str", True, "radar_link", 47)
    reads = {c.name for c in radar.calls if c.kind == "read"}
    assert {"range", "frame_id"} <= reads  # has_parameter / get_parameter in the wrapper


def test_free_function_wrappers_give_one_call_per_call_site(radar: CppResult) -> None:
    found = topics(radar)
    assert ("publish", "left_status", "std_msgs/msg/String", 5, NODE, 58, ()) in found
    assert ("publish", "right_status", "std_msgs/msg/String", 5, NODE, 59, ()) in found


def test_a_name_the_wrapper_builds_keeps_its_prefix(radar: CppResult) -> None:
    assert ("publish", "radar/debug", "std_msgs/msg/String", 1, NODE, 60, ()) in topics(radar)


def test_a_fixed_name_stays_where_it_is_written_once(radar: CppResult) -> None:
    """start_heartbeat() is called twice: ROS makes two publishers on one topic, the graph
    has one; the call is the one in the function, not one per call site."""
    beats = [row(c) for c in radar.calls if c.name == "heartbeat"]
    assert beats == [("publish", "heartbeat", "std_msgs/msg/Empty", 1, NODE, 31, ())]
    # a fixed name inside a template wrapper (its call depends on NodeT): once, there
    overrides = [(c.kind, c.location.file, c.location.line) for c in radar.calls
                 if c.name == "allow_qos_overrides"]
    assert ("declare", "src/radar/include/radar/factories.hpp", 27) in overrides
    assert len({c[1:] for c in overrides}) == 1


def test_the_calls_inside_wrappers_are_not_reported_with_unknown_names(
        radar: CppResult) -> None:
    assert [c.name for c in radar.calls if "?" in c.name] == []
    assert "CPP_DYNAMIC_NAME" not in [d.code for d in radar.diagnostics]
    # only what its LifecycleNode base makes by itself is located in the header
    assert [c for c in radar.calls
            if c.location.file == "src/radar/include/radar/managed_node.hpp"
            and not (c.type or "").startswith("lifecycle_msgs/")] == []


def test_a_function_that_keeps_its_string_to_itself_is_not_a_wrapper(
        radar: CppResult) -> None:
    """log_topic(node, "not_a_topic") only logs its string."""
    assert [c for c in radar.calls if "not_a_topic" in c.name] == []
    assert [c for c in radar.calls if c.location.file == NODE and c.location.line == 63] == []


def test_every_call_of_the_node(radar: CppResult) -> None:
    assert sorted(found[:2] for found in topics(radar)) == [
        ("publish", "far"), ("publish", "heartbeat"), ("publish", "left_status"),
        ("publish", "points"), ("publish", "radar/debug"), ("publish", "right_status"),
        ("publish", "~transition_event"), ("subscribe", "command")]


def test_a_handle_the_wrapper_holds_names_the_namespace(sonar: CppResult) -> None:
    """Board::channel uses the board's own handle (NodeHandle(parent, "board")): the
    namespace is the board's; the queue the call site's, or the parameter's default."""
    found = {c.name: (c.queue_size, c.handle_namespace, c.location.line)
             for c in sonar.calls}
    assert found["board/channels/front"] == (3, "board", 64)
    assert found["board/channels/rear"] == (7, "board", 65)


def test_a_chain_of_wrappers(sonar: CppResult) -> None:
    """level3 -> level2 -> level1 -> advertise: the name level3 builds, on the handle the
    call site passes, at the call site; under the call site's conditions."""
    found = {c.name: row(c)[2:] for c in sonar.calls}
    assert found["~echo/raw"] == ("std_msgs/String", 2, "src/sonar/src/sonar_node.cpp", 66,
                                  ())
    assert found["diagnostics"] == ("std_msgs/String", 2, "src/sonar/src/sonar_node.cpp",
                                    68, ("argc > 2",))


def test_functions_that_call_each_other_are_no_wrappers(sonar: CppResult) -> None:
    """ping -> pong -> ping: how deep it goes is known at run time; the advertise in ping
    is read as before (its name unknown), once, and ends."""
    unknown = [(c.name, c.location.line) for c in sonar.calls if "?" in c.name]
    assert unknown == [("?/?", 54)]


def test_wrappers_deeper_than_the_bound_still_end(tmp_path: Path) -> None:
    """A chain longer than MAX_DEPTH: the outer functions are no wrappers; the call the
    innermost summarised wrapper is given still has its name from the one call site."""
    package = tmp_path / "src" / "deep"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="2"><name>deep</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>BSD</license></package>\n')
    levels = ["void f0(ros::NodeHandle& nh, const std::string& t) {\n"
              "  static ros::Publisher p = nh.advertise<std_msgs::Empty>(t, 1);\n}\n"]
    for i in range(1, 8):
        levels.append(f"void f{i}(ros::NodeHandle& nh, const std::string& t) "
                      f"{{ f{i - 1}(nh, t); }}\n")
    source = package / "src" / "deep.cpp"
    source.write_text(
        "#include <ros/ros.h>\n#include <std_msgs/Empty.h>\n" + "".join(levels)
        + "int main(int argc, char** argv) {\n  ros::init(argc, argv, \"deep\");\n"
        "  ros::NodeHandle nh;\n  f7(nh, \"bottom\");\n}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "bottom")]


def test_a_lambda_a_getter_returns_is_a_wrapper_bound_per_call_site(ws: Workspace) -> None:
    """nav2 MPPI: ``auto getParam = handler->getParamGetter(ns)`` returns a generic lambda
    that calls the handler's ``getParam(setting, ns + "." + name, default)``, which
    declares and reads the parameter; each call of the lambda is a declaration and a read
    of ``<ns>.<name>``, with the ``ns`` its own getter was given."""
    result = extract_cpp([str(FIXTURE / "src" / "radar" / "src" / "tuning.cpp")], ws,
                         cache_dir=None)
    assert [(c.kind, c.name, c.type, c.location.file, c.location.line)
            for c in result.calls] == [
        ("declare", "?.gain", "double", "src/radar/src/tuning.cpp", 10),
        ("read", "?.gain", "double", "src/radar/src/tuning.cpp", 10),
        ("declare", "?.horizon", "int", "src/radar/src/tuning.cpp", 11),
        ("read", "?.horizon", "int", "src/radar/src/tuning.cpp", 11),
        ("declare", "global.limit", "double", "src/radar/src/tuning.cpp", 13),
        ("read", "global.limit", "double", "src/radar/src/tuning.cpp", 13),
    ]


def test_a_class_template_whose_constructor_makes_the_service(ws: Workspace) -> None:
    """nav2's ServiceServer<ServiceT>(name, node, callback) creates the service on the
    node's interfaces (rclcpp::create_service(base, services, name, callback)); made by
    a factory (make_shared inside make_server<SrvT>) or by make_shared directly, each is
    a server at the construction, typed by its template argument."""
    result = extract_cpp([str(FIXTURE / "src" / "radar" / "src" / "services.cpp")], ws,
                         cache_dir=None)
    assert [(c.kind, c.name, c.type, c.location.file, c.location.line)
            for c in result.calls] == [
        ("server", "reset", "std_srvs/srv/Empty", "src/radar/src/services.cpp", 9),
        ("server", "trigger", "std_srvs/srv/Trigger", "src/radar/src/services.cpp", 11),
    ]


def test_a_class_template_constructor_that_types_nothing_keeps_its_calls(tmp_path) -> None:
    """laser_assembler's BaseAssembler<T>(max_size_param_name) reads the parameter its
    derived class names; the type does not come from the construction, so the read stays
    in the constructor (named by what callers pass) rather than waiting for a
    construction this unit may not show."""
    (tmp_path / "base.h").write_text(
        "#include <ros/ros.h>\n#include <string>\n"
        "template<class T> class Base {\n"
        "public:\n"
        "  explicit Base(const std::string & name) {\n"
        "    ros::NodeHandle private_ns(\"~\");\n"
        "    private_ns.param(name, size_, 400);\n"
        "  }\n"
        "  int size_;\n"
        "};\n")
    (tmp_path / "n.cpp").write_text('#include "base.h"\nvoid f() {}\n')
    result = extract_cpp([str(tmp_path / "n.cpp")], Workspace(root=str(tmp_path)),
                         cache_dir=None)
    assert [(c.kind, c.location.file, c.location.line) for c in result.calls] == [
        ("read", "base.h", 7)]


def test_a_name_from_an_interface_specs_static_member(ws: Workspace) -> None:
    """Autoware's NodeAdaptor shape: ``adaptor.create_publisher<Spec>()`` ->
    ``make_publisher<SpecT>(node)`` -> ``node->create_publisher<typename
    SpecT::Message>(SpecT::name, qos)``: the call site's spec gives the name (a
    ``char[]`` or ``auto`` static member) and the type (its ``Message`` or
    ``Service``); a spec the call site does not name leaves the call, its name
    unknown."""
    node = "src/adapi/src/adapi_node.cpp"
    result = extract_cpp([str(FIXTURE / node)], ws, cache_dir=None)
    found = topics(result)
    assert found == [
        ("publish", "/api/routing/state", "std_msgs/msg/String", 1, node, 8, ()),
        ("subscribe", "/api/engage", "std_msgs/msg/Bool", 1, node, 9, ()),
        # a spec the call site does not name (a template's own parameter): kept, unknown
        ("publish", "?", None, 1, node, 42, ()),
    ]
    assert any(d.code == "CPP_DYNAMIC_NAME" and d.location.line == 42
               for d in result.diagnostics)
    # through a class template's static make_shared and constructor (Service<SpecT>);
    # the overload that takes an instance calls the other one, whose overload set holds
    # itself too: no recursion
    servers = [(c.kind, c.name, c.type, c.location.line) for c in result.calls
               if c.kind == "server"]
    assert servers == [("server", "/api/routing/clear", "std_srvs/srv/Trigger", 11),
                       ("server", "/api/routing/reset", "std_srvs/srv/Empty", 15)]


def test_a_spec_wrappers_name_as_a_type_is_no_missed_call_site(ws: Workspace) -> None:
    """``adaptor::Service<Spec>::SharedPtr member_;`` spells a spec-named wrapper class
    (its constructor makes the service) as a type, not a call: in a unit with an error
    left, the recall check does not take it for a call site with no call extracted."""
    node = "src/adapi/src/checked_node.cpp"
    result = extract_cpp([str(FIXTURE / node)], ws, cache_dir=None)
    assert [(c.kind, c.name, c.location.line) for c in result.calls] == [
        ("server", "/api/routing/clear", 11)]
    assert [d.location.line for d in result.diagnostics if d.code == "CPP_CALL_MISSED"] == []
    assert any(d.code == "CPP_PARSE_ERROR" for d in result.diagnostics)


# nav2_ros_common (main): LifecycleNode::declare_or_get_parameter(name, default) calls
# the free template over any node, which calls the overload over a logger and the
# parameters interface; another overload takes (node, name, descriptor). The overloads
# an unresolved call may be are narrowed as C++ would (``this`` is no logger), and the
# default reaches the declaration through ``rclcpp::ParameterValue{default_value}``.
NAV_COMMON = """
#pragma once
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <geometry_msgs/msg/twist.hpp>
#include <geometry_msgs/msg/twist_stamped.hpp>

namespace nav {
using Descriptor = rcl_interfaces::msg::ParameterDescriptor;

template<typename ParameterT, typename NodeT>
ParameterT declare_or_get_parameter(
  NodeT node, const std::string & parameter_name, const Descriptor & descriptor = Descriptor())
{
  if (node->has_parameter(parameter_name)) {
    return node->get_parameter(parameter_name).template get_value<ParameterT>();
  }
  auto parameter = node->declare_parameter(parameter_name, rclcpp::PARAMETER_BOOL, descriptor);
  return parameter.template get<ParameterT>();
}

template<typename ParamType>
ParamType declare_or_get_parameter(
  const rclcpp::Logger & logger,
  rclcpp::node_interfaces::NodeParametersInterface::SharedPtr param_interface,
  const std::string & parameter_name, const ParamType & default_value,
  bool warn_if_no_override = false, const Descriptor & descriptor = Descriptor())
{
  if (param_interface->has_parameter(parameter_name)) {
    rclcpp::Parameter param(parameter_name, default_value);
    param_interface->get_parameter(parameter_name, param);
    return param.get_value<ParamType>();
  }
  return param_interface->declare_parameter(
    parameter_name, rclcpp::ParameterValue{default_value}, descriptor).template get<ParamType>();
}

template<typename ParamType, typename NodeT>
ParamType declare_or_get_parameter(
  NodeT node, const std::string & parameter_name, const ParamType & default_value,
  const Descriptor & descriptor = Descriptor())
{
  return declare_or_get_parameter(
    node->get_logger(), node->get_node_parameters_interface(), parameter_name,
    default_value, false, descriptor);
}

class LifecycleNode : public rclcpp::Node {
public:
  explicit LifecycleNode(const std::string & name) : rclcpp::Node(name) {}
  template<typename ParameterT>
  ParameterT declare_or_get_parameter(
    const std::string & parameter_name, const Descriptor & descriptor = Descriptor())
  {
    return nav::declare_or_get_parameter<ParameterT>(this, parameter_name, descriptor);
  }
  template<typename ParamType>
  ParamType declare_or_get_parameter(
    const std::string & parameter_name, const ParamType & default_value,
    const Descriptor & descriptor = Descriptor())
  {
    return nav::declare_or_get_parameter(this, parameter_name, default_value, descriptor);
  }
};
}  // namespace nav
"""

DECLARE_OR_GET = """
#include "smoother/lifecycle.hpp"

class Smoother : public nav::LifecycleNode {
public:
  Smoother() : nav::LifecycleNode("smoother") {
    stamped_ = declare_or_get_parameter("enable_stamped", true);
    auto mode = declare_or_get_parameter("feedback", std::string("OPEN_LOOP"));
    if (stamped_) {
      stamped_sub_ = create_subscription<geometry_msgs::msg::TwistStamped>(
        "cmd_vel", 1, [](geometry_msgs::msg::TwistStamped::SharedPtr) {});
    } else {
      sub_ = create_subscription<geometry_msgs::msg::Twist>(
        "cmd_vel", 1, [](geometry_msgs::msg::Twist::SharedPtr) {});
    }
  }
private:
  bool stamped_{false};
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr sub_;
  rclcpp::Subscription<geometry_msgs::msg::TwistStamped>::SharedPtr stamped_sub_;
};
"""


def _with_nav_common(tmp_path, name: str, source: str) -> CppResult:
    """The calls of ``source``, a ROS 2 package's file ``name`` that includes
    ``NAV_COMMON`` as ``smoother/lifecycle.hpp``."""
    (tmp_path / "package.xml").write_text(
        '<package format="3"><name>smoother</name><version>0.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">m</maintainer>'
        '<license>MIT</license><depend>rclcpp</depend><depend>geometry_msgs</depend>'
        '<export><build_type>ament_cmake</build_type></export></package>\n')
    (tmp_path / "include" / "smoother").mkdir(parents=True)
    (tmp_path / "include" / "smoother" / "lifecycle.hpp").write_text(NAV_COMMON)
    (tmp_path / name).write_text(source)
    return extract_cpp([str(tmp_path / name)], scan([str(tmp_path)]), cache_dir=None)


def test_an_overload_chain_gives_one_declaration_and_read_per_call(tmp_path) -> None:
    """Each ``declare_or_get_parameter(name, default)`` is one declaration (typed, with
    its default) and one read of that name; it was also a read and a declaration named
    '?' and, for a string default, ones named after the default ("OPEN_LOOP")."""
    result = _with_nav_common(tmp_path, "smoother.cpp", DECLARE_OR_GET)
    found = sorted((c.kind, c.name, c.type, c.default, c.variable) for c in result.calls
                   if c.kind in ("declare", "read"))
    # (the reads typed as the template returns them: ``ParamType``, bool and string)
    assert found == [
        ("declare", "enable_stamped", "bool", True, "stamped_"),
        ("declare", "feedback", "str", "OPEN_LOOP", None),
        ("read", "enable_stamped", "bool", None, "stamped_"),
        ("read", "feedback", "str", None, None),
    ]


DEPENDENT_CALLER = """
#include <memory>
#include "smoother/lifecycle.hpp"

template<typename ActionT>
class TimedBase {
protected:
  std::weak_ptr<nav::LifecycleNode> node_;
  std::string name_;
};

template<typename ActionT = int>
class Heading : public TimedBase<ActionT> {
public:
  void onConfigure() {
    auto node = this->node_.lock();
    limit_ = node->declare_or_get_parameter("limit", 2.5);
    speed_ = node->declare_or_get_parameter(this->name_ + ".speed", 1.0);
  }
  double speed_;
  double limit_;
};
"""


def test_a_wrapper_method_called_on_a_dependent_object(tmp_path) -> None:
    """nav2's DriveOnHeading<ActionT> reads its limits through ``this->node_.lock()``,
    whose type depends on the template parameter: the call is matched to the wrapper
    methods of that name (it was no call, and the parameters the launch file sets for
    the behavior server read as never read). The name built of the base's member and a
    literal keeps the literal (a ``+`` the parse keeps as an operator: '?' it was), so
    the host fills in the plugin's name."""
    result = _with_nav_common(tmp_path, "heading.cpp", DEPENDENT_CALLER)
    assert sorted((c.kind, c.name, c.type) for c in result.calls
                  if c.location.file and c.location.file.endswith("heading.cpp")) == [
        ("declare", "?.speed", "double"), ("declare", "limit", "double"),
        ("read", "?.speed", None), ("read", "limit", None)]


def test_a_spec_deduced_from_the_type_of_the_member_given(ws: Workspace) -> None:
    """Autoware universe 0.43's adaptor: ``adaptor.init_pub(pub_)`` with ``pub_`` a
    ``Publisher<Spec>::SharedPtr``, and inside ``using SpecT = typename
    SharedPtrT::element_type::SpecType; pub = create_publisher_impl<SpecT>(node_)``: the
    spec is the member's type's (its 21 default API nodes had a publisher and a server
    named '?' in the adaptor's header each, whether they made one or not, and none of
    their own interfaces). Also through a service class template's constructor, where
    clang keeps ``SpecT::name`` as a member reference, and through a second wrapper that
    passes its own parameter on (``init_twice(other_)``)."""
    node = "src/adapi/src/deduced_node.cpp"
    result = extract_cpp([str(FIXTURE / node)], ws, cache_dir=None)
    assert [(c.kind, c.name, c.type, c.location.file, c.location.line)
            for c in result.calls] == [
        ("publish", "/api/state", "std_msgs/msg/String", node, 8),
        ("server", "/api/reset", "std_srvs/srv/Trigger", node, 9),
        ("publish", "/api/other", "std_msgs/msg/String", node, 11),
    ]
    assert not [d for d in result.diagnostics if d.code == "CPP_DYNAMIC_NAME"]


MONITOR = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>

// MoveIt 1's PlanningSceneMonitor (planning_scene_monitor.h:264-265, .cpp:333 and its
// reconfigure callback): a method whose topic parameter defaults to a class constant,
// called with that default
class Monitor {
public:
  static const std::string DEFAULT_TOPIC;
  Monitor() : nh_("~") {}
  void start(int type, const std::string& topic = DEFAULT_TOPIC);
  void reconfigure(bool on) {
    if (on)
      start(1);
  }
private:
  ros::NodeHandle nh_;
  ros::Publisher pub_;
};
const std::string Monitor::DEFAULT_TOPIC = "monitored";

void Monitor::start(int type, const std::string& topic) {
  pub_ = nh_.advertise<std_msgs::String>(topic, 100, false);
}

int main(int argc, char** argv) {
  ros::init(argc, argv, "monitor");
  Monitor m;
  m.reconfigure(true);
  m.start(2, "given");
  ros::spin();
}
"""


def test_a_wrapper_called_with_its_name_left_to_the_default(write_tree) -> None:
    """A wrapper's call that leaves the name parameter to its default passes the
    default: it is a call of that name, not no call at all (the call inside the wrapper
    is not reported on its own, so it used to be lost)."""
    from tests.conftest import package_xml

    root = write_tree({"pkg/package.xml": package_xml("pkg", "catkin"),
                       "pkg/src/node.cpp": MONITOR})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("publish", "~given", "std_msgs/String"),
        ("publish", "~monitored", "std_msgs/String")]
