"""A counting loop over literal bounds (``for (int i = 1; i < 10; i++)``) runs its body:
it is no condition of what the body makes, and a name made of its variable is one name
per turn (VINS-Mono / VINS-Fusion's pose_graph advertises ``"path_" + to_string(i)`` for
i in 1..9; it was ``path_?`` under the loop's condition). A loop over a bound the code
reads at run time keeps its condition and its ``?``."""

from __future__ import annotations

from pathlib import Path

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

ROS1 = r"""
#include <ros/ros.h>
#include <nav_msgs/Path.h>
#include <std_msgs/String.h>
#include <cstdio>
#include <string>

ros::Publisher pub_path[10];
ros::Publisher pub_other[4];

int main(int argc, char** argv) {
  ros::init(argc, argv, "pose_graph");
  ros::NodeHandle n("~");
  for (int i = 1; i < 10; i++)
    pub_path[i] = n.advertise<nav_msgs::Path>("path_" + std::to_string(i), 1000);
  for (size_t k = 0; k <= 1; ++k) {
    char key[32];
    snprintf(key, sizeof(key), "camera%zu/topic", k);
    std::string topic;
    n.param(std::string(key), topic, std::string("image"));
    pub_other[k] = n.advertise<std_msgs::String>("fixed", 1);
  }
  int count = 0;
  n.param("count", count, 2);
  for (int j = 0; j < count; ++j)
    pub_other[j] = n.advertise<std_msgs::String>("dyn_" + std::to_string(j), 1);
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      n.advertise<std_msgs::String>("grid_" + std::to_string(a) + "_" + std::to_string(b), 1);
  for (int z = 3; z < 3; ++z)
    n.advertise<std_msgs::String>("never_" + std::to_string(z), 1);
  for (int w = 0; w < 100; ++w)
    n.advertise<std_msgs::String>("many_" + std::to_string(w), 1);
  ros::spin();
}
"""

ROS2 = r"""
#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/point_cloud2.hpp>

class Cloud : public rclcpp::Node {
 public:
  Cloud() : Node("os_cloud") {
    for (int i = 0; i < 2; ++i) {
      pubs_.push_back(create_publisher<sensor_msgs::msg::PointCloud2>(
          "points" + std::to_string(i + 1), 10));
    }
  }
  std::vector<rclcpp::Publisher<sensor_msgs::msg::PointCloud2>::SharedPtr> pubs_;
};

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Cloud>());
}
"""


def _calls(tmp_path: Path, text: str) -> list[tuple[str, str, tuple[str, ...]]]:
    package = tmp_path / "src" / "demo"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(package_xml("demo"))
    (package / "src" / "node.cpp").write_text(text)
    result = extract_cpp([str(package / "src" / "node.cpp")], scan([str(tmp_path / "src")]),
                         cache_dir=None)
    return sorted((c.kind, c.name, tuple(k.text for k in c.conditions))
                  for c in result.calls)


def test_a_name_made_of_a_counting_loop_s_variable_is_one_name_per_turn(tmp_path: Path):
    calls = _calls(tmp_path, ROS1)
    assert [c for c in calls if "path_" in c[1]] == [
        ("publish", f"~path_{i}", ()) for i in range(1, 10)]
    assert [c for c in calls if c[0] == "read"] == [
        ("read", "~camera0/topic", ()), ("read", "~camera1/topic", ()), ("read", "~count", ())]
    assert ("publish", "~fixed", ()) in calls
    assert [c for c in calls if "grid_" in c[1]] == [
        ("publish", f"~grid_{a}_{b}", ()) for a in range(2) for b in range(2)]
    # a bound read at run time: the loop may not run, its variable not known
    assert ("publish", "~dyn_?", ("int j = 0; j < count; ++j",)) in calls
    # a loop that never runs keeps its condition; one of many turns is not read per turn
    assert ("publish", "~never_?", ("int z = 3; z < 3; ++z",)) in calls
    assert ("publish", "~many_?", ()) in calls


def test_ros2_publishers_per_turn(tmp_path: Path):
    assert _calls(tmp_path, ROS2) == [("publish", "points1", ()), ("publish", "points2", ())]
