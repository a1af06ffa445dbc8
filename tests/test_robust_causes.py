"""Causes of architecture bugs of the ROBUST dataset that check missed, each rebuilt
small (bench/robust_bugs.py measures the real ones): a rospy publisher without a queue
size in a Python 2 script whose print statements go on over lines (kobuki dd40270), and
a launch file that pins a node's names outside the namespace it is included in
(turtlebot 9ffffca, openni_launch a482f82). Also a crash met on the way: a va_list
handed to a call (openni_camera, in turtlebot 3e32933's tree)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.api import analyse_path
from haros_arch.extract.cpp import extract_cpp
from haros_arch.extract.python import extract_python
from haros_arch.pipeline import Options
from haros_arch.query.command import check
from haros_arch.workspace import scan

OPTIONS = Options(cache_dir=None, jobs=1)

PUBLISHERS = """\
import rospy
from std_msgs.msg import String

def main(rate, extra):
    rospy.init_node('odometer')
    a = rospy.Publisher('pose2d', String)
    b = rospy.Publisher('yaw', String, queue_size=None)
    c = rospy.Publisher('heading', String, queue_size=5)
    d = rospy.Publisher('speed', String, queue_size=rate)
    e = rospy.Publisher('spread', String, **extra)
    f = rospy.Publisher('positional', String, None, False, False, None, 3)
    g = rospy.Subscriber('odom', String, None)
"""


def test_a_rospy_call_without_queue_size_is_marked(write_tree) -> None:
    folder = write_tree({"pkg/package.xml": package_xml("pkg"),
                         "pkg/scripts/odometer.py": PUBLISHERS})
    result = extract_python([str(folder / "pkg" / "scripts" / "odometer.py")],
                            scan([str(folder)]), package="pkg")
    assert [(c.kind, c.name, c.queue_size, c.queue_size_missing) for c in result.calls
            if c.kind in ("publish", "subscribe")] == [
        ("publish", "pose2d", None, True),
        ("publish", "yaw", None, True),            # None written: rospy's default too
        ("publish", "heading", 5, False),
        ("publish", "speed", None, False),         # given, its value unknown
        ("publish", "spread", None, False),        # may come through **extra
        ("publish", "positional", 3, False),
        ("subscribe", "odom", None, True),
    ]


LAUNCH = """\
<launch>
  <group ns="robot1">
    <node pkg="base" type="odometer.py" name="odometer"/>
    <node pkg="nodelet" type="nodelet" name="smoother"
          args="load base/Smoother /base_manager">
      <remap from="smoother/out" to="/mux/input/teleop"/>
      <remap from="smoother/odometry" to="odom"/>
      <remap from="smoother/clock" to="/clock"/>
    </node>
    <node pkg="nodelet" type="nodelet" name="shaper"
          args="load base/Smoother base_manager">
      <remap from="/joint_states" to="/robot1/joint_states"/>
    </node>
  </group>
</launch>
"""


def test_check_reports_both_causes_on_a_launched_workspace(write_tree) -> None:
    folder = write_tree({
        "src/base/package.xml": package_xml("base"),
        "src/base/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0)\nproject(base)\n"
                                   "find_package(catkin REQUIRED)\ncatkin_package()\n"
                                   "catkin_install_python(PROGRAMS scripts/odometer.py\n"
                                   "  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})\n",
        # a script runs whole: its main called (a function nothing calls makes no call)
        "src/base/scripts/odometer.py": PUBLISHERS + "\nif __name__ == '__main__':\n"
                                                     "    main(rospy.get_param('~rate'), {})\n",
        "src/base/launch/robot.launch": LAUNCH,
        "project.yaml": "project: p\nworkspace: src\nconfigurations:\n"
                        "  robot:\n    launch: [base/launch/robot.launch]\n",
    })
    analysis = analyse_path(str(folder / "project.yaml"), OPTIONS)
    assert analysis.model is not None
    found = check(analysis.model, analysis.project).findings
    missing = sorted(f.message for f in found if f.rule == "queue-size-missing")
    assert missing == [
        "/robot1/odometer: the rospy publisher of /robot1/pose2d has no queue_size, "
        "so it publishes synchronously",
        "/robot1/odometer: the rospy publisher of /robot1/yaw has no queue_size, "
        "so it publishes synchronously"]
    pinned = [f for f in found if f.rule == "launch-global-names"]
    assert [f.message for f in pinned] == [
        "/robot1/smoother is launched with global names its namespace cannot move "
        "(remaps: smoother/out:=/mux/input/teleop; nodelet manager: /base_manager)"]
    # the line its <node starts on, not the one its start tag ends on
    assert (pinned[0].location.file, pinned[0].location.line) == (
        "base/launch/robot.launch", 4)


PYTHON2 = """\
import rospy
from std_msgs.msg import String

def report(x, y):
    print "pose: x: %.2f" % x \\
        + ", y: %.2f" % y
    print "both: %s" % (x,
                        y)  # a comment after the statement
    print >>log, "done",
    if x > y: print "x"
    print '''usage:
  odometer  # not a comment
'''

rospy.init_node('odometer')
pub = rospy.Publisher('pose2d', String)
"""


def test_a_python2_statement_continued_over_lines_costs_no_call(write_tree) -> None:
    """kobuki's getOdom2D.py: a print statement continued by a backslash made the
    repaired file a syntax error, and the node lost every call; so did a print after
    an if's colon and one of a string over several lines (kobuki's DockDriveActionClient
    and turtlebot_config)."""
    folder = write_tree({"pkg/package.xml": package_xml("pkg"),
                         "pkg/scripts/odometer.py": PYTHON2})
    result = extract_python([str(folder / "pkg" / "scripts" / "odometer.py")],
                            scan([str(folder)]), package="pkg")
    assert [d.code for d in result.diagnostics] == ["PY_PYTHON2"]
    assert [(c.kind, c.name, c.location.line, c.queue_size_missing)
            for c in result.calls if c.kind == "publish"] == [("publish", "pose2d", 16, True)]


VA_LIST = """
#include <cstdarg>
#include <cstdio>
#include <ros/ros.h>
#include <std_msgs/String.h>
void report(const char * format, ...) {
  char text[64];
  va_list args;
  va_start(args, format);
  vsnprintf(text, sizeof(text), format, args);
  va_end(args);
  std::string topic = "status";
  ros::NodeHandle nh;
  auto pub = nh.advertise<std_msgs::String>(topic, 1);
}
"""


def test_a_va_list_passed_to_a_call_is_no_crash(write_tree) -> None:
    """openni_camera's exception header hands a ``va_list`` (a typedef of an array type)
    to vsnprintf in a function whose names are looked up: the array's element type was
    asked of the typedef, which has none, and the run stopped (turtlebot 3e32933's tree)."""
    root = write_tree({"cam/package.xml": package_xml("cam"), "cam/src/node.cpp": VA_LIST})
    result = extract_cpp([str(root / "cam" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "status")]
