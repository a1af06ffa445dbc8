"""A member of an API class whose mere construction is a call (a tf broadcaster's
``/tf``) makes that call at its declaration only when it can be made with no argument.
camera_info_manager's ``CameraInfoManager`` takes a handle: a member of it is made where
a constructor initialises it (cv_camera's ``info_manager_(node_, camera_name)``,
capture.cpp:20, on the private handle), and its declaration (capture.h:212) had added a
second ``set_camera_info`` server, on the node's namespace, that the node never serves."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp_nodes
from haros_arch.workspace import scan

HEADER = """#include <ros/ros.h>
#include <camera_info_manager/camera_info_manager.h>
#include <tf2_ros/transform_broadcaster.h>
class Capture {
public:
  Capture(ros::NodeHandle& node, const std::string& camera_name);
private:
  ros::NodeHandle node_;
  camera_info_manager::CameraInfoManager info_manager_;
  tf2_ros::TransformBroadcaster broadcaster_;
};
"""

CAPTURE = """#include <cam/capture.h>
Capture::Capture(ros::NodeHandle& node, const std::string& camera_name)
  : node_(node), info_manager_(node_, camera_name)
{
}
"""

MAIN = """#include <cam/capture.h>
int main(int argc, char** argv)
{
  ros::init(argc, argv, "cam");
  ros::NodeHandle pnh("~");
  Capture capture(pnh, "camera");
  ros::spin();
}
"""


def test_a_member_made_with_arguments_is_made_by_its_constructor(tmp_path) -> None:
    package = tmp_path / "src" / "cam"
    (package / "src").mkdir(parents=True)
    (package / "include" / "cam").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="2"><name>cam</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>BSD</license><depend>roscpp</depend></package>\n')
    (package / "include" / "cam" / "capture.h").write_text(HEADER)
    (package / "src" / "capture.cpp").write_text(CAPTURE)
    (package / "src" / "main.cpp").write_text(MAIN)
    src = package / "src"
    batch = extract_cpp_nodes([[str(src / "main.cpp"), str(src / "capture.cpp")]],
                              scan([str(tmp_path)]), cache_dir=None, jobs=1)
    assert sorted((c.kind, c.name) for c in batch.results[0].calls) == [
        ("publish", "/tf"), ("server", "~set_camera_info")]
