"""A nodelet's ``getName()`` is its own name, the namespace of its private handle, as
``ros::this_node::getName()`` is a node's. PX4-Avoidance's local planner reads
``nh_private_.getParam(nodelet::Nodelet::getName() + "/pointcloud_topics", ...)``
(local_planner_nodelet.cpp:129) and gives ``getName()`` to its world visualiser: the
names were ``~?/pointcloud_topics`` and ``?``."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODELET = """
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <pluginlib/class_list_macros.h>
namespace ex {
class Planner : public nodelet::Nodelet {
 public:
  void onInit() override {
    ros::NodeHandle nh("");
    ros::NodeHandle pnh("~");
    std::vector<std::string> topics;
    pnh.getParam(nodelet::Nodelet::getName() + "/pointcloud_topics", topics);
    nh.param<std::string>(getName() + "/world_name", world_, "");
    pub_ = nh.advertise<std_msgs::String>(getName() + "/status", 1);
  }
  std::string world_;
  ros::Publisher pub_;
};
}
PLUGINLIB_EXPORT_CLASS(ex::Planner, nodelet::Nodelet)
"""


def test_a_nodelet_s_name_starts_a_private_name(write_tree) -> None:
    root = write_tree({"ex/package.xml": package_xml("ex"), "ex/src/planner.cpp": NODELET})
    result = extract_cpp([str(root / "ex" / "src" / "planner.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "~status"),
        ("read", "~pointcloud_topics"),
        ("read", "~world_name"),
    ]
