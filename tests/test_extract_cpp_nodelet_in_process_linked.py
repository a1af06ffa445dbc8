"""An executable whose main() loads, under its own name, a nodelet of the library it
links (apriltag_ros 94b3b843's apriltag_ros_continuous_node: ``nodelet.load(
ros::this_node::getName(), "apriltag_ros/ContinuousDetector", remap, nargv)``, linked
with the detector's library) runs that class as a nodelet host would, with what it
builds: the detector's ``onInit`` makes a ``TagDetector(pnh)``, whose constructor in
another source (common_functions.cpp) reads ``tag_family``, ``standalone_tags``, ... .
Only the class's own methods were read for the executable, so the 10 settings
continuous_detection.launch loads were 'set but never read'."""

from __future__ import annotations

import os
from typing import Any

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

PACKAGE = ('<?xml version="1.0"?>\n<package format="2"><name>tags</name>'
           "<version>0.1.0</version><description>d</description>"
           '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
           "<buildtool_depend>catkin</buildtool_depend><depend>roscpp</depend>"
           "<depend>nodelet</depend><depend>pluginlib</depend><depend>std_msgs</depend>"
           '<export><nodelet plugin="${prefix}/nodelet_plugins.xml"/></export></package>\n')

CMAKE = """project(tags)
find_package(catkin REQUIRED COMPONENTS roscpp nodelet pluginlib std_msgs)
catkin_package()
add_library(tags_common src/common.cpp)
add_library(tags_detector src/detector.cpp)
target_link_libraries(tags_detector tags_common ${catkin_LIBRARIES})
add_executable(tags_node src/tags_node.cpp)
target_link_libraries(tags_node tags_detector ${catkin_LIBRARIES})
"""

PLUGINS = """<library path="lib/libtags_detector">
  <class name="tags/Detector" type="tags::Detector" base_class_type="nodelet::Nodelet">
    <description>d</description>
  </class>
</library>
"""

COMMON_H = """#include <ros/ros.h>
#include <std_msgs/String.h>
namespace tags {
class TagFinder {
 public:
  explicit TagFinder(ros::NodeHandle pnh);
 private:
  std::string family_;
  ros::Publisher found_;
};
}
"""

COMMON_CPP = """#include "common.h"
namespace tags {
TagFinder::TagFinder(ros::NodeHandle pnh) {
  pnh.param<std::string>("tag_family", family_, "tag36h11");
  found_ = pnh.advertise<std::string_msgs_placeholder>("found", 1);
}
}
""".replace("std::string_msgs_placeholder", "std_msgs::String")

DETECTOR_CPP = """#include <memory>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include "common.h"
namespace tags {
class Detector : public nodelet::Nodelet {
 public:
  void onInit() override {
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    pnh.param("queue_size", queue_size_, 1);
    finder_ = std::make_shared<TagFinder>(pnh);
  }
 private:
  int queue_size_;
  std::shared_ptr<TagFinder> finder_;
};
}
PLUGINLIB_EXPORT_CLASS(tags::Detector, nodelet::Nodelet)
"""

NODE_CPP = """#include <ros/ros.h>
#include <nodelet/loader.h>
int main(int argc, char **argv) {
  ros::init(argc, argv, "tags");
  nodelet::Loader nodelet;
  nodelet::M_string remap(ros::names::getRemappings());
  nodelet::V_string nargv;
  nodelet.load(ros::this_node::getName(), "tags/Detector", remap, nargv);
  ros::spin();
  return 0;
}
"""

LAUNCH = """<launch>
  <node pkg="tags" type="tags_node" name="tags_node">
    <param name="queue_size" value="2"/>
    <param name="tag_family" value="tag25h9"/>
    <param name="tag_familly" value="tag25h9"/>
  </node>
</launch>
"""


def test_the_executable_runs_what_its_in_process_nodelet_builds(write_tree: Any) -> None:
    root = write_tree({
        "src/tags/package.xml": PACKAGE, "src/tags/CMakeLists.txt": CMAKE,
        "src/tags/nodelet_plugins.xml": PLUGINS,
        "src/tags/src/common.h": COMMON_H, "src/tags/src/common.cpp": COMMON_CPP,
        "src/tags/src/detector.cpp": DETECTOR_CPP, "src/tags/src/tags_node.cpp": NODE_CPP,
        "src/tags/launch/tags.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [tags/launch/tags.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    (node,) = [n for n in config.nodes if n.name == "/tags_node"]
    reads = sorted(link.param_name for link in node.reads)
    assert reads == ["/tags_node/queue_size", "/tags_node/tag_family"]
    assert [link.topic_name for link in node.publishers] == ["/tags_node/found"]
    unread = sorted(e for f in run_catalogue(model) if f.rule == "parameter-set-not-read"
                    for e in f.entities if e.startswith("parameter:"))
    assert unread == ["parameter:/tags_node/tag_familly"]
