"""Two parameters' values in one segment of a name: ros_kortex's simulation driver names
its action client ``"/" + m_robot_name + "/" + m_prefix + m_arm_name +
"_joint_trajectory_controller/follow_joint_trajectory"`` and doosan's hardware interface
``"/" + m_strRobotName + m_strRobotModel + "/stop"``, each member read from a parameter.
The run of two values is one ``?``; where the configuration sets every parameter a ``?``
is made of, the graph fills it with their values joined, and leaves the ``?`` otherwise
(earlier the name kept its ``?`` whatever the launch set)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Node
from haros_arch.model.load import call_from_data
from haros_arch.model.serialise import to_data
from haros_arch.workspace import Workspace, scan
from tests.conftest import package_xml

NODE = """
#include <ros/ros.h>
#include <std_msgs/String.h>
class Arm
{
public:
  explicit Arm(ros::NodeHandle & nh)
  {
    ros::param::get("~robot_name", m_robot_name);
    ros::param::get("~prefix", m_prefix);
    ros::param::get("~arm", m_arm_name);
    nh.getParam("model", m_model);
    m_pub_cmd = nh.advertise<std_msgs::String>(
        "/" + m_robot_name + "/" + m_prefix + m_arm_name + "_controller/command", 1);
    m_pub_stop = nh.advertise<std_msgs::String>("/" + m_robot_name + m_model + "/stop", 1);
    m_pub_own = nh.advertise<std_msgs::String>(m_prefix + m_arm_name + "_state", 1);
  }
private:
  std::string m_robot_name, m_prefix, m_arm_name, m_model;
  ros::Publisher m_pub_cmd, m_pub_stop, m_pub_own;
};
int main(int argc, char ** argv)
{
  ros::init(argc, argv, "ex");
  ros::NodeHandle nh("~");
  Arm arm(nh);
  ros::spin();
}
"""

SETS = {"robot_name": "my_gen3", "prefix": "left_", "arm": "gen3", "model": "m1013"}


def _config(root, given: dict[str, str]) -> Configuration:
    result = extract_cpp([str(root / "ex" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    node = Node("ex", "ex", calls=list(result.calls))
    config = build(Configuration("c"), LaunchModel(
        nodes=[NodeDecl("/ex", "ex", "ex")],
        params=[ParamDecl(f"/ex/{key}", value, "str") for key, value in given.items()]),
        Workspace(root="/nowhere"), {node.name: node})
    return config


def _publishers(root, given: dict[str, str]) -> list[str]:
    config = _config(root, given)
    return sorted(link.rosname.full for link in config.links if link.kind == "publish")


def test_a_segment_of_two_parameters_is_filled_when_both_are_set(write_tree) -> None:
    root = write_tree({"ex/package.xml": package_xml("ex"), "ex/src/node.cpp": NODE})
    result = extract_cpp([str(root / "ex" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    named = sorted((c.name, c.name_param, c.name_more) for c in result.calls
                   if c.kind == "publish")
    assert named == [
        ("/?/?_controller/command", "~robot_name",
         [["~prefix", None], ["~arm", None, "+"]]),
        ("/?/stop", "~robot_name", [["~model", None, "+"]]),
        ("~?_state", "~prefix", [["~arm", None, "+"]]),
    ]
    assert _publishers(root, SETS) == [
        "/ex/left_gen3_state", "/my_gen3/left_gen3_controller/command",
        "/my_gen3m1013/stop"]


def test_a_segment_stays_unknown_unless_every_parameter_is_set(write_tree) -> None:
    root = write_tree({"ex/package.xml": package_xml("ex"), "ex/src/node.cpp": NODE})
    # the arm not set: the second segment of the command and the state topic stay ``?``
    # (a private name led by a value not known may be any name: ``?_state``)
    given = {k: v for k, v in SETS.items() if k != "arm"}
    assert _publishers(root, given) == [
        "/my_gen3/?_controller/command", "/my_gen3m1013/stop", "?_state"]
    # an empty prefix is a value: the segment is the arm's name alone
    assert _publishers(root, {**SETS, "prefix": ""}) == [
        "/ex/gen3_state", "/my_gen3/gen3_controller/command", "/my_gen3m1013/stop"]
    assert _publishers(root, {}) == ["/?/?_controller/command", "/?/stop", "?_state"]
    # the info says which of the segment's parameters the configuration does not set
    unset = [d.message for d in _config(root, given).diagnostics
             if d.code == "NAME_PARAM_UNSET"]
    assert unset and all("parameter ~arm," in m for m in unset), unset


def test_a_joined_entry_survives_the_json_model() -> None:
    data = {"kind": "publish", "name": "/?/stop", "name_param": "~robot_name",
            "name_more": [["~model", None, "+"]]}
    call = call_from_data(data)
    assert call.name_more == [["~model", None, "+"]]
    assert call_from_data(to_data(call)).name_more == [["~model", None, "+"]]
