"""A local that a parameter read fills and that a branch writes again before it names a
topic: Autoware's image_rectifier and pixel_cloud_fusion (core_perception 411330c) read
``camera_info_src`` into a string, then ``if (name_space_str != "/") camera_info_topic_str
= name_space_str + camera_info_topic_str;`` (the node's namespace before it) and
subscribe to it. The name was taken as the parameter's value alone, ``/camera_info``, so
image_rectifier_ladybug.launch's five rectifiers in ``/camera2`` ... ``/camera6`` were
reported subscribing to ``/camera_info`` with nothing publishing it (they subscribe to
``/camera2/camera_info`` ...). Where such a write may run between the read and the use,
the name is not known (``?``), not the parameter's value."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue
from haros_arch.workspace import scan

NODE = r"""
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <std_msgs/String.h>
#include <string>

void onInfo(const sensor_msgs::CameraInfo::ConstPtr& msg) {}
void onText(const std_msgs::String::ConstPtr& msg) {}

int main(int argc, char** argv) {
  ros::init(argc, argv, "rectifier");
  ros::NodeHandle node_handle("~");
  std::string info_topic, text_topic, name_space = ros::this_node::getNamespace();
  node_handle.param<std::string>("camera_info_src", info_topic, "/camera_info");
  node_handle.param<std::string>("text_src", text_topic, "/text");
  if (name_space != "/") {
    if (name_space.substr(0, 2) == "//") {
      name_space.erase(name_space.begin());
    }
    info_topic = name_space + info_topic;
  }
  ros::Subscriber info = node_handle.subscribe(info_topic, 1, onInfo);
  ros::Subscriber text = node_handle.subscribe(text_topic, 1, onText);
  ros::spin();
}
"""


def test_the_read_alone_names_no_topic_a_branch_rewrites(tmp_path: Path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("rect"))
    source = tmp_path / "rectifier.cpp"
    source.write_text(NODE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="noetic")
    assert [(c.name, c.name_param) for c in result.calls if c.kind == "subscribe"] == [
        ("~?", None), ("~?", "~text_src")]


def test_no_finding_on_the_parameter_s_value(write_tree: Any) -> None:
    root: Path = write_tree({
        "src/rect/package.xml": package_xml("rect"),
        "src/rect/CMakeLists.txt": "project(rect)\nfind_package(catkin REQUIRED roscpp)\n"
                                   "add_executable(rectifier src/rectifier.cpp)\n",
        "src/rect/src/rectifier.cpp": NODE,
        "src/rect/launch/rect.launch": (
            "<launch>\n"
            "  <node pkg='rect' type='rectifier' name='rectifier2' ns='/camera2'/>\n"
            "</launch>\n"),
        "project.yaml": "project: p\ndistro: noetic\n"
                        "configurations:\n  c: [rect/launch/rect.launch]\n",
    })
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    assert "/camera_info" not in {t.name for t in config.topics}
    assert "/text" in {t.name for t in config.topics}
    said = [f.message for f in run_catalogue(model, project)
            if f.rule == "subscriber-without-publisher"]
    assert said == ["/camera2/rectifier2 subscribes to /text but nothing publishes it"]
