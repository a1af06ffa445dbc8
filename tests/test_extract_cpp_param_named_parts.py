"""A name built around a parameter's value (``"/" + robot_name + "/base_feedback"`` with
``robot_name`` read from ``~robot_name``) keeps its text, and the graph puts the
parameter's value in its one ``?``. ros_kortex's examples pass ``robot_name`` to helper
functions (example_full_arm_movement.cpp:155-161): their 10 service clients and a
subscription were all named ``/my_gen3``, the parameter's value alone."""

from __future__ import annotations

import pytest

from haros_arch.extract.cpp import extract_cpp
from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Node
from haros_arch.workspace import Workspace, scan
from tests.conftest import package_xml

NODE = """
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <std_srvs/Empty.h>
void cb(const std_msgs::String::ConstPtr & m) {}
bool helper(ros::NodeHandle n, const std::string & robot_name)
{
  ros::ServiceClient c = n.serviceClient<std_srvs::Empty>("/" + robot_name + "/base/clear");
  ros::Subscriber s = n.subscribe(robot_name + "/feedback", 1, &cb);
  return true;
}
int main(int argc, char ** argv)
{
  ros::init(argc, argv, "ex");
  ros::NodeHandle n;
  std::string robot_name = "my_gen3";
  ros::param::get("~robot_name", robot_name);
  ros::ServiceClient c = n.serviceClient<std_srvs::Empty>("/" + robot_name + "/direct");
  helper(n, robot_name);
  std::string first, second;
  ros::param::get("~first", first);
  ros::param::get("~second", second);
  ros::Publisher p = n.advertise<std_msgs::String>("/" + first + "/" + second, 1);
}
"""


def test_a_name_around_a_parameter_value_keeps_its_text(write_tree) -> None:
    root = write_tree({"ex/package.xml": package_xml("ex"), "ex/src/node.cpp": NODE})
    result = extract_cpp([str(root / "ex" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    calls = sorted((c.kind, c.name, c.name_param) for c in result.calls if c.kind != "read")
    assert calls == [
        ("client", "/?/base/clear", "~robot_name"),
        ("client", "/?/direct", "~robot_name"),
        # two parameters: each '?' a parameter's value (below)
        ("publish", "/?/?", "~first"),
        ("subscribe", "?/feedback", "~robot_name"),
    ]
    node = Node("ex", "ex", calls=list(result.calls))
    config = build(Configuration("c"), LaunchModel(
        nodes=[NodeDecl("/ex", "ex", "ex")],
        params=[ParamDecl("/ex/robot_name", "arm", "str"), ParamDecl("/ex/first", "left", "str")]),
        Workspace(root="/nowhere"), {node.name: node})
    assert sorted((link.kind, link.rosname.full) for link in config.links
                  if link.kind in ("client", "subscribe", "publish")) == [
        ("client", "/arm/base/clear"), ("client", "/arm/direct"),
        # the second parameter not set: the name keeps its second '?'
        ("publish", "/left/?"), ("subscribe", "/arm/feedback")]
    # the parameter set, the second '?' is no parameter left unset
    assert "NAME_PARAM_UNSET" not in [d.code for d in config.diagnostics]


def test_a_name_of_two_parameter_values_takes_both(write_tree) -> None:
    """``"/" + first + "/" + second``, each read from a parameter: the second ``?`` is the
    second parameter's (``name_more``), as a Python name of several parameters is; the
    graph fills each from the configuration and leaves ``?`` where one is not given
    (ros_kortex's ``"/" + robot_name + "/" + prefix + ...``; survey Z23 filled the first
    only)."""
    root = write_tree({"ex/package.xml": package_xml("ex"), "ex/src/node.cpp": NODE})
    result = extract_cpp([str(root / "ex" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    [publish] = [c for c in result.calls if c.kind == "publish"]
    assert (publish.name, publish.name_param, publish.name_more) == (
        "/?/?", "~first", [["~second", None]])
    node = Node("ex", "ex", calls=list(result.calls))
    for given, expected in ((["left", "right"], "/left/right"), (["left"], "/left/?"),
                            ([], "/?/?")):
        config = build(Configuration("c"), LaunchModel(
            nodes=[NodeDecl("/ex", "ex", "ex")],
            params=[ParamDecl(f"/ex/{key}", value, "str")
                    for key, value in zip(("first", "second"), given, strict=False)]),
            Workspace(root="/nowhere"), {node.name: node})
        assert [link.rosname.full for link in config.links if link.kind == "publish"] == [
            expected]


MEMBER_NODE = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
class Hazards : public rclcpp::Node
{
public:
  Hazards() : rclcpp::Node("hazards")
  {
    topic_ =
      this->declare_parameter("publisher_topic", "hazard_detection");
    pub_ = create_publisher<std_msgs::msg::String>(topic_, rclcpp::SensorDataQoS());
    later_ = this->declare_parameter("later_topic", std::string("later"));
  }
  void start() { sub_ = create_subscription<std_msgs::msg::String>(later_, 10, cb); }
  static void cb(const std_msgs::msg::String::SharedPtr) {}
  std::string topic_, later_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};
"""


def test_a_name_held_by_a_member_the_parameter_was_assigned_to(write_tree) -> None:
    """``topic_ = declare_parameter("publisher_topic", "x")`` then ``create_publisher(
    topic_, ..)``, in the constructor or in another method: the name is the parameter's
    value, as it is through a local variable (create3_sim's hazards_vector_publisher.cpp:18-29
    and seven more of its nodes named their topics '?')."""
    root = write_tree({"ex/package.xml": package_xml("ex", "ament_cmake"),
                       "ex/src/node.cpp": MEMBER_NODE})
    result = extract_cpp([str(root / "ex" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    calls = sorted((c.kind, c.name, c.name_param, c.name_default) for c in result.calls
                   if c.kind in ("publish", "subscribe"))
    assert calls == [("publish", "?", "publisher_topic", "hazard_detection"),
                     ("subscribe", "?", "later_topic", "later")]


LOOP_NODE = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
class Hazards : public rclcpp::Node
{
public:
  Hazards() : rclcpp::Node("hazards")
  {
    topics_ = this->declare_parameter("subscription_topics", std::vector<std::string>());
    for (std::string topic : topics_) {
      subs_.push_back(create_subscription<std_msgs::msg::String>(topic, 10, cb));
    }
    auto outs = this->declare_parameter("publish_topics", std::vector<std::string>());
    for (const std::string & out : outs) {
      for (const std::string & side : sides_) {
        if (out.find(side) != std::string::npos) {
          pubs_.push_back(create_publisher<std_msgs::msg::String>(out, 10));
        }
      }
    }
  }
  static void cb(const std_msgs::msg::String::SharedPtr) {}
  std::vector<std::string> topics_;
  std::vector<std::string> sides_{"left", "right"};
  std::vector<rclcpp::Subscription<std_msgs::msg::String>::SharedPtr> subs_;
  std::vector<rclcpp::Publisher<std_msgs::msg::String>::SharedPtr> pubs_;
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Hazards>());
}
"""

LOOP_LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='ex', executable='hazards', name='hazards',
             parameters=[{'subscription_topics': ['bumper', '/cliff/left']}]),
    ])
"""


def test_a_call_in_a_loop_over_a_list_parameter_is_one_call_per_element(write_tree) -> None:
    """``for (std::string topic : topics_) create_subscription(topic, ..)`` with
    ``topics_`` a list parameter: one subscription per element the configuration gives
    the list (create3_sim's hazards_vector_publisher.cpp:51-58 subscribes its eight
    hazard topics so, its sensors_node its cliff and IR topics: all were '?'); the loop is
    then no condition of each. A list the configuration does not set keeps the one call,
    named '?', under its loop ("for each")."""
    import os

    from haros_arch.pipeline import Options, analyse
    from haros_arch.project import load

    root = write_tree({
        "src/ex/package.xml": package_xml("ex", "ament_cmake"),
        "src/ex/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(ex)\n"
                                 "add_executable(hazards src/node.cpp)\n",
        "src/ex/src/node.cpp": LOOP_NODE,
        "src/ex/launch/ex.launch.py": LOOP_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [ex/launch/ex.launch.py]\n"})
    result = extract_cpp([str(root / "src/ex/src/node.cpp")], scan([str(root / "src")]),
                         cache_dir=None)
    made = [(c.kind, c.name, c.name_param, c.name_each, [str(x) for x in c.conditions])
            for c in result.calls if c.kind in ("publish", "subscribe")]
    assert made == [
        ("subscribe", "?", "subscription_topics", ".",
         ["for each (std::string topic : topics_)"]),
        ("publish", "?", "publish_topics", ".",
         ["for each (const std::string & out : outs)",
          "for (const std::string & side : sides_)",
          "if (out.find(side) != std::string::npos)"])]
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    links = sorted((link.kind, link.rosname.full, tuple(str(c) for c in link.conditions))
                   for link in model.configuration("c").links
                   if link.kind in ("publish", "subscribe"))
    assert links == [
        ("publish", "?", ("for each (const std::string & out : outs)",
                          "for (const std::string & side : sides_)",
                          "if (out.find(side) != std::string::npos)")),
        ("subscribe", "/bumper", ()), ("subscribe", "/cliff/left", ())]


MAP_NODE = """
#include <map>
#include <rclcpp/rclcpp.hpp>
class Teleop : public rclcpp::Node
{
public:
  Teleop() : rclcpp::Node("teleop")
  {
    std::map<std::string, int64_t> default_linear_map{
      {"x", 5L},
      {"y", -1L},
    };
    this->declare_parameters("axis_linear", default_linear_map);
    this->get_parameters("axis_linear", linear_);
    std::map<std::string, double> changed{{"a", 1.0}};
    changed["b"] = 2.0;
    this->declare_parameters("changed", changed);
    this->get_parameters("changed", changed);
    this->get_parameters("other", linear_);
  }
  std::map<std::string, int64_t> linear_;
};
"""


def test_declare_parameters_of_a_local_map_declares_its_keys(write_tree) -> None:
    """teleop_twist_joy.cpp:89-94: ``declare_parameters("axis_linear", m)`` with ``m`` a
    local map initialised with string keys declares ``axis_linear.x`` ... each with the
    map's value as its default; it was ``axis_linear.?`` (5 settings of its launch files
    undecided). A map the body also changes keeps '?'. ``get_parameters(prefix, out)``
    reads what the node declared under the prefix: the keys declared there (it was
    ``axis_linear.?``, six unresolved names in teleop_twist_joy's launch); where they are
    not known, every parameter the node has under it: one read ``under`` the prefix,
    named with its ``.``, with nothing there an empty map, no error. Each declaration has
    the map's value type (it was '?')."""
    root = write_tree({"ex/package.xml": package_xml("ex", "ament_cmake"),
                       "ex/src/node.cpp": MAP_NODE})
    result = extract_cpp([str(root / "ex" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name, c.type, c.has_default, c.under) for c in result.calls] == [
        ("declare", "axis_linear.x", "int", True, False),
        ("declare", "axis_linear.y", "int", True, False),
        ("read", "axis_linear.x", None, False, False),
        ("read", "axis_linear.y", None, False, False),
        ("declare", "changed.?", "double", True, False),
        ("read", "changed.", None, True, True), ("read", "other.", None, True, True)]


ELEMENT_PART_NODE = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
class Monitor : public rclcpp::Node
{
public:
  Monitor() : rclcpp::Node("monitor")
  {
    std::vector<std::string> polygon_names =
      declare_parameter<std::vector<std::string>>("polygons", std::vector<std::string>());
    for (std::string polygon_name : polygon_names) {
      const std::string type = declare_parameter<std::string>(polygon_name + ".type", "");
      subs_.push_back(create_subscription<std_msgs::msg::String>(
        "/" + polygon_name + "/points", 10, &Monitor::cb));
    }
  }
  static void cb(const std_msgs::msg::String::SharedPtr) {}
  std::vector<rclcpp::Subscription<std_msgs::msg::String>::SharedPtr> subs_;
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Monitor>());
}
"""

# the list read through a wrapper of declare_parameter, as navigation2's LifecycleNode
# gives (``node->declare_or_get_parameter<std::vector<std::string>>("polygons")``)
WRAPPED_ELEMENT_NODE = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
class Base : public rclcpp::Node
{
public:
  Base() : rclcpp::Node("monitor") {}
  template<class T>
  T declare_or_get(const std::string & name, const T & value = T())
  {
    if (!has_parameter(name)) {
      return declare_parameter<T>(name, value);
    }
    return get_parameter(name).get_value<T>();
  }
};
class Monitor : public Base
{
public:
  Monitor()
  {
    std::vector<std::string> polygon_names =
      declare_or_get<std::vector<std::string>>("polygons");
    for (std::string polygon_name : polygon_names) {
      const std::string type = declare_or_get<std::string>(polygon_name + ".type");
      subs_.push_back(create_subscription<std_msgs::msg::String>(
        "/" + polygon_name + "/points", 10, &Monitor::cb));
    }
  }
  static void cb(const std_msgs::msg::String::SharedPtr) {}
  std::vector<rclcpp::Subscription<std_msgs::msg::String>::SharedPtr> subs_;
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Monitor>());
}
"""

# a loop counting over the list, its ids kept in a member of a member, as navigation2's
# controller server does (``params_.controller_ids[i]``, parameter_handler.cpp:130-132)
COUNTED_ELEMENT_NODE = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
struct Params { std::vector<std::string> ids; };
class Monitor : public rclcpp::Node
{
public:
  Monitor() : rclcpp::Node("monitor")
  {
    params_.ids = declare_parameter<std::vector<std::string>>(
      "polygons", std::vector<std::string>());
    for (size_t i = 0; i != params_.ids.size(); i++) {
      const std::string type = declare_parameter<std::string>(params_.ids[i] + ".type", "");
      subs_.push_back(create_subscription<std_msgs::msg::String>(
        "/" + params_.ids[i] + "/points", 10, &Monitor::cb));
    }
    for (size_t i = 1; i < params_.ids.size(); i++) {  // not each element
      declare_parameter<int>(params_.ids[i] + ".other", 0);
    }
  }
  static void cb(const std_msgs::msg::String::SharedPtr) {}
  Params params_;
  std::vector<rclcpp::Subscription<std_msgs::msg::String>::SharedPtr> subs_;
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Monitor>());
}
"""

ELEMENT_PART_LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='ex', executable='monitor', name='collision_monitor',
             parameters=[{'polygons': ['FootprintApproach', 'Stop'],
                          'FootprintApproach.type': 'polygon', 'Stop.type': 'circle',
                          'Slow.type': 'circle'}]),
    ])
"""


@pytest.mark.parametrize("code", [ELEMENT_PART_NODE, WRAPPED_ELEMENT_NODE,
                                  COUNTED_ELEMENT_NODE])
def test_a_name_made_of_each_element_of_a_list_parameter(write_tree, code: str) -> None:
    """``for (std::string polygon_name : polygon_names)`` over a list parameter, reading
    ``polygon_name + ".type"`` (navigation2's collision monitor,
    collision_monitor_node.cpp:307-312): one read per element the configuration gives,
    the element in the place of the ``?`` (was ``~/?.type``, so every polygon's settings
    were set and never read by name); the text around the element stays."""
    import os

    from haros_arch.pipeline import Options, analyse
    from haros_arch.project import load
    from haros_arch.query.catalogue import run_catalogue

    root = write_tree({
        "src/ex/package.xml": package_xml("ex", "ament_cmake"),
        "src/ex/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(ex)\n"
                                 "add_executable(monitor src/node.cpp)\n",
        "src/ex/src/node.cpp": code,
        "src/ex/launch/ex.launch.py": ELEMENT_PART_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [ex/launch/ex.launch.py]\n"})
    result = extract_cpp([str(root / "src/ex/src/node.cpp")], scan([str(root / "src")]),
                         cache_dir=None)
    made = {(c.kind, c.name, c.name_param, c.name_each) for c in result.calls
            if c.kind in ("subscribe", "declare", "read") and c.name != "polygons"
            and c.location.line > (20 if code is WRAPPED_ELEMENT_NODE else 0)
            and "other" not in c.name}
    # (the wrapper's own declare_parameter<T> depends on T: kept where it is written)
    assert made == {("read" if code is WRAPPED_ELEMENT_NODE else "declare", "?.type",
                     "polygons", "."), ("subscribe", "/?/points", "polygons", ".")}
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    config = model.configuration("c")
    assert sorted(link.rosname.full for link in config.links if link.kind == "subscribe"
                  ) == ["/FootprintApproach/points", "/Stop/points"]
    read = {link.rosname.full for link in config.links if link.kind == "read"}
    assert {"/collision_monitor/FootprintApproach.type", "/collision_monitor/Stop.type",
            "/collision_monitor/polygons"} <= read
    if code is WRAPPED_ELEMENT_NODE:
        return  # its dependent declaration keeps a '?': "set, not read" is undecided
    if code is COUNTED_ELEMENT_NODE:
        assert [c.name_param for c in result.calls if "other" in c.name] == [None]
        return
    assert len(read) == 3
    # the one set for no polygon of the list is set and never read
    unread = [f.message for f in run_catalogue(model) if f.rule == "parameter-set-not-read"]
    assert [m for m in unread if m.startswith("/collision_monitor/Slow.type ")]
    assert not [m for m in unread if m.startswith(("/collision_monitor/Stop.type ",
                                                   "/collision_monitor/FootprintApproach"))]


POLYGON_H = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
class Polygon
{
public:
  Polygon(rclcpp::Node * node, const std::string & polygon_name);
  void configure();
protected:
  rclcpp::Node * node_;
  std::string polygon_name_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};
"""

POLYGON_CPP = """
#include "ex/polygon.hpp"
#include "ex/zone.hpp"
Polygon::Polygon(rclcpp::Node * node, const std::string & polygon_name)
: node_(node), polygon_name_(polygon_name) {}
void Polygon::configure()
{
  node_->declare_parameter<bool>(polygon_name_ + ".enabled", true);
  sub_ = node_->create_subscription<std_msgs::msg::String>(
    polygon_name_ + "/points", 10, [](const std_msgs::msg::String::SharedPtr) {});
  // a list named after what another file passes: its elements are not known here
  std::vector<std::string> zones = node_->declare_parameter<std::vector<std::string>>(
    polygon_name_ + ".zones", std::vector<std::string>());
  for (std::string zone : zones) {
    Zone(node_, zone);
  }
}
"""

ZONE_H = """
#include <rclcpp/rclcpp.hpp>
class Zone
{
public:
  Zone(rclcpp::Node * node, const std::string & zone_name);
};
"""

ZONE_CPP = """
#include "ex/zone.hpp"
Zone::Zone(rclcpp::Node * node, const std::string & zone_name)
{
  node->declare_parameter<bool>(zone_name + ".visible", true);
}
"""

MONITOR_CPP = """
#include <memory>
#include "ex/polygon.hpp"
class Monitor : public rclcpp::Node
{
public:
  Monitor() : rclcpp::Node("monitor")
  {
    std::vector<std::string> names =
      declare_parameter<std::vector<std::string>>("polygons", std::vector<std::string>());
    for (std::string polygon_name : names) {
      polygons_.push_back(std::make_shared<Polygon>(this, polygon_name));
      polygons_.back()->configure();
    }
    std::string single = declare_parameter<std::string>("single", "one");
    polygons_.push_back(std::make_shared<Polygon>(this, "/" + single));
  }
  std::vector<std::shared_ptr<Polygon>> polygons_;
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Monitor>());
}
"""


def test_a_list_parameter_element_given_to_a_class_of_another_file(write_tree) -> None:
    """navigation2's collision monitor makes a ``Polygon`` per name of its ``polygons``
    list (collision_monitor_node.cpp:309-317), and the polygon, in polygon.cpp, reads
    ``polygon_name_ + ".enabled"`` and the rest: across the files of the node the call
    is named by each element of the list (``name_each``), and by the parameter a name
    given once holds (``name_param``)."""
    from haros_arch.extract.cpp import extract_cpp_nodes

    root = write_tree({"ex/package.xml": package_xml("ex", "ament_cmake"),
                       "ex/include/ex/polygon.hpp": POLYGON_H,
                       "ex/include/ex/zone.hpp": ZONE_H,
                       "ex/src/zone.cpp": ZONE_CPP,
                       "ex/src/polygon.cpp": POLYGON_CPP,
                       "ex/src/monitor.cpp": MONITOR_CPP})
    src = root / "ex" / "src"
    batch = extract_cpp_nodes([[str(src / "monitor.cpp"), str(src / "polygon.cpp"),
                                str(src / "zone.cpp")]],
                              scan([str(root)]), cache_dir=None, jobs=1)
    made = sorted((c.kind, c.name, c.name_param, c.name_each)
                  for c in batch.results[0].calls
                  if c.location.file.endswith("polygon.cpp"))
    assert made == [("declare", "/?.enabled", "single", None),
                    ("declare", "/?.zones", "single", None),
                    ("declare", "?.enabled", "polygons", "."),
                    ("declare", "?.zones", "polygons", "."),
                    ("subscribe", "/?/points", "single", None),
                    ("subscribe", "?/points", "polygons", ".")]
    zones = [(c.kind, c.name, c.name_param) for c in batch.results[0].calls
             if c.location.file.endswith("zone.cpp")]
    assert zones == [("declare", "?.visible", None)]


DEFAULT_LIST_NODE = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
class Wheels : public rclcpp::Node
{
public:
  Wheels() : rclcpp::Node("wheels")
  {
    auto names = declare_parameter<std::vector<std::string>>("wheels", {"left", "right"});
    for (const auto & w : names) {
      pubs_.push_back(create_publisher<std_msgs::msg::String>(w + "/cmd", 10));
    }
    auto cams = declare_parameter("cameras", std::vector<std::string>{"front"});
    for (const auto & c : cams) {
      subs_.push_back(create_subscription<std_msgs::msg::String>(c, 10, cb));
    }
  }
  static void cb(const std_msgs::msg::String::SharedPtr) {}
  std::vector<rclcpp::Publisher<std_msgs::msg::String>::SharedPtr> pubs_;
  std::vector<rclcpp::Subscription<std_msgs::msg::String>::SharedPtr> subs_;
};
"""


def test_a_list_parameter_s_default_in_code_gives_its_elements(write_tree) -> None:
    """``declare_parameter<std::vector<std::string>>("wheels", {"left", "right"})``:
    the braced list is the declaration's default (it was none), and a call named by
    each element of a list the configuration does not set is one call per element of
    that default (``/left/cmd``, ``/right/cmd``; they were ``/?/cmd``); a value the
    launch file gives wins."""
    import os

    from haros_arch.pipeline import Options, analyse
    from haros_arch.project import load

    launch = LOOP_LAUNCH.replace("executable='hazards', name='hazards',\n             "
                                 "parameters=[{'subscription_topics': ['bumper', "
                                 "'/cliff/left']}]",
                                 "executable='wheels', name='wheels',\n             "
                                 "parameters=[{'cameras': ['rear']}]")
    root = write_tree({
        "src/ex/package.xml": package_xml("ex", "ament_cmake"),
        "src/ex/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(ex)\n"
                                 "add_executable(wheels src/node.cpp)\n",
        "src/ex/src/node.cpp": DEFAULT_LIST_NODE,
        "src/ex/launch/ex.launch.py": launch,
        "project.yaml": "project: p\nconfigurations:\n  c: [ex/launch/ex.launch.py]\n"})
    result = extract_cpp([str(root / "src/ex/src/node.cpp")], scan([str(root / "src")]),
                         cache_dir=None)
    declared = {c.name: c.default for c in result.calls if c.kind == "declare"}
    assert declared == {"wheels": ["left", "right"], "cameras": ["front"]}
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    links = sorted((link.kind, link.rosname.full) for link in model.configuration("c").links
                   if link.kind in ("publish", "subscribe"))
    assert links == [("publish", "/left/cmd"), ("publish", "/right/cmd"),
                     ("subscribe", "/rear")]


INIT_PARAM_NODE = """
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
class Lidar : public rclcpp::Node
{
public:
  Lidar() : rclcpp::Node("lidar")
  {
    init_param();
    pub_ = create_publisher<std_msgs::msg::String>(topic_name_, 10);
    frames_ = create_publisher<std_msgs::msg::String>(frame_topic_, 10);
    twice_ = create_publisher<std_msgs::msg::String>(changed_, 10);
  }

private:
  void init_param()
  {
    this->declare_parameter<std::string>("topic_name", "scan");
    this->get_parameter("topic_name", topic_name_);
    frame_topic_ = this->declare_parameter("frame_topic", std::string("frames"));
    changed_ = this->declare_parameter("changed", std::string("a"));
  }
  void later() { changed_ = "b"; }
  std::string topic_name_, frame_topic_, changed_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_, frames_, twice_;
};
"""


def test_a_member_a_method_stores_a_parameter_in_names_the_call(write_tree) -> None:
    """rplidar_ros / sllidar_ros2: the constructor calls ``init_param()``, which stores
    the parameters in members (``get_parameter("topic_name", topic_name_)``, ``frame_ =
    declare_parameter(..)``), then makes its publisher on the member: the name is that
    parameter's value (it was ``?``) where that is the member's one write in the file;
    a member written twice stays unknown."""
    root = write_tree({
        "src/ex/package.xml": package_xml("ex", "ament_cmake"),
        "src/ex/src/node.cpp": INIT_PARAM_NODE})
    result = extract_cpp([str(root / "src/ex/src/node.cpp")], scan([str(root / "src")]),
                         cache_dir=None)
    made = [(c.name, c.name_param, c.name_default) for c in result.calls
            if c.kind == "publish"]
    assert made == [("?", "topic_name", "scan"), ("?", "frame_topic", "frames"),
                    ("?", None, None)]


LAYERS_NODE = """
#include <map>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <vendor/metric_map.h>
class Maps : public rclcpp::Node
{
public:
  Maps() : rclcpp::Node("maps")
  {
    declare_parameter<std::string>("pub_topic", prefix_);
    get_parameter("pub_topic", prefix_);
    for (const auto & [layer, data] : map_.layers) {
      pubs_[layer] = create_publisher<std_msgs::msg::String>(prefix_ + "/" + layer, 1);
      grids_[layer] = create_publisher<std_msgs::msg::String>(
        prefix_ + "/" + layer + "_grid", 1);
    }
  }
  std::string prefix_ = "map_server";
  vendor::MetricMap map_;
  std::map<std::string, rclcpp::Publisher<std_msgs::msg::String>::SharedPtr> pubs_, grids_;
};
"""


def test_a_parameter_then_a_value_not_known_the_parameter_fills_its_place(write_tree) -> None:
    """mrpt_map_server publishes each layer of its map on ``pub_mm_topic_ + "/" +
    layerName + "_gridmap"``, the layer's name a value of MRPT's (a library the parse
    does not have): the name was ``/?/?_gridmap`` whatever the launch file set; the
    parameter's value fills its first '?' (survey Z23), a global value too."""
    root = write_tree({"maps/package.xml": package_xml("maps", "ament_cmake"),
                       "maps/src/node.cpp": LAYERS_NODE})
    result = extract_cpp([str(root / "maps" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.name, c.name_param, c.name_default) for c in result.calls
            if c.kind == "publish"] == [
        ("?/?", "pub_topic", "map_server"), ("?/?_grid", "pub_topic", "map_server")]
    node = Node("maps", "maps", calls=list(result.calls))
    for value, names in ((None, ["/map_server/?", "/map_server/?_grid"]),
                         ("/mrpt_map", ["/mrpt_map/?", "/mrpt_map/?_grid"])):
        params = [] if value is None else [ParamDecl("/maps/pub_topic", value, "str")]
        config = build(Configuration("c"), LaunchModel(
            nodes=[NodeDecl("/maps", "maps", "maps", ros_version=2)], params=params),
            Workspace(root="/nowhere"), {node.name: node})
        assert [link.rosname.full for link in config.links if link.kind == "publish"] == names
        assert "NAME_PARAM_UNSET" not in [d.code for d in config.diagnostics]
