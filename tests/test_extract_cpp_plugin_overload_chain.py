"""A plugin whose method the host calls through the base class hands the plugin's name
to an overload that makes every call: navfn's ``NavfnROS::initialize(name,
costmap_ros)`` calls ``initialize(name, costmap, frame)``, which makes ``~<name>/plan``
and reads ``~<name>/allow_unknown``. The overriding method is called in the plugin's
own file too, by a constructor the host never runs, so its name took that constructor's
value alone and the plugin node had no call at all (the noetic navfn model's
``navfn/NavfnROS``: 0 calls; every ROS 1 robot that loads navfn had its NavfnROS
parameters "set but never read"). A program that builds the class with a name keeps that
name alone."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp_nodes
from haros_arch.workspace import scan

BASE = """#pragma once
#include <string>
namespace base_pkg {
struct Map { int x; };
struct MapROS { Map* get() { return &m; } std::string frame() { return "map"; } Map m; };
class BasePlanner {
public:
  virtual void initialize(std::string name, MapROS* map) = 0;
  virtual ~BasePlanner() {}
protected:
  BasePlanner() {}
};
}
"""

HEADER = """#pragma once
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <base_pkg/base.h>
namespace plug {
class Planner : public base_pkg::BasePlanner {
public:
  Planner();
  Planner(std::string name, base_pkg::MapROS* map);
  void initialize(std::string name, base_pkg::MapROS* map);
  void initialize(std::string name, base_pkg::Map* map, std::string frame);
private:
  bool initialized_;
  bool allow_unknown_;
  ros::Publisher plan_pub_;
};
}
"""

SOURCE = """#include <plug/planner.h>
#include <pluginlib/class_list_macros.hpp>
PLUGINLIB_EXPORT_CLASS(plug::Planner, base_pkg::BasePlanner)
namespace plug {
Planner::Planner() : initialized_(false), allow_unknown_(true) {}
Planner::Planner(std::string name, base_pkg::MapROS* map)
  : initialized_(false), allow_unknown_(true) {
  initialize(name, map);
}
void Planner::initialize(std::string name, base_pkg::Map* map, std::string frame) {
  if (!initialized_) {
    ros::NodeHandle private_nh("~/" + name);
    plan_pub_ = private_nh.advertise<std_msgs::String>("plan", 1);
    private_nh.param("allow_unknown", allow_unknown_, true);
    initialized_ = true;
  }
}
void Planner::initialize(std::string name, base_pkg::MapROS* map) {
  initialize(name, map->get(), map->frame());
}
}
"""

MAIN = """#include <plug/planner.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "planner_node");
  base_pkg::MapROS map;
  plug::Planner planner("my_planner", &map);
  ros::spin();
  return 0;
}
"""


def test_the_host_s_name_reaches_the_overload_that_makes_the_calls(tmp_path: Path):
    base = tmp_path / "base_pkg"
    (base / "include" / "base_pkg").mkdir(parents=True)
    (base / "package.xml").write_text(
        '<package format="2"><name>base_pkg</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>BSD</license><depend>roscpp</depend></package>\n')
    (base / "include" / "base_pkg" / "base.h").write_text(BASE)
    package = tmp_path / "plug"
    (package / "src").mkdir(parents=True)
    (package / "include" / "plug").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="2"><name>plug</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>BSD</license><depend>roscpp</depend><depend>base_pkg</depend>'
        '</package>\n')
    (package / "include" / "plug" / "planner.h").write_text(HEADER)
    (package / "src" / "planner.cpp").write_text(SOURCE)
    (package / "src" / "main.cpp").write_text(MAIN)
    src = package / "src"
    batch = extract_cpp_nodes([[str(src / "planner.cpp")],
                               [str(src / "main.cpp"), str(src / "planner.cpp")]],
                              scan([str(tmp_path)]), cache_dir=None, jobs=1,
                              entries=["plug::Planner", None])
    plugin, program = ([(c.kind, c.name) for c in r.calls] for r in batch.results)
    # the plugin: named by its host
    assert sorted(plugin) == [("publish", "~?/plan"), ("read", "~?/allow_unknown")]
    # the program: the name it builds the class with, and no call of the host's
    assert sorted(program) == [("publish", "~my_planner/plan"),
                               ("read", "~my_planner/allow_unknown")]
