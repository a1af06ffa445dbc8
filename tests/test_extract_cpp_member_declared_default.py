"""A member a node class fills from a parameter it declares with the member's earlier
value as the default, handed to a helper class built in another function: slam_toolbox's
``setParams`` writes ``map_name_ = "/map"``, declares ``map_name`` with it and reads it
back; ``MapSaver`` (map_saver.cpp) subscribes on the member it is given. The
subscription is named by the parameter with the declared default, as the node's own
publisher on the member is (``?`` with no default before: NAME_PARAM_UNSET when the
launch file does not set ``map_name``)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """
#include <rclcpp/rclcpp.hpp>
#include <nav_msgs/msg/occupancy_grid.hpp>
class Saver {
public:
  template<class NodeT>
  Saver(NodeT node, const std::string & map_name);
protected:
  std::string map_name_;
  rclcpp::Subscription<nav_msgs::msg::OccupancyGrid>::SharedPtr sub_;
};
class Mapper : public rclcpp::Node {
public:
  Mapper();
  void setParams();
  void setup();
protected:
  std::string map_name_, frame_;
  std::unique_ptr<Saver> saver_;
  rclcpp::Publisher<nav_msgs::msg::OccupancyGrid>::SharedPtr pub_;
};
"""

SAVER = """
#include "mapper.hpp"
template<class NodeT>
Saver::Saver(NodeT node, const std::string & map_name) : map_name_(map_name) {
  sub_ = node->template create_subscription<nav_msgs::msg::OccupancyGrid>(
    map_name_, rclcpp::QoS(1), [](nav_msgs::msg::OccupancyGrid::ConstSharedPtr) {});
}
template Saver::Saver(rclcpp::Node::SharedPtr, const std::string &);
"""

MAPPER = """
#include "mapper.hpp"
Mapper::Mapper() : rclcpp::Node("mapper") {}
void Mapper::setParams() {
  map_name_ = std::string("/map");
  if (!this->has_parameter("map_name")) {
    this->declare_parameter("map_name", map_name_);
  }
  map_name_ = this->get_parameter("map_name").as_string();
  frame_ = this->get_parameter("frame").as_string();
}
void Mapper::setup() {
  setParams();
  saver_ = std::make_unique<Saver>(shared_from_this(), map_name_);
  pub_ = create_publisher<nav_msgs::msg::OccupancyGrid>(map_name_, 1);
}
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<Mapper>();
  node->setup();
  rclcpp::spin(node);
}
"""


def test_a_member_handed_on_keeps_the_declared_default(write_tree) -> None:
    root = write_tree({"mp/package.xml": package_xml("mp", "ament_cmake"),
                       "mp/src/mapper.hpp": HEADER, "mp/src/saver.cpp": SAVER,
                       "mp/src/mapper.cpp": MAPPER})
    result = extract_cpp([str(root / "mp" / "src" / "mapper.cpp"),
                          str(root / "mp" / "src" / "saver.cpp")],
                         scan([str(root)]), cache_dir=None)
    named = sorted((c.kind, c.name, c.name_param, c.name_default) for c in result.calls
                   if c.kind in ("subscribe", "publish"))
    assert named == [
        ("publish", "?", "map_name", "/map"),
        ("subscribe", "?", "map_name", "/map"),
    ]
