"""A virtual method given a handle by its base class's code takes that handle in the
class that overrides it: costmap_2d's ``ObstacleLayer::onInitialize`` (obstacle_layer.cpp)
makes ``NodeHandle nh("~/" + name_)`` and calls ``setupDynamicReconfigure(nh)``, which
``VoxelLayer`` overrides (voxel_layer.cpp) to serve its VoxelPlugin config there. The
override's handle was not known (``?``), so its reads were of ``?/z_voxels``, and
turtlebot_navigation's ``obstacle_layer/z_voxels`` (origin_z, z_resolution,
unknown_threshold, mark_threshold) was "set but never read"."""

from __future__ import annotations

import pytest
from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

BASE_H = """#pragma once
#include <ros/ros.h>
#include <string>

class Base {
public:
  Base() {}
  virtual ~Base() {}
  void initialize(const std::string& name);
protected:
  virtual void setup(ros::NodeHandle& nh);
  std::string name_;
  bool enabled_;
  double x_;
};

class Derived : public Base {
protected:
  void setup(ros::NodeHandle& nh) override;
  int z_;
};
"""

BASE_CPP = """#include "vo/base.h"
void Base::initialize(const std::string& name) {
  name_ = name;
  ros::NodeHandle nh("~/" + name_);
  nh.param("enabled", enabled_, true);
  setup(nh);
}
void Base::setup(ros::NodeHandle& nh) { nh.param("base_only", x_, 1.0); }
"""

DERIVED_CPP = """#include "vo/base.h"
void Derived::setup(ros::NodeHandle& nh) {
  nh.param("z_voxels", z_, 10);
  Base::setup(nh);
}
"""

MAIN_CPP = """#include "vo/base.h"
int main(int argc, char** argv) {
  ros::init(argc, argv, "vo");
  Derived d;
  d.initialize("layer");
  ros::spin();
  return 0;
}
"""


@pytest.mark.parametrize("one_file", [True, False])
def test_an_override_takes_the_handle_its_base_passes(write_tree, one_file):
    files = {"src/vo/src/base.cpp": BASE_CPP, "src/vo/src/derived.cpp": DERIVED_CPP,
             "src/vo/src/main.cpp": MAIN_CPP}
    if one_file:
        files = {"src/vo/src/main.cpp": "\n".join(
            text.replace('#include "vo/base.h"', "") for text in files.values())}
    sources = " ".join(f.split("/", 2)[2] for f in files)
    root = write_tree({
        **files,
        "src/vo/include/vo/base.h": BASE_H,
        "src/vo/package.xml": package_xml("vo").replace(
            "</package>", "<depend>roscpp</depend></package>"),
        "src/vo/CMakeLists.txt": ("project(vo)\nfind_package(catkin REQUIRED)\n"
                                  "catkin_package()\ninclude_directories(include)\n"
                                  f"add_executable(vo {sources})\n"),
        "src/vo/launch/vo.launch": "<launch><node pkg='vo' type='vo' name='vo'/></launch>",
        "project.yaml": "project: p\ndistro: noetic\nworkspace: src\nconfigurations:\n"
                        "  c: [vo/launch/vo.launch]\n",
    })
    if one_file:
        (root / "src/vo/src/main.cpp").write_text(
            '#include "vo/base.h"\n' + (root / "src/vo/src/main.cpp").read_text())
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    reads = sorted(link.name for link in config.links if link.kind == "read")
    assert reads == ["/vo/layer/base_only", "/vo/layer/enabled", "/vo/layer/z_voxels"], reads
