"""Two parameters' values joined in a name handed to a constructor in another file:
ros_kortex's real-robot driver (kortex_arm_driver.cpp:518, 6cd75d45) starts its action
server with ``new JointTrajectoryActionServer(m_prefix + m_arm_name +
"_joint_trajectory_controller/follow_joint_trajectory", ...)``, the server's constructor
(joint_trajectory_action_server.cpp:25) naming it with that parameter. A string with one
parameter's value is passed with the parameter marked; a run of two values was passed
as a bare ``?`` (its parts two unknowns side by side), so the server stayed
``?_joint_trajectory_controller/...`` whatever the launch set. Now both are marked, the
second JOINED to the first, as in the caller's own names
(test_extract_cpp_param_joined_segment)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Node
from haros_arch.workspace import Workspace, scan
from tests.conftest import package_xml

SERVER_H = """#include <ros/ros.h>
#include <std_msgs/String.h>
class Server
{
public:
  Server(const std::string & server_name, ros::NodeHandle & nh);
private:
  ros::Publisher m_pub;
};
"""

SERVER = """#include "ex/server.h"
Server::Server(const std::string & server_name, ros::NodeHandle & nh)
{
  m_pub = nh.advertise<std_msgs::String>(server_name + "/feedback", 1);
}
"""

DRIVER = """#include <ros/ros.h>
#include "ex/server.h"
class Driver
{
public:
  explicit Driver(ros::NodeHandle & nh) : m_node_handle(nh)
  {
    parseRosArguments();
    startActionServers();
  }
  void parseRosArguments()
  {
    ros::param::get("~prefix", m_prefix);
    ros::param::get("~arm", m_arm_name);
  }
  void startActionServers()
  {
    m_joint = new Server(m_prefix + m_arm_name + "_joint_trajectory_controller", m_node_handle);
    m_alone = new Server(m_arm_name + "_alone", m_node_handle);
  }
private:
  ros::NodeHandle m_node_handle;
  std::string m_prefix, m_arm_name;
  Server * m_joint;
  Server * m_alone;
};
int main(int argc, char ** argv)
{
  ros::init(argc, argv, "ex");
  ros::NodeHandle nh("~");
  Driver driver(nh);
  ros::spin();
}
"""


def _result(write_tree):
    root = write_tree({"ex/package.xml": package_xml("ex"), "ex/include/ex/server.h": SERVER_H,
                       "ex/src/server.cpp": SERVER, "ex/src/driver.cpp": DRIVER})
    return extract_cpp([str(root / "ex" / "src" / "driver.cpp"),
                        str(root / "ex" / "src" / "server.cpp")], scan([str(root)]),
                       cache_dir=None)


def _publishers(calls, given: dict[str, str]) -> list[str]:
    node = Node("ex", "ex", calls=list(calls))
    config = build(Configuration("c"), LaunchModel(
        nodes=[NodeDecl("/ex", "ex", "ex")],
        params=[ParamDecl(f"/ex/{key}", value, "str") for key, value in given.items()]),
        Workspace(root="/nowhere"), {node.name: node})
    return sorted(link.rosname.full for link in config.links if link.kind == "publish")


def test_a_joined_run_handed_to_a_constructor_keeps_its_parameters(write_tree) -> None:
    result = _result(write_tree)
    named = sorted((c.name, c.name_param, c.name_more) for c in result.calls
                   if c.kind == "publish")
    assert named == [
        ("~?_alone/feedback", "~arm", None),
        ("~?_joint_trajectory_controller/feedback", "~prefix", [["~arm", None, "+"]]),
    ]
    assert _publishers(result.calls, {"prefix": "left_", "arm": "gen3"}) == [
        "/ex/gen3_alone/feedback", "/ex/left_gen3_joint_trajectory_controller/feedback"]
    # the prefix not set: the joined run stays unknown (not the arm's value alone; a
    # private name led by a value not known may be any name: ``?_...``)
    assert _publishers(result.calls, {"arm": "gen3"}) == [
        "/ex/gen3_alone/feedback", "?_joint_trajectory_controller/feedback"]


def test_empty_values_before_text_of_their_segment_leave_that_text(write_tree) -> None:
    # ros_kortex's gripper server with ``prefix`` and ``gripper`` both "" (its launch
    # file's defaults for a gen3): ``_gripper_controller/gripper_cmd``, a name; it stayed
    # ``?`` with NAME_PARAM_UNSET saying the set ``~prefix`` was not set
    result = _result(write_tree)
    assert _publishers(result.calls, {"prefix": "", "arm": ""}) == [
        "/ex/_alone/feedback", "/ex/_joint_trajectory_controller/feedback"]
