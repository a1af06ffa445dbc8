"""Stand-in gaps of PX4-Avoidance's local planner: its standalone program builds a
``nodelet::Loader`` and loads its nodelet with ``ros::names::getRemappings()``
(local_planner_node_main.cpp), its nodelet a ``tf::TransformListener(ros::Duration(
tf::Transformer::DEFAULT_CACHE_TIME), true)``: three clang errors, one in a function that
calls the ROS API, which left the node partial. The loader's load, under the node's
own name with the node's remappings, runs the nodelet as the node
(``CPP_NODELET_IN_PROCESS``, in place of ``CPP_PLUGINS_LOADED``)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

MAIN = """
#include <nodelet/loader.h>
#include <ros/ros.h>
int main(int argc, char **argv) {
  ros::init(argc, argv, "planner_nodelet");
  nodelet::Loader nodelet;
  nodelet::M_string remap(ros::names::getRemappings());
  nodelet::V_string nargv;
  std::string nodelet_name = ros::this_node::getName();
  nodelet.load(nodelet_name, "PlannerNodelet", remap, nargv);
  ros::spin();
  return 0;
}
"""

NODELET = """
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <tf/transform_listener.h>
#include <std_msgs/String.h>
class Planner : public nodelet::Nodelet {
 public:
  void onInit() override {
    ros::NodeHandle nh("");
    tf_listener_ = new tf::TransformListener(
        ros::Duration(tf::Transformer::DEFAULT_CACHE_TIME), true);
    pub_ = nh.advertise<std_msgs::String>("plan", 1);
  }
  tf::TransformListener* tf_listener_;
  ros::Publisher pub_;
};
"""


def test_a_nodelet_loader_and_tf_s_cache_time_parse(tmp_path) -> None:
    (tmp_path / "main.cpp").write_text(MAIN)
    (tmp_path / "planner.cpp").write_text(NODELET)
    main = extract_cpp([str(tmp_path / "main.cpp")], Workspace(root=str(tmp_path)),
                       cache_dir=None)
    assert [d.code for d in main.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_PLUGINS_LOADED", "CPP_NODELET_IN_PROCESS")] == [
        "CPP_NODELET_IN_PROCESS"]
    nodelet = extract_cpp([str(tmp_path / "planner.cpp")], Workspace(root=str(tmp_path)),
                          cache_dir=None)
    assert sorted((c.kind, c.name) for c in nodelet.calls) == [
        ("publish", "plan"), ("subscribe", "/tf"), ("subscribe", "/tf_static")]
    assert [d.code for d in nodelet.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_CALL_MISSED")] == []
