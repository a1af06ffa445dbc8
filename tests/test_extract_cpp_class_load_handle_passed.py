"""The parameter naming the class a pluginlib ClassLoader creates, read on a handle the
node's main passes to a constructor in another file: jsk_aerial_robot's
AerialRobotBase(nh, nh_private) reads ``flight_navigation_plugin_name`` on ``nh_`` (the
node's public handle) and gives it to ``createInstance``. The read that marks the load
kept the handle's namespace joined into its name, and the public handle's ``""`` then
made it the global ``/flight_navigation_plugin_name``: a read of a parameter no launch
file sets (the bringup sets ``/dragon/flight_navigation_plugin_name``), so the class
the launch file names was never loaded into the node. It is now named on that handle,
as the read the code makes there is."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """
#pragma once
#include <ros/ros.h>
#include <pluginlib/class_loader.h>
#include <boost/shared_ptr.hpp>
namespace host {
class ControlBase {
 public:
  virtual ~ControlBase() {}
  virtual void initialize(ros::NodeHandle nh) { nh_ = nh; }
 protected:
  ros::NodeHandle nh_;
};
}
class Host {
 public:
  Host(ros::NodeHandle nh, ros::NodeHandle nhp);
 private:
  ros::NodeHandle nh_, nhp_;
  pluginlib::ClassLoader<host::ControlBase> loader_;
  boost::shared_ptr<host::ControlBase> controller_, navigator_;
};
"""

HOST = """
#include <host/host.h>
Host::Host(ros::NodeHandle nh, ros::NodeHandle nhp)
  : nh_(nh), nhp_(nhp), loader_("host", "host::ControlBase") {
  std::string name;
  nh_.param("control_name", name, std::string("host/pid"));
  controller_ = loader_.createInstance(name);
  controller_->initialize(nh_);
  std::string other;
  nhp_.param("navigator_name", other, std::string("host/nav"));
  navigator_ = loader_.createInstance(other);
}
"""

MAIN = """
#include <host/host.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "host");
  ros::NodeHandle nh;
  ros::NodeHandle nhp("~");
  Host* h = new Host(nh, nhp);
  ros::spin();
  delete h;
}
"""


def test_the_class_load_is_read_on_the_handle_passed(write_tree) -> None:
    root = write_tree({"host/package.xml": package_xml("host"),
                       "host/include/host/host.h": HEADER,
                       "host/src/host.cpp": HOST,
                       "host/src/host_node.cpp": MAIN})
    result = extract_cpp([str(root / "host/src/host.cpp"), str(root / "host/src/host_node.cpp")],
                         scan([str(root)]), cache_dir=None)
    reads = sorted((c.name, c.location.line, c.loads is not None) for c in result.calls
                   if c.kind == "read")
    assert reads == [("control_name", 5, False), ("control_name", 6, True),
                     ("~navigator_name", 9, False), ("~navigator_name", 10, True)]
