"""A ROS 1 message's fixed-size array field is a ``boost::array<T, N>``, as gencpp makes
it, not a ``std::vector<T>``: ardrone_autonomy's driver hands
``imu_msg.linear_acceleration_covariance`` (``float64[9]``) to its own
``ReadCovParams(const std::string &, boost::array<double, 9> &)``, which reads the
parameter the call names; with a vector there the call was an error, and the read lost
its name (``?``, CPP_CALL_MISSED)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp, interfaces
from haros_arch.workspace import scan

SOURCE = """\
#include <boost/array.hpp>
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>
#include <pkg/Pose.h>
bool readCov(const std::string& name, boost::array<double, 9>& cov) {
  std::vector<double> values;
  if (!ros::param::get(name, values)) return false;
  for (size_t i = 0; i < cov.size(); ++i) cov[i] = values[i];
  return true;
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "imu");
  ros::NodeHandle nh;
  sensor_msgs::Imu msg;
  readCov("~cov/la", msg.linear_acceleration_covariance);
  msg.orientation_covariance.fill(0.0);
  pkg::Pose pose;
  pose.covariance.fill(0.0);
  pose.names.push_back("x");
  ros::Publisher pub = nh.advertise<sensor_msgs::Imu>("imu", 10);
}
"""


def test_a_fixed_size_array_field_is_a_boost_array(write_tree) -> None:
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "catkin").replace(
            "</package>", "<depend>roscpp</depend><depend>sensor_msgs</depend></package>"),
        "pkg/msg/Pose.msg": "float64[36] covariance\nstring[] names\n",
        "pkg/src/imu.cpp": SOURCE})
    result = extract_cpp([str(root / "pkg" / "src" / "imu.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert [(c.kind, c.name, c.location.line) for c in result.calls] == [
        ("read", "~cov/la", 15), ("publish", "imu", 20)]
    assert [d.message for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_CALL_MISSED", "CPP_INCLUDE_MISSING")] == []


def test_rendered_fields() -> None:
    text = interfaces.render(interfaces.parse_definition(
        "pkg", "Cam", "float64[9] K\nfloat64[] D\nuint8[4] bytes\n"))
    assert "boost::array<double, 9> K;" in text
    assert "std::vector<double> D;" in text
    assert "boost::array<uint8_t, 4> bytes;" in text
