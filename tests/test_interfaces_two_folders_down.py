"""A package's message and service definitions two folders below its msg/ and srv/
(kortex_driver 6cd75d4: ``add_message_files(DIRECTORY msg/generated/${sub_dir})`` for
each folder of ``msg/generated``, ``msg/generated/actuator_config/AxisPosition.msg``) were
not found: each header was synthesised without fields, 574 CPP_MESSAGE_UNKNOWN and 1,172
CPP_MESSAGE_FIELD in ros_kortex, and ``from kortex_driver.msg import *`` knew none of
them. Deeper folders stay unread."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.extract.cpp.interfaces import definition_files
from haros_arch.extract.python.msg_types import interface_names
from haros_arch.workspace import scan

NODE = """\
#include <ros/ros.h>
#include <arm/AxisPosition.h>
int main(int argc, char ** argv) {
  ros::init(argc, argv, "driver");
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<arm::AxisPosition>("axis", 1);
  arm::AxisPosition msg;
  msg.position = 1.5;
  pub.publish(msg);
}
"""


def _tree(write_tree):
    return write_tree({
        "arm/package.xml": package_xml("arm", "catkin"),
        "arm/msg/generated/actuator_config/AxisPosition.msg": "float32 position\n",
        "arm/srv/generated/actuator_config/GetAxisOffsets.srv": "---\nfloat32 offset\n",
        "arm/msg/a/b/c/Deep.msg": "int32 x\n",
        "arm/src/driver.cpp": NODE,
    })


def test_definitions_two_folders_below_their_kind_are_found(write_tree) -> None:
    root = _tree(write_tree)
    assert sorted(definition_files(str(root / "arm"), "msg")) == ["AxisPosition.msg"]
    assert sorted(definition_files(str(root / "arm"), "srv")) == ["GetAxisOffsets.srv"]
    workspace = scan([str(root)])
    assert interface_names(workspace, "arm", "msg") == {"AxisPosition"}
    assert interface_names(workspace, "arm", "srv") == {
        "GetAxisOffsets", "GetAxisOffsetsRequest", "GetAxisOffsetsResponse"}


def test_a_node_using_such_a_message_reads_its_fields(write_tree) -> None:
    root = _tree(write_tree)
    result = extract_cpp([str(root / "arm/src/driver.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("publish", "axis", "arm/AxisPosition")]
    codes = {d.code for d in result.diagnostics}
    assert not codes & {"CPP_MESSAGE_UNKNOWN", "CPP_MESSAGE_FIELD", "CPP_PARSE_ERROR"}, (
        result.diagnostics)
