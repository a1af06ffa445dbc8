"""A condition over a global variable of the node's source file that one parameter read
writes (VINS-Mono's ar_demo: ``n.getParam("use_undistored_img", USE_UNDISTORED_IMG);
if (USE_UNDISTORED_IMG) sub = n.subscribe("image_undistored", ...); else
sub = n.subscribe("image_raw", ...)``) is decided per instance, as one over a member is:
the launch file's false drops the first subscription (it was a subscriber-without-publisher
warning on a topic the node never subscribes there). A global written again, or one a
header declares (another file may write it), decides nothing."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import scan

NODE = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include "ar/flags.h"

bool USE_UNDISTORTED;
bool COUNTED = false;

void cb(const std_msgs::String::ConstPtr& msg) {}

int main(int argc, char** argv) {
  ros::init(argc, argv, "ar");
  ros::NodeHandle n("~");
  n.getParam("use_undistorted", USE_UNDISTORTED);
  ros::Subscriber sub;
  if (USE_UNDISTORTED)
    sub = n.subscribe("image_undistorted", 100, cb);
  else
    sub = n.subscribe("image_raw", 100, cb);
  n.param("counted", COUNTED, false);
  COUNTED = !COUNTED;
  ros::Publisher count, header;
  if (COUNTED) count = n.advertise<std_msgs::String>("count", 1);
  n.param("from_header", FROM_HEADER, false);
  if (FROM_HEADER) header = n.advertise<std_msgs::String>("header_flag", 1);
  ros::spin();
  return 0;
}
"""

LAUNCH = """<launch>
  <node pkg="ar" type="ar" name="ar">
    <param name="use_undistorted" type="bool" value="false"/>
  </node>
</launch>
"""


def _tree(write_tree):
    return write_tree({
        "src/ar/package.xml": package_xml("ar"),
        "src/ar/CMakeLists.txt": "project(ar)\nadd_executable(ar src/ar.cpp)\n",
        "src/ar/include/ar/flags.h": "extern bool FROM_HEADER;\n",
        "src/ar/src/ar.cpp": NODE,
        "src/ar/launch/ar.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [ar/launch/ar.launch]\n",
    })


def test_the_extractor_names_the_global_a_read_stores_into(write_tree) -> None:
    root = _tree(write_tree)
    result = extract_cpp([str(root / "src/ar/src/ar.cpp")], scan([str(root)]), cache_dir=None)
    stored = {c.name: c.variable for c in result.calls if c.kind == "read"}
    assert stored == {"~use_undistorted": "USE_UNDISTORTED", "~counted": None,
                      "~from_header": None}


def test_a_condition_over_such_a_global_is_decided(write_tree) -> None:
    root = _tree(write_tree)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    config = model.configuration("c")
    links = {(link.kind, link.rosname.full): [c.text for c in link.conditions]
             for link in config.links if link.kind in ("subscribe", "publish")}
    assert ("subscribe", "/ar/image_undistorted") not in links
    assert links[("subscribe", "/ar/image_raw")] == []
    assert links[("publish", "/ar/count")] == ["COUNTED"]
    assert links[("publish", "/ar/header_flag")] == ["FROM_HEADER"]
