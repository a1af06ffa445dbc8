"""A parameter read inside glog's CHECK (``CHECK(pnh_.getParam("log_gt_data", log_gt_))``)
is required: CHECK aborts the program when the read finds nothing, so the value the
member held before (its initialiser, ``log_gt_(false)``) is no default
(Kimera-VIO-ROS's RosDataProviderInterface, whose launch file set ``~log_gt_data`` only
when not online: the node aborted online). A plain read into an initialised member keeps
that value as its default."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HEADER = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>
class Provider {
 public:
  Provider();
 protected:
  ros::NodeHandle nh_, pnh_;
  bool log_gt_;
  double rate_;
  std::string path_;
};
"""

SOURCE = """\
#include "pkg/p.h"
#include <glog/logging.h>
Provider::Provider() : nh_(), pnh_("~"), log_gt_(false), rate_(1.0), path_("") {
  CHECK(pnh_.getParam("log_gt_data", log_gt_));
  pnh_.getParam("rate", rate_);
  CHECK(pnh_.getParam("params_path", path_));
  CHECK(!path_.empty());
  ros::Publisher p = nh_.advertise<std_msgs::String>("x", 1);
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  Provider p;
  ros::spin();
}
"""


def test_a_read_glog_checks_has_no_default(write_tree) -> None:
    xml = package_xml("pkg", "catkin").replace(
        "</package>", "<depend>roscpp</depend><depend>std_msgs</depend>"
        "<depend>glog</depend></package>")
    root = write_tree({"pkg/package.xml": xml, "pkg/include/pkg/p.h": HEADER,
                       "pkg/src/n.cpp": SOURCE})
    result = extract_cpp([str(root / "pkg" / "src" / "n.cpp")], scan([str(root)]),
                         cache_dir=None)
    reads = sorted((c.name, c.has_default, c.tested) for c in result.calls
                   if c.kind == "read")
    assert reads == [("~log_gt_data", False, False), ("~params_path", False, False),
                     ("~rate", True, False)]
