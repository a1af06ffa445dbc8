"""A string a constructor moves into a member (``suffix_(std::move(suffix))``) is the
value moved: autoware_utils' ``PublishedTimePublisher`` keeps its topic suffix so, and
every planning node that holds one published a topic named ``?`` where the suffix,
``/debug/published_time``, is known (the topic it follows is a run-time value)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/header.hpp>
#include <std_msgs/msg/string.hpp>
#include <map>
#include <string>
#include <utility>

class Stamper
{
public:
  explicit Stamper(rclcpp::Node * node, std::string suffix = "/debug/published_time",
                   std::string prefix = "stamped")
  : node_(node), suffix_(std::move(suffix)), prefix_(std::forward<std::string>(prefix)) {}

  void publish_if_subscribed(const rclcpp::PublisherBase::ConstSharedPtr & publisher)
  {
    ensure(publisher->get_topic_name());
  }

private:
  void ensure(const std::string & topic_name)
  {
    if (publishers_.find(topic_name) == publishers_.end()) {
      publishers_[topic_name] =
        node_->create_publisher<std_msgs::msg::Header>(topic_name + suffix_, 1);
    }
    moved_ = node_->create_publisher<std_msgs::msg::Header>(prefix_ + "/moved", 1);
  }

  rclcpp::Node * node_;
  std::string suffix_;
  std::string prefix_;
  std::map<std::string, rclcpp::Publisher<std_msgs::msg::Header>::SharedPtr> publishers_;
  rclcpp::Publisher<std_msgs::msg::Header>::SharedPtr moved_;
};

class Planner : public rclcpp::Node
{
public:
  Planner() : rclcpp::Node("planner")
  {
    path_ = create_publisher<std_msgs::msg::String>("~/output/path", 1);
    stamper_ = std::make_unique<Stamper>(this);
    timer_ = create_wall_timer(std::chrono::seconds(1), [this]() {
      stamper_->publish_if_subscribed(path_);
    });
  }

  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr path_;
  std::unique_ptr<Stamper> stamper_;
  rclcpp::TimerBase::SharedPtr timer_;
};
"""


def test_a_moved_constructor_argument_names_the_member(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("planner", "ament_cmake"))
    source = tmp_path / "planner.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="jazzy")
    names = sorted(c.name for c in result.calls if c.kind == "publish")
    assert names == ["?/debug/published_time", "stamped/moved", "~output/path"]
