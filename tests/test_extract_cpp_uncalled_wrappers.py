"""A function of the node's files whose ROS call takes its name from a parameter (a
wrapper) runs only where something runs it: when no file of the node calls it nor uses
it otherwise (its address taken, bound as a callback, named by a template's dependent
call), its call is never made and gives nothing, not a read named ``?``. msckf_vio's
image processor compiles utils.cpp, whose ``getTransformEigen(nh, field)`` passes
``field`` to the ``getTransformCV`` the processor calls with its transforms' names; no
file of that node calls ``getTransformEigen``, yet the node read a parameter ``?/?``."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HEADER = """\
#pragma once
#include <string>
#include <ros/ros.h>
namespace cfg {
double readValue(const ros::NodeHandle & nh, const std::string & field);
double readScaled(const ros::NodeHandle & nh, const std::string & field);
double readUnused(const ros::NodeHandle & nh, const std::string & field);
double readPointed(const ros::NodeHandle & nh, const std::string & field);
double readPointed(const ros::NodeHandle & nh, int index);
class Reader {
 public:
  double read(const ros::NodeHandle & nh, const std::string & field);
};
class Base {
 public:
  virtual ~Base() {}
  virtual void setup(const ros::NodeHandle & nh, const std::string & field) = 0;
};
class Impl : public Base {
 public:
  void setup(const ros::NodeHandle & nh, const std::string & field) override;
};
}  // namespace cfg
"""
SOURCE = """\
#include "cfg/config.h"
namespace cfg {
double readValue(const ros::NodeHandle & nh, const std::string & field) {
  double value = 0.0;
  nh.getParam(field, value);
  return value;
}
double readScaled(const ros::NodeHandle & nh, const std::string & field) {
  return 2.0 * readValue(nh, field);
}
double readUnused(const ros::NodeHandle & nh, const std::string & field) {
  double value = 0.0;
  nh.getParam(field, value);
  return value;
}
double readPointed(const ros::NodeHandle & nh, const std::string & field) {
  double value = 0.0;
  nh.getParam(field, value);
  return value;
}
double Reader::read(const ros::NodeHandle & nh, const std::string & field) {
  double value = 0.0;
  nh.getParam(field, value);
  return value;
}
void Impl::setup(const ros::NodeHandle & nh, const std::string & field) {
  int value = 0;
  nh.getParam(field, value);
}
}  // namespace cfg
"""
MAIN = """\
#include "cfg/config.h"
%s
int main(int argc, char ** argv) {
  ros::init(argc, argv, "tracker");
  ros::NodeHandle nh("~");
  double gain = cfg::readValue(nh, "gain");
%s
  return 0;
}
"""
# main's other uses, one per case
POINTER = """\
  double (*reader)(const ros::NodeHandle &, const std::string &) = &cfg::readScaled;
  reader(nh, std::string(argv[1]));"""
# a template whose call depends on its parameter: clang keeps only the overloaded name
TEMPLATE = """\
template <typename T> double run(const ros::NodeHandle & nh, const T & field) {
  return cfg::readPointed(nh, field);
}"""


# a member called on an object whose type depends on a template parameter: unresolved
DEPENDENT = """\
template <typename R> struct User {
  R reader;
  double go(const ros::NodeHandle & nh, const std::string & name) {
    return reader.read(nh, name);
  }
};"""


# a table outside any function
TABLE = """\
typedef double (*Reader)(const ros::NodeHandle &, const std::string &);
static const Reader kReaders[] = {&cfg::readUnused};"""


def _reads(write_tree, uses: str = "", before: str = "") -> list[tuple[str, int]]:
    root = write_tree({"cfg/package.xml": package_xml("cfg", "catkin").replace(
                           "</package>", "<depend>roscpp</depend></package>"),
                       "cfg/include/cfg/config.h": HEADER,
                       "cfg/src/config.cpp": SOURCE,
                       "cfg/src/main.cpp": MAIN % (before, uses)})
    sources = [str(root / "cfg" / "src" / f) for f in ("main.cpp", "config.cpp")]
    result = extract_cpp(sources, scan([str(root)]), cache_dir=None)
    return sorted((c.name, c.location.line) for c in result.calls if c.kind == "read")


def test_a_wrapper_no_file_of_the_node_calls_gives_no_read(write_tree) -> None:
    # readScaled (line 9) passes field on, and nothing calls it: readValue's read is
    # "~gain" alone; readUnused, readPointed and Reader::read are called by nothing.
    # Impl::setup (line 28) overrides a virtual method a host may call: kept unknown
    assert _reads(write_tree) == [("?/?", 28), ("~gain", 5)]


def test_a_wrapper_whose_address_is_taken_keeps_its_unknown_read(write_tree) -> None:
    # readScaled, called through a pointer, passes field on to readValue: unknown
    assert _reads(write_tree, POINTER) == [("?/?", 5), ("?/?", 28), ("~gain", 5)]


def test_a_wrapper_a_template_may_call_keeps_its_unknown_read(write_tree) -> None:
    # main runs the template (one that nothing runs makes no call: extract.cpp._reached)
    reads = _reads(write_tree, "  run(nh, std::string(argv[1]));", TEMPLATE)
    assert [line for _, line in reads if line == 18] == [18]


def test_a_wrapper_a_table_outside_functions_holds_keeps_its_unknown_read(write_tree) -> None:
    reads = _reads(write_tree, "", TABLE)
    assert [line for _, line in reads if line == 13] == [13]  # readUnused's read


def test_a_method_a_dependent_call_may_call_keeps_its_unknown_read(write_tree) -> None:
    reads = _reads(write_tree, "", DEPENDENT)
    assert [line for _, line in reads if line == 23] == [23]  # Reader::read's read


PLUGIN = """\
#include <string>
#include <ros/ros.h>
#include <vendor/plugin_base.h>
class Plugin : public vendor::PluginBase {
 public:
  void configure(const ros::NodeHandle & nh, const std::string & field) {
    int value = 0;
    nh.getParam(field, value);
  }
};
int main(int argc, char ** argv) {
  ros::init(argc, argv, "host");
  return 0;
}
"""


def test_a_method_of_a_class_whose_base_is_unknown_keeps_its_unknown_read(write_tree) -> None:
    """The missing vendor header's ``PluginBase`` may declare ``configure`` virtual: the
    method may override it, and a host may call it."""
    root = write_tree({"host/package.xml": package_xml("host", "catkin").replace(
                           "</package>", "<depend>roscpp</depend></package>"),
                       "host/src/plugin.cpp": PLUGIN})
    result = extract_cpp([str(root / "host" / "src" / "plugin.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [c.location.line for c in result.calls if c.kind == "read"] == [8]
