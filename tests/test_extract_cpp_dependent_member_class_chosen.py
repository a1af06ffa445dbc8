"""A member call in a class template on an object whose class the template's arguments
choose: ros_controllers' JointTrajectoryController (noetic) calls
``hw_iface_adapter_.init(joints_, controller_nh_)`` on a ``HardwareInterfaceAdapter<
HardwareInterface, State>``; its specialisations for velocity and effort interfaces (a
closed-loop base) read PID gains and ``velocity_ff/<joint>`` on that handle, those for
position interfaces nothing. clang leaves the call unresolved in the template, which is
what the parse walks: the node was complete with none of those reads (the model rebuilt
lost them). The handle given to code the parse cannot choose makes the node partial."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
#include <ros/ros.h>
#include <vector>
struct PositionIface {};
struct VelocityIface {};
template <class Iface, class State> class Adapter {
public:
  bool init(std::vector<int>& joints, ros::NodeHandle& nh) { return true; }
  void reset() {}
};
template <class State> class ClosedLoop {
public:
  bool init(std::vector<int>& joints, ros::NodeHandle& nh) {
    double ff = 0.0;
    nh.param("velocity_ff/joint1", ff, 0.0);
    return true;
  }
  void reset() {}
};
template <class State> class Adapter<VelocityIface, State> : public ClosedLoop<State> {};
template <class State, class Iface> class Controller {
public:
  typedef Adapter<Iface, State> HwAdapter;
  bool init(ros::NodeHandle& nh) {
    controller_nh_ = nh;
    double rate = 50.0;
    controller_nh_.param("state_publish_rate", rate, 50.0);
    {call}
    return true;
  }
  ros::NodeHandle controller_nh_;
  std::vector<int> joints_;
  HwAdapter adapter_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "controller");
  ros::NodeHandle nh("~");
  Controller<double, VelocityIface> controller;
  controller.init(nh);
  ros::spin();
}
"""


def _extract(write_tree, call: str):
    root = write_tree({
        "ctl/package.xml": package_xml("ctl", "catkin").replace(
            "<export>", "<depend>roscpp</depend><export>"),
        "ctl/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0.2)\nproject(ctl)\n"
                              "find_package(catkin REQUIRED COMPONENTS roscpp)\n"
                              "add_executable(ctl src/ctl.cpp)\n",
        "ctl/src/ctl.cpp": SOURCE.replace("{call}", call),
    })
    ws = scan([str(root)])
    pkg = ws.packages["ctl"]
    pkg.nodes, _ = cmake.parse_package(pkg, ws)
    found = extract_nodes(pkg.nodes, ws, cache_dir=None, jobs=1)
    return pkg.nodes[0], found


def test_a_handle_given_to_a_class_the_template_chooses_leaves_the_node_partial(
        write_tree) -> None:
    node, found = _extract(write_tree, "adapter_.init(joints_, controller_nh_);")
    assert ("read", "~state_publish_rate") in [(c.kind, c.name) for c in node.calls]
    said = [d.message for d in found if d.code == "CPP_NODE_TO_UNKNOWN"]
    assert len(said) == 1 and "init of HwAdapter" in said[0]
    assert node.completeness == "partial"


def test_a_call_that_gives_no_handle_keeps_the_node_whole(write_tree) -> None:
    node, found = _extract(write_tree, "adapter_.reset();")
    assert "CPP_NODE_TO_UNKNOWN" not in [d.code for d in found]
    assert node.completeness == "complete"
