"""Two unknown values side by side are one unknown run: a handle made in another file
of the node on ``sensor_name + std::to_string(index)``, both passed by a caller whose
values are not known (jsk_aerial_robot's estimator sensor plugins), names its calls
``?/estimate_flag``, spelled once, not ``??/estimate_flag`` beside ``?/estimate_flag``."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

HEADER = r"""
#include <ros/ros.h>
#include <std_srvs/SetBool.h>
#include <string>
class Sensor {
 public:
  void initialize(ros::NodeHandle nh, std::string sensor_name, int index);
  bool cb(std_srvs::SetBool::Request&, std_srvs::SetBool::Response&) { return true; }
 private:
  ros::NodeHandle nh_, indexed_nhp_;
  ros::ServiceServer srv_;
  ros::Publisher pub_;
};
"""

SENSOR = r"""
#include "sensor.h"
void Sensor::initialize(ros::NodeHandle nh, std::string sensor_name, int index) {
  nh_ = nh;
  indexed_nhp_ = ros::NodeHandle(nh_, sensor_name + std::to_string(index));
  srv_ = indexed_nhp_.advertiseService("estimate_flag", &Sensor::cb, this);
  pub_ = nh_.advertise<std_srvs::SetBool::Request>(
      "kf/" + sensor_name + std::to_string(index) + "/data", 10);
}
"""

MAIN = r"""
#include "sensor.h"
#include <vector>
int main(int argc, char** argv) {
  ros::init(argc, argv, "est");
  ros::NodeHandle nh;
  std::vector<std::string> names;
  nh.getParam("sensor_plugin", names);
  std::vector<Sensor> sensors(names.size());
  for (size_t i = 0; i < names.size(); ++i) {
    sensors[i].initialize(nh, names[i], i);
  }
  ros::spin();
}
"""


def test_unknown_values_side_by_side_are_one_unknown_run(tmp_path):
    (tmp_path / "sensor.h").write_text(HEADER)
    (tmp_path / "sensor.cpp").write_text(SENSOR)
    (tmp_path / "main.cpp").write_text(MAIN)
    result = extract_cpp([str(tmp_path / "main.cpp"), str(tmp_path / "sensor.cpp")],
                         Workspace(root=str(tmp_path)), cache_dir=None, jobs=1)
    named = sorted((c.kind, c.name, c.handle_namespace) for c in result.calls
                   if c.kind in ("server", "publish"))
    assert named == [("publish", "kf/?/data", None), ("server", "?/estimate_flag", "?")]
