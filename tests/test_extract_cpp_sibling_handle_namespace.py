"""The calls an API row makes beside its main one (``siblings`` of a call with a
``name_suffix``) are on the main call's handle. ros_control_boilerplate (0f9cd01) reads
joint limits with ``joint_limits_interface::getJointLimits(joint_names_[id], nh_,
limits)``, ``nh_`` the handle GenericHWInterface's constructor (in its own file) takes
from main's ``ros::NodeHandle nh``: the main read was ``joint_limits/?/has_position_limits``
but the ten others ``/joint_limits/?/min_position`` and so on, global names (the
handle's namespace, given by the call sites, was expanded into their text but they were
said on no handle), so they were "global names" and never met the node's namespace."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """
#include <ros/ros.h>
#include <string>
#include <vector>
class GenericHW {
 public:
  GenericHW(const ros::NodeHandle& nh);
  void registerJointLimits(std::size_t id);
  ros::NodeHandle nh_;
  std::vector<std::string> joint_names_;
};
"""

HW = """
#include "generic_hw.h"
#include <joint_limits_interface/joint_limits_rosparam.h>
GenericHW::GenericHW(const ros::NodeHandle& nh) : nh_(nh) {}
void GenericHW::registerJointLimits(std::size_t id) {
  joint_limits_interface::JointLimits limits;
  joint_limits_interface::getJointLimits(joint_names_[id], nh_, limits);
}
"""

MAIN = """
#include "generic_hw.h"
int main(int argc, char** argv) {
  ros::init(argc, argv, "hw");
  ros::NodeHandle HANDLE;
  GenericHW hw(HANDLE);
  hw.registerJointLimits(0);
  ros::spin();
}
"""


def _reads(write_tree, handle: str) -> list[str]:
    root = write_tree({"hw/package.xml": package_xml("hw"), "hw/src/generic_hw.h": HEADER,
                       "hw/src/generic_hw.cpp": HW,
                       "hw/src/main.cpp": MAIN.replace("HANDLE", handle)})
    result = extract_cpp([str(root / "hw" / "src" / "main.cpp"),
                          str(root / "hw" / "src" / "generic_hw.cpp")],
                         scan([str(root)]), cache_dir=None)
    return sorted(c.name for c in result.calls if c.kind == "read")


def test_the_reads_beside_the_main_one_are_on_its_handle(write_tree) -> None:
    reads = _reads(write_tree, "nh")
    assert len(reads) == 12
    assert all(name.startswith("joint_limits/?/") for name in reads), reads


def test_on_another_handle_all_share_the_main_one_s_namespace(write_tree) -> None:
    reads = _reads(write_tree, 'nh("~")')
    main = next(name for name in reads if name.endswith("/has_position_limits"))
    namespace = main.removesuffix("has_position_limits")
    assert len(reads) == 12
    assert all(name.startswith(namespace) for name in reads), reads
