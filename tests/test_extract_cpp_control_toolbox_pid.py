"""ROS 1 control_toolbox's Pid, installed (not in the workspace): ``init(nh)`` reads the
gains from the handle's namespace (``p`` required, the others with defaults) and serves
their dynamic_reconfigure there; ``initParam(prefix)`` the same under that namespace.
Without a stand-in the class was unknown and each tracker given a handle made the node
partial (cob_frame_tracker's six PIDs: ``CPP_CLASS_UNSEEN``, ``CPP_NODE_TO_UNKNOWN``), so
every parameter set in its private namespace was undecided."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

PACKAGE = ('<?xml version="1.0"?>\n<package format="2"><name>tracker</name>'
           "<version>0.1.0</version><description>d</description>"
           '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
           "<depend>roscpp</depend><depend>control_toolbox</depend>"
           "<depend>std_msgs</depend></package>\n")

SOURCE = """#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <control_toolbox/pid.h>
class Tracker {
 public:
  bool start() {
    ros::NodeHandle nh_tracker("tracker");
    pid_x_.init(ros::NodeHandle(nh_tracker, "pid_x"));
    pid_y_.initParam("~pid_y");
    double p, i, d, i_max, i_min;
    pid_x_.getGains(p, i, d, i_max, i_min);
    pub_ = nh_tracker.advertise<std_msgs::Float64>("effort", 1);
    return true;
  }
  control_toolbox::Pid pid_x_;
  control_toolbox::Pid pid_y_;
  ros::Publisher pub_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "tracker");
  Tracker t;
  t.start();
}
"""


def test_a_pid_reads_its_gains_where_it_is_given(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(PACKAGE)
    (tmp_path / "tracker.cpp").write_text(SOURCE)
    result = extract_cpp([str(tmp_path / "tracker.cpp")], scan([str(tmp_path)]),
                         cache_dir=None, distro="noetic")
    assert not [d.code for d in result.diagnostics if d.code in (
        "CPP_CLASS_UNSEEN", "CPP_NODE_TO_UNKNOWN", "CPP_ERROR_NEAR_CALL",
        "CPP_INCLUDE_MISSING")]
    calls = {(c.kind, c.name) for c in result.calls}
    for ns in ("tracker/pid_x", "~pid_y"):
        for key in ("p", "i", "d", "i_clamp", "i_clamp_min", "i_clamp_max", "antiwindup",
                    "publish_state"):
            assert ("read", f"{ns}/{key}") in calls
        assert ("server", f"{ns}/set_parameters") in calls
        assert ("publish", f"{ns}/parameter_updates") in calls
        assert ("publish", f"{ns}/parameter_descriptions") in calls
    assert ("publish", "tracker/effort") in calls
    # p is required (init fails without it); the others have the library's defaults
    p = next(c for c in result.calls if c.name == "tracker/pid_x/p")
    i = next(c for c in result.calls if c.name == "tracker/pid_x/i")
    assert not p.has_default and i.has_default
