"""roscpp's options objects built by their constructor of a topic, queue, md5sum and
datatype: a relay advertises the ShapeShifter type it received with
``ros::AdvertiseOptions opts("output", 1, msg->getMD5Sum(), msg->getDataType(),
msg->getMessageDefinition(), connect_cb); pub_ = pnh_->advertise(opts);``
(jsk_topic_tools' relay, mux, passthrough, lightweight_throttle, snapshot and
synchronized_throttle nodelets). The stand-in had no such constructor: a clang error in
the function that calls the API, the nodelet partial and its publisher lost. The call is
made where ``advertise(opts)`` is, named by the constructor's topic and typed by its
datatype when that is text (else not known)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

SOURCE = """
#include <ros/ros.h>
#include <std_msgs/String.h>
class Relay {
 public:
  void advertise(const std::string& md5, const std::string& datatype,
                 const std::string& definition) {
    ros::SubscriberStatusCallback connect_cb = boost::bind(&Relay::connected, this);
    ros::AdvertiseOptions opts("output", 1, md5, datatype, definition, connect_cb,
                               connect_cb);
    opts.latch = true;
    pub_ = nh_.advertise(opts);
    ros::AdvertiseOptions text("chatter", 5, "992ce8a1687cec8c8bd883ec73ca41d1",
                               "std_msgs/String", "string data");
    chatter_ = nh_.advertise(text);
    ros::SubscribeOptions in("input", 3, md5, datatype);
    sub_ = nh_.subscribe(in);
  }
  void connected();
 private:
  ros::NodeHandle nh_;
  ros::Publisher pub_, chatter_;
  ros::Subscriber sub_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "relay");
  Relay relay;
  relay.advertise("*", "*", "");
  ros::spin();
}
"""


def test_options_built_by_their_constructor_name_the_call(tmp_path) -> None:
    (tmp_path / "relay.cpp").write_text(SOURCE)
    result = extract_cpp([str(tmp_path / "relay.cpp")], Workspace(root=str(tmp_path)),
                         cache_dir=None)
    assert sorted((c.kind, c.name, c.type, c.queue_size) for c in result.calls
                  if c.kind in ("publish", "subscribe")) == [
        ("publish", "chatter", "std_msgs/String", 5), ("publish", "output", None, 1),
        ("subscribe", "input", None, 3)]
    assert [d.code for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED")] == []
