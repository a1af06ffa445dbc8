"""A class template whose constructor calls a method of its own that makes the ROS
call, named after a member the constructor initialises from its parameter
(depthai_bridge's ``BridgePublisher(queue, node, rosTopic, ...) : _rosTopic(rosTopic)
{ _rosPublisher = advertise(depth, ...); }`` with ``advertise`` calling
``_node->create_publisher<RosMsg>(_rosTopic, ...)``): the call is made at each
construction, named by its argument and typed by its template argument, as when the
call is written in the constructor's body. It was one call named ``?`` of type ``?``
(``CPP_CALL_UNRESOLVED``)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

IN_CLASS = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <std_msgs/msg/int32.hpp>
template <class M>
class Bridge {
 public:
  Bridge(std::shared_ptr<rclcpp::Node> node, std::string topic, int depth)
      : node_(node), topic_(topic) {
    pub_ = advertise(depth);
  }
  typename rclcpp::Publisher<M>::SharedPtr advertise(int depth) {
    return node_->template create_publisher<M>(topic_, depth);
  }
 private:
  std::shared_ptr<rclcpp::Node> node_;
  std::string topic_;
  typename rclcpp::Publisher<M>::SharedPtr pub_;
};
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("talker");
  Bridge<std_msgs::msg::String> a(node, std::string("color/image"), 30);
  Bridge<std_msgs::msg::Int32> b(node, std::string("color/detections"), 5);
  rclcpp::spin(node);
  return 0;
}
"""

HEADER = """\
#pragma once
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
namespace bridge {
template <class RosMsg, class SimMsg>
class BridgePublisher {
public:
  BridgePublisher(std::shared_ptr<rclcpp::Node> node, const std::string& rosTopic,
                  int depth);
  typename rclcpp::Publisher<RosMsg>::SharedPtr advertise(int queueSize);
private:
  std::shared_ptr<rclcpp::Node> _node;
  std::string _rosTopic;
  typename rclcpp::Publisher<RosMsg>::SharedPtr _rosPublisher;
};
template <class RosMsg, class SimMsg>
BridgePublisher<RosMsg, SimMsg>::BridgePublisher(std::shared_ptr<rclcpp::Node> node,
                                                 const std::string& rosTopic, int depth)
    : _node(node), _rosTopic(rosTopic) {
  _rosPublisher = advertise(depth);
}
template <class RosMsg, class SimMsg>
typename rclcpp::Publisher<RosMsg>::SharedPtr BridgePublisher<RosMsg, SimMsg>::advertise(
    int queueSize) {
  return _node->create_publisher<RosMsg>(_rosTopic + "/raw", queueSize);
}
}  // namespace bridge
"""

NODE = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <std_msgs/msg/int32.hpp>
#include <bridge/bridge_publisher.hpp>
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("example");
  auto image = std::make_unique<bridge::BridgePublisher<std_msgs::msg::String, int>>(
      node, std::string("color/image"), 30);
  bridge::BridgePublisher<std_msgs::msg::Int32, int> detections(
      node, std::string("color/detections"), 10);
  rclcpp::spin(node);
}
"""

DEPENDS = "<depend>rclcpp</depend><depend>std_msgs</depend>"


def test_a_method_the_class_template_s_constructor_calls_is_named_per_construction(
        tmp_path) -> None:
    (tmp_path / "pkg" / "src").mkdir(parents=True)
    (tmp_path / "pkg" / "package.xml").write_text(package_xml("pkg", "ament_cmake").replace(
        "</package>", DEPENDS + "</package>"))
    source = tmp_path / "pkg" / "src" / "talker.cpp"
    source.write_text(IN_CLASS)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    calls = sorted((c.kind, c.name, c.type, c.queue_size) for c in result.calls)
    assert calls == [("publish", "color/detections", "std_msgs/msg/Int32", 5),
                     ("publish", "color/image", "std_msgs/msg/String", 30)], calls
    assert not [d for d in result.diagnostics if d.code == "CPP_CALL_UNRESOLVED"]


def test_an_out_of_class_method_named_after_a_member_in_a_header(tmp_path) -> None:
    (tmp_path / "bridge" / "include" / "bridge").mkdir(parents=True)
    (tmp_path / "bridge" / "package.xml").write_text(package_xml(
        "bridge", "ament_cmake").replace("</package>", DEPENDS + "</package>"))
    (tmp_path / "bridge" / "include" / "bridge" / "bridge_publisher.hpp").write_text(HEADER)
    (tmp_path / "example" / "src").mkdir(parents=True)
    (tmp_path / "example" / "package.xml").write_text(package_xml(
        "example", "ament_cmake").replace(
            "</package>", DEPENDS + "<depend>bridge</depend></package>"))
    source = tmp_path / "example" / "src" / "node.cpp"
    source.write_text(NODE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    calls = sorted((c.kind, c.name, c.type, c.queue_size) for c in result.calls)
    assert calls == [("publish", "color/detections/raw", "std_msgs/msg/Int32", 10),
                     ("publish", "color/image/raw", "std_msgs/msg/String", 30)], calls


def test_a_method_also_called_outside_a_constructor_keeps_its_call(tmp_path) -> None:
    # ``reset()`` calls it again: that call is not a construction's, so the method's
    # own call stays where it is written, beside each construction's, its member filled
    # with what each construction gives it, as for a class that is no template (it was
    # ``?``: the constructions' arguments were known by the specialisation only)
    code = IN_CLASS.replace("  typename rclcpp::Publisher<M>::SharedPtr advertise(",
                            "  void reset() { pub_ = advertise(1); }\n"
                            "  typename rclcpp::Publisher<M>::SharedPtr advertise(")
    (tmp_path / "pkg" / "src").mkdir(parents=True)
    (tmp_path / "pkg" / "package.xml").write_text(package_xml("pkg", "ament_cmake").replace(
        "</package>", DEPENDS + "</package>"))
    source = tmp_path / "pkg" / "src" / "talker.cpp"
    source.write_text(code)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    names = sorted(c.name for c in result.calls)
    assert names == ["color/detections", "color/detections", "color/image", "color/image"], (
        names)


def test_a_method_nothing_calls_makes_no_call(tmp_path) -> None:
    # a member function of a class template that is not virtual exists only where it is
    # called: ``neverCalled()`` is called nowhere, so its publisher is no call of the node
    code = IN_CLASS.replace("  typename rclcpp::Publisher<M>::SharedPtr advertise(",
                            "  void neverCalled() { other_ = node_->template create_publisher<M>("
                            "topic_ + \"/spare\", 1); }\n"
                            "  typename rclcpp::Publisher<M>::SharedPtr other_;\n"
                            "  typename rclcpp::Publisher<M>::SharedPtr advertise(")
    (tmp_path / "pkg" / "src").mkdir(parents=True)
    (tmp_path / "pkg" / "package.xml").write_text(package_xml("pkg", "ament_cmake").replace(
        "</package>", DEPENDS + "</package>"))
    source = tmp_path / "pkg" / "src" / "talker.cpp"
    source.write_text(code)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    names = sorted(c.name for c in result.calls)
    assert names == ["color/detections", "color/image"], names


def test_a_method_bound_as_a_callback_keeps_its_call(tmp_path) -> None:
    # its address is taken (a timer's callback): it exists, and runs when the timer fires
    code = IN_CLASS.replace("    pub_ = advertise(depth);\n",
                            "    pub_ = advertise(depth);\n"
                            "    timer_ = node_->create_wall_timer(std::chrono::seconds(1),"
                            " std::bind(&Bridge::later, this));\n").replace(
        "  typename rclcpp::Publisher<M>::SharedPtr advertise(",
        "  void later() { other_ = node_->template create_publisher<M>("
        "topic_ + \"/later\", 1); }\n"
        "  typename rclcpp::Publisher<M>::SharedPtr other_;\n"
        "  rclcpp::TimerBase::SharedPtr timer_;\n"
        "  typename rclcpp::Publisher<M>::SharedPtr advertise(")
    (tmp_path / "pkg" / "src").mkdir(parents=True)
    (tmp_path / "pkg" / "package.xml").write_text(package_xml("pkg", "ament_cmake").replace(
        "</package>", DEPENDS + "</package>"))
    source = tmp_path / "pkg" / "src" / "talker.cpp"
    source.write_text(code)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    names = sorted(c.name for c in result.calls if c.kind == "publish")
    # each object's ``later()`` publishes under its own topic (was ``?/later``)
    assert names == ["color/detections", "color/detections/later", "color/image",
                     "color/image/later"], names


TAG_DISPATCHED = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <std_msgs/msg/int32.hpp>
#include <type_traits>
template <class M>
class Bridge {
 public:
  Bridge(std::shared_ptr<rclcpp::Node> node, std::string topic, int depth)
      : node_(node), topic_(topic) {
    advertise(depth, std::is_same<M, std_msgs::msg::String>{});
  }
  void advertise(int depth, std::false_type) {
    pub_ = node_->template create_publisher<M>(topic_, depth);
  }
  void advertise(int depth, std::true_type) {
    pub_ = node_->template create_publisher<M>(topic_ + "/str", depth);
  }
 private:
  std::shared_ptr<rclcpp::Node> node_;
  std::string topic_;
  typename rclcpp::Publisher<M>::SharedPtr pub_;
};
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("talker");
  Bridge<std_msgs::msg::String> a(node, std::string("color/image"), 30);
  Bridge<std_msgs::msg::Int32> b(node, std::string("color/detections"), 5);
  rclcpp::spin(node);
  return 0;
}
"""


def test_tag_dispatched_overloads_are_chosen_per_construction(tmp_path) -> None:
    # ``advertise(depth, std::is_same<M, String>{})`` with a ``std::true_type`` and a
    # ``std::false_type`` overload (depthai_bridge's BridgePublisher): each construction
    # makes the one its template argument picks
    (tmp_path / "pkg" / "src").mkdir(parents=True)
    (tmp_path / "pkg" / "package.xml").write_text(package_xml("pkg", "ament_cmake").replace(
        "</package>", DEPENDS + "</package>"))
    source = tmp_path / "pkg" / "src" / "talker.cpp"
    source.write_text(TAG_DISPATCHED)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    calls = sorted((c.kind, c.name, c.type, c.queue_size) for c in result.calls)
    assert calls == [("publish", "color/detections", "std_msgs/msg/Int32", 5),
                     ("publish", "color/image/str", "std_msgs/msg/String", 30)], calls


def test_a_call_of_a_type_of_its_own_stays_in_the_method(tmp_path) -> None:
    # its type is no construction's: read where it is written, through the call sites
    # (both constructions name it: its name is not known there)
    code = IN_CLASS.replace(
        "    return node_->template create_publisher<M>(topic_, depth);",
        "    info_ = node_->template create_publisher<std_msgs::msg::String>("
        "topic_ + \"/info\", 1);\n"
        "    return node_->template create_publisher<M>(topic_, depth);").replace(
        "  std::string topic_;", "  std::string topic_;\n"
        "  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr info_;")
    (tmp_path / "pkg" / "src").mkdir(parents=True)
    (tmp_path / "pkg" / "package.xml").write_text(package_xml("pkg", "ament_cmake").replace(
        "</package>", DEPENDS + "</package>"))
    source = tmp_path / "pkg" / "src" / "talker.cpp"
    source.write_text(code)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    calls = sorted((c.name, c.type) for c in result.calls)
    assert ("color/image", "std_msgs/msg/String") in calls, calls
    assert ("color/detections", "std_msgs/msg/Int32") in calls, calls
    assert any(name.endswith("/info") for name, _ in calls), calls


def test_the_method_s_call_made_at_the_constructions_is_no_missed_call(tmp_path) -> None:
    # a unit with an error is searched for ROS calls no call was extracted at: the
    # method's, made at the constructions, is not one (as a wrapper's body is not)
    code = IN_CLASS.replace("  rclcpp::spin(node);", "  not_declared_anywhere(node);\n"
                            "  rclcpp::spin(node);")
    (tmp_path / "pkg" / "src").mkdir(parents=True)
    (tmp_path / "pkg" / "package.xml").write_text(package_xml("pkg", "ament_cmake").replace(
        "</package>", DEPENDS + "</package>"))
    source = tmp_path / "pkg" / "src" / "talker.cpp"
    source.write_text(code)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    names = sorted(c.name for c in result.calls)
    assert names == ["color/detections", "color/image"], names
    assert not [d.message for d in result.diagnostics if d.code == "CPP_CALL_MISSED"]


def test_a_fixed_type_call_of_a_tag_dispatched_overload_is_made_where_it_is_chosen(
        tmp_path) -> None:
    # depthai_bridge's ``advertise(int, std::true_type)`` makes image_transport's
    # publisher (a type of its own, Image) and the ``/camera_info`` one: only the
    # constructions whose template argument picks that overload make them. They were
    # read through the call sites for every construction: the tracker's
    # TrackDetection2DArray publisher gave a false Image ``/color/yolov4_tracklets``
    code = TAG_DISPATCHED.replace(
        "    pub_ = node_->template create_publisher<M>(topic_ + \"/str\", depth);",
        "    info_ = node_->template create_publisher<std_msgs::msg::Int32>("
        "topic_ + \"/info\", 1);\n"
        "    pub_ = node_->template create_publisher<M>(topic_ + \"/str\", depth);").replace(
        "  std::string topic_;", "  std::string topic_;\n"
        "  rclcpp::Publisher<std_msgs::msg::Int32>::SharedPtr info_;")
    (tmp_path / "pkg" / "src").mkdir(parents=True)
    (tmp_path / "pkg" / "package.xml").write_text(package_xml("pkg", "ament_cmake").replace(
        "</package>", DEPENDS + "</package>"))
    source = tmp_path / "pkg" / "src" / "talker.cpp"
    source.write_text(code)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    calls = sorted((c.kind, c.name, c.type) for c in result.calls)
    assert calls == [("publish", "color/detections", "std_msgs/msg/Int32"),
                     ("publish", "color/image/info", "std_msgs/msg/Int32"),
                     ("publish", "color/image/str", "std_msgs/msg/String")], calls


def test_a_condition_inside_the_method_goes_with_the_call_made_at_a_construction(
        tmp_path) -> None:
    # depthai_bridge's camera_info publisher is made only ``if(!_cameraName.empty())``
    # inside ``advertise``: made at the construction, it is still under that condition
    # (it was made there as if it always were)
    code = TAG_DISPATCHED.replace(
        "    pub_ = node_->template create_publisher<M>(topic_ + \"/str\", depth);",
        "    if (!cam_.empty()) {\n"
        "      info_ = node_->template create_publisher<std_msgs::msg::Int32>("
        "cam_ + \"/info\", 1);\n    }\n"
        "    pub_ = node_->template create_publisher<M>(topic_ + \"/str\", depth);").replace(
        "  std::string topic_;", "  std::string topic_;\n  std::string cam_;\n"
        "  rclcpp::Publisher<std_msgs::msg::Int32>::SharedPtr info_;").replace(
        "std::string topic, int depth)\n      : node_(node), topic_(topic)",
        "std::string topic, int depth, std::string cam = \"\")\n"
        "      : node_(node), topic_(topic), cam_(cam)").replace(
        '"color/image"), 30)', '"color/image"), 30, "color")')
    (tmp_path / "pkg" / "src").mkdir(parents=True)
    (tmp_path / "pkg" / "package.xml").write_text(package_xml("pkg", "ament_cmake").replace(
        "</package>", DEPENDS + "</package>"))
    source = tmp_path / "pkg" / "src" / "talker.cpp"
    source.write_text(code)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    calls = sorted((c.name, c.type, tuple(str(k) for k in c.conditions))
                   for c in result.calls)
    assert calls == [("color/detections", "std_msgs/msg/Int32", ()),
                     ("color/image/str", "std_msgs/msg/String", ()),
                     ("color/info", "std_msgs/msg/Int32", ("if (!cam_.empty())",))], calls
