"""Gazebo classic's visibility macros (gazebo/util/system.hh: ``GZ_PLUGIN_VISIBLE``,
``GAZEBO_VISIBLE`` and the per-library ``GZ_<LIB>_VISIBLE``) between ``class`` and a
plugin's name. The stand-in did not define them: ``class GZ_PLUGIN_VISIBLE
PedestrianSFMPlugin : public ModelPlugin`` (ros_motion_planning ec1272b,
pedestrian_sfm_plugin.h:43; rotors_simulator's plugins the same) did not parse, the
class was unknown and its calls missed (CPP_CALL_MISSED, the plugin partial). And
Gazebo's namespaces (``common``, ``physics``, ``event``, ...) are declared in
``gazebo``: what a plugin uses of them (``common::Time last_update_;``) is Gazebo's,
not a class of a workspace package that happens to be called ``common``
(ros_motion_planning has one: CPP_CLASS_UNSEEN "common::Time of ROS package common",
the plugin partial for it)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """#include <ros/ros.h>
#include <std_msgs/Int32.h>
#include <gazebo/common/Plugin.hh>
#include <gazebo/physics/physics.hh>
#include <gazebo/util/system.hh>
namespace gazebo
{
class GZ_PLUGIN_VISIBLE WalkerPlugin : public ModelPlugin
{
public:
  WalkerPlugin();
  void Load(physics::ModelPtr _model, sdf::ElementPtr _sdf) override;
private:
  ros::NodeHandle* node_;
  ros::Publisher pose_pub_;
  common::Time last_update_;
  physics::ModelPtr model_;
};
class GAZEBO_VISIBLE Helper
{
public:
  void start(ros::NodeHandle& nh) { pub_ = nh.advertise<std_msgs::Int32>("helper", 1); }
  ros::Publisher pub_;
};
}
"""

SOURCE = """#include "walker/walker_plugin.h"
using namespace gazebo;
GZ_REGISTER_MODEL_PLUGIN(WalkerPlugin)
WalkerPlugin::WalkerPlugin() {}
void WalkerPlugin::Load(physics::ModelPtr _model, sdf::ElementPtr _sdf)
{
  node_ = new ros::NodeHandle("walker");
  pose_pub_ = node_->advertise<std_msgs::Int32>("pose", 10);
  Helper helper;
  helper.start(*node_);
}
"""


def test_plugin_class_with_gazebo_visibility_macro(write_tree) -> None:
    root = write_tree({"walker/package.xml": package_xml("walker"),
                       "common/package.xml": package_xml("common").replace(
                           "</package>", "<depend>roscpp</depend></package>"),
                       "common/include/common/time.h": "namespace common { class Clock "
                                                      "{ public: Clock(); }; }\n",
                       "walker/include/walker/walker_plugin.h": HEADER,
                       "walker/src/walker_plugin.cpp": SOURCE})
    result = extract_cpp([str(root / "walker" / "src" / "walker_plugin.cpp")],
                         scan([str(root)]), include_dirs=[str(root / "walker" / "include")],
                         cache_dir=None)
    assert sorted(c.name for c in result.calls if c.kind == "publish") == [
        "walker/helper", "walker/pose"]
    assert not [d for d in result.diagnostics
                if d.code in ("CPP_CALL_MISSED", "CPP_CLASS_UNSEEN")], result.diagnostics
