"""A name beside a call's name (a camera publisher's camera_info) goes in that name's
namespace; when the last segment of the name is not known (``?``), it may hold more
segments at run time, so that namespace is not known either. depthai's ImagePublisher
makes ``create_camera_publisher(node, pubConfig.topicName + pubConfig.topicSuffix)``
with a name not known: its camera_info was ``camera_info`` in the node's namespace,
one topic for every stream, and another camera publisher in the launch file made a
false multiple-publishers warning. A known last segment keeps its namespace."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <rclcpp/rclcpp.hpp>
#include <image_transport/image_transport.hpp>
std::string streamName();
class Cam : public rclcpp::Node {
public:
  Cam() : rclcpp::Node("cam") {
    lost_ = image_transport::create_camera_publisher(this, streamName());
    known_ = image_transport::create_camera_publisher(this, "~/" + streamName() + "/image_raw");
    plain_ = image_transport::create_camera_publisher(this, "left/image_raw");
  }
  image_transport::CameraPublisher lost_, known_, plain_;
};
"""


def test_the_namespace_of_a_name_not_known_is_not_known(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("cam", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>image_transport</depend></package>"))
    source = tmp_path / "cam.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    infos = sorted(c.name for c in result.calls
                   if c.kind == "publish" and c.name.endswith("camera_info"))
    assert infos == ["?/camera_info", "left/camera_info", "~?/camera_info"], infos
