"""A member of an API class built in a constructor's initialiser list whose arguments
name a method an error made invalid (industrial_core's JointTrajectoryAction:
``action_server_(node_, "joint_trajectory_action", boost::bind(&JointTrajectoryAction::goalCB,
this, _1), ...)`` while ``goalCB`` took a GoalHandle type the parse did not have) is an
expression clang leaves unresolved, with no error of its own there: the action server was
lost and the node said complete. It is kept as the class's row reads it, with
CPP_CALL_UNRESOLVED."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

ACTION = """
#include <ros/ros.h>
#include <actionlib/server/simple_action_server.h>
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <boost/bind.hpp>
template <class T> struct Box { typedef int Valid; };
class Action {
 public:
  Action() : server_(nh_, "follow", boost::bind(&Action::goalCB, this, _1), false) {
    nh_.param("rate", rate_, 1.0);
  }
  void goalCB(typename Box<int>::Handle goal);
 private:
  ros::NodeHandle nh_;
  double rate_;
  actionlib::SimpleActionServer<control_msgs::FollowJointTrajectoryAction> server_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "action");
  Action a;
  ros::spin();
}
"""


def _extract(write_tree, source: str):
    root = write_tree({"pkg/package.xml": package_xml("pkg", "catkin"),
                       "pkg/src/node.cpp": source})
    return extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                       cache_dir=None)


def test_an_api_member_whose_initialiser_clang_left_unresolved(write_tree) -> None:
    result = _extract(write_tree, ACTION)
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("action-server", "follow", "control_msgs/FollowJointTrajectory"),
        ("read", "rate", "double")]
    assert [d.location.line for d in result.diagnostics
            if d.code == "CPP_CALL_UNRESOLVED"] == [8]


def test_a_resolved_initialiser_is_one_call(write_tree) -> None:
    result = _extract(write_tree, ACTION.replace("Box<int>::Handle", "Box<int>::Valid"))
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("action-server", "follow", "control_msgs/FollowJointTrajectory"),
        ("read", "rate", "double")]
    assert not [d for d in result.diagnostics if d.code in (
        "CPP_CALL_UNRESOLVED", "CPP_PARSE_ERROR")]
