"""A LifecycleNode built with its communication interface off
(``LifecycleNode(name, ns, options, false)``, as ros2_control's controller base does at
controller_interface_base.cpp:77) publishes no transitions and serves no state machine;
one built with it on does."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

NODE = """\
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>

void make_quiet(const rclcpp::NodeOptions & options)
{
  auto quiet = std::make_shared<rclcpp_lifecycle::LifecycleNode>(
    "quiet", "", options, false);
}

void make_loud(const rclcpp::NodeOptions & options)
{
  auto loud = std::make_shared<rclcpp_lifecycle::LifecycleNode>("loud", "", options, true);
}
"""


def test_a_lifecycle_node_without_its_interface_makes_none(tmp_path: Path) -> None:
    (tmp_path / "n.cpp").write_text(NODE)
    result = extract_cpp([str(tmp_path / "n.cpp")], Workspace(root=str(tmp_path)),
                         cache_dir=None)
    # loud's transitions and state machine (line 13), none of quiet's (line 7)
    assert sorted({(c.location.line, c.name) for c in result.calls}) == [
        (13, "~change_state"), (13, "~get_available_states"),
        (13, "~get_available_transitions"), (13, "~get_state"),
        (13, "~get_transition_graph"), (13, "~transition_event")]
