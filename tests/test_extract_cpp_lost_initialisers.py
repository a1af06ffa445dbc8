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


# ros_controllers' JointTrajectoryController (joint_trajectory_controller_impl.h:296-299):
# in a class template, ``new ActionServer(nh, name, std::bind(&C::goalCB, this, _1), ...)``
# holds arguments that depend on the template's parameters, and clang keeps only their
# list, no call of the constructor: its action server was lost with no word (the
# controller's model had its command topic and state, not follow_joint_trajectory)
TEMPLATE = """
#include <ros/ros.h>
#include <memory>
#include <functional>
#include <actionlib/server/action_server.h>
#include <control_msgs/FollowJointTrajectoryAction.h>
template <class Segment>
class Controller {
 public:
  typedef actionlib::ActionServer<control_msgs::FollowJointTrajectoryAction> ActionServer;
  typedef ActionServer::GoalHandle GoalHandle;
  void goalCB(GoalHandle gh) {}
  void cancelCB(GoalHandle gh) {}
  bool init(ros::NodeHandle& controller_nh) {
    action_server_.reset(new ActionServer(controller_nh, "follow_joint_trajectory",
                         std::bind(&Controller::goalCB, this, std::placeholders::_1),
                         std::bind(&Controller::cancelCB, this, std::placeholders::_1),
                         false));
    return true;
  }
 private:
  std::shared_ptr<ActionServer> action_server_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "controller");
  ros::NodeHandle nh("~");
  Controller<double> c;
  c.init(nh);
}
"""


def test_a_new_api_object_clang_left_unresolved_in_a_template(write_tree) -> None:
    result = _extract(write_tree, TEMPLATE)
    assert [(c.kind, c.name, c.type, c.location.line) for c in result.calls] == [
        ("action-server", "~follow_joint_trajectory", "control_msgs/FollowJointTrajectory",
         14)]
    assert [d.location.line for d in result.diagnostics
            if d.code == "CPP_CALL_UNRESOLVED"] == [14]


def test_a_new_api_object_clang_resolved_is_one_call(write_tree) -> None:
    # outside a template the constructor call is there: read as before, no diagnostic
    source = TEMPLATE.replace("template <class Segment>\n", "").replace(
        "Controller<double> c;", "Controller c;")
    result = _extract(write_tree, source)
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("action-server", "~follow_joint_trajectory", "control_msgs/FollowJointTrajectory")]
    assert not [d for d in result.diagnostics if d.code in (
        "CPP_CALL_UNRESOLVED", "CPP_PARSE_ERROR")]
