"""The walk of a translation unit leaves out what cannot change its result (``visitor``:
a function with no call of an API or wrapper name, no recovered call, no construction of
a class of the workspace; ``members``: the functions whose text cannot name a member or
hold a call asked about; ``wrappers``: calls that match no row and no wrapper). What such
a function gives other functions is still read where it is used: a wrapper defined in
one function and called in another, a member written in one function and used as a
topic in another, a constructor called through an alias in a member initialiser, a
member written by a macro whose text is not in the function."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = """
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <message_filters/subscriber.h>
#include <string>

#define BUMP() count_ += 1

ros::Publisher advertise_on(ros::NodeHandle& nh, const std::string& topic) {
  return nh.advertise<std_msgs::String>(topic, 1);
}

ros::Publisher advertise_relayed(ros::NodeHandle& nh, const std::string& base) {
  return advertise_on(nh, "relay/" + base);
}

class Relay {
 public:
  using Listener = message_filters::Subscriber<std_msgs::String>;
  Relay() : listener_(nh_, "input", 5) {}
  void init() { out_topic_ = "relayed"; }  // no call: not walked, its value read on demand
  void start() {
    ros::NodeHandle pnh("~");
    pnh.param("count", count_, 0);
    pnh.param("verbose", verbose_, false);
    out_ = nh_.advertise<std_msgs::String>(out_topic_, 1);
    status_ = advertise_relayed(nh_, "status");
  }
  void reset() { BUMP(); }
  double scale(double x) const { return x * 2.0 + offset_; }

 private:
  ros::NodeHandle nh_;
  Listener listener_;
  std::string out_topic_;
  int count_ = 0;
  bool verbose_ = false;
  double offset_ = 0.5;
  ros::Publisher out_, status_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "relay");
  Relay relay;
  relay.init();
  relay.start();
  ros::spin();
}
"""


def test_what_a_function_left_unwalked_gives_is_still_read(write_tree) -> None:
    root = write_tree({
        "src/relay/package.xml": package_xml("relay"),
        "src/relay/CMakeLists.txt": "project(relay)\nadd_executable(relay src/relay.cpp)\n",
        "src/relay/src/relay.cpp": NODE,
    })
    result = extract_cpp([str(root / "src/relay/src/relay.cpp")], scan([str(root)]),
                         cache_dir=None)
    topics = {(c.kind, c.name, c.queue_size) for c in result.calls
              if c.kind in ("publish", "subscribe")}
    assert topics == {
        ("subscribe", "input", 5),  # message_filters' constructor through ``Listener``
        ("publish", "relayed", 1),  # the member init() writes
        ("publish", "relay/status", 1),  # a wrapper of a wrapper, each a function
    }
    stored = {c.name: c.variable for c in result.calls if c.kind == "read"}
    # count_ is written again by a macro in reset(): not the read's one write
    assert stored == {"~count": None, "~verbose": "verbose_"}
    assert result.rosname == "relay"
