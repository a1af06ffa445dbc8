"""``std::string::append`` and ``assign`` of a value of a library the parse does not have
(robocup-pkg's robot_comm: ``name.append(m.name())`` of a protobuf message, its
generated headers missing) were an error, "call to member function 'append' is
ambiguous", in the function that advertises the relayed topic, so the node was partial;
``+=`` and ``=`` already took such a value. ``append`` is read as ``+=`` is: the name
keeps the library's part unknown, ``/relay/?`` (it was ``/relay/``, the error's call
dropped), and ``info.append("/info")`` of a known text is known."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = """
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <vendor/message.pb.h>
void relay(ros::NodeHandle& nh, const vendor::Message& m) {
  std::string name = "/relay/";
  name.append(m.name());
  ros::Publisher pub = nh.advertise<std_msgs::String>(name, 1);
  std::string other;
  other.assign(m.topic());
  ros::Publisher out = nh.advertise<std_msgs::String>("out", 1);
  std::string info = "/camera";
  info.append("/info");
  ros::Publisher camera = nh.advertise<std_msgs::String>(info, 1);
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "relay");
  ros::NodeHandle nh;
  vendor::Message m;
  relay(nh, m);
}
"""


def test_a_string_appended_an_unknown_library_s_value_keeps_the_call(write_tree) -> None:
    root = write_tree({"comm/package.xml": package_xml("comm"),
                       "comm/src/relay.cpp": NODE})
    result = extract_cpp([str(root / "comm" / "src" / "relay.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "/camera/info"), ("publish", "/relay/?"), ("publish", "out")]
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED")] == []
