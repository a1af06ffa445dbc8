"""A ROS 1 nodelet's ``getName()`` (and ``ros::this_node::getName()``) is the node's own
full name: followed by ``/`` it begins a private name (PX4-Avoidance reads
``getName() + "/pointcloud_topics"``), but followed by more of the same segment it is not
the private namespace: kobuki_auto_docking serves its action on ``name_ + "_action"``,
``name_`` the nodelet's getName(), ``/<nodelet>_action``, which was named ``~_action``
(``/<nodelet>/_action``). Now that part of the name is not known (``?_action``). A
handle made on the name alone is the private one (moveit's benchmarks: ``ros::NodeHandle
nh(ros::this_node::getName())``)."""

from __future__ import annotations

from pathlib import Path

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include <ros/ros.h>
#include <std_msgs/String.h>

namespace dock {
class Docking : public nodelet::Nodelet {
  void onInit() override {
    std::string name = getName();
    ros::NodeHandle& nh = getNodeHandle();
    status_ = nh.advertise<std_msgs::String>(name + "_status", 1);
    debug_ = nh.advertise<std_msgs::String>(getName() + "/debug", 1);
    own_ = nh.advertise<std_msgs::String>(ros::this_node::getName() + "_own", 1);
    ros::NodeHandle named(ros::this_node::getName());
    named_ = named.advertise<std_msgs::String>("named", 1);
  }
  ros::Publisher status_, debug_, own_, named_;
};
}  // namespace dock
PLUGINLIB_EXPORT_CLASS(dock::Docking, nodelet::Nodelet)
"""


def test_a_nodelet_name_followed_by_a_suffix_is_not_its_private_namespace(
        tmp_path: Path) -> None:
    root = tmp_path / "dock"
    (root / "src").mkdir(parents=True)
    (root / "package.xml").write_text(package_xml("dock").replace(
        "</package>", "<depend>roscpp</depend><depend>nodelet</depend>"
        "<depend>std_msgs</depend></package>"))
    source = root / "src" / "docking.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)], {}), cache_dir=None,
                         distro="noetic")
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "?_own"), ("publish", "?_status"), ("publish", "~debug"),
        ("publish", "~named")]
