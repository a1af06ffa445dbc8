"""ROS 1 nodelets built on perception_pcl's ``pcl_ros::PCLNodelet`` (jsk_pcl_ros'
LINEMODTrainer, TransformPointcloudInBoundingBox, ...) where pcl_ros is installed, not in
the workspace: the base was a name declared permissively, so its ``pnh_`` (the private
handle NodeletLazy::onInit() makes) was a permissive value and every name made on it was
``?/input``; the parameters its onInit() reads were unseen. The fallback stand-in declares
the class (a NodeletLazy) and an API row its onInit() (pcl_nodelet.h of perception_pcl
2f70209f: NodeletLazy's reads, then four private ones)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

MANIFEST = """<package format="2"><name>p</name><version>0.0.0</version>
<description>d</description><maintainer email="a@b.c">a</maintainer><license>BSD</license>
<buildtool_depend>catkin</buildtool_depend><depend>roscpp</depend><depend>nodelet</depend>
<depend>pcl_ros</depend><depend>sensor_msgs</depend></package>
"""

TRAINER = """\
#include <pcl_ros/pcl_nodelet.h>
#include <sensor_msgs/PointCloud2.h>
#include <pluginlib/class_list_macros.h>
namespace p {
class Trainer : public pcl_ros::PCLNodelet {
 protected:
  void onInit() {
    PCLNodelet::onInit();
    pnh_->param("n_points", n_points_, 150);
    sub_ = pnh_->subscribe("input", max_queue_size_, &Trainer::cb, this);
    pub_output_ = advertise<sensor_msgs::PointCloud2>(*pnh_, "output", 1);
  }
  void subscribe() {}
  void unsubscribe() {}
  void cb(const sensor_msgs::PointCloud2::ConstPtr& msg) {}
  int n_points_;
  ros::Subscriber sub_;
};
}
PLUGINLIB_EXPORT_CLASS(p::Trainer, nodelet::Nodelet)
"""


def test_a_pcl_nodelet_s_handles_and_base_reads(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(MANIFEST)
    source = tmp_path / "trainer.cpp"
    source.write_text(TRAINER)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_NAMES_DECLARED")] == []
    assert [(c.kind, c.name, c.type, c.location.line) for c in result.calls] == [
        ("read", "~use_multithread_callback", "bool", 8),
        ("read", "~lazy", "bool", 8),
        ("read", "~verbose_connection", "bool", 8),
        ("read", "~max_queue_size", "int", 8),
        ("read", "~use_indices", "bool", 8),
        ("read", "~latched_indices", "bool", 8),
        ("read", "~approximate_sync", "bool", 8),
        ("read", "~n_points", "int", 9),
        ("subscribe", "~input", "sensor_msgs/PointCloud2", 10),
        ("publish", "~output", "sensor_msgs/PointCloud2", 11),
    ]
