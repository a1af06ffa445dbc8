"""A name built in a local string stream keeps the text written to it.
youbot_driver_ros_interface (db124ec) names each arm's topics so:
``topicName.str(""); topicName << armConfig.commandTopicName <<
"arm_controller/position_command"; node.subscribe<...>(topicName.str(), ...)``; the
names were ``?`` whole, now the text after the unknown prefix stays
(``?arm_controller/position_command``). What a stream holds is known only where every
write since its last emptying runs before the read: a write under a branch the read is
outside of, a stream written in earlier turns of a loop without being emptied in that
turn, a stream made with a text (later writes overwrite it) or handed to a function
leave the name ``?``."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <sstream>
#include <string>
void cb(const std_msgs::String::ConstPtr& m) {}
void fill(std::stringstream& s);
struct Arm { std::string commandTopicName; };
int main(int argc, char** argv) {
  ros::init(argc, argv, "yb");
  ros::NodeHandle node;
  Arm arm;
  arm.commandTopicName = argv[0];
  std::stringstream topicName;
  topicName.str("");
  topicName << arm.commandTopicName << "arm_controller/position_command";
  ros::Subscriber s = node.subscribe(topicName.str(), 10, cb);
  topicName.str("");
  topicName << "base/" << 3 << "/switchOffMotors";
  ros::Publisher p = node.advertise<std_msgs::String>(topicName.str(), 10);
  std::ostringstream maybe;
  maybe << "a";
  if (argc > 3) maybe << "b";
  ros::Publisher q = node.advertise<std_msgs::String>(maybe.str(), 10);
  std::stringstream piled;
  for (int i = 0; i < 3; i++) {
    piled << "robot" << i;
    ros::Publisher r = node.advertise<std_msgs::String>(piled.str() + "/piled", 10);
  }
  for (int i = 0; i < 2; i++) {
    std::stringstream each;
    each << "robot" << i << "/odom";
    ros::Publisher r = node.advertise<std_msgs::String>(each.str(), 10);
  }
  std::stringstream given("base");
  given << "/given";
  ros::Publisher g = node.advertise<std_msgs::String>(given.str(), 10);
  std::stringstream handed;
  handed << "handed";
  fill(handed);
  ros::Publisher h = node.advertise<std_msgs::String>(handed.str(), 10);
  std::ostringstream rate;
  rate << "rate_" << 2.5;
  ros::Publisher f = node.advertise<std_msgs::String>(rate.str(), 10);
  ros::spin();
}
"""


def test_names_written_to_a_string_stream(write_tree) -> None:
    root = write_tree({"yb/package.xml": package_xml("yb"), "yb/src/main.cpp": NODE})
    result = extract_cpp([str(root / "yb" / "src" / "main.cpp")], scan([str(root)]),
                         cache_dir=None)
    names = sorted((c.kind, c.name) for c in result.calls if c.kind != "read")
    assert names == sorted([
        ("subscribe", "?arm_controller/position_command"),
        ("publish", "base/3/switchOffMotors"),
        ("publish", "?"),  # maybe "ab": a write under the if
        ("publish", "?/piled"),  # earlier turns' writes are still in it
        ("publish", "robot0/odom"),
        ("publish", "robot1/odom"),
        ("publish", "?"),  # made with "base": "/given" overwrites it from the start
        ("publish", "?"),  # handed to fill(), which may write it
        ("publish", "rate_?"),  # a float's text depends on the stream's format
    ])


LOOPED = """
#include <ros/ros.h>
#include <sstream>
#include <string>
int main(int argc, char** argv) {
  ros::init(argc, argv, "yb");
  ros::NodeHandle n("~");
  int i = 1;
  std::stringstream armNameParam;
  armNameParam << "youBotArmName" << i;
  while (n.hasParam(armNameParam.str())) {
    std::string armName;
    n.getParam(armNameParam.str(), armName);
    armNameParam.str("");
    armNameParam << "youBotArmName" << (++i);
  }
  std::stringstream fixed;
  fixed << "fixed";
  for (int k = 0; k < 2; k++) n.hasParam(fixed.str());
  ros::spin();
}
"""


def test_a_stream_written_again_in_the_loop_that_reads_it(write_tree) -> None:
    # youbot_oodl.cpp: the loop's condition reads youBotArmName1, then what the body
    # wrote in the turn before (youBotArmName2, ...): not one known name
    root = write_tree({"yb/package.xml": package_xml("yb"), "yb/src/main.cpp": LOOPED})
    result = extract_cpp([str(root / "yb" / "src" / "main.cpp")], scan([str(root)]),
                         cache_dir=None)
    names = sorted(c.name for c in result.calls if c.kind == "read")
    assert names == ["~?", "~?", "~fixed"]

