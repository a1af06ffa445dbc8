"""A variable-length array given to a call on a value the parse declared permissively
(OpenMower's mower_comms_v1: ``uint8_t buf[size]; crc.process_bytes(buf, size + 1);``
with ``boost::crc_ccitt_type crc;`` and boost/crc.hpp not found): no template deduces a
variably modified type, so the call was an error ("no matching function for call to
object of type 'haros_any'") in functions that call the ROS API, and the node partial
(7 places); worse, with no other error left to remove, the declaration of the unknown
class was undone. The permissive class takes any arguments as a last resort."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <boost/crc.hpp>
boost::crc_ccitt_type crc;
ros::Publisher status_pub;
void send(size_t size) {
  uint8_t buf[size];
  crc.reset();
  crc.process_bytes(buf, size - 2);
  std_msgs::String msg;
  status_pub.publish(msg);
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "comms");
  ros::NodeHandle n;
  status_pub = n.advertise<std_msgs::String>("status", 1);
  send(4);
}
"""


def test_a_variable_length_array_passed_to_a_permissive_call(write_tree) -> None:
    root = write_tree({"comms/package.xml": package_xml("comms"),
                       "comms/src/node.cpp": NODE})
    result = extract_cpp([str(root / "comms" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "status")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_PARSE_ERROR" not in codes
    assert "CPP_NAMES_DECLARED" in codes
