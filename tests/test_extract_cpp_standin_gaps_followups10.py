"""Stand-in gap seen on real code (bench/README, helper followups9): two ``std::map``
compared (MoveIt 2's plan_execution.cpp, ``attached_objects !=
trajectory_attached_objects``, in the jazzy ``moveit_ros_move_group`` model) and two
``std::set``: the stand-ins declared no ``==`` / ``!=`` for them, so the comparison was a
C++ error in a function that calls the ROS API and the node was partial."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <map>
#include <set>
#include <string>
#include <unordered_map>

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("node");
  std::map<std::string, const int*> a, b;
  std::set<std::string> c, d;
  std::unordered_map<std::string, int> e, f;
  if (a != b || !(a == b) || c != d || c == d || e == f || e != f) {
    auto pub = node->create_publisher<std_msgs::msg::String>("out", 10);
  }
  rclcpp::spin(node);
}
"""


def test_maps_and_sets_compared(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("node", "ament_cmake"))
    source = tmp_path / "node.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="jazzy")
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED",
                          "CPP_INCLUDE_MISSING")] == []
    assert [(c.kind, c.name) for c in result.calls if c.name == "out"] == [("publish", "out")]
