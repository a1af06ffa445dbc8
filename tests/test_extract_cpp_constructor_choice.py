"""A member that the class's constructors initialise differently holds the value of the
constructor the node's code calls (slam_gmapping: ``SlamGMapping()`` leaves ``node_``
the default handle, ``SlamGMapping(nh, pnh)`` takes the nodelet's): each call that
reads it is made once per constructor and kept where a file of the node calls that
constructor; a default constructor's where none is called (a loader makes the class);
every one where the file itself constructs the class by several."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """
#include <ros/ros.h>
#include <std_msgs/String.h>
class Mapper {
public:
  Mapper();
  Mapper(ros::NodeHandle & nh, ros::NodeHandle & pnh);
  explicit Mapper(int seed);
  void start();
private:
  ros::NodeHandle node_;
  ros::NodeHandle private_nh_;
  ros::Publisher map_pub_;
  int seed_;
};
"""

MAPPER = """
#include "mapper.h"
Mapper::Mapper() : private_nh_("~"), seed_(0) {}
Mapper::Mapper(ros::NodeHandle & nh, ros::NodeHandle & pnh)
: node_(nh), private_nh_(pnh), seed_(0) {}
Mapper::Mapper(int seed) : private_nh_("~"), seed_(seed) {}
void Mapper::start()
{
  int throttle;
  private_nh_.param("throttle", throttle, 1);
  map_pub_ = node_.advertise<std_msgs::String>("map", 1);
}
"""

MAIN = """
#include "mapper.h"
int main(int argc, char ** argv)
{
  ros::init(argc, argv, "mapper");
  Mapper m;
  m.start();
}
"""

REPLAY = """
#include "mapper.h"
int main(int argc, char ** argv)
{
  ros::init(argc, argv, "replay");
  Mapper m(7);
  m.start();
}
"""

NODELET = """
#include "mapper.h"
void load()
{
  ros::NodeHandle nh("robot");
  ros::NodeHandle pnh("robot/mapper");
  Mapper * m = new Mapper(nh, pnh);
  m->start();
}
"""

BOTH = """
#include "mapper.h"
void Mapper::start()
{
  map_pub_ = node_.advertise<std_msgs::String>("map", 1);
}
Mapper::Mapper() {}
Mapper::Mapper(ros::NodeHandle & nh, ros::NodeHandle & pnh) : node_(nh), private_nh_(pnh) {}
int main(int argc, char ** argv)
{
  ros::init(argc, argv, "both");
  ros::NodeHandle nh("left");
  Mapper a;
  Mapper b(nh, nh);
  a.start();
  b.start();
}
"""


def _names(root: Path, *files: str) -> list[tuple[str, str]]:
    result = extract_cpp([str(root / "mapper" / "src" / f) for f in files],
                         scan([str(root)]), cache_dir=None)
    return [(c.kind, c.name) for c in result.calls]


def _tree(write_tree) -> Path:
    return write_tree({
        "mapper/package.xml": package_xml("mapper"),
        "mapper/src/mapper.h": HEADER,
        "mapper/src/mapper.cpp": MAPPER,
        "mapper/src/main.cpp": MAIN,
        "mapper/src/replay.cpp": REPLAY,
        "mapper/src/nodelet.cpp": NODELET,
        "mapper/src/both.cpp": BOTH,
    })


def test_the_constructor_the_node_calls_chooses_the_member(write_tree) -> None:
    root = _tree(write_tree)
    # Mapper(): node_ the node's own handle, private_nh_ "~" (not the "?" of the
    # constructor that takes the handles, which no file of this node calls)
    assert _names(root, "main.cpp", "mapper.cpp") == [
        ("read", "~throttle"), ("publish", "map")]
    # Mapper(int) leaves node_ as Mapper() does
    assert _names(root, "replay.cpp", "mapper.cpp") == [
        ("read", "~throttle"), ("publish", "map")]
    # Mapper(nh, pnh): the handles the construction gives
    assert _names(root, "nodelet.cpp", "mapper.cpp") == [
        ("read", "robot/mapper/throttle"), ("publish", "robot/map")]


def test_a_class_no_file_constructs_takes_its_default_constructor(write_tree) -> None:
    """A nodelet or plugin class: its loader calls the constructor without arguments."""
    root = _tree(write_tree)
    assert _names(root, "mapper.cpp") == [("read", "~throttle"), ("publish", "map")]


def test_a_file_that_constructs_by_both_keeps_both(write_tree) -> None:
    root = _tree(write_tree)
    assert sorted(_names(root, "both.cpp")) == [("publish", "left/map"), ("publish", "map")]
