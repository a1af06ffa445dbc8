"""``this->member_`` in a class template, read with libclang 18.

libclang 18 keeps ``this->node_`` and ``this->topic_name`` in a class template as
dependent member accesses that refer to nothing (clang 19 looks the current instantiation
up), and asks for ``template`` before ``create_subscription<MsgT>`` called through one.
yasmin's ``MonitorState<MsgT>`` subscribes with ``this->node_->create_subscription<MsgT>(
this->topic_name, ...)``: the call was unresolved, its topic ``?`` and not given per
construction (``odom`` for the monitor demo), and its node partial for that error. The
member is now the field of that name the class (or a base it names) declares, and the
error, which a compiler does not give there, is not said.
"""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

ROS2 = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
template <typename MsgT>
class Monitor {
public:
  Monitor(rclcpp::Node::SharedPtr node, const std::string& topic) : node_(node), topic_(topic) {
    this->sub_ = this->node_->create_subscription<MsgT>(
        this->topic_, 10, [this](const typename MsgT::SharedPtr msg) { (void)msg; });
    this->pub_ = this->node_->template create_publisher<MsgT>(this->topic_ + "/echo", 10);
  }
  rclcpp::Node::SharedPtr node_;
  std::string topic_;
  typename rclcpp::Subscription<MsgT>::SharedPtr sub_;
  typename rclcpp::Publisher<MsgT>::SharedPtr pub_;
};
class Odom : public Monitor<std_msgs::msg::String> {
public:
  explicit Odom(rclcpp::Node::SharedPtr node) : Monitor<std_msgs::msg::String>(node, "odom") {}
};
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("n");
  Odom odom(node);
  rclcpp::spin(node);
}
"""

ROS1 = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
template <typename M>
class Base {
protected:
  ros::NodeHandle pnh_{"~"};
};
template <typename M>
class Derived : public Base<M> {
public:
  Derived() { pub_ = this->pnh_.template advertise<M>("state", 1); }
  ros::Publisher pub_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  Derived<std_msgs::String> d;
  ros::spin();
}
"""


def test_a_member_read_through_this_in_a_class_template(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("mon", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"))
    source = tmp_path / "mon.cpp"
    source.write_text(ROS2)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("publish", "odom/echo", "std_msgs/msg/String"),
        ("subscribe", "odom", "std_msgs/msg/String")]
    codes = {d.code for d in result.diagnostics}
    assert not codes & {"CPP_ERROR_NEAR_CALL", "CPP_CALL_UNRESOLVED", "CPP_DYNAMIC_NAME",
                        "CPP_PARSE_ERROR"}, codes


def test_a_handle_member_of_a_base_through_this(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("der").replace(
        "</package>", "<depend>roscpp</depend><depend>std_msgs</depend></package>"))
    source = tmp_path / "der.cpp"
    source.write_text(ROS1)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    # the base's private handle: ~state (was ?/state)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "~state")]
