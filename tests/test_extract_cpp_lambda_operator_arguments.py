"""A lambda called through its variable outside a template (``getP(ns, "takeoff_height",
h)``) is clang's operator call of its ``operator()``, whose arguments list the lambda
object first: each parameter took the argument before its own, so jetyak_uav_utils'
``[](std::string ns, std::string name, double &p) { ros::param::get(ns + name, p); }``
read ``?~`` and none of its 32 parameters per node (64 false parameter-set-not-read).
Now each call site reads its own name; a functor's ``operator()`` likewise."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

NODE = r"""
#include <ros/ros.h>
#include <string>
struct Getter {
  void operator()(const std::string & ns, const std::string & name, int & value) const {
    ros::param::get(ns + name, value);
  }
};
struct Behaviors {
  double height, width;
  void download(std::string ns_param);
};
void Behaviors::download(std::string ns_param) {
  auto getP = [](std::string ns, std::string name, double & param) {
    if (!ros::param::get(ns + name, param)) ROS_WARN("FAILED: %s", name.c_str());
  };
  std::string ns = ns_param;
  getP(ns, "takeoff_height", height);
  getP(ns, "land_width", width);
}
int main(int argc, char ** argv) {
  ros::init(argc, argv, "lam");
  Behaviors b;
  b.download("~");
  Getter get;
  int rate = 0;
  get(std::string("/robot/"), "rate", rate);
}
"""


def test_each_call_of_a_lambda_reads_the_name_its_arguments_make(write_tree):
    root = write_tree({
        "src/lam/package.xml": package_xml("lam", "catkin").replace(
            "</package>", "<depend>roscpp</depend></package>"),
        "src/lam/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0.2)\nproject(lam)\n"
                                  "find_package(catkin REQUIRED COMPONENTS roscpp)\n"
                                  "catkin_package()\nadd_executable(lam src/lam.cpp)\n",
        "src/lam/src/lam.cpp": NODE,
        "project.yaml": "project: p\ndistro: noetic\nconfigurations: {}\n",
    })
    model = analyse(load(str(root / "project.yaml")),
                    {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    node = next(n for p in model.packages for n in p.nodes if n.executable == "lam")
    reads = sorted(c.name for c in node.calls if c.kind == "read")
    assert "~takeoff_height" in reads and "~land_width" in reads, reads
    assert "/robot/rate" in reads, reads
    assert not any(name.startswith("?") for name in reads), reads
