"""A node handle member set in a nodelet's ``onInit`` (``private_nh_ =
getPrivateNodeHandle();``, the nodelet idiom) keeps its namespace, as one set in the
constructor does: the parameters read through it are private."""

from __future__ import annotations

from pathlib import Path

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODELET = """
#include <ros/ros.h>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include <sensor_msgs/LaserScan.h>

namespace demo {
class Scanner : public nodelet::Nodelet {
 public:
  Scanner() {}
 private:
  void onInit() override;
  ros::NodeHandle nh_, private_nh_;
  ros::Publisher pub_;
  double angle_min_;
};

void Scanner::onInit() {
  nh_ = getNodeHandle();
  private_nh_ = getPrivateNodeHandle();
  private_nh_.param<double>("angle_min", angle_min_, -3.14);
  pub_ = nh_.advertise<sensor_msgs::LaserScan>("scan", 10);
}
}  // namespace demo

PLUGINLIB_EXPORT_CLASS(demo::Scanner, nodelet::Nodelet)
"""


def test_handles_set_in_on_init_keep_their_namespace(tmp_path: Path) -> None:
    package = tmp_path / "src" / "demo"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(package_xml("demo"))
    (package / "src" / "scanner.cpp").write_text(NODELET)
    result = extract_cpp([str(package / "src" / "scanner.cpp")], scan([str(tmp_path / "src")]),
                         cache_dir=None)
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "scan"), ("read", "~angle_min")]


NODELET_REASSIGNED = """
#include <ros/ros.h>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>

namespace demo {
class Detector {
 public:
  explicit Detector(ros::NodeHandle nh) : nh_(nh) { read(); }
  bool read() { nh_.param("image_view/enable", enable_, true); return true; }
  ros::NodeHandle nh_;
  bool enable_;
};

class DetectorNodelet : public nodelet::Nodelet {
  void onInit() override {
    ros::NodeHandle handle("~");
    handle = getPrivateNodeHandle();
    int rate;
    handle.param("rate", rate, 10);
    ros::NodeHandle maybe;
    if (rate > 5) {
      maybe = ros::NodeHandle("fast");
    }
    maybe.param("limit", rate, 1);
    detector_ = new Detector(handle);
  }
  Detector* detector_;
};
}  // namespace demo

PLUGINLIB_EXPORT_CLASS(demo::DetectorNodelet, nodelet::Nodelet)
"""


def test_a_local_handle_written_again_is_the_last_write_before_its_use(tmp_path: Path) -> None:
    """darknet_ros 1027a28's nodelet: ``ros::NodeHandle NodeHandle("~"); NodeHandle =
    getPrivateNodeHandle();`` then the detector built with it reads its parameters
    privately; they were read as ``?/...``. A write in a branch that may not run leaves
    the handle's namespace unknown."""
    package = tmp_path / "src" / "demo"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(package_xml("demo"))
    (package / "src" / "detector.cpp").write_text(NODELET_REASSIGNED)
    result = extract_cpp([str(package / "src" / "detector.cpp")],
                         scan([str(tmp_path / "src")]), cache_dir=None)
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("read", "?/limit"), ("read", "~image_view/enable"), ("read", "~rate")]
