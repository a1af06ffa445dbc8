"""What chooses an image_transport subscriber's transport besides the node's
``image_transport`` parameter: the default its TransportHints are made with (a text, a
program argument, a parameter's value), the transport ROS 2 code passes itself, and ROS 1
private parameters a node's command line sets (``_image_transport:=compressed``)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.graph import build
from haros_arch.launch import load
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Location, Node, PrimitiveCall
from haros_arch.model.load import node_from_data
from haros_arch.model.serialise import to_data
from haros_arch.workspace import Workspace, scan

ROS1 = """
#include <ros/ros.h>
#include <image_transport/image_transport.h>
#include <sensor_msgs/Image.h>
void cb(const sensor_msgs::ImageConstPtr&) {}
class V { public: void cb(const sensor_msgs::ImageConstPtr&) {} };
int main(int argc, char** argv) {
  ros::init(argc, argv, "viewer");
  ros::NodeHandle n, pn("~");
  image_transport::ImageTransport it(n);
  V v;
  std::string in_transport = argv[1];
  image_transport::Subscriber a = it.subscribe("a", 1, cb);
  image_transport::Subscriber b = it.subscribe("b", 1, &V::cb, &v,
      image_transport::TransportHints("compressed"));
  image_transport::TransportHints hints("theora", ros::TransportHints(), pn);
  image_transport::Subscriber c = it.subscribe("c", 1, &V::cb, &v, hints);
  image_transport::Subscriber d = it.subscribe("d", 1, cb, ros::VoidPtr(), in_transport);
  image_transport::Subscriber e = it.subscribe("e", 1, cb, ros::VoidPtr(),
      image_transport::TransportHints(in_transport));
  std::string t;
  pn.param<std::string>("transport", t, "compressed");
  image_transport::Subscriber f = it.subscribe("f", 1, &V::cb, &v,
      image_transport::TransportHints(t));
  image_transport::Subscriber g = it.subscribe("g", 1, &V::cb, &v,
      image_transport::TransportHints(std::string(getenv("X"))));
  image_transport::Subscriber h = it.subscribe(n.resolveName("h"), 1, cb);
  image_transport::TransportHints own("raw", ros::TransportHints(), pn, "depth_transport");
  image_transport::Subscriber k = it.subscribe("k", 1, cb, ros::VoidPtr(), own);
  bool is_compressed;
  pn.param("is_compressed", is_compressed, false);
  image_transport::Subscriber m = it.subscribe("m", 1, &V::cb, &v,
      image_transport::TransportHints(is_compressed ? "compressed" : "raw"));
  ros::spin();
}
"""

ROS2 = """
#include <rclcpp/rclcpp.hpp>
#include <image_transport/image_transport.hpp>
#include <sensor_msgs/msg/image.hpp>
void cb(const sensor_msgs::msg::Image::ConstSharedPtr&) {}
int main(int argc, char** argv) {
  auto vargv = rclcpp::init_and_remove_ros_arguments(argc, argv);
  auto node = rclcpp::Node::make_shared("viewer");
  std::string in_transport = vargv[1];
  auto a = image_transport::create_subscription(node.get(), "a", cb, in_transport);
  auto b = image_transport::create_subscription(node.get(), "b", cb, "compressed");
  auto c = image_transport::create_subscription(node.get(), "c", cb);
  std::string t = "raw";
  node->declare_parameter<std::string>("in_transport", t);
  node->get_parameter("in_transport", t);
  auto d = image_transport::create_subscription(node.get(), "d", cb, t);
  image_transport::ImageTransport it(node);
  image_transport::TransportHints hints(node.get(), "compressed");
  auto f = it.subscribe("f", 1, cb, nullptr, &hints);
  auto g = image_transport::create_subscription(node.get(), "g", cb, std::string(getenv("X")));
  image_transport::TransportHints plain(node.get());
  auto k = image_transport::create_subscription(node.get(), "k", cb, plain.getTransport());
  image_transport::TransportHints own(node.get(), "raw", "depth_transport");
  auto m = image_transport::create_subscription(node.get(), "m", cb, own.getTransport());
  rclcpp::spin(node);
}
"""


def subscriptions(tmp_path, text, build_type):
    package = tmp_path / "cam"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(package_xml("cam", build_type))
    (package / "src" / "viewer.cpp").write_text(text)
    result = extract_cpp([str(package / "src" / "viewer.cpp")], scan([str(tmp_path)], {}),
                         cache_dir=None)
    found = {}
    for c in result.calls:
        if c.kind == "subscribe":
            found.setdefault(c.name, []).append((
                c.transport, c.transport_default, c.transport_arg, c.transport_param,
                c.transport_fixed, tuple(f"{k.statement} {k.text}" for k in c.conditions)))
    return {name: calls[0][:5] if len(calls) == 1 and not calls[0][5] else calls
            for name, calls in found.items()}


def test_ros1_hints_give_the_default_the_parameter_overrides(tmp_path):
    assert subscriptions(tmp_path, ROS1, "catkin") == {
        "a": ("?/", None, None, None, False),  # no hints: raw
        "b": ("?/", "compressed", None, None, False),
        "c": ("?/", "theora", None, None, False),  # a variable made with them
        "d": ("?/", None, 1, None, False),  # a string converts to hints: argv[1]
        "e": ("?/", None, 1, None, False),
        "f": ("?/", "compressed", None, "~transport", False),  # a parameter's value
        "g": ("?/", "?", None, None, False),  # not known: not raw
        # a base roscpp resolved and remapped: the transport's topic is below it
        "h": ("?", None, None, None, False),
        # hints reading a parameter of another name: that parameter gives it
        "k": ("?/", "raw", None, "~depth_transport", True),
        # chosen by a test: one subscription per side, each under its side
        "m": [("?/", "compressed", None, None, False, ("if is_compressed",)),
              ("?/", None, None, None, False, ("else is_compressed",))],
    }


def test_ros2_code_passes_the_transport_itself(tmp_path):
    assert subscriptions(tmp_path, ROS2, "ament_cmake") == {
        "a": ("?", None, 1, None, True),
        "b": ("compressed", None, None, None, False),
        "c": ("raw", None, None, None, False),  # create_subscription's default
        "d": ("?", "raw", None, "in_transport", True),
        "f": ("?/", "compressed", None, None, False),  # TransportHints(node, default)
        "g": ("?", "?", None, None, True),
        # the transport TransportHints read (image_pipeline's ``hints.getTransport()``):
        # their parameter, as if the hints were given
        "k": ("?", None, None, None, False),
        "m": ("?", "raw", None, "depth_transport", True),  # (rtabmap's depth_hints)
    }


def graph(decls, params=(), nodes=()):
    launch = LaunchModel(nodes=list(decls), params=list(params))
    return build(Configuration("c"), launch, Workspace(root="/nowhere"),
                 {n.name: n for n in nodes})


def subscribed(config, node):
    return sorted((link.resource.name, link.type) for link in config.links
                  if link.node.name == node and link.kind == "subscribe")


HERE = Location("image_transport", "src/republish.cpp", 61, 14)


def republish(version, **fields):
    image = "sensor_msgs/Image" if version == 1 else "sensor_msgs/msg/Image"
    return Node("image_transport", "republish", calls=[PrimitiveCall(
        "subscribe", "in", image, 1, location=HERE, **fields)])


def test_ros1_republish_subscribes_the_transport_its_first_argument_names():
    node = republish(1, transport="?", transport_arg=1)
    decl = NodeDecl("/decompress", "image_transport", "republish",
                    args="compressed in:=/camera/image_raw raw out:=/camera/image",
                    remaps=[("in", "/camera/image_raw"), ("out", "/camera/image")])
    assert subscribed(graph([decl], nodes=[node]), "/decompress") == [
        ("/camera/image_raw/compressed", "sensor_msgs/CompressedImage")]
    # the node's parameter wins over the argument
    config = graph([decl], [ParamDecl("/decompress/image_transport", "theora")], [node])
    assert subscribed(config, "/decompress") == [
        ("/camera/image_raw/theora", "theora_image_transport/Packet")]
    # no argument given (or not known): the transport is not known, not raw
    bare = NodeDecl("/decompress", "image_transport", "republish")
    assert subscribed(graph([bare], nodes=[node]), "/decompress") == [("/in/?", None)]


def test_ros2_transport_passed_by_the_code_is_no_hints_parameter():
    by_argument = republish(2, transport="?", transport_arg=1, transport_fixed=True)
    decl = NodeDecl("/republish", "image_transport", "republish", args="compressed raw",
                    ros_version=2)
    hint = [ParamDecl("/republish/image_transport", "theora")]
    assert subscribed(graph([decl], hint, [by_argument]), "/republish") == [
        ("/in/compressed", "sensor_msgs/msg/CompressedImage")]
    by_parameter = republish(2, transport="?", transport_param="in_transport",
                             transport_default="raw", transport_fixed=True)
    component = NodeDecl("/republish", "image_transport", "republish", ros_version=2)
    assert subscribed(graph([component], nodes=[by_parameter]), "/republish") == [
        ("/in", "sensor_msgs/msg/Image")]
    chosen = [ParamDecl("/republish/in_transport", "compressed", node="/republish",
                        key="in_transport")]
    assert subscribed(graph([component], chosen, [by_parameter]), "/republish") == [
        ("/in/compressed", "sensor_msgs/msg/CompressedImage")]


def test_fields_survive_the_saved_model():
    node = republish(2, transport="?", transport_arg=1, transport_param="p",
                     transport_default="raw", transport_fixed=True)
    (back,) = node_from_data(to_data(node), "image_transport").calls
    assert (back.transport_arg, back.transport_param, back.transport_default,
            back.transport_fixed) == (1, "p", "raw", True)


def test_ros1_command_line_sets_private_parameters(write_tree):
    root = write_tree({"src/pkg/package.xml": package_xml("pkg"),
                       "src/pkg/launch/main.launch": """
        <launch>
          <group ns="cam">
            <node name="transport" pkg="image_transport" type="republish"
                  args="in_transport in:=image_raw out:=image _image_transport:=compressed
                        _rate:=10 _scale:=0.5 _flag:=True __log:=x _:=y"/>
          </group>
        </launch>"""})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/pkg/launch/main.launch"), ws, {}, {})
    assert [(p.name, p.value, p.type) for p in model.params] == [
        ("/cam/transport/image_transport", "compressed", "str"),
        ("/cam/transport/rate", 10, "int"), ("/cam/transport/scale", 0.5, "double"),
        ("/cam/transport/flag", True, "bool")]
