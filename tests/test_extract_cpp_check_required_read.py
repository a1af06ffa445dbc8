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


DEBUG_ONLY = """\
#include <ros/ros.h>
#include <glog/logging.h>
class Provider {
 public:
  Provider() : pnh_("~"), rate_(2.0), depth_(4) {
    DCHECK(pnh_.getParam("rate", rate_));
    RAW_DCHECK(pnh_.getParam("depth", depth_), "no depth");
    CHECK(pnh_.getParam("frame", frame_));
  }
 private:
  ros::NodeHandle pnh_;
  double rate_;
  int depth_;
  std::string frame_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  Provider p;
  ros::spin();
}
"""


def test_a_read_glog_dchecks_keeps_its_default(write_tree) -> None:
    """glog's DCHECK is CHECK in a debug build only: a release build (NDEBUG, as ROS
    packages are built) never evaluates it, so a read in it does not abort the program
    when the parameter is not set, and the member's initialiser stays its default
    (DCHECK expanded to CHECK, the reads were required: a parameter-read-not-set where
    the node runs with its default)."""
    xml = package_xml("pkg", "catkin").replace(
        "</package>", "<depend>roscpp</depend><depend>glog</depend></package>")
    root = write_tree({"pkg/package.xml": xml, "pkg/src/n.cpp": DEBUG_ONLY})
    result = extract_cpp([str(root / "pkg" / "src" / "n.cpp")], scan([str(root)]),
                         cache_dir=None)
    reads = sorted((c.name, c.has_default, c.default) for c in result.calls
                   if c.kind == "read")
    assert reads == [("~depth", True, 4), ("~frame", False, None), ("~rate", True, 2.0)]
