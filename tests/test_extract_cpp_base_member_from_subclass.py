"""A base class's method names a topic with a member that a subclass's constructor, in
another file of the node, sets from a parameter: topic_tools' ToolBaseNode publishes on
``output_topic_`` and subscribes ``input_topic_`` (tool_base_node.cpp), which RelayNode's
constructor sets with ``declare_parameter`` (relay_node.cpp). The names were '?' (the
relay's topics unknown, which the shipped model's override had to fill in by hand)."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp_nodes
from haros_arch.workspace import scan

BASE_HEADER = """#include <string>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"
namespace tools {
class ToolBase : public rclcpp::Node
{
public:
  ToolBase(const std::string & name, const rclcpp::NodeOptions & options);
protected:
  void connect();
  std::string input_topic_;
  std::string output_topic_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};
}  // namespace tools
"""

BASE = """#include "tools/tool_base.hpp"
namespace tools {
ToolBase::ToolBase(const std::string & name, const rclcpp::NodeOptions & options)
: rclcpp::Node(name, options) {}
void ToolBase::connect()
{
  pub_ = create_publisher<std_msgs::msg::String>(output_topic_, 10);
  sub_ = create_subscription<std_msgs::msg::String>(
    input_topic_, 10, [this](std_msgs::msg::String::SharedPtr m) {pub_->publish(*m);});
}
}  // namespace tools
"""

RELAY = """#include "tools/tool_base.hpp"
namespace tools {
class Relay : public ToolBase
{
public:
  explicit Relay(const rclcpp::NodeOptions & options)
  : ToolBase("relay", options)
  {
    input_topic_ = declare_parameter<std::string>("input_topic");
    output_topic_ = declare_parameter<std::string>("output_topic", input_topic_ + "_relay");
    connect();
  }
};
}  // namespace tools
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<tools::Relay>(rclcpp::NodeOptions()));
}
"""

CONSTANT = """    if (output_topic_.empty()) {
      output_topic_ = "out";
    }
"""
# a second tool that stores another parameter in the same member and writes the other
# member with a constant beside its parameter, and a third that computes it
OTHER = """#include "tools/tool_base.hpp"
namespace tools {
class Mux : public ToolBase
{
public:
  explicit Mux(const rclcpp::NodeOptions & options)
  : ToolBase("mux", options)
  {
    input_topic_ = declare_parameter<std::string>("initial_topic", "a");
    output_topic_ = declare_parameter<std::string>("output_topic", "~/selected");
""" + CONSTANT + """    connect();
  }
};
class Demux : public ToolBase
{
public:
  explicit Demux(const rclcpp::NodeOptions & options)
  : ToolBase("demux", options)
  {
    output_topic_ = declare_parameter<std::string>("output_topic", "x");
    output_topic_ = output_topic_ + "/out";
    connect();
  }
};
}  // namespace tools
"""


def _write(root: Path, files: dict[str, str]) -> Path:
    package = root / "tools"
    (package / "src").mkdir(parents=True)
    (package / "include" / "tools").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="3"><name>tools</name><version>1.0.0</version>'
        "<description>x</description><maintainer email='a@b.c'>a</maintainer>"
        "<license>x</license><buildtool_depend>ament_cmake</buildtool_depend>"
        "<depend>rclcpp</depend><depend>std_msgs</depend>"
        "<export><build_type>ament_cmake</build_type></export></package>")
    (package / "include" / "tools" / "tool_base.hpp").write_text(BASE_HEADER)
    for name, text in files.items():
        (package / "src" / name).write_text(text)
    return package


def _topics(tmp_path: Path, files: dict[str, str],
            defaults: bool = False) -> list[tuple[object, ...]]:
    package = _write(tmp_path, files)
    units = [str(package / "src" / name) for name in files]
    batch = extract_cpp_nodes([units], scan([str(tmp_path)]), cache_dir=None, jobs=1)
    (result,) = batch.results
    for call in result.calls:  # the units' marks never reach the node
        assert call.name_member is None and call.stores is None
    return sorted(((c.kind, c.name, c.name_param, c.name_default, c.default_param)
                   if defaults else (c.kind, c.name, c.name_param)) for c in result.calls
                  if c.kind in ("publish", "subscribe"))


def test_a_base_member_a_subclass_sets_from_a_parameter_names_the_topic(tmp_path) -> None:
    # with the default the declaration gives: input_topic's value and "_relay"
    assert _topics(tmp_path, {"tool_base.cpp": BASE, "relay.cpp": RELAY}, True) == [
        ("publish", "?", "output_topic", "?_relay", "input_topic"),
        ("subscribe", "?", "input_topic", None, None)]


def test_a_string_default_of_the_parameter_is_the_name_s_default(tmp_path) -> None:
    mux = OTHER.replace(CONSTANT, "")
    mux = mux[:mux.index("class Demux")] + "}  // namespace tools\n"
    assert _topics(tmp_path, {"tool_base.cpp": BASE, "mux.cpp": mux}, True) == [
        ("publish", "?", "output_topic", "~/selected", None),
        ("subscribe", "?", "initial_topic", "a", None)]


def test_members_of_several_parameters_or_other_writes_stay_unknown(tmp_path) -> None:
    # input_topic_ holds input_topic or initial_topic (two tools in one process);
    # output_topic_ is written with a constant beside output_topic in mux.cpp, and
    # computed from it in Demux
    assert _topics(tmp_path, {"tool_base.cpp": BASE, "relay.cpp": RELAY,
                              "mux.cpp": OTHER}) == [
        ("publish", "?", None), ("subscribe", "?", None)]


def test_a_member_the_storing_file_also_computes_stays_unknown(tmp_path) -> None:
    demux = OTHER.replace("input_topic_ = declare_parameter<std::string>"
                          "(\"initial_topic\", \"a\");", "")
    demux = demux[:demux.index("class Mux")] + demux[demux.index("class Demux"):]
    # output_topic_: relay.cpp stores output_topic, demux.cpp computes it after its read
    assert _topics(tmp_path, {"tool_base.cpp": BASE, "relay.cpp": RELAY,
                              "demux.cpp": demux}) == [
        ("publish", "?", None), ("subscribe", "?", "input_topic")]
