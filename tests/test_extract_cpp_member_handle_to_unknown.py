"""A ROS 1 class that reads its parameters through a helper of a library whose header
is missing, giving it a handle it holds as a member (rpg_quadrotor_control 22b55b0:
sbus_bridge's ``loadParameters`` expands ``GET_PARAM(mass)`` to
``if (!quadrotor_common::getParam("mass", mass_, pnh_)) return false``; the header is
rpg_quadrotor_common's). The method makes no ROS API call by name, so no name was
declared and the statements stayed errors, and only a parameter or local of a node type
counted as the node given: the node was 'complete', and every parameter its launch file
sets was reported as set and never read (19 false findings). A member handle given to an
unknown name, written in the statement or in the file's macro it invokes, makes the node
partial (CPP_NODE_TO_UNKNOWN); a member that is no handle does not."""

from __future__ import annotations

import os
from typing import Any

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

SOURCE = """\
#include <string>
#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <quadrotor_common/parameter_helper.h>
class Bridge {
 public:
  Bridge(const ros::NodeHandle& nh, const ros::NodeHandle& pnh) : nh_(nh), pnh_(pnh) {
    if (!loadParameters()) ROS_ERROR("no parameters");
    pub_ = nh_.advertise<std_msgs::Bool>("armed", 1);
  }
  bool loadParameters();
 private:
  ros::NodeHandle nh_, pnh_;
  ros::Publisher pub_;
  std::string port_name_;
  double mass_;
};
bool Bridge::loadParameters() {
#define GET_PARAM(name) \\
  if (!quadrotor_common::getParam(#name, name##_, pnh_)) return false
  READS
  return true;
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "bridge");
  Bridge bridge(ros::NodeHandle(), ros::NodeHandle("~"));
  ros::spin();
}
"""


def _node(write_tree: Any, reads: str) -> Any:
    root = write_tree({
        "src/b/package.xml": package_xml("b"),
        "src/b/CMakeLists.txt": "project(b)\nadd_executable(bridge src/bridge.cpp)\n",
        "src/b/src/bridge.cpp": SOURCE.replace("READS", reads),
        "project.yaml": "project: p\nworkspace: [src]\ndistro: noetic\nconfigurations: {}\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    return next(n for p in model.packages for n in p.nodes if n.name == "b/bridge")


def test_a_member_handle_given_through_the_files_macro(write_tree: Any) -> None:
    node = _node(write_tree, "GET_PARAM(port_name);\n  GET_PARAM(mass);")
    assert node.completeness == "partial", node.completeness_reasons
    assert any("the node (pnh_) is given to quadrotor_common," in r
               for r in node.completeness_reasons), node.completeness_reasons


def test_a_member_handle_given_in_the_statement(write_tree: Any) -> None:
    node = _node(write_tree, 'quadrotor_common::getParam("mass", mass_, pnh_);')
    assert node.completeness == "partial", node.completeness_reasons
    assert any("the node (pnh_) is given to quadrotor_common::getParam," in r
               for r in node.completeness_reasons), node.completeness_reasons


def test_a_member_that_is_no_handle_is_no_such_place(write_tree: Any) -> None:
    node = _node(write_tree, "quadrotor_common::check(mass_, port_name_);")
    assert not any("is given to" in r for r in node.completeness_reasons), (
        node.completeness_reasons)


def test_the_handle_given_inside_a_macro_is_said_as_written(write_tree: Any) -> None:
    """Once a call of the unknown helper outside the macro makes the parse declare it,
    the macro's calls resolve and the handle is read from the expansion: its tokens
    then ran from the macro's definition to the place it is invoked (sbus_bridge: "the
    node (pnh_))returnfalseGET_PARAM(port_name)) is given to ..."). The argument as
    written in the macro is said."""
    global SOURCE
    kept = SOURCE
    SOURCE = SOURCE.replace(
        "pub_ = nh_.advertise",
        'quadrotor_common::getParam("rate", mass_, pnh_);\n    pub_ = nh_.advertise')
    try:
        node = _node(write_tree, "GET_PARAM(port_name);\n  GET_PARAM(mass);")
    finally:
        SOURCE = kept
    given = [r.split(": ", 1)[1] for r in node.completeness_reasons if "is given to" in r]
    assert given == ["the node (pnh_) is given to quadrotor_common::getParam, which the "
                     "parse does not know"] * 3, node.completeness_reasons
