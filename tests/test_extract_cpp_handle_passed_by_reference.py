"""A roscpp handle written more than once keeps its namespace through a call that may
change it in place only when the call does not: a method of the handle (advertise, ...:
none changes the namespace) or a function given it by non-const reference whose body
only reads through it (ros_deep_learning's ``__ros_declare_parameter(nh, name, value)``:
``hasParam``, ``setParam``). Each such call made every later name ``?/...``. A function
that assigns the handle, or one not read here, may change it: the names after it stay
unknown."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """#include <ros/ros.h>
#include <std_msgs/String.h>
static void declare(ros::NodeHandle& nh, const std::string& name, int value)
{
  if (!nh.hasParam(name))
    nh.setParam(name, value);
}
static void handed_on(ros::NodeHandle& nh, const std::string& name) { declare(nh, name, 0); }
static void moved(ros::NodeHandle& nh) { nh = ros::NodeHandle("elsewhere"); }
void unseen(ros::NodeHandle& nh);
int main(int argc, char** argv)
{
  ros::init(argc, argv, "n");
  ros::NodeHandle nh("a");
  nh = ros::NodeHandle("~");
  ros::Publisher p = nh.advertise<std_msgs::String>("x", 1);
  ros::Publisher q = nh.advertise<std_msgs::String>("y", 1);
  declare(nh, "first", 1);
  handed_on(nh, "second");
  nh.getParam("third", argc);
  moved(nh);
  nh.getParam("fourth", argc);
  ros::NodeHandle other("b");
  other = ros::NodeHandle("~");
  unseen(other);
  other.getParam("fifth", argc);
  ros::spin();
}
"""


def test_calls_that_only_read_a_handle_keep_its_namespace(write_tree) -> None:
    root = write_tree({"pkg/package.xml": package_xml("pkg"), "pkg/src/node.cpp": NODE})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "~x"), ("publish", "~y"),
        ("read", "?/fifth"), ("read", "?/fourth"),
        ("read", "~first"), ("read", "~second"), ("read", "~third"),
        ("write", "~first"), ("write", "~second")]
