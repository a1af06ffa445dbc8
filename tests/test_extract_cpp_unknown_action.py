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
