"""Handles and names that cross the translation units of one ROS 1 node (a NodeHandle
made in main.cpp, given to a class defined in another file), and the NodeHandle
namespace kept apart so that the graph can remap it as roscpp does."""

from __future__ import annotations

from pathlib import Path

import pytest

from haros_arch.extract.cpp import CppBatch, extract_cpp_nodes
from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl
from haros_arch.model import Configuration, Node, PrimitiveCall
from haros_arch.workspace import Workspace, scan

HEADER = """#include <ros/ros.h>
#include <std_msgs/Int8.h>
#include <std_msgs/Empty.h>
class Sensors {
 public:
  Sensors(ros::NodeHandle& n, const std::string& topic);
 private:
  ros::Publisher pub_;
};
class Motors {
 public:
  explicit Motors(const ros::NodeHandle& nh);
  void spin();
 private:
  ros::NodeHandle nh_;
  ros::Subscriber sub_;
};
void attach(ros::NodeHandle& nh, const std::string& name);
"""

SENSORS = """#include "robot/parts.h"
Sensors::Sensors(ros::NodeHandle& n, const std::string& topic) {
  pub_ = n.advertise<std_msgs::Int8>(topic, 1);
}
Motors::Motors(const ros::NodeHandle& nh) : nh_(nh) {
  sub_ = nh_.subscribe<std_msgs::Empty>("stop", 1, &Motors::onStop, this);
}
void attach(ros::NodeHandle& nh, const std::string& name) {
  static ros::Publisher p = nh.advertise<std_msgs::Empty>(name, 1);
}
"""

MAIN = """#include <memory>
#include "robot/parts.h"
int main(int argc, char** argv) {
  ros::init(argc, argv, "driver");
  ros::NodeHandle n;
  ros::NodeHandle base("base");
  Sensors front(n, "laser");
  auto motors = std::make_shared<Motors>(ros::NodeHandle(base, "motors"));
  attach(n, "left");
  attach(base, "right");
  ros::spin();
}
"""

OTHER = """#include "robot/parts.h"
int main(int argc, char** argv) {
  ros::init(argc, argv, "other");
  ros::NodeHandle p("~");
  Sensors* s = new Sensors(p, "range");
}
"""


@pytest.fixture(scope="module")
def batch(tmp_path_factory: pytest.TempPathFactory) -> tuple[CppBatch, Path]:
    root = tmp_path_factory.mktemp("ws")
    package = root / "src" / "robot"
    (package / "src").mkdir(parents=True)
    (package / "include" / "robot").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="2"><name>robot</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>BSD</license></package>\n')
    (package / "include" / "robot" / "parts.h").write_text(HEADER.replace(
        "  void spin();", "  void spin();\n  void onStop(const std_msgs::Empty::ConstPtr&);"))
    for name, text in (("parts.cpp", SENSORS), ("main.cpp", MAIN), ("other.cpp", OTHER)):
        (package / "src" / name).write_text(text)
    src = package / "src"
    ws = scan([str(root)])
    nodes = [[str(src / "main.cpp"), str(src / "parts.cpp")],
             [str(src / "other.cpp"), str(src / "parts.cpp")],
             [str(src / "parts.cpp")]]
    return extract_cpp_nodes(nodes, ws, cache_dir=None, jobs=1), root


def rows(calls: list[PrimitiveCall]) -> list[tuple[object, ...]]:
    return sorted((c.kind, c.name, c.handle_namespace) for c in calls)


def test_handles_and_names_follow_constructors_and_functions_across_files(
        batch: tuple[CppBatch, Path]) -> None:
    """Constructor, make_shared and member initialiser; callers that disagree give one
    call per value."""
    result = batch[0].results[0]
    assert rows(result.calls) == [
        ("publish", "base/right", "base"),
        ("publish", "laser", None),
        ("publish", "left", None),
        ("subscribe", "base/motors/stop", "base/motors"),
    ]
    assert result.rosname == "driver"
    assert [d.code for d in result.diagnostics] == []


def test_a_shared_file_is_filled_per_node(batch: tuple[CppBatch, Path]) -> None:
    other = batch[0].results[1]
    # no caller in this node: attach never runs there, and its publisher named by its
    # arguments is not the node's (it was "?/?"); Motors, whose constructor subscribes
    # on the handle it is given, is not constructed by this node, so that subscription
    # is not its own (it was "?/stop")
    assert rows(other.calls) == [("publish", "~range", "~")]
    assert "CPP_DYNAMIC_NAME" not in [d.code for d in other.diagnostics]
    alone = batch[0].results[2]
    assert all("\x00" not in c.name for c in alone.calls)


def test_the_graph_remaps_a_handle_namespace_before_the_name_in_it() -> None:
    """roscpp: ``NodeHandle input("input")`` with ``input:=turtlesim1/turtle1`` gives
    /turtlesim1/turtle1/pose; the full name is remapped too."""
    calls = [PrimitiveCall("subscribe", "input/pose", "turtlesim/Pose",
                           handle_namespace="input"),
             PrimitiveCall("publish", "output/cmd_vel", "geometry_msgs/Twist",
                           handle_namespace="output"),
             PrimitiveCall("publish", "output/status", "std_msgs/String",
                           handle_namespace="output"),
             PrimitiveCall("read", "~gain", "double", handle_namespace="~")]
    mimic = Node("turtlesim", "mimic", calls=calls)
    decl = NodeDecl("/mimic", "turtlesim", "mimic", "/", remaps=[
        ("input", "turtlesim1/turtle1"), ("output", "/turtlesim2/turtle1"),
        ("/turtlesim2/turtle1/status", "/status")])
    config = build(Configuration("c"), LaunchModel(nodes=[decl]), Workspace(root="/x"),
                   {"turtlesim/mimic": mimic})
    assert sorted(link.rosname.full for link in config.links) == [
        "/mimic/gain", "/status", "/turtlesim1/turtle1/pose", "/turtlesim2/turtle1/cmd_vel"]
    decl2 = NodeDecl("/r/mimic", "turtlesim", "mimic", "/r/")
    config = build(Configuration("c"), LaunchModel(nodes=[decl2]), Workspace(root="/x"),
                   {"turtlesim/mimic": mimic})
    assert sorted(link.rosname.full for link in config.links) == [
        "/r/input/pose", "/r/mimic/gain", "/r/output/cmd_vel", "/r/output/status"]


def test_ros1_tf_listener_and_broadcaster(tmp_path: Path) -> None:
    package = tmp_path / "src" / "follow"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="2"><name>follow</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>BSD</license></package>\n')
    source = package / "src" / "follow.cpp"
    source.write_text(
        "#include <ros/ros.h>\n#include <tf/transform_listener.h>\n"
        "#include <tf/transform_broadcaster.h>\n"
        "int main(int argc, char** argv) {\n  ros::init(argc, argv, \"follow\");\n"
        "  ros::NodeHandle node;\n  tf::TransformListener listener;\n"
        "  tf::TransformBroadcaster out;\n  tf::StampedTransform t;\n"
        "  try { listener.lookupTransform(\"/a\", \"/b\", ros::Time(0), t); }\n"
        "  catch (tf::TransformException& ex) { return 1; }\n"
        "  out.sendTransform(tf::StampedTransform(t, ros::Time::now(), \"a\", \"c\"));\n}\n")
    batch = extract_cpp_nodes([[str(source)]], scan([str(tmp_path)]), cache_dir=None, jobs=1)
    result = batch.results[0]
    # tf is tf2 underneath since Hydro: the topics carry tf2_msgs/TFMessage
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("subscribe", "/tf", "tf2_msgs/TFMessage"),
        ("subscribe", "/tf_static", "tf2_msgs/TFMessage"),
        ("publish", "/tf", "tf2_msgs/TFMessage")]
    assert [d.code for d in result.diagnostics] == []


_NAV2_TF = """#pragma once
#include <memory>
#include "rclcpp/rclcpp.hpp"
#include "tf2_ros/buffer.h"
#include "tf2_ros/transform_listener.h"
#include "tf2_ros/transform_broadcaster.h"
namespace wrap {
struct TransformListener : tf2_ros::TransformListener
{
  using tf2_ros::TransformListener::TransformListener;
  using SharedPtr = std::shared_ptr<TransformListener>;
};
struct Broadcaster : tf2_ros::TransformBroadcaster
{
  using tf2_ros::TransformBroadcaster::TransformBroadcaster;
};
template<typename NodeT>
inline std::shared_ptr<Broadcaster> create_broadcaster(const NodeT & node)
{
  return std::make_shared<Broadcaster>(node);
}
}  // namespace wrap
"""


def test_classes_that_inherit_an_api_class_constructors(tmp_path: Path) -> None:
    """navigation2 wraps tf2_ros's classes in classes that inherit their constructors
    (``using tf2_ros::TransformListener::TransformListener;``) and makes them in
    function templates of a header, over any node type: the construction is tf2_ros's,
    made by the nodes whose files call the template and by no other."""
    package = tmp_path / "src" / "tfuser"
    (package / "src").mkdir(parents=True)
    (package / "include" / "tfuser").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="3"><name>tfuser</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>BSD</license><depend>rclcpp</depend><depend>tf2_ros</depend>'
        '</package>\n')
    (package / "include" / "tfuser" / "tf.hpp").write_text(_NAV2_TF)
    user = package / "src" / "user.cpp"
    user.write_text(
        '#include "tfuser/tf.hpp"\n'
        "class User : public rclcpp::Node {\npublic:\n"
        '  User() : Node("user") {\n'
        "    buffer_ = std::make_shared<tf2_ros::Buffer>(get_clock());\n"
        "    listener_ = std::make_shared<wrap::TransformListener>(*buffer_);\n"
        "    out_ = wrap::create_broadcaster(this);\n  }\n"
        "  std::shared_ptr<tf2_ros::Buffer> buffer_;\n"
        "  wrap::TransformListener::SharedPtr listener_;\n"
        "  std::shared_ptr<wrap::Broadcaster> out_;\n};\n"
        "int main(int argc, char ** argv) {\n  rclcpp::init(argc, argv);\n"
        "  rclcpp::spin(std::make_shared<User>());\n}\n")
    other = package / "src" / "other.cpp"  # includes the header, makes neither
    other.write_text(
        '#include "tfuser/tf.hpp"\n'
        "int main(int argc, char ** argv) {\n  rclcpp::init(argc, argv);\n"
        '  rclcpp::spin(std::make_shared<rclcpp::Node>("other"));\n}\n')
    batch = extract_cpp_nodes([[str(user)], [str(other)]], scan([str(tmp_path)]),
                              cache_dir=None, jobs=1,
                              include_dirs=[str(package / "include")])
    made, bare = batch.results
    assert sorted((c.kind, c.name, c.type) for c in made.calls) == [
        ("publish", "/tf", "tf2_msgs/msg/TFMessage"),
        ("subscribe", "/tf", "tf2_msgs/msg/TFMessage"),
        ("subscribe", "/tf_static", "tf2_msgs/msg/TFMessage")]
    assert bare.calls == []


def test_a_member_assigned_before_it_is_read_in_the_same_function(tmp_path: Path) -> None:
    """base_local_planner's OdometryHelperRos: ``setOdomTopic(topic)`` assigns the member
    and subscribes to it; the constructor passes its argument on, and the planner
    builds the helper with "odom"."""
    package = tmp_path / "src" / "helper"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="2"><name>helper</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>BSD</license></package>\n')
    source = package / "src" / "helper.cpp"
    source.write_text(
        "#include <string>\n#include <ros/ros.h>\n#include <nav_msgs/Odometry.h>\n"
        "class Helper {\npublic:\n"
        "  explicit Helper(std::string topic) { setTopic(topic); }\n"
        "  void setTopic(std::string topic) {\n"
        "    if (topic != topic_) {\n      topic_ = topic;\n      ros::NodeHandle gn;\n"
        "      sub_ = gn.subscribe<nav_msgs::Odometry>(topic_, 1, &Helper::cb, this);\n"
        "    }\n  }\n"
        "  void late() { ros::NodeHandle gn; pub_ = gn.advertise<nav_msgs::Odometry>(topic_, 1);"
        " topic_ = \"other\"; }\n"
        "  void maybe(bool on) { ros::NodeHandle gn; if (on) { topic_ = \"cond\"; }\n"
        "    pub_ = gn.advertise<nav_msgs::Odometry>(topic_, 1); }\n"
        "  void cb(const nav_msgs::Odometry::ConstPtr&) {}\n"
        "private:\n  std::string topic_;\n  ros::Subscriber sub_;\n  ros::Publisher pub_;\n};\n"
        "int main(int argc, char** argv) {\n  ros::init(argc, argv, \"helper\");\n"
        "  Helper helper(\"odom\");\n  helper.late();\n  helper.maybe(true);\n  ros::spin();\n}\n")
    batch = extract_cpp_nodes([[str(source)]], scan([str(tmp_path)]), cache_dir=None, jobs=1)
    # the read in late() comes before that function's own assignment, the one in
    # maybe() after an assignment that may not run: neither is its value
    assert [(c.kind, c.name) for c in batch.results[0].calls] == [
        ("subscribe", "odom"), ("publish", "?"), ("publish", "?")]
