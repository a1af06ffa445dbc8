"""A name held by a local variable made of a parameter's value and text (OpenMower's
xbot_pose_converter: ``std::string target_topic = topic + "/converted";`` after
``paramNh.getParam("topic", topic)``, then ``advertise(target_topic, 10)``) names that
parameter, as the same text written in the call does: the graph fills in the launch
file's value (it was ``?/converted``, a topic of no namespace)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """
#include <ros/ros.h>
#include <std_msgs/String.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "converter");
  ros::NodeHandle n;
  ros::NodeHandle paramNh("~");
  std::string topic;
  if (!paramNh.getParam("topic", topic)) {
    return 1;
  }
  std::string target_topic = topic + "/converted";
  std::string twice = topic + "/" + topic;
  ros::Publisher p = paramNh.advertise<std_msgs::String>(target_topic, 10, false);
  ros::Publisher q = n.advertise<std_msgs::String>(topic + "/direct", 10);
  ros::Publisher r = n.advertise<std_msgs::String>(twice, 10);
  ros::Subscriber s = n.subscribe(topic, 0, &cb);
}
"""


def test_a_local_made_of_a_parameter_names_it(write_tree) -> None:
    root = write_tree({
        "conv/package.xml": package_xml("conv"),
        "conv/src/node.cpp": NODE.replace("int main", "void cb(const std_msgs::String::"
                                          "ConstPtr&) {}\nint main"),
    })
    result = extract_cpp([str(root / "conv" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [c.name_more for c in result.calls if c.name == "?/?"] == [[["~topic", None]]]
    assert sorted((c.kind, c.name, c.name_param) for c in result.calls
                  if c.kind in ("publish", "subscribe")) == [
        # two parameter runs in one local: each named, as in a call (``name_more``)
        ("publish", "?/?", "~topic"),
        ("publish", "?/direct", "~topic"),
        ("publish", "~?/converted", "~topic"),
        ("subscribe", "?", "~topic"),
    ]


def test_a_global_value_that_begins_the_name_is_not_in_the_handles_namespace() -> None:
    """roscpp: ``paramNh("~").advertise("/ll/position/gps" + "/converted")`` is the global
    ``/ll/position/gps/converted`` (it was ``/converter1/ll/position/gps/converted``); a
    relative value stays in the handle's namespace; on a handle ``out`` as well."""
    from haros_arch.graph import build
    from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
    from haros_arch.model import Configuration, Node, PrimitiveCall
    from haros_arch.workspace import Workspace

    converter = Node("conv", "converter", calls=[
        PrimitiveCall("publish", "~?/converted", "std_msgs/String", name_param="~topic",
                      handle_namespace="~"),
        PrimitiveCall("publish", "~?/again", "std_msgs/String", name_param="~relative",
                      handle_namespace="~"),
        PrimitiveCall("publish", "out/?/more", "std_msgs/String", name_param="~topic",
                      handle_namespace="out"),
        PrimitiveCall("publish", "out/?", "std_msgs/String", name_param="~topic",
                      handle_namespace="out")])
    decl = NodeDecl("/ns/converter1", "conv", "converter", "/ns/")
    params = [ParamDecl("/ns/converter1/topic", "/ll/position/gps"),
              ParamDecl("/ns/converter1/relative", "gps")]
    config = build(Configuration("c"), LaunchModel(nodes=[decl], params=params),
                   Workspace(root="/x"), {"conv/converter": converter})
    assert sorted(link.rosname.full for link in config.links if link.kind == "publish") == [
        "/ll/position/gps", "/ll/position/gps/converted", "/ll/position/gps/more",
        "/ns/converter1/gps/again"]
