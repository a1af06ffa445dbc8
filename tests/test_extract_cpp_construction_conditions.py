"""The calls a constructor makes exist where the class is constructed: they carry the
conditions of its construction sites in the file, as a wrapper's calls carry those of
its call site (hector_mapping's HectorDrawings, made only ``if (p_pub_drawings)``,
advertises ``visualization_marker`` in its constructor)."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

DRAWINGS = """
#include <ros/ros.h>
#include <std_msgs/String.h>
class Drawings {
public:
  Drawings()
  {
    ros::NodeHandle nh;
    pub_ = nh.advertise<std_msgs::String>("marker", 1);
  }
private:
  ros::Publisher pub_;
};
"""

NODE = """
#include "drawings.h"
class Mapping {
public:
  Mapping()
  {
    ros::NodeHandle pnh("~");
    pnh.param("pub_drawings", drawings_on_, false);
    pnh.param("levels", levels_, 2);
    if (drawings_on_) {
      drawings_ = new Drawings();
    }
    for (int i = 0; i < levels_; ++i) {
      if (i == 0) {
        first_ = new Level();
      } else {
        other_ = new Level();
      }
    }
  }
private:
  bool drawings_on_;
  int levels_;
  Drawings * drawings_ = nullptr;
  struct Level {
    Level() { ros::NodeHandle nh; pub_ = nh.advertise<std_msgs::String>("level", 1); }
    ros::Publisher pub_;
  };
  Level * first_ = nullptr;
  Level * other_ = nullptr;
};
int main(int argc, char ** argv)
{
  ros::init(argc, argv, "mapping");
  Mapping mapping;
  Drawings * always = nullptr;
  if (argc > 3) {
    always = new Drawings();
  }
}
"""


def _conditions(root: Path, source: str) -> dict[str, list[str]]:
    result = extract_cpp([str(root / "mapping" / "src" / source)], scan([str(root)]),
                         cache_dir=None)
    return {c.name: [f"{k.statement} {k.text}" for k in c.conditions]
            for c in result.calls if c.kind == "publish"}


def test_a_constructor_s_calls_carry_its_construction_s_conditions(write_tree) -> None:
    root = write_tree({"mapping/package.xml": package_xml("mapping"),
                       "mapping/src/drawings.h": DRAWINGS,
                       "mapping/src/mapping.cpp": NODE,
                       "mapping/src/alone.cpp": '#include "drawings.h"\n'})
    found = _conditions(root, "mapping.cpp")
    # made under two different conditions: none of them is the constructor's; made
    # under two branches of one loop: the loop's is
    assert found["marker"] == []
    assert found["level"] == ["for int i = 0; i < levels_; ++i"]
    # a file that constructs the class nowhere: its calls as they are
    assert _conditions(root, "alone.cpp") == {"marker": []}


def test_the_one_construction_s_condition(write_tree) -> None:
    root = write_tree({"mapping/package.xml": package_xml("mapping"),
                       "mapping/src/drawings.h": DRAWINGS,
                       "mapping/src/mapping.cpp": NODE.replace(
                           "    always = new Drawings();\n", "")})
    assert _conditions(root, "mapping.cpp")["marker"] == ["if drawings_on_"]
