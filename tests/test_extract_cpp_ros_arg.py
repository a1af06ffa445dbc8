"""roscpp's ``ros::getROSArg(argc, argv, "robot")`` reads the ``robot:=steel`` word of the
node's command line. roslaunch gives ``args="robot:=steel"`` as such a word, and roscpp
also takes it for a remap nobody uses: survey Z28 found tiago_tutorials' run_loop_node
given it, and remap-unused reported it. The word is the node's argument (the remap is
used), and a name built from its value takes the launch file's."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

NODE = """
#include <ros/ros.h>
#include <std_msgs/String.h>

int main(int argc, char** argv)
{
  std::string model = ros::getROSArg(argc, argv, "robot");
  ros::init(argc, argv, "run_motion");
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<std_msgs::String>("/" + model + "/status", 1);
  ros::spin();
  return 0;
}
"""

LAUNCH = """<launch>
  <node pkg="demo" type="run_loop" name="alive" args="robot:=steel"/>
  <node pkg="demo" type="run_loop" name="other" ns="two" args="colour:=red">
    <remap from="robot" to="titanium"/>
  </node>
</launch>
"""


def test_a_ros_argument_the_code_reads_is_no_unused_remap(write_tree: Any) -> None:
    root: Path = write_tree({
        "src/demo/package.xml": package_xml("demo"),
        "src/demo/CMakeLists.txt": "project(demo)\nfind_package(catkin REQUIRED roscpp)\n"
                                   "add_executable(run_loop src/run_loop.cpp)\n",
        "src/demo/src/run_loop.cpp": NODE,
        "src/demo/launch/demo.launch": LAUNCH,
        "project.yaml": "project: p\ndistro: noetic\n"
                        "configurations:\n  c: [demo/launch/demo.launch]\n",
    })
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    found: dict[str, list[str]] = {}
    for finding in run_catalogue(model, project):
        found.setdefault(finding.rule, []).append(finding.message)
    # only the word the code does not read: robot:=... is its argument (a <remap> too:
    # roslaunch gives both as words of the command line)
    assert [m.split(" ")[0] for m in found["remap-unused"]] == ["colour:=red"]
    assert "remap-unused-undecided" not in found
    # the value names the topic; no parameter is read for it
    topics = sorted(t.name for t in config.topics)
    assert topics == ["/steel/status", "/titanium/status"]
    assert not [p for p in config.parameters if "robot" in p.name]
    (node,) = next(p for p in model.packages if p.name == "demo").nodes
    (read,) = [c for c in node.calls if c.argument]
    assert (read.kind, read.name, read.location.line) == ("read", "robot", 6)
