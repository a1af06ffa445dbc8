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
