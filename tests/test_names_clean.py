"""roscpp's ``ros::names::clean(name)`` in a topic name (image_pipeline's stereo_view:
``ros::names::clean(stereo_ns + "/left" + image)``, ``stereo_ns`` a handle's
``resolveName``): the name with each run of slashes made one and a last slash dropped,
not a name unknown (``?``)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

VIEW = """\
#include <ros/ros.h>
#include <sensor_msgs/Image.h>

void onImage(const sensor_msgs::Image::ConstPtr& msg) {}

int main(int argc, char** argv) {
  ros::init(argc, argv, "view");
  ros::NodeHandle nh;
  std::string stereo_ns = nh.resolveName("stereo");
  ros::Subscriber left = nh.subscribe(
      ros::names::clean(stereo_ns + "/left/" + "/image/"), 1, onImage);
  ros::Subscriber right = nh.subscribe(ros::names::clean("right//image"), 1, onImage);
  ros::spin();
}
"""

CMAKE = """\
cmake_minimum_required(VERSION 3.0.2)
project(view)
find_package(catkin REQUIRED COMPONENTS roscpp sensor_msgs)
catkin_package()
add_executable(view src/view.cpp)
"""


def test_a_cleaned_name_is_the_name_cleaned(write_tree):
    root = write_tree({
        "src/view/package.xml": package_xml("view"),
        "src/view/CMakeLists.txt": CMAKE,
        "src/view/src/view.cpp": VIEW,
        "src/view/launch/view.launch": (
            '<launch><group ns="robot"><node pkg="view" type="view" name="view">'
            '<remap from="stereo" to="wide"/></node></group></launch>\n'),
        "project.yaml": "project: p\nconfigurations:\n  c: [view/launch/view.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    (node,) = [n for n in config.nodes if n.name == "/robot/view"]
    assert sorted(link.rosname.full for link in node.links if link.kind == "subscribe") == [
        "/robot/right/image", "/robot/wide/left/image"]


APPENDED = """\
#include <ros/ros.h>
#include <sensor_msgs/Image.h>

void onImage(const sensor_msgs::Image::ConstPtr& msg) {}

int main(int argc, char** argv) {
  ros::init(argc, argv, "view");
  ros::NodeHandle nh;
  std::string stereo_ns = nh.resolveName("stereo");
  ros::Subscriber left = nh.subscribe(
      ros::names::clean(stereo_ns + "/left/" + nh.resolveName("image")), 1, onImage);
  ros::spin();
}
"""


def test_a_resolved_name_appended_is_unknown(write_tree):
    # resolveName gives a global name, remapped: after other text, the node's namespace
    # comes with it (/robot/stereo/left/robot/image at run time without a remap), and the
    # instance's remap of image its own: the piece is not known here
    root = write_tree({
        "src/view/package.xml": package_xml("view"),
        "src/view/CMakeLists.txt": CMAKE,
        "src/view/src/view.cpp": APPENDED,
        "src/view/launch/view.launch": (
            '<launch><group ns="robot"><node pkg="view" type="view" name="view"/>'
            '</group></launch>\n'),
        "project.yaml": "project: p\nconfigurations:\n  c: [view/launch/view.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (node,) = model.nodes
    assert [c.name for c in node.calls if c.kind == "subscribe"] == ["stereo/left/?"]
