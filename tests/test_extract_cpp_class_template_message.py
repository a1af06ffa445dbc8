"""A subscription made in a member of a class template whose callback takes the
template's type parameter (OpenMower's ``StateSubscriber<M>``: ``n->subscribe(topic_, 10,
&StateSubscriber::setMessage, this)``) is typed, per construction, by the template
argument of that construction, as its name is filled by the construction's topic; it
was ``?`` (the call is dependent, the parse leaves it unresolved)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

PACKAGE = ('<?xml version="1.0"?>\n<package format="2"><name>logic</name>'
           "<version>0.1.0</version><description>d</description>"
           '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
           "<depend>roscpp</depend><depend>std_msgs</depend></package>\n")

HEADER = """#include <ros/ros.h>
template <typename MESSAGE>
class StateSubscriber {
 public:
  explicit StateSubscriber(const std::string& topic);
  void Start(ros::NodeHandle* n);
  void setMessage(const MESSAGE& message);
 private:
  std::string topic_;
  MESSAGE message_{};
  ros::Subscriber subscriber_{};
};
template <typename MESSAGE>
StateSubscriber<MESSAGE>::StateSubscriber(const std::string& topic) : topic_{topic} {}
template <typename MESSAGE>
void StateSubscriber<MESSAGE>::Start(ros::NodeHandle* n) {
  subscriber_ = n->subscribe(topic_, 10, &StateSubscriber::setMessage, this);
}
template <typename MESSAGE>
void StateSubscriber<MESSAGE>::setMessage(const MESSAGE& message) { message_ = message; }
"""

SOURCE = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include <std_msgs/Float64.h>
#include "state_subscriber.h"
StateSubscriber<std_msgs::String> status_sub{"/ll/status"};
StateSubscriber<std_msgs::Float64> power_sub{"/ll/power"};
StateSubscriber<std_msgs::Float64> voltage_sub{"/ll/voltage"};
int main(int argc, char** argv) {
  ros::init(argc, argv, "logic");
  ros::NodeHandle n;
  status_sub.Start(&n);
  power_sub.Start(&n);
  voltage_sub.Start(&n);
}
"""


def test_each_construction_types_the_subscription_it_names(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(PACKAGE)
    (tmp_path / "state_subscriber.h").write_text(HEADER)
    (tmp_path / "logic.cpp").write_text(SOURCE)
    result = extract_cpp([str(tmp_path / "logic.cpp")], scan([str(tmp_path)]),
                         cache_dir=None, distro="noetic")
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("subscribe", "/ll/power", "std_msgs/Float64"),
        ("subscribe", "/ll/status", "std_msgs/String"),
        ("subscribe", "/ll/voltage", "std_msgs/Float64")]
