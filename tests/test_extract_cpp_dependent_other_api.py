"""A member call on an object of a template parameter's type is matched against the node
API by its method's name (``wrappers.DEPENDENT``), and only against the API of the code's
own ROS: ROS 1's ``NodeHandle::subscribe`` is no call a ROS 2 unit can make. Open-RMF's
fleet adapters compile RxCpp, whose ``source.subscribe(std::move(o))`` in its operator
templates (rx-observable.hpp, rx-lift.hpp, rx-connectable_observable.hpp) made every
caller of ``on_subscribe`` a "wrapper" of a ROS subscription: each node had a dozen
subscriptions named ``?`` with no type. The same dependent call in ROS 1 code is still
taken for the handle's ``subscribe``.

Likewise a call in a template whose name clang looked up to the code's own functions only
(``set_parameters(std::forward<Rest>(rest)...)`` in the variadic constructor of the JWT
library rmf_visualization_schedule vendors, jwt.ipp:302) is one of them, not rclcpp's
``Node::set_parameters``: the schedule visualizer had five parameter writes named ``?``."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

ROS2 = """\
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
template <class Source> struct Lift {
  Source source;
  template <class Sink> void on_subscribe(Sink o) const { source.subscribe(o); }
};
struct Stream {
  void subscribe(int) const {}
};
class Adapter : public rclcpp::Node {
 public:
  Adapter() : Node("adapter") {
    pub_ = create_publisher<std_msgs::msg::String>("state", 10);
    Lift<Stream> lift;
    lift.on_subscribe(3);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Adapter>());
}
"""

ROS1 = """\
#include <string>
#include <ros/ros.h>
#include <std_msgs/String.h>
template <class Handle> struct Listener {
  Handle handle;
  ros::Subscriber sub;
  void start(const std::string & topic) { sub = handle.subscribe(topic, 1, &cb); }
  static void cb(const std_msgs::String::ConstPtr &) {}
};
int main(int argc, char ** argv) {
  ros::init(argc, argv, "listener");
  Listener<ros::NodeHandle> listener;
  listener.start("chatter");
}
"""


def _calls(tmp_path, build: str, client: str, code: str) -> list[tuple[str, str]]:
    (tmp_path / "package.xml").write_text(package_xml("pkg", build).replace(
        "</package>", f"<depend>{client}</depend></package>"))
    source = tmp_path / "node.cpp"
    source.write_text(code)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    return sorted((c.kind, c.name) for c in result.calls)


def test_a_dependent_call_in_ros2_code_is_no_ros1_handle_call(tmp_path) -> None:
    assert _calls(tmp_path, "ament_cmake", "rclcpp", ROS2) == [("publish", "state")]


def test_a_dependent_call_in_ros1_code_is_still_the_handle_call(tmp_path) -> None:
    assert ("subscribe", "chatter") in _calls(tmp_path, "catkin", "roscpp", ROS1)


TOKEN = """\
#include <memory>
#include <string>
#include <utility>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
struct Secret { std::string value; };
struct Algo { int id; };
class Token {
 public:
  template <typename First, typename... Rest> Token(First && first, Rest &&... rest) {
    set_parameters(std::forward<First>(first), std::forward<Rest>(rest)...);
  }
  template <typename... Rest> void set_parameters(Secret secret, Rest &&... rest) {
    secret_ = secret.value;
    set_parameters(std::forward<Rest>(rest)...);
  }
  template <typename... Rest> void set_parameters(Algo algo, Rest &&... rest) {
    id_ = algo.id;
    set_parameters(std::forward<Rest>(rest)...);
  }
  void set_parameters() {}
  std::string secret_;
  int id_ = 0;
};
class Viz : public rclcpp::Node {
 public:
  Viz() : Node("viz") {
    pub_ = create_publisher<std_msgs::msg::String>("markers", 10);
    Token token(Secret{"s"}, Algo{2});
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Viz>());
}
"""

# the node's own dependent call, whose lookup waits for the template argument: kept
NODE_TEMPLATE = """\
#include <memory>
#include <rclcpp/rclcpp.hpp>
template <typename NodeT> void configure(NodeT & node) {
  node.set_parameters({rclcpp::Parameter("rate", 2.0)});
}
class Viz : public rclcpp::Node {
 public:
  Viz() : Node("viz") { configure(*this); }
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Viz>());
}
"""


def test_a_call_looked_up_to_the_codes_own_functions_is_no_api_call(tmp_path) -> None:
    assert _calls(tmp_path, "ament_cmake", "rclcpp", TOKEN) == [("publish", "markers")]


def test_a_call_looked_up_to_the_codes_own_functions_hides_no_call(tmp_path) -> None:
    # with an error in the unit, the site of such a call is no place a call was missed
    code = TOKEN.replace("    secret_ = secret.value;", "    secret_ = secret.value;\n"
                         "    std::string x = undefined_thing(secret_);")
    (tmp_path / "package.xml").write_text(package_xml("pkg", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend></package>"))
    source = tmp_path / "node.cpp"
    source.write_text(code)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [d.location.line for d in result.diagnostics
            if d.code == "CPP_CALL_MISSED"] == []


def test_a_dependent_call_on_a_node_of_a_template_parameter_is_kept(tmp_path) -> None:
    assert [k for k, _ in _calls(tmp_path, "ament_cmake", "rclcpp", NODE_TEMPLATE)] == [
        "write"]
