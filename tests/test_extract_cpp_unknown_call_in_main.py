"""An unqualified call in ``main`` of a function whose header is missing: lsd_slam's
live_slam calls ``XInitThreads();`` (<X11/Xlib.h>, not here) before ``ros::init``. Such
names were declared as friends of the permissive class, which only argument-dependent
lookup finds, so that a method's call of an invalid base's member is not hidden; a call
with no permissive argument found none, the statement stayed an error in the function
that makes the node's calls, and the node was partial (CPP_ERROR_NEAR_CALL). ``main`` is no
method, nor is a helper function: their unknown calls are declared at namespace scope. In
a method the friend stays."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

MAIN = """
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <X11/Xlib.h>
#include <GL/glut.h>
int main(int argc, char **argv) {
  XInitThreads();
  glutInit(&argc, argv);
  ros::init(argc, argv, "viewer");
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<std_msgs::String>("status", 1);
  ros::spin();
}
"""

HELPER = """
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <X11/Xlib.h>
static ros::Publisher open_display(ros::NodeHandle &nh) {
  XOpenDisplay(0);
  return nh.advertise<std_msgs::String>("display", 1);
}
int main(int argc, char **argv) {
  ros::init(argc, argv, "viewer");
  ros::NodeHandle nh;
  ros::Publisher pub = open_display(nh);
  ros::spin();
}
"""

METHOD = """
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <vendor/base.h>
class Viewer : public vendor::Base {
 public:
  void start(ros::NodeHandle &nh) {
    refresh();  // the base's, perhaps: no declaration may hide it
    pub_ = nh.advertise<std_msgs::String>("shown", 1);
  }
  ros::Publisher pub_;
};
int main(int argc, char **argv) {
  ros::init(argc, argv, "viewer");
  ros::NodeHandle nh;
  Viewer v;
  v.start(nh);
  ros::spin();
}
"""


def _extract(write_tree, code: str):
    root = write_tree({"v/package.xml": package_xml("v"), "v/src/main.cpp": code})
    return extract_cpp([str(root / "v" / "src" / "main.cpp")], scan([str(root)]),
                       cache_dir=None)


def test_an_unknown_call_in_main_is_declared_at_namespace_scope(write_tree) -> None:
    result = _extract(write_tree, MAIN)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "status")]
    codes = {d.code for d in result.diagnostics}
    assert "CPP_ERROR_NEAR_CALL" not in codes and "CPP_PARSE_ERROR" not in codes
    declared = [d.message for d in result.diagnostics if d.code == "CPP_NAMES_DECLARED"]
    assert declared and "XInitThreads()" in declared[0] and "glutInit()" in declared[0]


def test_so_is_one_in_a_free_helper_function(write_tree) -> None:
    result = _extract(write_tree, HELPER)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "display")]
    assert not [d for d in result.diagnostics if d.code in (
        "CPP_ERROR_NEAR_CALL", "CPP_PARSE_ERROR")]


def test_an_unknown_call_in_a_method_stays_a_friend(write_tree) -> None:
    result = _extract(write_tree, METHOD)
    assert ("publish", "shown") in [(c.kind, c.name) for c in result.calls]
    from haros_arch.extract.cpp import synthesis

    names = synthesis.Names(set(), None, set())
    text = METHOD.encode()
    names.learn([("use of undeclared identifier 'refresh'", text, text.index(b"refresh"))])
    header = names.header()
    assert "friend haros_any &refresh(" in header
    assert not [line for line in header.splitlines()
                if line.startswith("template <class... A> haros_any &refresh(")]


TWICE = """
#include <string>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <ignition/common/StringUtils.hh>
int main(int argc, char **argv) {
  ros::init(argc, argv, "logger");
  ros::NodeHandle nh;
  std::string name = "scan";
  using namespace ignition::common;
  if (EndsWith(name, "/front_scan") ||
      EndsWith(name, "/points")) {
    ros::Publisher pub = nh.advertise<std_msgs::String>("seen", 1);
  }
  ros::spin();
}
"""


def test_a_name_called_twice_in_main_stays_declared(write_tree) -> None:
    """subt 083c6a8's bridge_logger calls ignition-common's ``EndsWith`` (its header
    missing) twice in one condition: the second call made the name a friend as well,
    and a name both free and a friend was declared neither way, so both calls stayed
    errors in the function that advertises (CPP_ERROR_NEAR_CALL, the node partial)."""
    result = _extract(write_tree, TWICE)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "seen")]
    assert not [d for d in result.diagnostics if d.code in (
        "CPP_ERROR_NEAR_CALL", "CPP_PARSE_ERROR")]
