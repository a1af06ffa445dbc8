"""A header ``pkg/Name.h`` of a package not in the workspace is synthesised as a message's
(no fields), and clang's errors on its fields are our limit, not code that may hide a ROS
call. But a message has no member functions: bender's ``uchile_util/
ParameterServerWrapper.h`` holds a class whose ``getParameter("scan_out_frame", v, "")``
reads a parameter; its error was taken for a message field's, the node whole, and the
parameter its launch file sets ``parameter-set-not-read`` (survey R). A member called
there is an error like any other: near a ROS call, the node is partial."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

PACKAGE = ('<?xml version="1.0"?>\n<package format="2"><name>inverter</name>'
           "<version>0.1.0</version><description>d</description>"
           '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
           "<depend>roscpp</depend><depend>robot_util</depend><depend>robot_msgs</depend>"
           "</package>\n")

SOURCE = """#include <ros/ros.h>
#include <robot_util/ParameterWrapper.h>
#include <robot_msgs/Frame.h>
std::string frame;
int main(int argc, char** argv) {
  ros::init(argc, argv, "inverter");
  ros::NodeHandle priv("~");
  robot_util::ParameterWrapper psw;
  psw.getParameter("scan_out_frame", frame, "");
  robot_msgs::Frame out;
  out.name = frame;
  ros::Publisher pub = priv.advertise<robot_msgs::Frame>("frame", 1);
  pub.publish(out);
}
"""


def test_a_member_called_on_a_type_known_only_by_name_may_hide_a_call(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(PACKAGE)
    (tmp_path / "inverter.cpp").write_text(SOURCE)
    result = extract_cpp([str(tmp_path / "inverter.cpp")], scan([str(tmp_path)]),
                         cache_dir=None, distro="noetic")
    found = sorted((d.code, d.location.line) for d in result.diagnostics
                   if d.code in ("CPP_MESSAGE_FIELD", "CPP_PARSE_ERROR",
                                 "CPP_ERROR_NEAR_CALL"))
    # the field of the message is a message field; the call is an error near a ROS call
    assert found == [("CPP_ERROR_NEAR_CALL", 9), ("CPP_MESSAGE_FIELD", 11),
                     ("CPP_PARSE_ERROR", 9)]
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "~frame")]
