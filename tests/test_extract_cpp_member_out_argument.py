"""A member initialised in a constructor's list and then filled by a call that takes it
by non-const reference (a ROS 1 ``getParam`` out argument, also inside glog's
``CHECK(...)``) holds what the call stored, not its initialiser (bench/README, survey
Z46: Kimera-VIO-ROS's RosbagDataProvider initialises ``left_imgs_topic_("")``, reads
``CHECK(nh_private_.getParam("left_cam_rosbag_topic", left_imgs_topic_))`` and
advertises on it: the three publishers were on ``""``, the node's namespace itself).
A NodeHandle member handed to a helper by reference keeps its namespace, and a string
passed by const reference keeps its value."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include <glog/logging.h>

void configure(ros::NodeHandle& nh);
void log_topic(const std::string& topic);

class Provider {
 public:
  Provider() : nh_(), pnh_("~"), left_(""), imu_(""), fixed_("/fixed") {
    CHECK(pnh_.getParam("left_topic", left_));
    pnh_.getParam("imu_topic", imu_);
    configure(pnh_);
    log_topic(fixed_);
    left_pub_ = nh_.advertise<std_msgs::String>(left_, 10);
  }
  void start() {
    imu_pub_ = nh_.advertise<std_msgs::String>(imu_, 10);
    fixed_pub_ = nh_.advertise<std_msgs::String>(fixed_, 10);
    status_pub_ = pnh_.advertise<std_msgs::String>("status", 10);
  }
  ros::NodeHandle nh_, pnh_;
  std::string left_, imu_, fixed_;
  ros::Publisher left_pub_, imu_pub_, fixed_pub_, status_pub_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "provider");
  Provider provider;
  provider.start();
  ros::spin();
}
"""


def test_a_member_an_out_argument_filled_is_not_its_initialiser(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("provider"))
    source = tmp_path / "node.cpp"
    source.write_text(NODE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="noetic")
    # the parameter's value (the graph fills it from the launch file), not ""
    assert [(c.kind, c.name, c.name_param, c.location.line) for c in result.calls
            if c.kind == "publish"] == [
        ("publish", "?", "~left_topic", 15),
        ("publish", "?", "~imu_topic", 18),
        ("publish", "/fixed", None, 19),
        ("publish", "~status", None, 20),
    ]
