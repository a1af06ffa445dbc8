"""A Gazebo classic plugin's helper that reads its <plugin> element's values
(uuv_simulator's ``GetSDFParam<T>(sdf, name, param, default)``, over
``sdf->GetElement(name)->Get<T>()``) wraps SDFormat rows only, which are no ROS call:
its call sites are no place where a ROS call may be missed. Each of uuv's Gazebo plugins
was partial where an argument of it held an error (``ignition::math::Vector3d::Zero``
with ignition's headers missing): ``CPP_CALL_MISSED`` and ``CPP_ERROR_NEAR_CALL``."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

PACKAGE = ('<package format="2"><name>plug</name><version>0.0.0</version>'
           '<description>x</description><maintainer email="a@b.c">a</maintainer>'
           '<license>x</license><buildtool_depend>catkin</buildtool_depend>'
           '<depend>roscpp</depend><depend>gazebo_ros</depend></package>')

SOURCE = """#include <gazebo/gazebo.hh>
#include <gazebo/physics/physics.hh>
#include <ros/ros.h>
#include <std_msgs/String.h>
namespace gazebo {
template <typename T>
bool GetSDFParam(sdf::ElementPtr sdf, const std::string& name, T& param,
                 const T& default_value) {
  if (sdf->HasElement(name)) {
    param = sdf->GetElement(name)->Get<T>();
    return true;
  }
  param = default_value;
  return false;
}
class Plug : public ModelPlugin {
public:
  void Load(physics::ModelPtr model, sdf::ElementPtr sdf) {
    ros::NodeHandle nh;
    pub_ = nh.advertise<std_msgs::String>("out", 1);
    ReadGains(sdf);
  }
  void ReadGains(sdf::ElementPtr sdf) {
    double unused = 0.0;


    // the SDF's own values: no ROS call
    GetSDFParam<double>(sdf, "gain", gain_, 1.0);


    GetSDFParam<double>(sdf, "offset", offset_, undeclared_default);
  }
  ros::Publisher pub_;
  double gain_;
  double offset_;
};
GZ_REGISTER_MODEL_PLUGIN(Plug)
}
"""


def test_a_reader_of_the_plugin_element_is_no_ros_call_site(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(PACKAGE)
    source = tmp_path / "plugin.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="noetic")
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "out")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_PARSE_ERROR" in codes  # the argument's error stays information
    assert "CPP_CALL_MISSED" not in codes and "CPP_ERROR_NEAR_CALL" not in codes
