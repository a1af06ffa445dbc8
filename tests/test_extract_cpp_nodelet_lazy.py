"""nodelet_topic_tools::NodeletLazy, the base of pcl_ros' nodelets (pcl_ros/pcl_nodelet.h):
its subclasses use the handles ``nh_`` / ``pnh_`` its onInit() sets and publish through
its ``advertise<T>(nh, topic, queue)``. Without a stand-in every pcl_ros nodelet was
partial (``'pnh_' does not refer to a value``) and lost its ``~output`` publisher."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODELET = """
#include <nodelet_topic_tools/nodelet_lazy.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_msgs/String.h>
#include <pluginlib/class_list_macros.h>
namespace ex {
class Filter : public nodelet_topic_tools::NodeletLazy {
 protected:
  void onInit() override {
    nodelet_topic_tools::NodeletLazy::onInit();
    pnh_->getParam("max_queue_size", max_queue_size_);
    pub_output_ = advertise<sensor_msgs::PointCloud2>(*pnh_, "output", max_queue_size_);
    pub_status_ = advertise<std_msgs::String>(*nh_, "status", 1, true);
    onInitPostProcess();
  }
  void subscribe() override {
    sub_input_ = pnh_->subscribe("input", 1, &Filter::cb, this);
  }
  void unsubscribe() override { sub_input_.shutdown(); }
  void cb(const sensor_msgs::PointCloud2::ConstPtr & c) { pub_output_.publish(c); }
  int max_queue_size_ = 3;
  ros::Publisher pub_output_, pub_status_;
  ros::Subscriber sub_input_;
};
}
PLUGINLIB_EXPORT_CLASS(ex::Filter, nodelet::Nodelet)
"""


def test_a_lazy_nodelet_s_handles_and_publishers(write_tree) -> None:
    root = write_tree({"ex/package.xml": package_xml("ex"), "ex/src/filter.cpp": NODELET})
    result = extract_cpp([str(root / "ex" / "src" / "filter.cpp")], scan([str(root)]),
                         cache_dir=None)
    # ``max_queue_size_`` is 3 until onInit reads ``~max_queue_size`` into it: the queue
    # of ``~output`` is that parameter's value, not known here; NodeletLazy::onInit()
    # reads its own three parameters (an API row: nodelet_core's nodelet_lazy.h)
    assert sorted((c.kind, c.name, c.type, c.queue_size, c.latch) for c in result.calls) == [
        ("publish", "status", "std_msgs/String", 1, True),
        ("publish", "~output", "sensor_msgs/PointCloud2", None, False),
        ("read", "~lazy", "bool", None, False),
        ("read", "~max_queue_size", "int", None, False),
        ("read", "~use_multithread_callback", "bool", None, False),
        ("read", "~verbose_connection", "bool", None, False),
        ("subscribe", "~input", "sensor_msgs/PointCloud2", 1, False),
    ]
    assert [d for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_INCLUDE_MISSING", "CPP_CALL_MISSED")] == []
