"""A class template's server built the way nav2_ros_common builds its action servers:
a node's method template calls a factory template, which ``std::make_shared``s the
class template through its constructor template, which delegates (with arguments that
depend on a template parameter, so clang keeps no call) to the constructor over node
interfaces, which keeps the name in a member and passes that member to
``rclcpp_action::create_server`` (C's ``...`` in our stand-in takes the options and the
callback group). The server is named and typed where the node calls the factory."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

MANIFEST = """<package format="3"><name>servers</name><version>0.0.0</version>
<description>d</description><maintainer email="a@b.c">m</maintainer><license>MIT</license>
<depend>rclcpp</depend><depend>rclcpp_action</depend><depend>example_interfaces</depend>
<export><build_type>ament_cmake</build_type></export></package>
"""

HEADER = """#pragma once
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_action/rclcpp_action.hpp>
#include <example_interfaces/action/fibonacci.hpp>

// nav2_ros_common's shape: a class template whose constructor template delegates to the
// constructor over node interfaces, which keeps the name in a member and makes the server
template<typename ActionT>
class SimpleServer {
public:
  using Callback = std::function<void ()>;

  template<typename NodeT>
  explicit SimpleServer(NodeT node, const std::string & action_name, Callback callback,
                        std::chrono::milliseconds timeout = std::chrono::milliseconds(500))
  : SimpleServer(node->get_node_base_interface(), node->get_node_clock_interface(),
                 node->get_node_logging_interface(), node->get_node_waitables_interface(),
                 action_name, callback, timeout)
  {}

  explicit SimpleServer(
    rclcpp::node_interfaces::NodeBaseInterface::SharedPtr base,
    rclcpp::node_interfaces::NodeClockInterface::SharedPtr clock,
    rclcpp::node_interfaces::NodeLoggingInterface::SharedPtr logging,
    rclcpp::node_interfaces::NodeWaitablesInterface::SharedPtr waitables,
    const std::string & action_name, Callback callback,
    std::chrono::milliseconds timeout = std::chrono::milliseconds(500))
  : action_name_(action_name), callback_(callback), timeout_(timeout)
  {
    server_ = rclcpp_action::create_server<ActionT>(
      base, clock, logging, waitables, action_name_,
      std::bind(&SimpleServer::handle_goal, this, std::placeholders::_1, std::placeholders::_2),
      std::bind(&SimpleServer::handle_cancel, this, std::placeholders::_1),
      std::bind(&SimpleServer::handle_accepted, this, std::placeholders::_1),
      rcl_action_server_get_default_options(), nullptr);
  }

private:
  rclcpp_action::GoalResponse handle_goal(
    const rclcpp_action::GoalUUID &, std::shared_ptr<const typename ActionT::Goal>)
  {return rclcpp_action::GoalResponse::ACCEPT_AND_EXECUTE;}
  rclcpp_action::CancelResponse handle_cancel(
    const std::shared_ptr<rclcpp_action::ServerGoalHandle<ActionT>>)
  {return rclcpp_action::CancelResponse::ACCEPT;}
  void handle_accepted(const std::shared_ptr<rclcpp_action::ServerGoalHandle<ActionT>>) {}

  std::string action_name_;
  Callback callback_;
  std::chrono::milliseconds timeout_;
  typename rclcpp_action::Server<ActionT>::SharedPtr server_;
};

template<typename ActionT, typename NodeT>
std::shared_ptr<SimpleServer<ActionT>> make_server(
  const NodeT & node, const std::string & action_name,
  typename SimpleServer<ActionT>::Callback callback,
  std::chrono::milliseconds timeout = std::chrono::milliseconds(500))
{
  return std::make_shared<SimpleServer<ActionT>>(node, action_name, callback, timeout);
}

"""

SOURCE = """#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <example_interfaces/action/fibonacci.hpp>
#include "servers/simple_server.hpp"

class Counter : public rclcpp::Node {
public:
  Counter() : rclcpp::Node("counter") {
    server_ = make_server<example_interfaces::action::Fibonacci>(
      std::shared_ptr<rclcpp::Node>(this, [](rclcpp::Node *) {}), "count", [] {});
  }
private:
  std::shared_ptr<SimpleServer<example_interfaces::action::Fibonacci>> server_;
};

int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Counter>());
  return 0;
}
"""


def test_the_server_is_named_where_the_node_makes_it(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(MANIFEST)
    (tmp_path / "include" / "servers").mkdir(parents=True)
    (tmp_path / "include" / "servers" / "simple_server.hpp").write_text(HEADER)
    (tmp_path / "server.cpp").write_text(SOURCE)
    result = extract_cpp([str(tmp_path / "server.cpp")], scan([str(tmp_path)]),
                         cache_dir=None)
    found = [(c.kind, c.name, c.type, c.location.file, c.location.line)
             for c in result.calls]
    # before: ("action-server", "?", "?", "include/servers/simple_server.hpp", 34)
    assert found == [("action-server", "count", "example_interfaces/action/Fibonacci",
                      "server.cpp", 9)]


def test_a_delegation_to_no_wrapper_makes_none(tmp_path) -> None:
    """The same classes where the constructor over the interfaces makes no ROS call:
    no wrapper, no call."""
    (tmp_path / "package.xml").write_text(MANIFEST)
    (tmp_path / "include" / "servers").mkdir(parents=True)
    start = HEADER.index("    server_ = rclcpp_action::create_server")
    end = HEADER.index("nullptr);", start) + len("nullptr);")
    (tmp_path / "include" / "servers" / "simple_server.hpp").write_text(
        HEADER[:start] + HEADER[end:])
    (tmp_path / "server.cpp").write_text(SOURCE)
    result = extract_cpp([str(tmp_path / "server.cpp")], scan([str(tmp_path)]),
                         cache_dir=None)
    assert [c for c in result.calls if c.kind == "action-server"] == []


# navigation2's jazzy branch makes its servers so: ``std::make_unique<ActionServer>(...)``
# with ``using ActionServer = nav2_util::SimpleActionServer<Action>`` in the node's class,
# and, in a class template (nav2_behaviors' TimedBehavior<ActionT>), ``std::make_shared<
# ActionServer>(node, name_, ...)`` with ``using ActionServer = SimpleActionServer<ActionT>``
ALIASED = """#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <example_interfaces/action/fibonacci.hpp>
#include "servers/simple_server.hpp"

class Counter : public rclcpp::Node {
public:
  using CountServer = SimpleServer<example_interfaces::action::Fibonacci>;
  Counter() : rclcpp::Node("counter") {
    server_ = std::make_unique<CountServer>(
      std::shared_ptr<rclcpp::Node>(this, [](rclcpp::Node *) {}), "count", [] {});
  }
private:
  std::unique_ptr<CountServer> server_;
};

template<typename ActionT>
class Behavior {
public:
  using ActionServer = SimpleServer<ActionT>;
  void configure(std::shared_ptr<rclcpp::Node> node, const std::string & name) {
    name_ = name;
    server_ = std::make_shared<ActionServer>(node, name_, [] {});
  }
private:
  std::string name_;
  std::shared_ptr<ActionServer> server_;
};

class Repeat : public Behavior<example_interfaces::action::Fibonacci> {};

int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<Counter>();
  Repeat repeat;
  repeat.configure(node, "repeat");
  rclcpp::spin(node);
  return 0;
}
"""


def test_a_server_made_through_a_type_alias_is_named_where_it_is_made(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(MANIFEST)
    (tmp_path / "include" / "servers").mkdir(parents=True)
    (tmp_path / "include" / "servers" / "simple_server.hpp").write_text(HEADER)
    (tmp_path / "server.cpp").write_text(ALIASED)
    result = extract_cpp([str(tmp_path / "server.cpp")], scan([str(tmp_path)]),
                         cache_dir=None)
    found = sorted((c.kind, c.name, c.type, c.location.file, c.location.line)
                   for c in result.calls)
    # before: none (the alias hid the class template; the construction in the class
    # template depends on ActionT, a call clang does not resolve)
    assert found == [
        ("action-server", "count", "example_interfaces/action/Fibonacci", "server.cpp", 10),
        ("action-server", "repeat", "example_interfaces/action/Fibonacci", "server.cpp", 23)]
