"""roscpp's ``NodeHandle::createTimer(Rate r, Handler h, Obj o, oneshot, autostart)``, the
overload that takes a rate (mrs_uav_managers' ``nh_.createTimer(ros::Rate(rate_),
&UavManager::timerLanding, this, false, false)``), and the ``const`` member function one:
no overload in the stand-in matched, so the function that made the timers had an error
beside its ROS calls and the node was partial."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <ros/ros.h>
#include <std_msgs/String.h>
class Manager {
public:
  void init() {
    pub_ = nh_.advertise<std_msgs::String>("status", 10);
    landing_ = nh_.createTimer(ros::Rate(rate_), &Manager::timerLanding, this, false, false);
    check_ = nh_.createTimer(ros::Rate(2.0), &Manager::timerCheck, this);
    watch_ = nh_.createTimer(ros::Duration(1.0), &Manager::timerWatch, this);
  }
  void timerLanding(const ros::TimerEvent&) {}
  void timerCheck(const ros::TimerEvent&) {}
  void timerWatch(const ros::TimerEvent&) const {}
  ros::NodeHandle nh_;
  ros::Publisher pub_;
  ros::Timer landing_, check_, watch_;
  double rate_ = 10.0;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "manager");
  Manager manager;
  manager.init();
  ros::spin();
}
"""


def test_a_timer_made_at_a_rate_is_no_error(write_tree) -> None:
    root = write_tree({
        "mgr/package.xml": package_xml("mgr", "catkin"),
        "mgr/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(mgr)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp)\ncatkin_package()\n"
            "add_executable(manager src/manager.cpp)\n"),
        "mgr/src/manager.cpp": SOURCE})
    result = extract_cpp([str(root / "mgr" / "src" / "manager.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "status")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_PARSE_ERROR" not in codes and "CPP_ERROR_NEAR_CALL" not in codes
    assert "CPP_CALL_MISSED" not in codes


PERIODS = """#include <ros/ros.h>
#include <std_msgs/String.h>
class Status {
public:
  void init() {
    ros::WallDuration heartbeat;
    double rate_d = 1.0;
    if (nh_.getParam("conn/heartbeat_rate", rate_d) && rate_d != 0.0)
      heartbeat = ros::WallDuration(ros::Rate(rate_d));
    ros::Duration period(ros::Rate(5.0));
    if (period > ros::Duration::ZERO && last_ != ros::Time::ZERO)
      pub_ = nh_.advertise<std_msgs::String>("heartbeat", 10);
  }
  ros::NodeHandle nh_;
  ros::Publisher pub_;
  ros::Time last_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "status");
  Status status;
  status.init();
  ros::spin();
}
"""


def test_a_duration_of_a_rate_and_the_named_durations_are_no_error(write_tree) -> None:
    """mavros' sys_status and sys_time plugins turn a rate into a period,
    ``ros::WallDuration(ros::Rate(conn_heartbeat_d))`` (sys_status.cpp:456): rostime's
    Duration and WallDuration have ``explicit ...(const Rate &)``, which the stand-in
    lacked, so the plugin stopped there with an error near its calls and /mavros was
    partial. rostime's named durations and times (``ros::Duration::ZERO``,
    ``ros::Time::ZERO``) are there too."""
    root = write_tree({
        "st/package.xml": package_xml("st", "catkin"),
        "st/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(st)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp)\ncatkin_package()\n"
            "add_executable(status src/status.cpp)\n"),
        "st/src/status.cpp": PERIODS})
    result = extract_cpp([str(root / "st" / "src" / "status.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert [(c.kind, c.name) for c in result.calls] == [
        ("read", "conn/heartbeat_rate"), ("publish", "heartbeat")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_PARSE_ERROR" not in codes and "CPP_ERROR_NEAR_CALL" not in codes
