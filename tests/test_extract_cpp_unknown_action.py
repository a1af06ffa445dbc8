"""A ROS 1 ``pkg/DoAction.h`` whose package is neither in the workspace nor in the
catalogue of installed interfaces is still an action's header (genaction's name): its
parts are synthesised without fields, so an actionlib server or client of it is a call.
Before, it was a fieldless message: the ``SimpleActionServer`` member that
kobuki_auto_docking's constructor builds in its initialiser list (auto_docking_ros.cpp:24,
kobuki_msgs absent) gave no call, and its node stood complete without it."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """
#include <ros/ros.h>
#include <actionlib/server/simple_action_server.h>
#include <actionlib/client/simple_action_client.h>
#include <dock_msgs/DockAction.h>
#include <dock_msgs/Status.h>
class Dock {
public:
  explicit Dock(std::string name) : name_(name), as_(nh_, name_ + "_action", false),
                                    ac_("undock", true)
  {
    as_.start();
    pub_ = nh_.advertise<dock_msgs::Status>("status", 1);
  }
private:
  std::string name_;
  ros::NodeHandle nh_;
  actionlib::SimpleActionServer<dock_msgs::DockAction> as_;
  actionlib::SimpleActionClient<dock_msgs::DockAction> ac_;
  dock_msgs::DockResult result_;
  ros::Publisher pub_;
};
int main(int argc, char ** argv)
{
  ros::init(argc, argv, "dock");
  Dock dock("dock");
  ros::spin();
}
"""


def test_an_unknown_installed_action_keeps_its_server_and_client(write_tree) -> None:
    root = write_tree({"pkg/package.xml": package_xml("pkg", "catkin"),
                       "pkg/src/node.cpp": NODE})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("action-client", "undock", "dock_msgs/Dock"),
        ("action-server", "dock_action", "dock_msgs/Dock"),
        ("publish", "status", "dock_msgs/Status")]
    unknown = sorted(d.message for d in result.diagnostics if d.code == "CPP_MESSAGE_UNKNOWN")
    assert unknown == [
        "no definition found for dock_msgs/DockAction.h; it was synthesised without fields",
        "no definition found for dock_msgs/Status.h; it was synthesised without fields"]


GRASP = """
#include <ros/ros.h>
#include <actionlib/server/action_server.h>
#include <grasp_msgs/GraspAction.h>
#include "grasp_msgs/GraspGoal.h"
using namespace grasp_msgs;
using namespace actionlib;
class Grasp {
  typedef ActionServer<GraspAction> Server;
  typedef Server::GoalHandle GoalHandle;
public:
  explicit Grasp(ros::NodeHandle& n) : node_(n),
      server_(node_, "grasp_execution_action",
              boost::bind(&Grasp::goal, this, _1), boost::bind(&Grasp::cancel, this, _1),
              false) { server_.start(); }
private:
  void goal(GoalHandle gh) {
    if (gh.getGoal()->goal == GraspGoal::PRE_GRASP) gh.setAccepted();
    gh.setSucceeded();
  }
  void cancel(GoalHandle gh) {}
  ros::NodeHandle node_;
  Server server_;
};
int main(int argc, char ** argv)
{
  ros::init(argc, argv, "grasp");
  ros::NodeHandle node;
  Grasp grasp(node);
  ros::spin();
}
"""


def test_an_action_of_the_workspace_wins_over_stale_copies_of_its_messages(
        write_tree) -> None:
    """industrial_training's object_manipulation_msgs keeps the .msg files genaction made
    from GraspHandPostureExecution.action in ``msg/`` beside the action, outside
    add_message_files: ``GraspHandPostureExecutionAction.h`` was read from the stale
    .msg, a plain message without actionlib's nested types, and the node's action server
    (and every call of the unit) was lost to the errors."""
    root = write_tree({
        "grasp_msgs/package.xml": package_xml("grasp_msgs", "catkin"),
        "grasp_msgs/action/Grasp.action":
            "uint8 PRE_GRASP=1\nuint8 goal\n---\nbool ok\n---\nfloat32 progress\n",
        "grasp_msgs/msg/GraspAction.msg":
            "GraspActionGoal action_goal\nGraspActionResult action_result\n"
            "GraspActionFeedback action_feedback\n",
        "grasp_msgs/msg/GraspGoal.msg": "uint8 PRE_GRASP=1\nuint8 goal\n",
        "grasp_msgs/msg/GraspActionGoal.msg": "Header header\nGraspGoal goal\n",
        "grasp_msgs/msg/GraspActionResult.msg": "Header header\n",
        "grasp_msgs/msg/GraspActionFeedback.msg": "Header header\n",
        "pkg/package.xml": package_xml("pkg", "catkin"),
        "pkg/src/node.cpp": GRASP})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("action-server", "grasp_execution_action", "grasp_msgs/Grasp")]
    assert not [d for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"], \
        result.diagnostics
