"""A class no file of the node constructs makes no call through a function its constructor
passes its own parameters to: f1tenth's vesc_ackermann library builds two nodelets from
ackermann_to_vesc.cpp and vesc_to_odom.cpp, each constructor hands its NodeHandle to
``getRequiredParam(nh, "speed_to_erpm_gain", x)``; the AckermannToVesc nodelet never
builds a VescToOdom, yet read ``?/speed_to_erpm_gain`` (the handle of a constructor nobody
calls) and ``?/wheelbase``. Calls made directly in such a constructor were already left
out (``made_in``); a function that other callers give known values keeps those."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

# each file defines the same helper, as vesc_ackermann's do (declared before its use)
HELPER = """template <typename T> inline bool required(const ros::NodeHandle& nh, std::string name,
                                           T& value) {
  return nh.getParam(name, value);
}
"""
BUILT = """#include <ros/ros.h>
namespace p {
template <typename T> inline bool required(const ros::NodeHandle& nh, std::string name,
                                           T& value);
class Built { public: Built(ros::NodeHandle nh); double g_; };
Built::Built(ros::NodeHandle nh) { required(nh, "gain", g_); }
""" + HELPER + """}
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  ros::NodeHandle nh("drive");
  p::Built built(nh);
  ros::spin();
}
"""
UNBUILT = """#include <ros/ros.h>
namespace p {
template <typename T> inline bool required(const ros::NodeHandle& nh, std::string name,
                                           T& value);
class Unbuilt { public: Unbuilt(ros::NodeHandle nh); double w_; };
Unbuilt::Unbuilt(ros::NodeHandle nh) { required(nh, "wheelbase", w_); }
""" + HELPER + """}
"""


def test_a_constructor_nobody_calls_passes_no_handle(write_tree) -> None:
    root = write_tree({
        "p/package.xml": package_xml("p", "catkin"),
        "p/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(p)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp)\ncatkin_package()\n"
            "add_executable(n src/built.cpp src/unbuilt.cpp)\n"),
        "p/src/built.cpp": BUILT,
        "p/src/unbuilt.cpp": UNBUILT})
    sources = [str(root / "p" / "src" / name) for name in ("built.cpp", "unbuilt.cpp")]
    result = extract_cpp(sources, scan([str(root)]), cache_dir=None, jobs=1)
    assert sorted({c.name for c in result.calls}) == ["drive/gain"]
    assert "CPP_DYNAMIC_NAME" not in [d.code for d in result.diagnostics]
