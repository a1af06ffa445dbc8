"""A ROS 1 callback that takes ``pkg::Msg::ConstPtr`` of a message whose header is
missing, where the code also uses ``pkg::Msg`` itself as a type (teb_local_planner's
``CB_customObstacle(const costmap_converter::ObstacleArrayMsg::ConstPtr&)`` beside its
``costmap_converter::ObstacleArrayMsg custom_obstacle_msg_`` member,
teb_local_planner_ros.h, with costmap_converter's headers not installed): the name is
declared permissively as a class holding a class ``ConstPtr``, and the subscription's
type was None, as if the call gave no type. It is the message the written name gives,
as it was when ``Msg`` was only ever a scope."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = """\
#include <ros/ros.h>
#include <vendor_pkg/ThingMsg.h>
#include <vendor_pkg/interface.h>

vendor_pkg::ThingArrayMsg last;
void on_things(const vendor_pkg::ThingArrayMsg::ConstPtr& msg) {}
void on_pointer(const vendor_pkg::ThingArrayMsg::Ptr& msg) {}
void on_thing(const vendor_pkg::ThingMsg::ConstPtr& msg) {}

int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  vendor_pkg::Helper helper;
  ros::NodeHandle nh("~");
  ros::Subscriber a = nh.subscribe("things", 1, on_things);
  ros::Subscriber b = nh.subscribe("pointer", 1, on_pointer);
  ros::Subscriber c = nh.subscribe("thing", 1, on_thing);
  return 0;
}
"""


def test_a_pointer_typedef_of_a_message_declared_permissively_gives_the_message(
        write_tree) -> None:
    root = write_tree({"p/package.xml": package_xml("p", "catkin"),
                       "p/src/n.cpp": NODE})
    result = extract_cpp([str(root / "p" / "src" / "n.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert sorted((c.name, c.type) for c in result.calls) == [
        ("~pointer", "vendor_pkg/ThingArrayMsg"), ("~thing", "vendor_pkg/ThingMsg"),
        ("~things", "vendor_pkg/ThingArrayMsg")]
    assert any(d.code == "CPP_NAMES_DECLARED" for d in result.diagnostics)
