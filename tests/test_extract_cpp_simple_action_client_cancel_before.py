"""actionlib's ``SimpleActionClient::cancelGoalsAtAndBeforeTime(time)`` (frontier_exploration's
exploration_server cancels move_base's goals so in its cancel callback) is part of the
ROS 1 client's API: the stand-in declares it, so the unit parses without an error there."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <ros/ros.h>
#include <actionlib/client/simple_action_client.h>
#include <move_base_msgs/MoveBaseAction.h>
int main(int argc, char ** argv) {
  ros::init(argc, argv, "explorer");
  actionlib::SimpleActionClient<move_base_msgs::MoveBaseAction> client("move_base", true);
  client.waitForServer();
  client.cancelGoalsAtAndBeforeTime(ros::Time::now());
  ros::spin();
}
"""


def test_cancel_goals_at_and_before_time(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("explorer").replace(
        "</package>", "<depend>roscpp</depend><depend>actionlib</depend>"
        "<depend>move_base_msgs</depend></package>"))
    source = tmp_path / "explorer.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert ("action-client", "move_base") in {(c.kind, c.name) for c in result.calls}
    errors = [d.message for d in result.diagnostics
              if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")]
    assert errors == []
