"""PickNik's rosparam_shortcuts, installed, not in the workspace (its stand-in):
``get(parent, nh, name, value)`` reads ``name`` on ``nh``; ROS 2's ``get(node, name, value)``
declares it; ``shutdownIfError(parent, error)`` ends the process when ``error``, a count
of failed gets, is not zero, so each get the count gathers is a required read."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

ROS1 = r"""
#include <ros/ros.h>
#include <rosparam_shortcuts/rosparam_shortcuts.h>
#include <string>
#include <vector>
int main(int argc, char** argv) {
  ros::init(argc, argv, "shortcuts");
  ros::NodeHandle nh;
  ros::NodeHandle rpnh(nh, "poses");
  bool planned;
  std::string world;
  std::vector<double> offsets;
  std::size_t error = 0;
  error += !rosparam_shortcuts::get("poses", rpnh, "handover_planned", planned);
  error += !rosparam_shortcuts::get("poses", rpnh, "world_name", world);
  rosparam_shortcuts::shutdownIfError("poses", error);
  if (!rosparam_shortcuts::get("extra", nh, "offsets", offsets)) {
    ROS_WARN("no offsets: none used");
  }
  return 0;
}
"""

ROS2 = r"""
#include <rclcpp/rclcpp.hpp>
#include <rosparam_shortcuts/rosparam_shortcuts.h>
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("shortcuts");
  double rate;
  std::size_t error = 0;
  error += !rosparam_shortcuts::get(node, "rate", rate);
  rosparam_shortcuts::shutdownIfError(error);
  return 0;
}
"""


def _calls(tmp_path, text):
    source = tmp_path / "n.cpp"
    source.write_text(text)
    return extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None).calls


def test_a_get_reads_the_parameter_on_the_handle_it_is_given(tmp_path):
    reads = {c.name: c for c in _calls(tmp_path, ROS1) if c.kind == "read"}
    assert set(reads) == {"poses/handover_planned", "poses/world_name", "offsets"}
    assert reads["poses/handover_planned"].type == "bool"
    assert reads["poses/world_name"].type == "str"


def test_gets_a_shutdown_counts_are_required_and_a_handled_one_is_not(tmp_path):
    reads = {c.name: c for c in _calls(tmp_path, ROS1) if c.kind == "read"}
    # counted, then ``shutdownIfError("poses", error)``: required, no default
    assert (reads["poses/handover_planned"].tested,
            reads["poses/handover_planned"].has_default) == (False, False)
    assert reads["poses/world_name"].tested is False
    # its absence handled with a warning
    assert reads["offsets"].tested is True


def test_ros2_get_declares_the_parameter(tmp_path):
    calls = _calls(tmp_path, ROS2)
    assert [(c.kind, c.name) for c in calls if c.kind in ("declare", "read")] == [
        ("declare", "rate")]
