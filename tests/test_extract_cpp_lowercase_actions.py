"""ROS 1 actions may be named in lowercase, as messages may (industrial_calibration's
``action/manual_trigger.action``): genaction's headers ``<pkg/manual_triggerAction.h>``,
``<pkg/manual_triggerGoal.h>``, ... are synthesised from the package's ``action/`` file,
not replaced by an empty stand-in that leaves the action client's type unknown and
takes the goal for a class of another package whose code is not read (the node was
said partial)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <ros/ros.h>
#include <actionlib/client/simple_action_client.h>
#include <cal/manual_triggerAction.h>
#include <cal/helpers.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "asker");
  ros::NodeHandle nh;
  actionlib::SimpleActionClient<cal::manual_triggerAction> client(nh, "manual_trigger", true);
  client.waitForServer();
  cal::manual_triggerGoal goal;
  goal.display_message = "go";
  client.sendGoal(goal);
  ros::Publisher pub = nh.advertise<cal::manual_triggerFeedback>("progress", helpers::depth());
  ros::spin();
  return 0;
}
"""


def _tree(write_tree):
    return write_tree({
        "cal/package.xml": package_xml("cal", "catkin"),
        "cal/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(cal)\n"
            "find_package(catkin REQUIRED COMPONENTS actionlib actionlib_msgs\n"
            "  message_generation)\n"
            "add_action_files(DIRECTORY action FILES manual_trigger.action)\n"
            "generate_messages(DEPENDENCIES actionlib_msgs)\ncatkin_package()\n"),
        "cal/action/manual_trigger.action": (
            "string display_message\n---\nuint32 result\n---\nfloat32 percent_complete\n"),
        "cal/include/cal/helpers.h": "namespace helpers { inline int depth() { return 3; } }\n",
        "tool/package.xml": package_xml("tool", "catkin"),
        "tool/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(tool)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp actionlib cal)\n"
            "catkin_package()\nadd_executable(asker src/asker.cpp)\n"),
        "tool/src/asker.cpp": SOURCE})


def test_lowercase_action_headers_are_synthesised(write_tree) -> None:
    root = _tree(write_tree)
    result = extract_cpp([str(root / "tool" / "src" / "asker.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    calls = [(c.kind, c.name, c.type) for c in result.calls]
    assert ("action-client", "manual_trigger", "cal/manual_trigger") in calls, calls
    assert ("publish", "progress", "cal/manual_triggerFeedback") in calls, calls
    codes = [d.code for d in result.diagnostics]
    assert "CPP_INCLUDE_MISSING" not in codes
    assert "CPP_CLASS_UNSEEN" not in codes
    assert "CPP_PARSE_ERROR" not in codes and "CPP_ERROR_NEAR_CALL" not in codes


def test_a_lowercase_header_that_is_no_action_part_stays_the_package_s(write_tree) -> None:
    """``<cal/helpers.h>`` is the package's own header, though ``cal`` has actions."""
    root = _tree(write_tree)
    result = extract_cpp([str(root / "tool" / "src" / "asker.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert not [d for d in result.diagnostics if "helpers" in d.message]
