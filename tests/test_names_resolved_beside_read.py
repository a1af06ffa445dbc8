"""A name the code resolves (``resolveName``) and a parameter it reads under the same
name at the same call site are two calls: swri_roscpp's ``swri::getParam(nh, name, var)``
(marti_common, parameters.h) records ``nh.resolveName(name)`` in its set of used
parameters and then reads ``nh.getParam(name, var)``; both are made where the wrapper
is called. They were kept as one call, the resolved name (no link), so the read was
lost: param_example.launch's ``used_*`` parameters were all reported set and never read
(12 parameter-set-not-read warnings, of which only the four ``unused_*`` are true)."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

HEADER = """
#include <ros/ros.h>
#include <set>
#include <string>
namespace util {
static std::set<std::string> used;
static inline bool getParam(const ros::NodeHandle& nh, const std::string& name, int& value) {
  std::string resolved = nh.resolveName(name);
  used.insert(resolved);
  if (!nh.getParam(name, value)) {
    return false;
  }
  return true;
}
static inline void param(const ros::NodeHandle& nh, const std::string& name, double& value,
                         double fallback) {
  used.insert(nh.resolveName(name));
  nh.param(name, value, fallback);
}
}  // namespace util
"""

NODE = """
#include <ros/ros.h>
#include <util/parameters.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "example");
  ros::NodeHandle pnh("~");
  int count;
  util::getParam(pnh, "used_int", count);
  double rate;
  util::param(pnh, "used_double", rate, 2.0);
  return 0;
}
"""

LAUNCH = """<launch>
  <node pkg="util" type="example" name="example">
    <rosparam>
    used_int: 1
    used_double: 1.0
    unused_int: 0
    </rosparam>
  </node>
</launch>
"""


def test_a_read_beside_a_resolved_name_is_kept(write_tree: Any) -> None:
    root: Path = write_tree({
        "src/util/package.xml": package_xml("util"),
        "src/util/CMakeLists.txt": "project(util)\nfind_package(catkin REQUIRED roscpp)\n"
                                   "include_directories(include)\n"
                                   "add_executable(example src/example.cpp)\n",
        "src/util/include/util/parameters.h": HEADER,
        "src/util/src/example.cpp": NODE,
        "src/util/launch/example.launch": LAUNCH,
        "project.yaml": "project: p\ndistro: noetic\n"
                        "configurations:\n  c: [util/launch/example.launch]\n",
    })
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None, jobs=1))
    (node,) = next(p for p in model.packages if p.name == "util").nodes
    assert sorted((c.name, c.resolved) for c in node.calls) == [
        ("~used_double", False), ("~used_double", True),
        ("~used_int", False), ("~used_int", True)]
    (config,) = model.configurations
    read = {p.name for p in config.parameters if p.readers}
    assert read == {"/example/used_int", "/example/used_double"}
    unread = [f.message.split(" ")[0] for f in run_catalogue(model, project)
              if f.rule == "parameter-set-not-read"]
    assert unread == ["/example/unused_int"]
