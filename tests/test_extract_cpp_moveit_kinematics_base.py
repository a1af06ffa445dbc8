"""ROS 1 MoveIt's kinematics plugin base, installed (moveit_core not in the workspace): an
IKFast plugin generated for a robot derives ``kinematics::KinematicsBase`` and uses what
its ``initialize`` stores (``setValues``, ``tip_frame_``, ``base_frame_``,
``search_discretization_``). Without a stand-in each was an error in ``initialize``,
which reads the plugin's parameters, so the plugin (and move_group, which loads it) was
partial (fanuc_experimental's lrmate200id plugin)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

PACKAGE = ('<?xml version="1.0"?>\n<package format="2"><name>ik_plugin</name>'
           "<version>0.1.0</version><description>d</description>"
           '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
           "<depend>roscpp</depend><depend>moveit_core</depend>"
           "<depend>pluginlib</depend></package>\n")

SOURCE = """#include <ros/ros.h>
#include <moveit/kinematics_base/kinematics_base.h>
namespace ik {
class Plugin : public kinematics::KinematicsBase {
 public:
  bool initialize(const std::string &robot_description, const std::string &group_name,
                  const std::string &base_name, const std::string &tip_name,
                  double search_discretization) {
    setValues(robot_description, group_name, base_name, tip_name, search_discretization);
    ros::NodeHandle node_handle("~/" + group_name);
    std::string urdf_xml;
    node_handle.param("urdf_xml", urdf_xml, robot_description);
    if (tip_frame_ == base_frame_ || search_discretization_ <= 0.0) return false;
    node_handle.param("free_angle", free_angle_, 0.0);
    return true;
  }
  bool getPositionIK(const geometry_msgs::Pose &, const std::vector<double> &,
                     std::vector<double> &, moveit_msgs::MoveItErrorCodes &,
                     const kinematics::KinematicsQueryOptions &) const override;
  double free_angle_;
};
}  // namespace ik
"""


def test_an_ikfast_plugin_reads_its_parameters_whole(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(PACKAGE)
    (tmp_path / "plugin.cpp").write_text(SOURCE)
    result = extract_cpp([str(tmp_path / "plugin.cpp")], scan([str(tmp_path)]),
                         cache_dir=None, distro="noetic")
    assert not [(d.code, d.message) for d in result.diagnostics if d.code in (
        "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED", "CPP_CLASS_UNSEEN", "CPP_INCLUDE_MISSING")]
    assert [(c.kind, c.name.rsplit("/", 1)[-1]) for c in result.calls] == [
        ("read", "urdf_xml"), ("read", "free_angle")]
