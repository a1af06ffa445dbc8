"""image_transport publishers and subscribers and the topics of their transport plugins
(plugins.hosts.TRANSPORTS, plugins.transports)."""

from __future__ import annotations

from dataclasses import replace

from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Location, Node, PrimitiveCall
from haros_arch.model.load import node_from_data
from haros_arch.model.serialise import to_data
from haros_arch.model.source import Package
from haros_arch.workspace import Workspace


def call(kind, name, type_, transport, line=1):
    return PrimitiveCall(kind, name, type_, 1, location=Location("cam", "cam/src/c.cpp", line, 3),
                         transport=transport)


def graph(decls, params=(), nodes=(), packages=()):
    workspace = Workspace(root="/nowhere", packages={
        name: Package(name, name, root=f"/nowhere/{name}") for name in packages})
    launch = LaunchModel(nodes=list(decls), params=list(params))
    return build(Configuration("c"), launch, workspace, {n.name: n for n in nodes})


def topics(config, node):
    return sorted((link.kind, link.resource.name, link.type,
                   tuple(c.text for c in link.conditions))
                  for link in config.links if link.node.name == node and link.kind in (
                      "publish", "subscribe")
                  and not (link.type or "").startswith("dynamic_reconfigure/"))


def reads(config, node):  # the parameters that choose transports or a subscriber's one
    return sorted(link.resource.name for link in config.links
                  if link.node.name == node and link.kind == "read"
                  and link.resource.name.endswith(("_pub_plugins", "/image_transport")))


DRIVER = Node("cam", "driver", calls=[
    call("publish", "image_raw", "sensor_msgs/Image", "*"),
    call("publish", "camera_info", "sensor_msgs/CameraInfo", None)])
VIEWER = Node("cam", "viewer", calls=[call("subscribe", "image", "sensor_msgs/Image", "?")])
INSTALLED = "is installed"


def test_ros1_publisher_publishes_every_transport_installed_or_usually_installed():
    # compressed_image_transport is in the workspace: its topic is certain; the other two
    # transports of image_transport_plugins are published if their packages are installed
    config = graph([NodeDecl("/cam/driver", "cam", "driver", "/cam/",
                             remaps=[("image_raw", "/camera/color")])],
                   nodes=[DRIVER], packages=["compressed_image_transport"])
    assert topics(config, "/cam/driver") == [
        ("publish", "/cam/camera_info", "sensor_msgs/CameraInfo", ()),
        ("publish", "/camera/color", "sensor_msgs/Image", ()),
        # the base is remapped first, the transport's topic named below it
        ("publish", "/camera/color/compressed", "sensor_msgs/CompressedImage", ()),
        ("publish", "/camera/color/compressedDepth", "sensor_msgs/CompressedImage",
         (f"compressed_depth_image_transport {INSTALLED}",)),
        ("publish", "/camera/color/theora", "theora_image_transport/Packet",
         (f"theora_image_transport {INSTALLED}",)),
    ]
    assert reads(config, "/cam/driver") == ["/camera/color/disable_pub_plugins"]
    # each ROS 1 plugin reconfigures on the handle of its topic
    reconfigure = sorted((link.kind, link.resource.name) for link in config.links
                         if link.resource.name.startswith("/camera/color/compressed/")
                         and link.kind != "read")
    assert reconfigure == [("publish", "/camera/color/compressed/parameter_descriptions"),
                           ("publish", "/camera/color/compressed/parameter_updates"),
                           ("server", "/camera/color/compressed/set_parameters")]


def test_ros1_disable_list_removes_transports_and_an_unknown_one_makes_them_conditional():
    decl = NodeDecl("/cam/driver", "cam", "driver", "/cam/")
    config = graph([decl], [ParamDecl("/cam/image_raw/disable_pub_plugins",
                                      ["image_transport/theora", "image_transport/compressed"])],
                   nodes=[DRIVER], packages=["compressed_image_transport",
                                             "theora_image_transport"])
    published = [name for kind, name, _, _ in topics(config, "/cam/driver")]
    assert published == ["/cam/camera_info", "/cam/image_raw",
                         "/cam/image_raw/compressedDepth"]
    param = config.parameter("/cam/image_raw/disable_pub_plugins")
    assert param is not None and param.is_read
    config = graph([decl], [ParamDecl("/cam/image_raw/disable_pub_plugins", "?")],
                   nodes=[DRIVER], packages=["compressed_image_transport"])
    (compressed,) = [t for t in topics(config, "/cam/driver") if t[1].endswith("/compressed")]
    assert compressed[3] == ("image_transport/compressed is not in "
                             "/cam/image_raw/disable_pub_plugins",)


def test_ros2_enable_list_names_the_transports_under_the_base_relative_to_the_namespace():
    decl = NodeDecl("/cam/driver", "cam", "driver", "/cam/", ros_version=2)
    driver = Node("cam", "driver", calls=[call("publish", "image_raw", "sensor_msgs/msg/Image",
                                               "*")])
    config = graph([decl], [ParamDecl("/cam/driver/image_raw.enable_pub_plugins",
                                      ["image_transport/raw", "image_transport/zstd"])],
                   nodes=[driver], packages=["zstd_image_transport"])
    assert topics(config, "/cam/driver") == [
        ("publish", "/cam/image_raw", "sensor_msgs/msg/Image", ()),
        ("publish", "/cam/image_raw/zstd", "sensor_msgs/msg/CompressedImage", ())]
    assert reads(config, "/cam/driver") == ["/cam/driver/image_raw.enable_pub_plugins"]


def test_subscriber_transport_comes_from_its_parameter():
    decl = NodeDecl("/viewer", "cam", "viewer")
    # not set: raw, the base topic; the parameter is read
    config = graph([decl], nodes=[VIEWER])
    assert topics(config, "/viewer") == [("subscribe", "/image", "sensor_msgs/Image", ())]
    assert set(reads(config, "/viewer")) == {"/viewer/image_transport"}
    config = graph([decl, NodeDecl("/cam/driver", "cam", "driver", "/")],
                   [ParamDecl("/viewer/image_transport", "compressed")], nodes=[VIEWER, DRIVER])
    assert topics(config, "/viewer") == [
        ("subscribe", "/image/compressed", "sensor_msgs/CompressedImage", ())]
    assert config.parameter("/viewer/image_transport").is_read
    # a value not known: a topic below the base with an unknown last part
    config = graph([decl], [ParamDecl("/viewer/image_transport", 3)], nodes=[VIEWER])
    assert [name for _, name, _, _ in topics(config, "/viewer")] == ["/image/?"]


def test_subscriber_transport_written_in_ros2_code_is_used_as_it_is():
    viewer = Node("cam", "viewer", calls=[
        call("subscribe", "image", "sensor_msgs/msg/Image", "theora")])
    config = graph([NodeDecl("/viewer", "cam", "viewer", ros_version=2)],
                   [ParamDecl("/viewer/image_transport", "compressed")], nodes=[viewer])
    assert topics(config, "/viewer") == [
        ("subscribe", "/image/theora", "theora_image_transport/msg/Packet", ())]


def test_transport_mark_survives_the_json_model():
    data = to_data(DRIVER)
    assert [c.transport for c in node_from_data(data, "cam").calls] == ["*", None]


def test_ros2_transport_topics_are_remapped_on_their_own_not_with_the_base():
    # image_transport expands the base without remapping it (usb_cam's launch file
    # remaps image_raw and image_raw/compressed one by one)
    driver = Node("cam", "driver", calls=[call("publish", "image_raw", "sensor_msgs/msg/Image",
                                               "*")])
    decl = NodeDecl("/camera1", "cam", "driver", "/", ros_version=2,
                    remaps=[("image_raw", "camera1/image_raw"),
                            ("image_raw/compressed", "camera1/image_compressed")])
    config = graph([decl], nodes=[driver], packages=["compressed_image_transport",
                                                     "theora_image_transport"])
    published = [name for _, name, _, _ in topics(config, "/camera1")]
    assert published == ["/camera1/image_compressed", "/camera1/image_raw",
                         "/image_raw/compressedDepth", "/image_raw/theora", "/image_raw/zstd"]


def test_ros2_transport_topics_are_named_below_a_base_the_code_remapped():
    # image_pipeline resolves (and remaps) the base itself before it gives it to
    # image_transport (``=`` mark): the remap of the base reaches its transports' topics
    driver = Node("cam", "driver", calls=[
        call("publish", "image_rect", "sensor_msgs/msg/Image", "*="),
        call("subscribe", "image", "sensor_msgs/msg/Image", "compressed=", line=2)])
    decl = NodeDecl("/rectify", "cam", "driver", "/", ros_version=2,
                    remaps=[("image_rect", "/left/image_rect"), ("image", "/left/image")])
    config = graph([decl], nodes=[driver], packages=["compressed_image_transport"])
    assert [(kind, name) for kind, name, _, _ in topics(config, "/rectify")
            if not name.endswith(("compressedDepth", "theora", "zstd"))] == [
        ("publish", "/left/image_rect"), ("publish", "/left/image_rect/compressed"),
        ("subscribe", "/left/image/compressed")]


def test_transports_below_a_remapped_base_are_remapped_from_their_own_name():
    # clearpath_sensors' flir_blackfly gives image_proc's debayer (which resolves its
    # base itself, "=") image_color:=color/image and, ROS 1 style, a rule per transport,
    # image_color/compressed:=color/compressed: the plugin names its topic below the
    # remapped base, /cam/color/image/compressed, and that is what rcl remaps, so the
    # per-transport rule is unused and the node is shown to use color/image/compressed,
    # not image_color/compressed
    debayer = Node("cam", "debayer", calls=[
        call("publish", "image_color", "sensor_msgs/msg/Image", "*=")])
    decl = NodeDecl("/cam/debayer", "cam", "debayer", "/cam/", ros_version=2,
                    remaps=[("image_color", "color/image"),
                            ("image_color/compressed", "color/compressed")])
    config = graph([decl], nodes=[debayer], packages=["compressed_image_transport"])
    links = {link.resource.name: link.rosname.given for link in config.links
             if link.kind == "publish"}
    assert links["/cam/color/image/compressed"] == "color/image/compressed"
    assert "/cam/color/compressed" not in links
    unused = {r.text: r for r in config.remaps}["image_color/compressed:=color/compressed"]
    assert not unused.users
    assert "/cam/color/image/compressed" in unused.near
    assert "/cam/image_color/compressed" not in unused.near
    # a base no remap changed: the transport stays named below the code's base
    config = graph([replace(decl, remaps=[("image_color/compressed", "color/compressed")])],
                   nodes=[debayer], packages=["compressed_image_transport"])
    links = {link.resource.name: link.rosname.given for link in config.links
             if link.kind == "publish"}
    assert links["/cam/color/compressed"] == "image_color/compressed"


def test_transport_plugins_read_their_parameters():
    # ROS 1: each publisher plugin's dynamic_reconfigure config, under its topic
    config = graph([NodeDecl("/cam/driver", "cam", "driver", "/cam/")],
                   [ParamDecl("/cam/image_raw/compressed/jpeg_quality", 80)],
                   nodes=[DRIVER], packages=["compressed_image_transport"])
    assert config.parameter("/cam/image_raw/compressed/jpeg_quality").is_read
    # ROS 2: declared as <base>.<transport>.<parameter> (the base relative to the node's
    # namespace) and as the deprecated <base>.<parameter>; zstd only the first
    driver = Node("cam", "driver", calls=[call("publish", "image_raw", "sensor_msgs/msg/Image",
                                               "*")])
    config = graph([NodeDecl("/driver", "cam", "driver", "/", ros_version=2)],
                   nodes=[driver], packages=["compressed_image_transport", "zstd_image_transport"])
    declared = sorted(link.resource.name for link in config.links if link.kind == "read")
    assert "/driver/image_raw.compressed.jpeg_quality" in declared
    assert "/driver/image_raw.jpeg_quality" in declared
    assert "/driver/image_raw.zstd.zstd_level" in declared
    assert "/driver/image_raw.zstd_level" not in declared


def test_ros1_subscriber_names_its_transport_topic_from_the_base_as_written():
    # a camera subscriber resolves (and remaps) the base first (camera_subscriber.cpp
    # resolveName); a plain Subscriber appends the transport to the base as written
    viewer = Node("cam", "viewer", calls=[
        call("subscribe", "image", "sensor_msgs/Image", "?/"),
        call("subscribe", "camera/image", "sensor_msgs/Image", "?", line=2)])
    config = graph([NodeDecl("/viewer", "cam", "viewer",
                             remaps=[("image", "/cam/color"), ("camera/image", "/cam/mono")])],
                   [ParamDecl("/viewer/image_transport", "compressed")], nodes=[viewer])
    assert [name for _, name, _, _ in topics(config, "/viewer")] == [
        "/cam/mono/compressed", "/image/compressed"]


def test_ros2_subscriber_reads_the_transport_parameter_only_when_its_node_declares_it():
    # jazzy's TransportHints get_parameter_or("image_transport", ..., "raw") and never
    # declare it: a launch value of an undeclared parameter does not reach them
    viewer = Node("cam", "viewer", calls=[call("subscribe", "image", "sensor_msgs/msg/Image",
                                               "?/")])
    decl = NodeDecl("/viewer", "cam", "viewer", ros_version=2)
    setting = [ParamDecl("/viewer/image_transport", "compressed")]
    config = graph([decl], setting, nodes=[viewer])
    assert topics(config, "/viewer") == [("subscribe", "/image", "sensor_msgs/msg/Image", ())]
    assert reads(config, "/viewer") == []
    declaring = Node("cam", "viewer", calls=[
        *viewer.calls, PrimitiveCall("declare", "image_transport", "str", has_default=True,
                                     default="raw", location=Location("cam", "c.cpp", 2, 3))])
    config = graph([decl], setting, nodes=[declaring])
    assert topics(config, "/viewer") == [
        ("subscribe", "/image/compressed", "sensor_msgs/msg/CompressedImage", ())]
    assert set(reads(config, "/viewer")) == {"/viewer/image_transport"}


def camera_subscriber(version):
    image = "sensor_msgs/Image" if version == 1 else "sensor_msgs/msg/Image"
    info = "sensor_msgs/CameraInfo" if version == 1 else "sensor_msgs/msg/CameraInfo"
    here = Location("cam", "cam/src/c.cpp", 4, 3)
    return Node("cam", "scan", calls=[
        PrimitiveCall("subscribe", "image", image, 1, location=here, transport="?"),
        PrimitiveCall("subscribe", "camera_info", info, 1, location=here, camera_of="image")])


def test_ros1_camera_info_is_named_beside_the_image_topic_as_remapped():
    # image_transport's CameraSubscriber resolves and remaps the image topic first and
    # subscribes camera_info in its namespace (depthimage_to_laserscan's launch files
    # remap only image)
    decl = NodeDecl("/scan", "cam", "scan", "/", remaps=[("image", "/camera/depth/image_raw")])
    config = graph([decl], nodes=[camera_subscriber(1)])
    assert [name for _, name, _, _ in topics(config, "/scan")] == [
        "/camera/depth/camera_info", "/camera/depth/image_raw"]
    # written as the code wrote it: no global name of the code
    (info,) = [link for link in config.links if link.resource.name.endswith("camera_info")]
    assert info.call.name == "camera_info"
    # not remapped: beside the image topic in the node's namespace
    config = graph([NodeDecl("/robot/scan", "cam", "scan", "/robot/")],
                   nodes=[camera_subscriber(1)])
    assert [name for _, name, _, _ in topics(config, "/robot/scan")] == [
        "/robot/camera_info", "/robot/image"]


def test_ros2_camera_info_follows_the_expanded_image_topic_not_its_remap():
    # ROS 2's CameraSubscriber only expands the image topic: a remap of image alone leaves
    # camera_info where it was, a remap of camera_info moves it
    decl = NodeDecl("/scan", "cam", "scan", "/", ros_version=2,
                    remaps=[("image", "/camera/depth/image_raw")])
    config = graph([decl], nodes=[camera_subscriber(2)])
    assert [name for _, name, _, _ in topics(config, "/scan")] == [
        "/camera/depth/image_raw", "/camera_info"]
    decl = NodeDecl("/scan", "cam", "scan", "/", ros_version=2,
                    remaps=[("image", "/camera/depth/image_raw"),
                            ("camera_info", "/camera/depth/camera_info")])
    config = graph([decl], nodes=[camera_subscriber(2)])
    assert [name for _, name, _, _ in topics(config, "/scan")] == [
        "/camera/depth/camera_info", "/camera/depth/image_raw"]



def test_ros2_camera_info_follows_a_base_the_code_resolved_and_remapped():
    # a ROS 2 node that gives its camera subscriber a base it resolved itself
    # (resolve_topic_name: remapped, the "=" mark) has camera_info named beside the
    # remapped image topic, where a remap of that camera_info then applies (apriltag_ros'
    # launch file remaps both)
    tags = camera_subscriber(2)
    tags = Node("cam", "scan", calls=[replace(tags.calls[0], transport="?="),
                                      tags.calls[1]])
    decl = NodeDecl("/tags/scan", "cam", "scan", "/tags/", ros_version=2,
                    remaps=[("/tags/image", "/camera/image_rect"),
                            ("/camera/camera_info", "/camera/raw/camera_info")])
    config = graph([decl], nodes=[tags])
    assert [name for _, name, _, _ in topics(config, "/tags/scan")] == [
        "/camera/image_rect", "/camera/raw/camera_info"]
    (instance,) = config.nodes
    assert "/camera/camera_info" in instance.remaps_applied

SCAN = """
#include <ros/ros.h>
#include <image_transport/image_transport.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/CameraInfo.h>
void cb(const sensor_msgs::ImageConstPtr&, const sensor_msgs::CameraInfoConstPtr&) {}
int main(int argc, char** argv) {
  ros::init(argc, argv, "scan");
  ros::NodeHandle n;
  image_transport::ImageTransport it(n);
  image_transport::CameraSubscriber sub = it.subscribeCamera("depth/image", 10, cb);
  ros::spin();
}
"""


def extracted(tmp_path, text):
    """The calls of a ROS 1 package's one C++ source ``text``."""
    from haros_arch.extract.cpp import extract_cpp
    from haros_arch.workspace import scan
    from tests.conftest import package_xml

    package = tmp_path / "cam"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(package_xml("cam", "catkin"))
    (package / "src" / "scan.cpp").write_text(text)
    result = extract_cpp([str(package / "src" / "scan.cpp")], scan([str(tmp_path)], {}),
                         cache_dir=None)
    return sorted((c.kind, c.name, c.camera_of) for c in result.calls)


def test_ros1_camera_subscriber_marks_its_camera_info_with_the_image_topic(tmp_path):
    assert extracted(tmp_path, SCAN) == [
        ("subscribe", "depth/camera_info", "depth/image"),
        ("subscribe", "depth/image", None)]


SCAN_CLASS = """
#include <ros/ros.h>
#include <image_transport/image_transport.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/CameraInfo.h>
class Scan {
 public:
  Scan(ros::NodeHandle& n) : it_(n) {
    sub_ = it_.subscribeCamera("image", 10, &Scan::cb, this);
  }
  void cb(const sensor_msgs::ImageConstPtr&, const sensor_msgs::CameraInfoConstPtr&) {}
  image_transport::ImageTransport it_;
  image_transport::CameraSubscriber sub_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "scan");
  ros::NodeHandle n;
  Scan scan(n);
  ros::spin();
}
"""


def test_camera_info_on_a_handle_given_to_a_class_stays_relative(tmp_path):
    # depthimage_to_laserscan's class takes the node's handle: its camera_info was the
    # global /camera_info once the handle's namespace ("") was filled in
    assert extracted(tmp_path, SCAN_CLASS) == [
        ("subscribe", "camera_info", "image"), ("subscribe", "image", None)]


def test_ros2_parameters_of_a_base_not_known_are_not_known():
    # OrbbecSDK_ROS2 publishes its images on stream_name_[i] + "/image_raw", a map filled
    # at run time: the base '?' cut by the namespace's length left nothing of it, and the
    # node was said to read '/camera/camera/.enable_pub_plugins' and
    # '.compressed.format', names no launch file sets
    driver = Node("cam", "driver", calls=[call("publish", "?", "sensor_msgs/msg/Image", "*"),
                                          call("publish", "?/image_raw",
                                               "sensor_msgs/msg/Image", "*", line=2)])
    config = graph([NodeDecl("/camera/camera", "cam", "driver", "/camera/", ros_version=2)],
                   nodes=[driver], packages=["compressed_image_transport"])
    read = {link.resource.name for link in config.links
            if link.node.name == "/camera/camera" and link.kind == "read"}
    assert not [name for name in read if name.startswith("/camera/camera/.")], read
    assert {"/camera/camera/?.enable_pub_plugins", "/camera/camera/?.compressed.format",
            "/camera/camera/?.image_raw.enable_pub_plugins",
            "/camera/camera/?.image_raw.compressed.format"} <= read
