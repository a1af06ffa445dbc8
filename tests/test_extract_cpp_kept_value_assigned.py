"""A ROS 1 ``getParam(name, v)`` leaves ``v`` as it was when the parameter is not
there: a local declared bare and assigned before the read, whatever runs, holds a
default (base_local_planner's ``double backup_vel; ... backup_vel = -0.1; getParam(
"backup_vel", backup_vel); getParam("escape_vel", backup_vel);``). Only an initialiser
counted, so ``escape_vel`` was "read but never set" in every ROS 1 configuration that
loads TrajectoryPlannerROS without it. A local first written after the read holds
nothing then."""

from __future__ import annotations

import textwrap

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

NODE = """
    #include <ros/ros.h>
    int main(int argc, char** argv) {
      ros::init(argc, argv, "kv");
      ros::NodeHandle nh("~");
      double backup_vel;
      backup_vel = -0.1;
      if (nh.getParam("backup_vel", backup_vel))
        ROS_WARN("deprecated");
      nh.getParam("escape_vel", backup_vel);
      int count;
      if (argc > 1)
        count = 3;
      nh.getParam("count", count);
      double late;
      nh.getParam("late", late);
      late = 2.0;
      ros::spin();
      return 0;
    }
    """


def test_a_local_assigned_before_the_read_holds_a_default(write_tree):
    root = write_tree({
        "src/kv/package.xml": package_xml("kv").replace(
            "</package>", "<depend>roscpp</depend></package>"),
        "src/kv/CMakeLists.txt": ("project(kv)\nfind_package(catkin REQUIRED)\n"
                                  "catkin_package()\nadd_executable(kv src/kv.cpp)\n"),
        "src/kv/src/kv.cpp": textwrap.dedent(NODE),
        "src/kv/launch/kv.launch": "<launch><node pkg='kv' type='kv' name='kv'/></launch>",
        "project.yaml": "project: p\ndistro: noetic\nworkspace: src\nconfigurations:\n"
                        "  c: [kv/launch/kv.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    held = {c.name: c.has_default for n in model.nodes for c in n.calls if c.kind == "read"}
    # escape_vel: assigned first; count: only in a branch; late: only after the read
    assert held == {"~backup_vel": True, "~escape_vel": True, "~count": False,
                    "~late": False}
    unset = sorted(f.entities[0] for f in run_catalogue(model)
                   if f.rule == "parameter-read-not-set")
    assert unset == ["parameter:/kv/count", "parameter:/kv/late"]
