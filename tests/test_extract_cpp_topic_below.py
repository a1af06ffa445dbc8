"""A name below the topic of a publisher the node made: autoware_utils'
``PublishedTimePublisher`` publishes ``publisher->get_topic_name() +
"/debug/published_time"`` for each publisher it is handed, the topic as resolved and
remapped (53 Autoware nodes published ``?/debug/published_time``)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl
from haros_arch.model import Configuration, Node
from haros_arch.workspace import Workspace, scan
from tests.conftest import package_xml

NODE = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/bool.hpp>
#include <std_msgs/msg/header.hpp>
class Stamps
{
public:
  explicit Stamps(rclcpp::Node * node, std::string suffix = "/debug/published_time")
  : node_(node), suffix_(std::move(suffix)) {}
  void publish_if_subscribed(const rclcpp::PublisherBase::ConstSharedPtr & publisher)
  {
    ensure(publisher->get_topic_name());
  }
private:
  void ensure(const std::string & topic_name)
  {
    if (!pub_) {
      pub_ = node_->create_publisher<std_msgs::msg::Header>(topic_name + suffix_, 1);
    }
  }
  rclcpp::Node * node_;
  std::string suffix_;
  rclcpp::Publisher<std_msgs::msg::Header>::SharedPtr pub_;
};
class Smoother : public rclcpp::Node
{
public:
  Smoother() : rclcpp::Node("smoother")
  {
    path_pub_ = create_publisher<std_msgs::msg::Bool>("~/output/path", 1);
    other_ = create_publisher<std_msgs::msg::Bool>(std::string("~/") + get_name(), 1);
    stamps_ = std::make_unique<Stamps>(this);
    timer_ = create_wall_timer(std::chrono::milliseconds(100), std::bind(&Smoother::tick, this));
  }
  void tick()
  {
    path_pub_->publish(std_msgs::msg::Bool());
    stamps_->publish_if_subscribed(path_pub_);
  }
  rclcpp::Publisher<std_msgs::msg::Bool>::SharedPtr path_pub_, other_;
  std::unique_ptr<Stamps> stamps_;
  rclcpp::TimerBase::SharedPtr timer_;
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Smoother>());
}
"""


def test_a_name_below_a_publishers_remapped_topic(write_tree) -> None:
    root = write_tree({"sm/package.xml": package_xml("sm", "ament_cmake"),
                       "sm/src/node.cpp": NODE})
    result = extract_cpp([str(root / "sm" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    below = [(c.name, c.name_below) for c in result.calls if c.name_below]
    assert below == [("?/debug/published_time", "~/output/path")]
    node = Node("sm", "sm", calls=list(result.calls))
    config = build(Configuration("c"), LaunchModel(nodes=[NodeDecl(
        "/planning/smoother", "sm", "sm", remaps=[("~/output/path", "/planning/path")])]),
        Workspace(root="/nowhere"), {node.name: node})
    topics = sorted(link.rosname.full for link in config.links if link.kind == "publish")
    assert "/planning/path" in topics
    assert "/planning/path/debug/published_time" in topics


def test_an_overload_the_node_never_calls_makes_no_call(write_tree) -> None:
    """autoware_utils' ``PublishedTimePublisher`` has two ``publish_if_subscribed``
    overloads (a stamp, a header), each making the publisher below the topic of the
    publisher it is handed: a node that calls one got a second ``?/debug/published_time``
    call from the other (one per node), whose publisher parameter no call gives. That
    parameter's topic is what the node's calls give it (``links``): none, so no call."""
    from haros_arch.extract.cpp import extract_cpp_nodes

    source = NODE.replace("""private:
  void ensure(""", """  void publish_if_subscribed(
    const rclcpp::PublisherBase::ConstSharedPtr & publisher, const std_msgs::msg::Header & h)
  {
    (void)h;
    ensure(publisher->get_topic_name());
  }
private:
  void ensure(""")
    assert source != NODE
    root = write_tree({"sm/package.xml": package_xml("sm", "ament_cmake"),
                       "sm/src/node.cpp": source})
    batch = extract_cpp_nodes([[str(root / "sm" / "src" / "node.cpp")]], scan([str(root)]),
                              cache_dir=None, jobs=1)
    calls = batch.results[0].calls
    assert sorted((c.name, c.name_below) for c in calls if c.kind == "publish") == [
        ("?/debug/published_time", "~/output/path"), ("~?", None), ("~output/path", None)]
