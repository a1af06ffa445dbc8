"""rosconsole's conditional macros (``ROS_ERROR_COND(cond, ...)``, ``_COND_NAMED``,
``_STREAM_COND``) evaluate ``cond`` where the logger of their level is enabled
(``ROSCONSOLE_DEFINE_LOCATION``: ``logger_enabled_ && (cond)``): info and above by
default. The stand-in dropped the condition, so a ROS call in it was lost: the Palouse
RoboSub control node (PalouseRobosub/robosub 40e79ed, src/movement/control_system.cpp:
20-36) loads its settings with ``ROS_ERROR_COND(!ros::param::getCached(
"control/mass", sub_mass[0]), "Failed to load mass of the submarine.")``, seven reads
CPP_CALL_MISSED and the node partial. A debug condition is evaluated only where the
level is lowered at run time: its call is not made by default."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = """#include <ros/ros.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "control");
  ros::NodeHandle nh("~");
  double mass, rate;
  int level;
  ROS_ERROR_COND(!ros::param::getCached("control/mass", mass), "Failed to load mass.");
  if (argc > 1)
    ROS_WARN_STREAM_COND(!nh.getParam("rate", rate), "no rate " << rate);
  else
    ROS_INFO("no arguments");
  ROS_DEBUG_COND(!nh.getParam("debug_level", level), "no level");
  ros::spin();
  return 0;
}
"""


def test_a_log_macro_s_condition_makes_its_calls(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("p", "catkin"))
    source = tmp_path / "control.cpp"
    source.write_text(NODE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    calls = [(c.kind, c.name, c.location.line, [k.statement for k in c.conditions])
             for c in result.calls]
    # made unconditionally, or under the code's own test; the debug one not at all
    assert calls == [("read", "control/mass", 7, []), ("read", "~rate", 9, ["if"])]
    assert not [d for d in result.diagnostics if d.code in (
        "CPP_CALL_MISSED", "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")]
