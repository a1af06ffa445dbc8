"""A field's default initialiser is not what it holds where an object of its class is
assigned as a whole in the unit (``config_ = conf``, or a constructor's ``config_(conf)``):
the copy brings what the caller set. depthai's ImagePublisher keeps ``pubConfig =
pubConf;`` in ``setup``, then publishes ``pubConfig.topicName + pubConfig.topicSuffix``;
``topicName = ""`` in the struct, set by each caller in another file: every camera
stream was ``/image_raw`` at the root, and a launch file with two cameras got false
multiple-publishers warnings. A struct never copied keeps its defaults."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HEADER = """\
#pragma once
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
namespace cam {
struct Config {
  std::string topicName = "";
  std::string suffix = "/image_raw";
};
struct Fixed {
  std::string topicName = "fixed";
};
class Pub {
public:
  explicit Pub(rclcpp::Node* node, const Config& first) : node_(node), first_(first) {}
  void setup(const Config& conf);
  rclcpp::Node* node_;
  Config config_;
  Config first_;
  Fixed fixed_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_, again_, kept_;
};
}  // namespace cam
"""

SOURCE = """\
#include "cam/pub.hpp"
namespace cam {
void Pub::setup(const Config& conf) {
  config_ = conf;
  pub_ = node_->create_publisher<std_msgs::msg::String>(config_.topicName + config_.suffix, 1);
  again_ = node_->create_publisher<std_msgs::msg::String>(first_.topicName + "/info", 1);
  kept_ = node_->create_publisher<std_msgs::msg::String>(fixed_.topicName + "/status", 1);
}
}  // namespace cam
"""


def test_a_field_of_an_object_copied_whole_is_not_its_default(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("cam", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"))
    (tmp_path / "include" / "cam").mkdir(parents=True)
    (tmp_path / "include" / "cam" / "pub.hpp").write_text(HEADER)
    source = tmp_path / "pub.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    names = sorted(c.name for c in result.calls if c.kind == "publish")
    assert len(names) == 3, names
    assert "/image_raw" not in names and "/info" not in names, names
    assert "fixed/status" in names, names  # never copied: its initialiser holds
