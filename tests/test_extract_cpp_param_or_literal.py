"""A name held by a variable a parameter read writes by reference, and the body writes
one literal beside (ROS 1's ``if (!pnh.getParam("topic", topic)) topic = "scan";``):
the parameter's value, that literal where it is not set. The literal was lost: the
topic was ``?`` wherever the launch did not set the parameter. A variable written a
second value that is no literal keeps no default."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <string>
#include <ros/ros.h>
#include <std_msgs/String.h>
void cb(const std_msgs::String::ConstPtr&) {}
std::string other();
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  ros::NodeHandle nh, pnh("~");
  std::string topic;
  if (!pnh.getParam("topic", topic)) {
    topic = "scan";
  }
  std::string third;
  if (!pnh.getParam("third", third))
    third = "third_default";
  std::string computed;
  if (!pnh.getParam("computed", computed))
    computed = other();
  ros::Subscriber s = nh.subscribe(topic, 1, cb);
  ros::Publisher p = nh.advertise<std_msgs::String>(third, 1);
  ros::Publisher q = nh.advertise<std_msgs::String>(computed, 1);
  ros::spin();
}
"""


def test_the_literal_written_beside_a_read_is_the_names_default(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("n").replace(
        "</package>", "<depend>roscpp</depend><depend>std_msgs</depend></package>"))
    source = tmp_path / "n.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    named = sorted((c.kind, c.name_param, c.name_default) for c in result.calls
                   if c.kind in ("publish", "subscribe"))
    assert named == [("publish", "~computed", None), ("publish", "~third", "third_default"),
                     ("subscribe", "~topic", "scan")], named
