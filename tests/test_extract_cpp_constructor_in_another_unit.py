"""A node whose files build a class through a constructor another file of the node
defines: voxblox's esdf_server_node.cc builds ``EsdfServer(nh, nh_private)``, defined in
esdf_server.cc, whose class derives from TsdfServer; tsdf_server.cc (linked for the
library) also defines ``TsdfServer(nh, nh_private)``, which only the tsdf_server node
calls. The unit that builds the object without its constructor's code took every word of
the class's declaration, the base's name too, for code it cannot see; the node then kept
what TsdfServer's unused constructor passes on, as ``?`` (74 ``?/...`` calls in the
esdf_server node beside the same calls named ``~...``; 72 are now gone: two reads that an
inline helper makes, called once from that constructor, stay). Another unit of the node that
has the constructor's code shows what it builds. A derived class's code in its own file
calls on a handle member of the base that the base's constructor, in another file, sets
(voxblox's EsdfServer publishes on TsdfServer's ``nh_private_``): the handle is what
that constructor gives it for the node, not the default handle (``esdf_pointcloud``
was read in the node's namespace instead of its private one)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """#include <ros/ros.h>
#include <std_msgs/String.h>
namespace m {
inline double readSize(const ros::NodeHandle& pnh) {
  double size = 0.1;
  pnh.param("size", size, size);
  return size;
}
inline int readDepth(const ros::NodeHandle& pnh) {
  int depth = 4;
  pnh.param("depth", depth, depth);
  return depth;
}
class Base {
 public:
  Base(const ros::NodeHandle& nh, const ros::NodeHandle& pnh);
  Base(const ros::NodeHandle& nh, const ros::NodeHandle& pnh, double size, int depth);
  ros::NodeHandle nh_, pnh_;
  ros::Publisher map_pub_;
  ros::Subscriber cloud_sub_;
  double size_;
};
class Derived : public Base {
 public:
  Derived(const ros::NodeHandle& nh, const ros::NodeHandle& pnh);
  ros::Publisher slice_pub_;
};
}  // namespace m
"""
BASE = """#include "m/server.h"
namespace m {
Base::Base(const ros::NodeHandle& nh, const ros::NodeHandle& pnh)
    : Base(nh, pnh, readSize(pnh), readDepth(pnh)) {}
Base::Base(const ros::NodeHandle& nh, const ros::NodeHandle& pnh, double size, int depth)
    : nh_(nh), pnh_(pnh), size_(size) {
  map_pub_ = pnh_.advertise<std_msgs::String>("map", 1, true);
  cloud_sub_ = nh_.subscribe("cloud", 1, &Base::onCloud, this);
}
}  // namespace m
"""
DERIVED = """#include "m/server.h"
namespace m {
Derived::Derived(const ros::NodeHandle& nh, const ros::NodeHandle& pnh)
    : Base(nh, pnh, readSize(pnh), 8) {
  slice_pub_ = pnh_.advertise<std_msgs::String>("slice", 1);
}
}  // namespace m
"""
NODE = """#include "m/server.h"
int main(int argc, char** argv) {
  ros::init(argc, argv, "derived");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  m::Derived server(nh, pnh);
  ros::spin();
  return 0;
}
"""


def _calls(write_tree) -> list[tuple[str, str]]:
    root = write_tree({
        "m/package.xml": package_xml("m", "catkin"),
        "m/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(m)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)\ncatkin_package()\n"
            "include_directories(include)\n"
            "add_library(m src/base.cpp src/derived.cpp)\n"
            "add_executable(derived_node src/node.cpp)\n"
            "target_link_libraries(derived_node m)\n"),
        "m/include/m/server.h": HEADER.replace(
            "  double size_;\n", "  void onCloud(const std_msgs::String::ConstPtr& msg) {}\n"
            "  double size_;\n"),
        "m/src/base.cpp": BASE,
        "m/src/derived.cpp": DERIVED,
        "m/src/node.cpp": NODE})
    sources = [str(root / "m" / "src" / name) for name in ("node.cpp", "base.cpp",
                                                           "derived.cpp")]
    result = extract_cpp(sources, scan([str(root)]), cache_dir=None, jobs=1)
    return sorted({(c.kind, c.name) for c in result.calls})


def test_a_constructor_another_unit_defines_shows_what_it_builds(write_tree) -> None:
    calls = _calls(write_tree)
    # what Base's two-handle constructor, which no file of the node calls, passes to the
    # other one is never made: no call on an unknown handle
    assert ("publish", "?/map") not in calls and ("subscribe", "?/cloud") not in calls
    assert ("publish", "~map") in calls and ("subscribe", "cloud") in calls


def test_a_base_handle_member_set_in_another_unit_is_what_it_sets(write_tree) -> None:
    calls = _calls(write_tree)
    assert ("publish", "~slice") in calls and ("publish", "slice") not in calls
