"""The test of an ``if`` (or loop, ``switch``) a function-like macro's expansion makes is
read off the macro's ``#define``, each parameter the invocation's argument. The parse
puts such a statement at the macro's name, and its text was the invocation's arguments:
riptide_autonomy's UwrtBtNode.cpp (``INIT_IF_NEEDED(tfListener,
std::make_shared<tf2_ros::TransformListener>(*tfBuffer))``, whose ``#define`` tests
``!variable``) was said to subscribe /tf "only under if (tfListener,
std::make_shared<...>(*tfBuffer))". The ``#define`` read is the one the parse expanded
there, in the source or in a header of the workspace (one of two definitions an
``#ifdef`` chooses between)."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE_CPP = """
#include <ros/ros.h>
#include <std_msgs/String.h>
#define INIT_IF_NEEDED(variable, val) \\
    do { \\
        if(!variable) { \\
            variable = val; \\
        } \\
    } while (0)
#define EACH_TOPIC(count, ...) for (int i = 0; i < count; ++i) { __VA_ARGS__; }
#include "other.h"
ros::Publisher pub;
ros::Subscriber sub;
void cb(const std_msgs::String::ConstPtr & msg) {}
int main(int argc, char ** argv)
{
  ros::init(argc, argv, "node");
  ros::NodeHandle n;
  INIT_IF_NEEDED(pub, n.advertise<std_msgs::String>("out", 1));
  EACH_TOPIC(argc, sub = n.subscribe("in", 1, cb));
  ELSEWHERE(n.subscribe("far", 1, cb));
  GUARDED(argc > 2, n.subscribe("chosen", 1, cb));
  if (argc > 5) { n.subscribe("plain", 1, cb); }
  ros::spin();
}
"""

OTHER_H = """
#define ELSEWHERE(call) if (ros::ok()) { call; }
#ifdef FAST_LOOP
#define GUARDED(test, call) if (test) { call; }
#else
#define GUARDED(test, call) \\
    while (ros::ok() && \\
           (test)) { call; }
#endif
"""


def test_a_macro_s_statement_tests_its_definition_s_text(write_tree) -> None:
    root: Path = write_tree({"drv/package.xml": package_xml("drv"),
                             "drv/src/node.cpp": NODE_CPP, "drv/src/other.h": OTHER_H})
    result = extract_cpp([str(root / "drv" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    found = {c.name: [f"{k.statement} {k.text}" for k in c.conditions]
             for c in result.calls if c.kind in ("subscribe", "publish")}
    # the do-while(0) around it tests 0, as a do written so does
    assert found["out"] == ["do 0", "if !pub"], found
    assert found["in"] == ["for int i = 0; i < argc; ++i"], found
    # defined in a header: read there
    assert found["far"] == ["if ros::ok()"], found
    # the definition the #ifdef keeps, continued lines joined
    assert found["chosen"] == ["while ros::ok() && (argc > 2)"], found
    assert found["plain"] == ["if argc > 5"], found
