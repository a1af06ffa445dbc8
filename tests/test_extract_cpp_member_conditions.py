"""Source conditions over a member that holds a parameter's value: teleop_twist_joy
reads ``param<bool>("is_3D", pimpl_->is_3D, false)`` and then the 3-D axes only ``if
(pimpl_->is_3D)``. A member whose one write in the unit is the read stands for that
parameter in the condition (``Condition.parameters``, keyed by its text), so the graph
decides it from the configuration's value or the default; a member the unit writes
elsewhere too (a callback) stays undecided. The object's own members (``use_extra_``)
the graph knows by name from the reads that store them (``PrimitiveCall.variable``)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>
struct Impl { bool is_3D; int axis; int vertical; };
class Teleop {
public:
  Teleop(ros::NodeHandle* nh, ros::NodeHandle* nh_param) {
    pimpl_ = new Impl;
    nh_param->param<bool>("is_3D", pimpl_->is_3D, false);
    nh_param->param("use_extra", use_extra_, true);
    nh_param->param("toggled", toggled_, false);
    if (pimpl_->is_3D) {
      nh_param->param<int>("axis_vertical", pimpl_->vertical, 1);
    }
    sub_ = nh->subscribe("toggle", 1, &Teleop::toggle, this);
  }
  void setup(ros::NodeHandle& nh) {
    if (use_extra_) {
      extra_ = nh.advertise<std_msgs::String>("extra", 1);
    }
    if (toggled_) {
      other_ = nh.advertise<std_msgs::String>("other", 1);
    }
  }
  void toggle(const std_msgs::String::ConstPtr&) { toggled_ = !toggled_; }
  Impl* pimpl_;
  bool use_extra_, toggled_;
  ros::Publisher extra_, other_;
  ros::Subscriber sub_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "teleop");
  ros::NodeHandle nh, pnh("~");
  Teleop t(&nh, &pnh);
  t.setup(nh);
  ros::spin();
}
"""


def test_a_member_written_by_one_read_stands_for_its_parameter(write_tree) -> None:
    root = write_tree({"tj/package.xml": package_xml("tj"),
                       "tj/src/teleop.cpp": NODE})
    result = extract_cpp([str(root / "tj" / "src" / "teleop.cpp")], scan([str(root)]),
                         cache_dir=None)
    held = {c.name: [(k.text, k.parameters) for k in c.conditions] for c in result.calls
            if c.name in ("~axis_vertical", "extra", "other")}
    stored = {c.name: c.variable for c in result.calls if c.name == "~use_extra"}
    assert stored == {"~use_extra": "use_extra_"}
    assert held == {
        "~axis_vertical": [("pimpl_->is_3D", (("pimpl_->is_3D", "~is_3D"),))],
        "extra": [("use_extra_", None)],
        "other": [("toggled_", None)],  # the callback writes it too: not the parameter
    }


LIBRARY = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>
struct Impl { bool is_3D; int vertical; };
class Teleop {
public:
  Teleop(ros::NodeHandle* nh, ros::NodeHandle* nh_param);
  Impl* pimpl_;
  ros::Publisher pub_;
};
Teleop::Teleop(ros::NodeHandle* nh, ros::NodeHandle* nh_param) {
  pimpl_ = new Impl;
  nh_param->param<bool>("is_3D", pimpl_->is_3D, false);
  if (pimpl_->is_3D) {
    nh_param->param<int>("axis_vertical", pimpl_->vertical, 1);
  }
}
"""

MAIN = r"""
#include <ros/ros.h>
class Teleop { public: Teleop(ros::NodeHandle* nh, ros::NodeHandle* nh_param); };
int main(int argc, char** argv) {
  ros::init(argc, argv, "teleop");
  ros::NodeHandle nh, pnh("~");
  Teleop t(&nh, &pnh);
  ros::spin();
}
"""


def test_a_member_read_on_a_handle_another_file_passes(write_tree) -> None:
    """The read is on the private handle the node's main file passes: the parameter
    in the condition is named as the read is (``~is_3D``), not left out."""
    root = write_tree({"tj/package.xml": package_xml("tj"),
                       "tj/src/teleop.cpp": LIBRARY, "tj/src/node.cpp": MAIN})
    result = extract_cpp([str(root / "tj" / "src" / "node.cpp"),
                          str(root / "tj" / "src" / "teleop.cpp")], scan([str(root)]),
                         cache_dir=None)
    held = {c.name: [(k.text, k.parameters) for k in c.conditions] for c in result.calls
            if c.name == "~axis_vertical"}
    assert held == {"~axis_vertical": [("pimpl_->is_3D", (("pimpl_->is_3D", "~is_3D"),))]}


def _findings(write_tree, is_3d: str, messages: bool = False) -> list:
    import json

    from haros_arch.cli import main
    root = write_tree({
        "tj/package.xml": package_xml("tj", "catkin"),
        "tj/CMakeLists.txt": ("cmake_minimum_required(VERSION 3.0.2)\nproject(tj)\n"
                              "find_package(catkin REQUIRED COMPONENTS roscpp)\n"
                              "catkin_package()\n"
                              "add_executable(teleop_node src/node.cpp src/teleop.cpp)\n"),
        "tj/src/teleop.cpp": LIBRARY, "tj/src/node.cpp": MAIN,
        "tj/launch/teleop.launch": (
            '<launch><node pkg="tj" type="teleop_node" name="teleop">'
            f'<param name="is_3D" value="{is_3d}"/><param name="axis_vertical" value="2"/>'
            "</node></launch>")})
    out = root / "check.json"
    main(["check", str(root), "--format", "json", "-o", str(out), "--fail-on", "never"])
    return sorted((f["rule"], f["message"] if messages else f["entities"])
                  for f in json.loads(out.read_text())["findings"]
                  if f["rule"].startswith("parameter-set-not-read"))


def test_the_graph_decides_the_condition_from_the_launch_value(write_tree) -> None:
    # is_3D true: axis_vertical is read; false: it is set and never read
    assert _findings(write_tree, "true") == []
    assert _findings(write_tree, "false") == [
        ("parameter-set-not-read", ["parameter:/teleop/axis_vertical"])]


def test_the_finding_names_the_read_its_condition_dropped(write_tree) -> None:
    """"No node reads it" sent the user to code that reads it, under a test the launch
    file makes false (hdl_graph_slam's statistical filter settings with
    ``outlier_removal_method`` NONE, A-LOAM's ``output_bag_file`` with ``to_bag``
    false): the message names that read, its condition and where it is."""
    assert _findings(write_tree, "false", messages=True) == [(
        "parameter-set-not-read",
        "/teleop/axis_vertical is set by the launch file but no node reads it in this "
        "configuration: /teleop reads it only under if (pimpl_->is_3D) "
        "(tj/src/teleop.cpp:13), which does not hold here; similar names that are read: "
        "none")]
