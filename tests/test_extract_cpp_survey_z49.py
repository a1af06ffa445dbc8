"""What real ROS 2 code needed of the C++ extraction (survey Z49).

- yasmin's ``ROSClientsCache`` keys its cached publishers and clients by
  ``std::type_index(typeid(MsgT))``, its ``GetParametersState`` tests a blackboard value's
  ``std::any::type()`` and reads ``Parameter::as_byte_array()``: the stand-ins lacked the
  three, the functions that make the calls were C++ errors and four demo nodes partial.
- yasmin's state class templates call the cache's static member template,
  ``ROSClientsCache::get_or_create_publisher<MsgT>(node, topic_name, qos)``: in the class
  template the call is not resolved, so the class ``ROSClientsCache`` was not known as
  the qualifier and was taken for the message type (``yasmin_ros/ROSClientsCache``)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan


def _package(tmp_path, *depends: str) -> None:
    (tmp_path / "package.xml").write_text(package_xml("z49", "ament_cmake").replace(
        "</license>", "</license>" + "".join(f"<depend>{d}</depend>" for d in depends)))


CACHE = """\
#include <any>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <typeindex>
#include <typeinfo>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/int32.hpp>
class Cache {
 public:
  template <typename MsgT>
  static typename rclcpp::Publisher<MsgT>::SharedPtr get(rclcpp::Node::SharedPtr node,
                                                          const std::string & topic) {
    auto key = std::make_tuple(topic, std::type_index(typeid(MsgT)));
    auto & pubs = publishers();
    auto it = pubs.find(key);
    if (it != pubs.end()) {
      return std::static_pointer_cast<rclcpp::Publisher<MsgT>>(it->second);
    }
    auto pub = node->create_publisher<MsgT>(topic, 10);
    pubs[key] = std::static_pointer_cast<void>(pub);
    return pub;
  }
 private:
  using Key = std::tuple<std::string, std::type_index>;
  static std::map<Key, std::shared_ptr<void>> & publishers() {
    static std::map<Key, std::shared_ptr<void>> found;
    return found;
  }
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("cache");
  std::any value = std::vector<uint8_t>{};
  if (value.type() == typeid(std::vector<uint8_t>)) {
    node->declare_parameter("blob", std::vector<uint8_t>{});
    auto bytes = node->get_parameter("blob").as_byte_array();
  }
  auto pub = Cache::get<std_msgs::msg::Int32>(node, "count");
  rclcpp::spin(node);
  return 0;
}
"""


def test_type_index_any_type_and_as_byte_array(tmp_path) -> None:
    _package(tmp_path, "rclcpp", "std_msgs")
    source = tmp_path / "cache.cpp"
    source.write_text(CACHE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert not [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"]
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("declare", "blob"), ("publish", "count"), ("read", "blob")]
    assert [c.type for c in result.calls if c.kind == "publish"] == ["std_msgs/msg/Int32"]


STATE = """\
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/int32.hpp>
namespace states {
class Cache {
 public:
  template <typename MsgT>
  static typename rclcpp::Publisher<MsgT>::SharedPtr get_or_create_publisher(
      rclcpp::Node::SharedPtr node, const std::string & topic_name,
      const rclcpp::QoS & qos = rclcpp::QoS(10)) {
    return node->create_publisher<MsgT>(topic_name, qos);
  }
};
template <typename MsgT> class PublisherState {
 public:
  explicit PublisherState(const std::string & topic_name, rclcpp::QoS qos = 10)
      : PublisherState(nullptr, topic_name, qos) {}
  PublisherState(const rclcpp::Node::SharedPtr & node, const std::string & topic_name,
                 rclcpp::QoS qos = 10) {
    if (node == nullptr) {
      node_ = std::make_shared<rclcpp::Node>("states");
    } else {
      node_ = node;
    }
    pub_ = Cache::get_or_create_publisher<MsgT>(node_, topic_name, qos);
  }
 protected:
  rclcpp::Node::SharedPtr node_;
 private:
  typename rclcpp::Publisher<MsgT>::SharedPtr pub_;
};
}  // namespace states
class CountState : public states::PublisherState<std_msgs::msg::Int32> {
 public:
  CountState() : states::PublisherState<std_msgs::msg::Int32>("count") {}
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto state = std::make_shared<CountState>();
  rclcpp::shutdown();
  return 0;
}
"""


def test_a_static_member_template_called_in_a_template_is_typed_by_its_argument(
        tmp_path) -> None:
    _package(tmp_path, "rclcpp", "std_msgs")
    source = tmp_path / "state.cpp"
    source.write_text(STATE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    made = [(c.name, c.type) for c in result.calls
            if c.kind == "publish" and c.name != "?"]
    assert made == [("count", "std_msgs/msg/Int32")]


FORWARD = """\
#include <memory>
#include <set>
#include <string>
#include <vector>
#include <iterator>
#include <moveit/macros/class_forward.hpp>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_action/rclcpp_action.hpp>
#include <std_msgs/msg/string.hpp>
#include <example_interfaces/action/fibonacci.hpp>
namespace tasks {
MOVEIT_CLASS_FORWARD(Stage);
using Fibonacci = example_interfaces::action::Fibonacci;
using FibonacciServer = rclcpp_action::Server<Fibonacci>;
class Stage {
 public:
  explicit Stage(const rclcpp::Node::SharedPtr & node) {
    pub_ = node->create_publisher<std_msgs::msg::String>("stage_status", 10);
    server_ = rclcpp_action::create_server<Fibonacci>(
      node, "fibonacci",
      FibonacciServer::GoalCallback(
        [](const rclcpp_action::GoalUUID &, std::shared_ptr<const Fibonacci::Goal>) {
          return rclcpp_action::GoalResponse::ACCEPT_AND_EXECUTE;
        }),
      FibonacciServer::CancelCallback(
        [](std::shared_ptr<rclcpp_action::ServerGoalHandle<Fibonacci>>) {
          return rclcpp_action::CancelResponse::ACCEPT;
        }),
      FibonacciServer::AcceptedCallback(
        [](std::shared_ptr<rclcpp_action::ServerGoalHandle<Fibonacci>>) {}));
  }
 private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  FibonacciServer::SharedPtr server_;
};
}  // namespace tasks
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("stages");
  std::vector<std::string> names{"a", "b"};
  std::set<std::string> unique;
  std::copy(names.begin(), names.end(), std::inserter(unique, unique.end()));
  tasks::StagePtr stage = std::make_shared<tasks::Stage>(node);
  tasks::StageConstPtr seen = stage;
  rclcpp::spin(node);
  return 0;
}
"""


def test_moveit_class_forward_action_server_callback_types_and_inserter(tmp_path) -> None:
    # moveit_task_constructor: ``MOVEIT_CLASS_FORWARD(Stage);`` of an installed
    # moveit_core (not known, the macro read as a type made ``Stage`` a variable that hid
    # the class), ``ActionServerType::GoalCallback(...)`` of rclcpp_action's Server and
    # ``std::inserter``: each was a C++ error in a function that makes ROS calls
    _package(tmp_path, "rclcpp", "rclcpp_action", "std_msgs", "example_interfaces",
             "moveit_core")
    source = tmp_path / "stages.cpp"
    source.write_text(FORWARD)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert not [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"]
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("action-server", "fibonacci"), ("publish", "stage_status")]


TWO_NODES = """\
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
namespace bridge {
void declareParameters(rclcpp::Node * node) {
  node->declare_parameter("port", 8765);
}
class Bridge : public rclcpp::Node {
 public:
  Bridge() : Node("bridge") {
    declareParameters(this);
    pub_ = create_publisher<std_msgs::msg::String>("status", 10);
  }
 private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
}  // namespace bridge
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  {
    auto dummy = std::make_shared<rclcpp::Node>("dummy");
    dummy->declare_parameter("num_threads", 0);
  }
  auto node = std::make_shared<bridge::Bridge>();
  rclcpp::spin(node);
  return 0;
}
"""


def test_a_free_helper_makes_its_calls_on_the_node_of_its_caller(tmp_path) -> None:
    # foxglove_bridge's executable makes a ``dummy`` node in main() to read num_threads,
    # then its bridge node, whose constructor calls ``declareParameters(this)``: the
    # helper's declarations had no node (the graph's '/?' node of the process), though
    # its one caller is the bridge's constructor
    _package(tmp_path, "rclcpp", "std_msgs")
    source = tmp_path / "bridge.cpp"
    source.write_text(TWO_NODES)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert result.rosnames == ["bridge", "dummy"]
    assert sorted((c.kind, c.name, c.node_name) for c in result.calls) == [
        ("declare", "num_threads", "dummy"), ("declare", "port", "bridge"),
        ("publish", "status", "bridge")]
