"""boost::bind of an overloaded member function (motoman_driver's JointTrajectoryAction:
``boost::bind(&JointTrajectoryAction::goalCB, this, _1)`` beside a goalCB of two
parameters): boost's overloads by arity pick the one the bound arguments fill; the
stand-in takes them so, with no C++ error that makes the constructor partial."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <ros/ros.h>
#include <boost/bind.hpp>
#include <std_msgs/String.h>
class Relay {
 public:
  Relay() {
    sub_ = nh_.subscribe<std_msgs::String>("in", 1, boost::bind(&Relay::onIn, this, _1));
    sub2_ = nh_.subscribe<std_msgs::String>("in2", 1,
                                            boost::bind(&Relay::onIn, this, _1, 2));
    timer_ = nh_.createTimer(ros::Duration(1.0), boost::bind(&Relay::tick, this));
    pub_ = nh_.advertise<std_msgs::String>("out", 1);
  }
  void onIn(const std_msgs::String::ConstPtr & msg);
  void onIn(const std_msgs::String::ConstPtr & msg, int group);
  void tick() const;
  static void log(const std::string & text);
  static void log(const std::string & text, int level);
  ros::NodeHandle nh_;
  ros::Subscriber sub_, sub2_;
  ros::Publisher pub_;
  ros::Timer timer_;
};
int main(int argc, char ** argv) {
  ros::init(argc, argv, "relay");
  Relay relay;
  auto say = boost::bind(&Relay::log, _1, 3);
  ros::spin();
}
"""


def test_bind_of_an_overloaded_member_function(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("relay").replace(
        "</package>", "<depend>roscpp</depend><depend>std_msgs</depend></package>"))
    source = tmp_path / "relay.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [
        ("subscribe", "in"), ("subscribe", "in2"), ("publish", "out")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_PARSE_ERROR" not in codes and "CPP_ERROR_NEAR_CALL" not in codes
