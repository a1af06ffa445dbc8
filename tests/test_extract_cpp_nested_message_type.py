"""A message type written as a member of a class (Autoware's interface specs:
``create_publisher<VectorMap::Message>(VectorMap::name, qos)``, ``struct VectorMap {
using Message = autoware_map_msgs::msg::LaneletMapBin; ... }``) is the member's type,
not the class that qualifies it: the map loader published ``/map/vector_map`` as
``autoware/component_interface_specs/map/VectorMap``, a type mismatch with every
subscriber."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <std_msgs/msg/int32.hpp>
namespace specs {
struct Chatter {
  using Message = std_msgs::msg::String;
  static constexpr char name[] = "/chatter";
};
}
class Talker : public rclcpp::Node {
 public:
  using Chatter = specs::Chatter;
  Talker() : rclcpp::Node("talker") {
    pub_ = create_publisher<Chatter::Message>(Chatter::name, 1);
    count_ = create_publisher<specs::Chatter::Message>("count_text", 1);
    plain_ = create_publisher<std_msgs::msg::Int32>("count", 1);
  }
  rclcpp::Publisher<Chatter::Message>::SharedPtr pub_, count_;
  rclcpp::Publisher<std_msgs::msg::Int32>::SharedPtr plain_;
};
"""


def test_a_message_type_named_as_a_member_of_a_class(write_tree) -> None:
    root = write_tree({"talk/package.xml": package_xml("talk", "ament_cmake"),
                       "talk/src/talker.cpp": SOURCE})
    result = extract_cpp([str(root / "talk/src/talker.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("publish", "/chatter", "std_msgs/msg/String"),
        ("publish", "count", "std_msgs/msg/Int32"),
        ("publish", "count_text", "std_msgs/msg/String")]
