"""The calls a function makes exist where it is called: they carry the source conditions
every call of it in the node's files shares, with those its caller is called under
(motoman's JointTrajectoryInterface::init(connection) calls the single-group
``init(connection, joint_names)``, whose override in another file calls the base one
back, only in the ``else`` of ``if (getJointGroups("topic_list", ...))``; the
subscription of ``JointTrajectory`` it makes is not unconditional). None where one call
is unconditional, where the function is used otherwise than called (a callback), or
where it overrides a method of a class the node's files do not define."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

IFACE_H = """
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <std_msgs/Int32.h>
#include <string>
#include <vector>
bool getGroups(const std::string & param, std::vector<int> & groups);
class Interface {
public:
  virtual ~Interface() {}
  bool init();
  virtual bool init(const std::vector<std::string> & names);
  virtual bool init(const std::vector<int> & groups);
  void single(const std_msgs::String::ConstPtr & msg) {}
  void multi(const std_msgs::Int32::ConstPtr & msg) {}
protected:
  ros::NodeHandle node_;
  ros::Subscriber sub_;
};
"""

IFACE_CPP = """
#include "iface.h"
bool getGroups(const std::string & param, std::vector<int> & groups)
{
  return ros::param::has(param);
}
bool Interface::init()
{
  std::vector<int> groups;
  if (getGroups("topic_list", groups)) {
    return init(groups);
  } else {
    std::vector<std::string> names;
    return init(names);
  }
}
bool Interface::init(const std::vector<std::string> & names)
{
  sub_ = node_.subscribe("command", 0, &Interface::single, this);
  return true;
}
bool Interface::init(const std::vector<int> & groups)
{
  sub_ = node_.subscribe("command", 0, &Interface::multi, this);
  return true;
}
"""

STREAMER_CPP = """
#include "iface.h"
class Streamer : public Interface {
public:
  using Interface::init;
  bool init(const std::vector<std::string> & names) override
  {
    bool ok = Interface::init(names);
    enable_ = node_.advertise<std_msgs::String>("enabled", 1);
    return ok;
  }
private:
  ros::Publisher enable_;
};
int main(int argc, char ** argv)
{
  ros::init(argc, argv, "streamer");
  Streamer streamer;
  streamer.init();
  ros::spin();
}
"""


def _conditions(root: Path, *sources: str) -> dict[tuple[str, str], list[str]]:
    result = extract_cpp([str(root / "drv" / "src" / s) for s in sources],
                         scan([str(root)]), cache_dir=None)
    return {(c.kind, c.type or ""): [f"{k.statement} {k.text}" for k in c.conditions]
            for c in result.calls if c.kind in ("subscribe", "publish")}


def _tree(write_tree, streamer: str = STREAMER_CPP) -> Path:
    return write_tree({"drv/package.xml": package_xml("drv"),
                       "drv/src/iface.h": IFACE_H, "drv/src/iface.cpp": IFACE_CPP,
                       "drv/src/streamer.cpp": streamer})


def test_the_calls_of_a_function_carry_its_call_sites_conditions(write_tree) -> None:
    found = _conditions(_tree(write_tree), "streamer.cpp", "iface.cpp")
    single = found[("subscribe", "std_msgs/String")]
    multi = found[("subscribe", "std_msgs/Int32")]
    assert len(single) == 1 and "getGroups" in single[0]
    assert len(multi) == 1 and "getGroups" in multi[0]
    assert single != multi  # the else branch against the then branch
    # the override, run by the base's virtual call: the same condition as the base's
    assert found[("publish", "std_msgs/String")] == single


def test_one_unconditional_call_leaves_none(write_tree) -> None:
    streamer = STREAMER_CPP.replace(
        "  streamer.init();\n",
        "  streamer.init();\n  std::vector<int> two{1, 2};\n  streamer.init(two);\n")
    found = _conditions(_tree(write_tree, streamer), "streamer.cpp", "iface.cpp")
    assert found[("subscribe", "std_msgs/Int32")] == []
    assert found[("subscribe", "std_msgs/String")] != []


def test_a_function_used_as_a_callback_may_run_anywhere(write_tree) -> None:
    streamer = STREAMER_CPP.replace(
        "  streamer.init();\n",
        "  streamer.init();\n"
        "  bool (Interface::*f)(const std::vector<int> &) = &Interface::init;\n")
    found = _conditions(_tree(write_tree, streamer), "streamer.cpp", "iface.cpp")
    assert found[("subscribe", "std_msgs/Int32")] == []


def test_a_method_a_library_class_may_call(write_tree) -> None:
    # onInit overrides nodelet::Nodelet's: the loader calls it, whatever the file does
    node = """
#include <ros/ros.h>
#include <nodelet/nodelet.h>
#include <std_msgs/String.h>
class Relay : public nodelet::Nodelet {
public:
  void onInit() override
  {
    pub_ = getNodeHandle().advertise<std_msgs::String>("out", 1);
  }
  void restart(bool again) { if (again) { onInit(); } }
private:
  ros::Publisher pub_;
};
"""
    root = write_tree({"drv/package.xml": package_xml("drv"), "drv/src/relay.cpp": node})
    result = extract_cpp([str(root / "drv" / "src" / "relay.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.name, c.conditions) for c in result.calls if c.kind == "publish"] == [
        ("out", ())]


def test_an_error_that_may_hide_a_call_leaves_none(write_tree) -> None:
    # the parse drops a statement that names init: it may call it unconditionally
    streamer = STREAMER_CPP.replace(
        "int main(", "void again(Streamer & s) { s.init(unknown_names); }\nint main(")
    found = _conditions(_tree(write_tree, streamer), "streamer.cpp", "iface.cpp")
    assert found[("subscribe", "std_msgs/String")] == []
    assert found[("subscribe", "std_msgs/Int32")] == []


def test_a_loop_around_the_call_is_not_carried(write_tree) -> None:
    # a helper called once per element of a list: its calls are made per element
    node = IFACE_CPP.replace(
        "    return init(groups);\n",
        "    for (int g : groups) { init(groups); }\n    return true;\n")
    root = write_tree({"drv/package.xml": package_xml("drv"), "drv/src/iface.h": IFACE_H,
                       "drv/src/iface.cpp": node, "drv/src/streamer.cpp": STREAMER_CPP})
    found = _conditions(root, "streamer.cpp", "iface.cpp")
    assert found[("subscribe", "std_msgs/Int32")] == ['if getGroups("topic_list", groups)']


MANAGER_H = """
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
struct Resources { bool loaded() const; };
class Manager : public rclcpp::Node {
public:
  Manager(std::shared_ptr<rclcpp::Executor> executor, const std::string & name);
  Manager(std::unique_ptr<Resources> resources, std::shared_ptr<rclcpp::Executor> executor,
          const std::string & name);
private:
  void subscribe_to_description();
  void on_description(const std_msgs::msg::String & msg) {}
  std::unique_ptr<Resources> resources_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};
"""

MANAGER_CPP = """
#include "manager.hpp"
Manager::Manager(std::shared_ptr<rclcpp::Executor> executor, const std::string & name)
: rclcpp::Node(name) {
  std::string description = "";
  get_parameter("robot_description", description);
  if (description.empty()) {
    subscribe_to_description();
  }
}
Manager::Manager(std::unique_ptr<Resources> resources,
                 std::shared_ptr<rclcpp::Executor> executor, const std::string & name)
: rclcpp::Node(name), resources_(std::move(resources)) {
  if (!resources_->loaded()) {
    subscribe_to_description();
  }
}
void Manager::subscribe_to_description() {
  sub_ = create_subscription<std_msgs::msg::String>(
    "~/robot_description", rclcpp::QoS(1).transient_local(),
    std::bind(&Manager::on_description, this, std::placeholders::_1));
}
"""

MANAGER_MAIN = """
#include "manager.hpp"
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto executor = std::make_shared<rclcpp::executors::MultiThreadedExecutor>();
  auto cm = std::make_shared<Manager>(executor, "controller_manager");
  executor->add_node(cm);
  executor->spin();
}
"""


def test_a_site_in_a_constructor_the_node_never_builds_is_none(write_tree) -> None:
    # humble ros2_control_node builds ControllerManager(executor, name), whose
    # constructor subscribes ~/robot_description only when no robot_description
    # parameter is given; the other constructor, never built there, subscribes under
    # another condition: the subscription carried none, and every humble launch that
    # gives the manager its description had a false subscriber-without-publisher
    # (franka_ros2; survey Z23)
    root = write_tree({"cm/package.xml": package_xml("cm", "ament_cmake"),
                       "cm/src/manager.hpp": MANAGER_H, "cm/src/manager.cpp": MANAGER_CPP,
                       "cm/src/main.cpp": MANAGER_MAIN})
    result = extract_cpp([str(root / "cm" / "src" / s) for s in ("main.cpp", "manager.cpp")],
                         scan([str(root)]), cache_dir=None)
    (sub,) = [c for c in result.calls if c.kind == "subscribe"]
    assert [f"{k.statement} {k.text}" for k in sub.conditions] == [
        "if description.empty()"]
