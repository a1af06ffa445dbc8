"""A constant of a missing header as one branch of a conditional whose other branch is a
number: vectornav's driver configures its binary output with ``COMMONGROUP_QUATERNION |
... | (user_data.adjust_ros_timestamp ? COMMONGROUP_TIMESTARTUP : 0)`` in main(), its
SDK's headers not found. Declared as a permissive value, which converts to int and is
built from one, the constant made clang's conditional ambiguous ("'haros_any' can be
converted to 'int' and vice versa"), an error in the function that makes the node's
publishers: the node was partial. Such a constant is now an enumerator, as the SDK's
own is; a lower-case name, or a branch that is no number, is left as it was. And its
``using namespace vn::protocol::uart;`` (with ``vn::math``, ``vn::sensors``), of
namespaces no name is written qualified in, was "expected namespace name" (the last
part taken for a value): such a directive's parts are declared namespaces."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
#include <vn/sensors.h>
#include <ros/ros.h>
#include <std_msgs/Int32.h>

using namespace vn::protocol::uart;

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "vnpub");
  ros::NodeHandle pn("~");
  bool stamp = false;
  pn.param<bool>("adjust_ros_timestamp", stamp, false);
  BinaryOutputRegister bor(
    ASYNCMODE_PORT1, 40,
    COMMONGROUP_QUATERNION | COMMONGROUP_ANGULARRATE |
      (stamp ? COMMONGROUP_TIMESTARTUP : 0),
    TIMEGROUP_NONE | (stamp ? 0x0 : TIMEGROUP_GPSTOW));
  ros::Publisher pub = pn.advertise<std_msgs::Int32>("imu/groups", 10);
  ros::spin();
}
"""


def test_a_constant_beside_a_number_in_a_conditional(write_tree) -> None:
    root = write_tree({"pkg/package.xml": package_xml("pkg", "catkin"),
                       "pkg/src/main.cpp": SOURCE})
    result = extract_cpp([str(root / "pkg" / "src" / "main.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("read", "~adjust_ros_timestamp"), ("publish", "~imu/groups")]
