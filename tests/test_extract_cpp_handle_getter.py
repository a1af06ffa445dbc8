"""A handle a getter returns has the namespace of what the getter returns.
hector_localization (c2c3df1): PoseEstimationNode reads its parameters and makes its
topics on ``getPrivateNodeHandle()`` and ``getNodeHandle()``, virtual getters of its
header that return ``private_nh_`` (built ``("~")``) and ``nh_``; every name of the
pose_estimation node was ``?/...`` (35 unresolved names). Now a method without
parameters whose body returns a handle gives that handle's namespace, when every body
a call of it may run (an override the unit defines too) agrees; else it stays
unknown."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """
#include <ros/ros.h>
#include <std_msgs/String.h>
class PoseEstimationNode {
 public:
  PoseEstimationNode();
  virtual ~PoseEstimationNode();
  bool init();
 protected:
  virtual ros::NodeHandle& getNodeHandle() { return nh_; }
  virtual ros::NodeHandle& getPrivateNodeHandle() { return private_nh_; }
  ros::NodeHandle& other() { return other_nh_; }
 private:
  ros::NodeHandle nh_, private_nh_, other_nh_;
  ros::Publisher state_, other_;
  ros::Subscriber imu_;
  bool publish_covariances_;
};
"""

NODE = """
#include "pose_estimation_node.h"
#include <sensor_msgs/Imu.h>
PoseEstimationNode::PoseEstimationNode() : private_nh_("~"), other_nh_("other") {}
PoseEstimationNode::~PoseEstimationNode() {}
void imu(const sensor_msgs::Imu::ConstPtr& m) {}
bool PoseEstimationNode::init() {
  getPrivateNodeHandle().getParam("publish_covariances", publish_covariances_);
  state_ = getNodeHandle().advertise<std_msgs::String>("state", 10);
  imu_ = getNodeHandle().subscribe("raw_imu", 10, imu);
  other_ = other().advertise<std_msgs::String>("x", 10);
  return true;
}
"""

MAIN = """
#include "pose_estimation_node.h"
DERIVED
int main(int argc, char** argv) {
  ros::init(argc, argv, "pose_estimation");
  PoseEstimationNode node;
  node.init();
  ros::spin();
}
"""

# an override of the unit that returns another handle: which runs is not known here
DERIVED = """
class Renamed : public PoseEstimationNode {
 protected:
  ros::NodeHandle& getPrivateNodeHandle() override { return mine_; }
  ros::NodeHandle mine_{"mine"};
};
"""


def _calls(write_tree, derived: str) -> list[tuple[str, str]]:
    root = write_tree({"pe/package.xml": package_xml("pe"),
                       "pe/src/pose_estimation_node.h": HEADER,
                       "pe/src/pose_estimation_node.cpp": NODE.replace(
                           '#include <sensor_msgs/Imu.h>',
                           '#include <sensor_msgs/Imu.h>\n' + derived),
                       "pe/src/main.cpp": MAIN.replace("DERIVED", "")})
    result = extract_cpp([str(root / "pe" / "src" / "main.cpp"),
                          str(root / "pe" / "src" / "pose_estimation_node.cpp")],
                         scan([str(root)]), cache_dir=None)
    return sorted((c.kind, c.name) for c in result.calls)


def test_a_getter_gives_the_handle_it_returns(write_tree) -> None:
    assert _calls(write_tree, "") == [("publish", "other/x"), ("publish", "state"),
                                      ("read", "~publish_covariances"),
                                      ("subscribe", "raw_imu")]


def test_overrides_that_return_other_handles_leave_it_unknown(write_tree) -> None:
    calls = _calls(write_tree, DERIVED)
    assert ("read", "?/publish_covariances") in calls
    assert ("publish", "state") in calls
