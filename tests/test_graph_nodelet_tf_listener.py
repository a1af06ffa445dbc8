"""A ROS 1 tf listener given no handle, in a nodelet: the manager's process's node.

tf2_ros' ``TransformListener(buffer, spin_thread = true)`` (geometry2
tf2_ros/src/transform_listener.cpp) subscribes ``/tf`` and ``/tf_static`` on its member
``ros::NodeHandle node_``, default-constructed unless the constructor is given a handle;
tf's ``TransformListener(max_cache_time, spin_thread)`` hands its own default ``node_`` to
the tf2 listener (geometry tf/src/transform_listener.cpp). A default ``ros::NodeHandle``
is roscpp's handle of the process: in a nodelet loaded into a manager, the manager's, so
a ``<remap from="/tf" ...>`` given to the nodelet does not reach the listener, the
manager's does (pointcloud_to_laserscan's nodelets, lunar-devel bb361b4:
``tf2_listener_.reset(new tf2_ros::TransformListener(*tf2_))``). Given
``getNodeHandle()``, the listener is the nodelet's; run standalone, the process is the
nodelet's own."""

from __future__ import annotations

import os
from typing import Any

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

PACKAGE = ('<?xml version="1.0"?>\n<package format="2"><name>filt</name>'
           "<version>0.1.0</version><description>d</description>"
           '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
           "<buildtool_depend>catkin</buildtool_depend><depend>roscpp</depend>"
           "<depend>nodelet</depend><depend>pluginlib</depend><depend>tf2_ros</depend>"
           "<depend>tf</depend>"
           '<export><nodelet plugin="${prefix}/nodelets.xml"/></export></package>\n')

CMAKE = """project(filt)
find_package(catkin REQUIRED COMPONENTS roscpp nodelet pluginlib tf2_ros tf)
catkin_package()
add_library(filt_nodelet src/{name}.cpp)
"""

PLUGINS = """<library path="lib/libfilt_nodelet">
  <class name="filt/Filter" type="filt::Filter" base_class_type="nodelet::Nodelet">
    <description>d</description>
  </class>
</library>
"""

TF2 = """#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include <tf2_ros/transform_listener.h>
namespace filt {
class Filter : public nodelet::Nodelet {
 public:
  void onInit() override {
    listener_.reset(new tf2_ros::TransformListener(buffer_));
    given_.reset(new tf2_ros::TransformListener(other_, getNodeHandle()));
  }
 private:
  tf2_ros::Buffer buffer_, other_;
  boost::shared_ptr<tf2_ros::TransformListener> listener_, given_;
};
}
PLUGINLIB_EXPORT_CLASS(filt::Filter, nodelet::Nodelet)
"""

TF1 = """#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include <tf/transform_listener.h>
namespace filt {
class Filter : public nodelet::Nodelet {
 public:
  void onInit() override {
    listener_.reset(new tf::TransformListener(ros::Duration(10.0)));
  }
 private:
  boost::shared_ptr<tf::TransformListener> listener_;
};
}
PLUGINLIB_EXPORT_CLASS(filt::Filter, nodelet::Nodelet)
"""

LAUNCH = """<launch>
  <group ns="robot">
    <node pkg="nodelet" type="nodelet" name="mgr" args="manager">
      <remap from="/tf_static" to="/mgr_tf_static"/>
    </node>
    <node pkg="nodelet" type="nodelet" name="filter" args="load filt/Filter /robot/mgr">
      <remap from="/tf" to="/robot/tf"/>
    </node>
    <node pkg="nodelet" type="nodelet" name="alone" args="standalone filt/Filter">
      <remap from="/tf" to="/alone_tf"/>
    </node>
  </group>
</launch>
"""


def _config(write_tree: Any, name: str, source: str) -> Any:
    root = write_tree({
        "src/filt/package.xml": PACKAGE, "src/filt/CMakeLists.txt": CMAKE.format(name=name),
        "src/filt/nodelets.xml": PLUGINS, f"src/filt/src/{name}.cpp": source,
        "src/filt/launch/filt.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [filt/launch/filt.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    return config


def _subscribed(instance: Any) -> list[tuple[int, str]]:
    return sorted((link.location.line, link.rosname.full) for link in instance.links
                  if link.kind == "subscribe")


def test_a_tf2_listener_given_no_handle_is_the_managers(write_tree: Any) -> None:
    config = _config(write_tree, "tf2", TF2)
    # line 8, no handle: the manager's remaps (its /tf_static), not the nodelet's /tf;
    # line 9, getNodeHandle(): the nodelet's remaps
    assert _subscribed(config.node("/robot/filter")) == [
        (8, "/mgr_tf_static"), (8, "/tf"), (9, "/robot/tf"), (9, "/tf_static")]
    # standalone, the process is the nodelet's: its remaps for both
    assert _subscribed(config.node("/robot/alone")) == [
        (8, "/alone_tf"), (8, "/tf_static"), (9, "/alone_tf"), (9, "/tf_static")]
    (said,) = [d for d in config.diagnostics if d.code == "NODELET_PROCESS_HANDLES"]
    assert "2 call(s)" in said.message and "/robot/mgr's" in said.message


def test_a_tf_listener_given_no_handle_is_the_managers(write_tree: Any) -> None:
    config = _config(write_tree, "tf1", TF1)
    assert _subscribed(config.node("/robot/filter")) == [(8, "/mgr_tf_static"), (8, "/tf")]
    assert _subscribed(config.node("/robot/alone")) == [(8, "/alone_tf"), (8, "/tf_static")]
