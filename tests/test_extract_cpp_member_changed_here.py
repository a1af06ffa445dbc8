"""A member that a function changes in place (``num_submaps_++``) holds no longer the
value its constructor gave it where that function reads it after: slam_toolbox's
merge_maps_kinematic (jazzy, merge_maps_kinematic.cpp:96-102) counts its submaps up and
advertises ``"/map_" + std::to_string(num_submaps_)`` for each; the names were read with
the constructor's ``num_submaps_ = 0`` as ``/map_0`` and ``/map_metadata_0``, not
``/map_?``."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """
#include <string>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
class Merge : public rclcpp::Node
{
public:
  Merge() : rclcpp::Node("merge")
  {
    num_ = 0;
    prefix_ = "robot";
    pubs_.push_back(create_publisher<std_msgs::msg::String>("/map_" + std::to_string(num_), 1));
  }
  void add()
  {
    num_++;
    pubs_.push_back(create_publisher<std_msgs::msg::String>(
      "/map_" + std::to_string(num_), 1));
    pubs_.push_back(create_publisher<std_msgs::msg::String>(prefix_ + "/status", 1));
  }
  void rename()
  {
    prefix_ += "_2";
    pubs_.push_back(create_publisher<std_msgs::msg::String>(prefix_ + "/renamed", 1));
  }
private:
  int num_;
  std::string prefix_;
  std::vector<rclcpp::Publisher<std_msgs::msg::String>::SharedPtr> pubs_;
};
"""


def test_a_member_changed_by_the_function_is_not_its_constructor_value(write_tree) -> None:
    root = write_tree({"ex/package.xml": package_xml("ex", "ament_cmake"),
                       "ex/src/node.cpp": NODE})
    result = extract_cpp([str(root / "ex" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    published = [c.name for c in result.calls if c.kind == "publish"]
    assert published == [
        "/map_0",  # in the constructor, after its assignment
        "/map_?",  # counted up first
        "robot/status",  # a member the function does not change: the constructor's
        "?/renamed"]  # changed in place first
