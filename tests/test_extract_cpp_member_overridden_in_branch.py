"""A member a function writes with a value that always runs and then again in a branch
the read is outside of holds either value where it is read, not the value a constructor
gives it first. rpg_dvs_ros b7fce27's DAVIS driver, in its constructor: ``ns =
ros::this_node::getNamespace(); if (ns == "/") ns = "/dvs";`` then ``advertise(ns +
"/events", ...)``: the constructor's first write was taken as the member's value (a
name that was the node's namespace alone, or with ``other = "x"; if (...) other =
"y";``, a plain ``x/count``). roscpp's ``ros::this_node::getNamespace()`` is the node's
namespace: a name made of it and a ``/``-led text is that text, relative."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """#include <ros/ros.h>
#include <std_msgs/Int32.h>
class Driver {
 public:
  explicit Driver(ros::NodeHandle & nh) : nh_(nh) {
    ns_ = ros::this_node::getNamespace();
    if (ns_ == "/")
      ns_ = "/dvs";
    events_ = nh_.advertise<std_msgs::Int32>(ns_ + "/events", 1);
    other_ = "x";
    if (nh_.ok())
      other_ = "y";
    count_ = nh_.advertise<std_msgs::Int32>(other_ + "/count", 1);
    same_ = "z";
    if (nh_.ok())
      same_ = "z";
    same_pub_ = nh_.advertise<std_msgs::Int32>(same_ + "/same", 1);
    status_ = nh_.advertise<std_msgs::Int32>(ros::this_node::getNamespace() + "/status", 1);
  }
 private:
  ros::NodeHandle nh_;
  std::string ns_, other_, same_;
  ros::Publisher events_, count_, same_pub_, status_;
};
int main(int argc, char ** argv) {
  ros::init(argc, argv, "driver");
  ros::NodeHandle nh;
  Driver driver(nh);
  ros::spin();
}
"""


def test_member_written_again_in_a_branch(write_tree) -> None:
    root = write_tree({"drv/package.xml": package_xml("drv"), "drv/src/drv.cpp": NODE})
    result = extract_cpp([str(root / "drv" / "src" / "drv.cpp")], scan([str(root)]),
                         cache_dir=None)
    names = sorted(c.name for c in result.calls if c.kind == "publish")
    assert names == ["?/count", "?/events", "status", "z/same"], names
