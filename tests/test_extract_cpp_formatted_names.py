"""Names a formatting function builds from a literal format string keep the format's
text, ``?`` for each argument not known (its value where it is known): {fmt}'s and
std's ``format`` (mqtt_client's ``fmt::format("bridge.ros2mqtt.{}.qos", ros_topic)``),
``snprintf`` / ``sprintf`` into a character array read later as the name
(livox_ros_driver2's ``snprintf(name_str, sizeof(name_str), "livox/lidar_%s", ip)``),
``boost::format`` with ``%`` and ``std::to_string``. Before, each such name was ``?``.
``f % kNs`` (a member operator, whose call lists its object first) reads ``kNs``: it
was taken for a write, and every name built from ``kNs`` in the function was ``?``."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.extract.cpp.formats import boost_pieces, brace_pieces, printf_pieces
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """
#include <cstdio>
#include <cstring>
#include <format>
#include <string>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <boost/format.hpp>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
static const char kNs[] = "fleet";
class Bridge : public rclcpp::Node
{
public:
  Bridge() : rclcpp::Node("bridge")
  {
    std::string topic = declare_parameter("topic", std::string("t"));
    int id = declare_parameter("id", 0);
    declare_parameter(fmt::format("bridge.ros2mqtt.{}.qos", topic), 1);
    declare_parameter(fmt::format("bridge.{1}.{0}", "depth", kNs), 1);
    declare_parameter(std::format("robot_{}.rate_{:d}", id, 5), 1.0);
    declare_parameter(fmt::format("pad.{:>4}.x", id), 1);
    const char * shape = "{}/a";
    declare_parameter(fmt::format(shape, id), 1);
    declare_parameter(fmt::format(fmt::runtime(topic), id), 1);
    char name_str[48];
    memset(name_str, 0, sizeof(name_str));
    snprintf(name_str, sizeof(name_str), "livox/lidar_%s", topic.c_str());
    std::string topic_name(name_str);
    a_ = create_publisher<std_msgs::msg::String>(topic_name, 10);
    char cam[32];
    sprintf(cam, "cam%d/image_%02d/%zu%%", 2, id, sizeof(cam));
    b_ = create_publisher<std_msgs::msg::String>(cam, 10);
    c_ = create_publisher<std_msgs::msg::String>((boost::format("%s/odom") % topic).str(), 10);
    d_ = create_publisher<std_msgs::msg::String>(
      boost::str(boost::format("%1%/%2%_%1%") % kNs % 7), 10);
    e_ = create_publisher<std_msgs::msg::String>("robot_" + std::to_string(4) + "/cmd", 10);
    f_ = create_publisher<std_msgs::msg::String>("robot_" + std::to_string(id) + "/cmd", 10);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr a_, b_, c_, d_, e_, f_;
};
"""


def test_formatted_names_keep_their_text(write_tree) -> None:
    root = write_tree({"ex/package.xml": package_xml("ex", "ament_cmake"),
                       "ex/src/node.cpp": NODE})
    result = extract_cpp([str(root / "ex" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    declared = [c.name for c in result.calls if c.kind == "declare"]
    assert declared == [
        "topic", "id", "bridge.ros2mqtt.?.qos", "bridge.fleet.depth", "robot_?.rate_5",
        "pad.?.x",
        "?/a",  # a format held by a constant is as good as the literal
        "?"]  # a format only known at run time
    published = [c.name for c in result.calls if c.kind == "publish"]
    assert published == ["livox/lidar_?", "cam2/image_?/?%", "?/odom", "fleet/7_fleet",
                         "robot_4/cmd", "robot_?/cmd"]


def test_format_pieces() -> None:
    assert printf_pieces("a%") is None  # a directive cut short
    assert printf_pieces("%n") is None
    assert brace_pieces("{name}") is None  # a named field is not read
    assert brace_pieces("{}{1}") is None  # numbering mixed
    assert brace_pieces("a}b") is None
    assert boost_pieces("%1%%s") is None
    assert [p if isinstance(p, str) else p.index for p in printf_pieces("%*d|%s") or []] == [
        1, "|", 2]


COMPILED = """
#include <string>
#include <fmt/compile.h>
#include <rclcpp/rclcpp.hpp>
class Manager : public rclcpp::Node
{
public:
  Manager() : rclcpp::Node("manager")
  {
    std::string name = declare_parameter("name", std::string("c"));
    const std::string param_name = fmt::format(FMT_COMPILE("{}.params_file"), name);
    rclcpp::Parameter files;
    if (get_parameter(param_name, files)) {
      declare_parameter(fmt::format(FMT_STRING("{}.type"), name), std::string());
    }
  }
};
"""


def test_a_format_string_compiled_or_checked_is_its_literal(write_tree) -> None:
    """ros2_control's controller_manager (jazzy, controller_manager.cpp:1327) builds
    ``fmt::format(FMT_COMPILE("{}.params_file"), controller_name)``: with FMT_COMPILE
    unknown, clang found the call ambiguous (an error in load_controller) and its
    parameter reads were lost, ros2_control_node partial."""
    root = write_tree({"ex/package.xml": package_xml("ex", "ament_cmake"),
                       "ex/src/node.cpp": COMPILED})
    result = extract_cpp([str(root / "ex" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    names = [(c.kind, c.name) for c in result.calls]
    assert ("read", "?.params_file") in names
    assert ("declare", "?.type") in names
    assert not [d for d in result.diagnostics if "ambiguous" in d.message]


# image_view's extract_images and image_saver keep a ``boost::format`` member and give it
# the format a parameter holds with ``parse``: no parse error beside the subscription
SAVER = """
#include <string>
#include <boost/format.hpp>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
class Saver
{
public:
  Saver()
  {
    ros::NodeHandle local_nh("~");
    std::string format_string;
    local_nh.param("filename_format", format_string, std::string("frame%04i.jpg"));
    filename_format_.parse(format_string);
    sub_ = nh_.subscribe("image", 1, &Saver::cb, this);
  }
  void cb(const sensor_msgs::ImageConstPtr& msg) {
    std::string name = (filename_format_ % 3).str();
    filename_format_.clear();
  }
private:
  ros::NodeHandle nh_;
  ros::Subscriber sub_;
  boost::format filename_format_;
};
int main(int argc, char** argv) { ros::init(argc, argv, "saver"); Saver s; ros::spin(); }
"""


def test_a_format_member_given_its_format_by_parse(write_tree) -> None:
    root = write_tree({"ex/package.xml": package_xml("ex", "catkin"),
                       "ex/src/saver.cpp": SAVER})
    result = extract_cpp([str(root / "ex" / "src" / "saver.cpp")], scan([str(root)]),
                         cache_dir=None)
    errors = [d for d in result.diagnostics if d.code.startswith("CPP_") and (
        "parse" in d.message or "clear" in d.message)]
    assert errors == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("read", "~filename_format"), ("subscribe", "image")]
