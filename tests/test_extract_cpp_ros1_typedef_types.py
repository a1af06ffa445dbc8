"""A ROS 1 message whose header is not there, named by its header's own typedef
(``pkg::NameConstPtr``, ``pkg::NamePtr``), declared permissively as the header that
would bring it is missing: the message is ``pkg/Name``, not ``pkg/NameConstPtr``
(costmap_converter's map_msgs::OccupancyGridUpdateConstPtr, through costmap_2d).
With the message header itself missing, its stand-in already gave the message."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

SOURCE = """
#include <ros/ros.h>
#include <zz_mapping/costmap.h>  // missing; it would bring the message headers
class Converter {
 public:
  Converter() : n_("~") {
    a_ = n_.subscribe("updates", 1, &Converter::onUpdate, this);
    b_ = n_.subscribe("pose", 1, &Converter::onPose, this);
    zz_mapping::Layer layer(n_);  // a type of the missing header, where the API is called
  }
  void onUpdate(const zz_msgs::GridUpdateConstPtr& update) {}
  void onPose(const zz_msgs::PosePtr& pose) {}
  ros::NodeHandle n_;
  ros::Subscriber a_, b_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  Converter c;
  return 0;
}
"""


def test_a_ros1_typedef_of_a_missing_message_header_names_the_message(tmp_path):
    source = tmp_path / "n.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    got = {c.name: c.type for c in result.calls if c.kind == "subscribe"}
    assert got == {"~updates": "zz_msgs/GridUpdate", "~pose": "zz_msgs/Pose"}
