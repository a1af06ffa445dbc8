"""An executable that links the library of a plugin it never builds (teb_local_planner
b68c328: test_optim_node links the planner's library, whose TebLocalPlannerROS move_base
loads by pluginlib, and calls only a static method of that class). The plugin's
``initialize(name, ...)`` runs in its host's process, with the plugin's name: none of its
calls are the executable's, nor is what it hands the library's helpers (a config reader,
the static method) on ``~/<name>``. Before: the executable read every parameter twice,
as ``~x`` and ``~?/x``, subscribed to ``~?/obstacles`` and served ``~?/set_parameters``;
the static method's reads were only ``~?/radius`` (main's own handle lost)."""

from __future__ import annotations

from pathlib import Path

from conftest import package_xml

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.workspace import scan

HEADER = """\
#include <string>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <pluginlib/class_loader.h>
namespace planner {
struct Config {
  double rate;
  std::string frame;
  void load(const ros::NodeHandle & nh);
};
class Converter { public: virtual ~Converter() {} };
class LocalPlanner {
public:
  virtual ~LocalPlanner() {}
  virtual void initialize(std::string name) = 0;
};
class PlannerROS : public LocalPlanner {
public:
  PlannerROS();
  void initialize(std::string name) override;
  static double footprint(const ros::NodeHandle & nh);
private:
  void onObstacles(const std_msgs::String::ConstPtr & msg) {}
  Config config_;
  ros::Subscriber sub_;
  pluginlib::ClassLoader<Converter> loader_;
};
}  // namespace planner
"""

CONFIG = """\
#include "planner/planner.h"
namespace planner {
void Config::load(const ros::NodeHandle & nh) {
  nh.param("rate", rate, 10.0);
  nh.param("frame", frame, std::string("map"));
}
}  // namespace planner
"""

PLUGIN = """\
#include "planner/planner.h"
#include <pluginlib/class_list_macros.h>
namespace planner {
PlannerROS::PlannerROS() : loader_("planner", "planner::Converter") {}
void PlannerROS::initialize(std::string name) {
  ros::NodeHandle nh("~/" + name);
  config_.load(nh);
  footprint(nh);
  sub_ = nh.subscribe("obstacles", 1, &PlannerROS::onObstacles, this);
  boost::shared_ptr<Converter> converter = loader_.createInstance("planner/Simple");
}
double PlannerROS::footprint(const ros::NodeHandle & nh) {
  double radius = 0.2;
  nh.getParam("radius", radius);
  return radius;
}
}  // namespace planner
PLUGINLIB_EXPORT_CLASS(planner::PlannerROS, planner::LocalPlanner)
"""

MAIN = """\
#include "planner/planner.h"
int main(int argc, char ** argv) {
  ros::init(argc, argv, "test_planner");
  ros::NodeHandle n("~");
  planner::Config config;
  config.load(n);
  double radius = planner::PlannerROS::footprint(n);
  %s
  ros::spin();
}
"""


def _extract(write_tree, more: str = "") -> CppResult:
    root: Path = write_tree({
        "planner/package.xml": package_xml("planner", "catkin"),
        "planner/include/planner/planner.h": HEADER,
        "planner/src/config.cpp": CONFIG,
        "planner/src/planner_ros.cpp": PLUGIN,
        "planner/src/test_planner.cpp": MAIN % more,
    })
    return extract_cpp([str(root / "planner/src" / name) for name in (
        "test_planner.cpp", "config.cpp", "planner_ros.cpp")], scan([str(root)]),
        cache_dir=None)


def _calls(result: CppResult) -> set[tuple[str, str]]:
    return {(call.kind, call.name) for call in result.calls}


def test_the_plugin_a_host_loads_is_none_of_the_executable_s(write_tree) -> None:
    assert _calls(_extract(write_tree)) == {
        ("read", "~rate"), ("read", "~frame"), ("read", "~radius")}


def test_the_executable_that_builds_the_plugin_makes_its_calls(write_tree) -> None:
    """main() builds the planner and calls its ``initialize``: its calls, on the name
    given, and the plugin its loader creates (``CPP_PLUGIN_IN_PROCESS``) the process's."""
    found = _extract(write_tree, 'planner::PlannerROS p; p.initialize("local");')
    assert _calls(found) >= {
        ("read", "~rate"), ("read", "~radius"), ("read", "~local/rate"),
        ("read", "~local/frame"), ("read", "~local/radius"), ("subscribe", "~local/obstacles")}
    assert "CPP_PLUGIN_IN_PROCESS" in {d.code for d in found.diagnostics}


def test_an_error_beside_the_static_call_builds_no_plugin(write_tree) -> None:
    """mpc_local_planner's test_mpc_optim_node: its ``start()`` calls the plugin class's
    static ``getRobotFootprintFromParamServer(nh)`` and has parse errors elsewhere
    (teb_local_planner's obstacle classes, not in the tree). The words of a function with
    errors are where a construction may hide, but a class written there only as the
    scope of static calls the parse read constructs nothing there: its ``initialize``
    still ran in the executable (119 reads on ``~?/``, ``~?/obstacles``)."""
    found = _extract(write_tree, "std::string broken = 2.5;")
    assert "CPP_PARSE_ERROR" in {d.code for d in found.diagnostics}
    assert _calls(found) == {("read", "~rate"), ("read", "~frame"), ("read", "~radius")}
    # a class also written otherwise there (a construction the error may hide) keeps them
    kept = _extract(write_tree, "std::string broken = 2.5; planner::PlannerROS * p = 0;")
    assert ("subscribe", "~?/obstacles") in _calls(kept)
