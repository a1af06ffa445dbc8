"""A ROS 1 nodelet's own handles and the handles its code constructs.

nodelet's ``Nodelet::init`` makes the handles ``getNodeHandle()`` and
``getPrivateNodeHandle()`` give (and their MT twins) in the nodelet's namespace, with the
remaps it was loaded with. A ``ros::NodeHandle`` the nodelet's code constructs is roscpp's
handle of the process: loaded into a manager, it resolves in the manager's namespace, ``~``
is the manager's private namespace, and the manager's remaps apply, not the nodelet's
(laser_filters' scan_to_cloud_filter_chain advertised on a member ``ros::NodeHandle nh;``
until 7c18194 passed it ``getNodeHandle()``). Run alone (``nodelet standalone``) the
process is the nodelet's: nothing changes. A handle whose origin the code does not show
(a function given handles of both kinds) stays the nodelet's, as before."""

from __future__ import annotations

import os
from typing import Any

from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl
from haros_arch.model import Configuration, Location, Node, PrimitiveCall
from haros_arch.model.load import call_from_data
from haros_arch.model.serialise import to_data
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import Workspace

PACKAGE = ('<?xml version="1.0"?>\n<package format="2"><name>filt</name>'
           "<version>0.1.0</version><description>d</description>"
           '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
           "<buildtool_depend>catkin</buildtool_depend><depend>roscpp</depend>"
           "<depend>nodelet</depend><depend>pluginlib</depend><depend>std_msgs</depend>"
           '<export><nodelet plugin="${prefix}/nodelets.xml"/></export></package>\n')

CMAKE = """project(filt)
find_package(catkin REQUIRED COMPONENTS roscpp nodelet pluginlib std_msgs)
catkin_package()
add_library(filt_nodelet src/filt.cpp)
"""

PLUGINS = """<library path="lib/libfilt_nodelet">
  <class name="filt/Filter" type="filt::Filter" base_class_type="nodelet::Nodelet">
    <description>d</description>
  </class>
</library>
"""

SOURCE = """#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include <std_msgs/String.h>
namespace filt {
class Chain {
 public:
  explicit Chain(ros::NodeHandle& h) {
    sub_ = h.subscribe("chain_in", 1, &Chain::cb, this);
  }
  void cb(const std_msgs::String::ConstPtr&) {}
 private:
  ros::Subscriber sub_;
};

class Filter : public nodelet::Nodelet {
 public:
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    ros::NodeHandle raw;
    ros::NodeHandle raw_private("~");
    ros::NodeHandle child(nh, "sub");
    pub_ = nh.advertise<std_msgs::String>("out", 1);
    pnh.param("rate", rate_, 1.0);
    raw_pub_ = raw.advertise<std_msgs::String>("cloud", 1);
    raw_private.param("frame", frame_, std::string("base"));
    member_pub_ = member_.advertise<std_msgs::String>("member_out", 1);
    child_pub_ = child.advertise<std_msgs::String>("child_out", 1);
    ros::NodeHandle loaded("~");
    loaded = getPrivateNodeHandle();
    loaded_pub_ = loaded.advertise<std_msgs::String>("loaded_out", 1);
    one_.reset(new Chain(nh));
    two_.reset(new Chain(raw));
  }
 private:
  ros::NodeHandle member_;
  double rate_;
  std::string frame_;
  ros::Publisher pub_, raw_pub_, member_pub_, child_pub_, loaded_pub_;
  boost::shared_ptr<Chain> one_, two_;
};
}
PLUGINLIB_EXPORT_CLASS(filt::Filter, nodelet::Nodelet)
"""

LAUNCH = """<launch>
  <group ns="robot">
    <node pkg="nodelet" type="nodelet" name="mgr" args="manager">
      <remap from="cloud" to="mgr_cloud"/>
    </node>
    <group ns="sensors">
      <node pkg="nodelet" type="nodelet" name="filter" args="load filt/Filter /robot/mgr">
        <remap from="out" to="filtered"/>
        <remap from="cloud" to="nodelet_cloud"/>
      </node>
    </group>
    <node pkg="nodelet" type="nodelet" name="alone" args="standalone filt/Filter">
      <remap from="cloud" to="alone_cloud"/>
    </node>
  </group>
</launch>
"""


def _analyse(write_tree: Any) -> Any:
    root = write_tree({
        "src/filt/package.xml": PACKAGE, "src/filt/CMakeLists.txt": CMAKE,
        "src/filt/nodelets.xml": PLUGINS, "src/filt/src/filt.cpp": SOURCE,
        "src/filt/launch/filt.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [filt/launch/filt.launch]\n",
    })
    return analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                   Options(cache_dir=None, jobs=1))


DUAL_CMAKE = """project(filt)
find_package(catkin REQUIRED COMPONENTS roscpp nodelet pluginlib std_msgs)
catkin_package()
add_executable(filt_node src/filt.cpp)
add_library(filt_nodelet src/filt.cpp)
target_compile_definitions(filt_nodelet PRIVATE BUILDING_NODELET=1)
"""

DUAL_SOURCE = """#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include <std_msgs/String.h>
namespace filt {
class Chain {
 public:
  Chain(ros::NodeHandle& h, ros::NodeHandle& p) : nh_(h), pnh_(p) {
    pub_ = nh_.advertise<std_msgs::String>("out", 1);
    pnh_.param("rate", rate_, 1.0);
    raw_pub_ = raw_.advertise<std_msgs::String>("cloud", 1);
  }
 private:
  ros::NodeHandle nh_, pnh_, raw_;
  ros::Publisher pub_, raw_pub_;
  double rate_;
};
}
#if BUILDING_NODELET
namespace filt {
class Filter : public nodelet::Nodelet {
  void onInit() override { chain_.reset(new Chain(getNodeHandle(), getPrivateNodeHandle())); }
  boost::shared_ptr<Chain> chain_;
};
}
PLUGINLIB_EXPORT_CLASS(filt::Filter, nodelet::Nodelet)
#else
int main(int argc, char** argv) {
  ros::init(argc, argv, "filt");
  ros::NodeHandle nh, pnh("~");
  filt::Chain chain(nh, pnh);
  ros::spin();
}
#endif
"""


def test_a_handle_main_makes_says_nothing_of_a_nodelets(write_tree: Any) -> None:
    # one source built as a program and as a nodelet library, read as the program (the
    # macro only the library defines): main() runs in no nodelet, so the handles it
    # passes are of no origin known; the member nothing sets is the process's
    root = write_tree({
        "src/filt/package.xml": PACKAGE, "src/filt/CMakeLists.txt": DUAL_CMAKE,
        "src/filt/nodelets.xml": PLUGINS, "src/filt/src/filt.cpp": DUAL_SOURCE,
        "project.yaml": "project: p\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None, jobs=1))
    nodes = {n.name: n for p in model.packages for n in p.nodes}
    origins = {(c.kind, c.name): c.handle_origin for c in nodes["filt/filt/Filter"].calls}
    assert origins == {("publish", "out"): None, ("read", "~rate"): None,
                       ("publish", "cloud"): "process"}


SPLIT_CMAKE = """project(filt)
find_package(catkin REQUIRED COMPONENTS roscpp nodelet pluginlib std_msgs)
catkin_package()
add_library(filt_nodelet src/filt.cpp src/worker.cpp)
"""

WORKER_H = """#include <ros/ros.h>
#include <std_msgs/String.h>
namespace filt {
struct Worker { explicit Worker(ros::NodeHandle nh); ros::Publisher pub_; };
struct Other { explicit Other(ros::NodeHandle nh); ros::Publisher pub_; };
struct Both { explicit Both(ros::NodeHandle nh); ros::Publisher pub_; };
}
"""

WORKER_CPP = """#include "worker.h"
namespace filt {
Worker::Worker(ros::NodeHandle nh) { pub_ = nh.advertise<std_msgs::String>("worker_out", 1); }
Other::Other(ros::NodeHandle nh) { pub_ = nh.advertise<std_msgs::String>("other_out", 1); }
Both::Both(ros::NodeHandle nh) { pub_ = nh.advertise<std_msgs::String>("both_out", 1); }
}
"""

SPLIT_SOURCE = """#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include "worker.h"
namespace filt {
class Filter : public nodelet::Nodelet {
 public:
  void onInit() override {
    worker_.reset(new Worker(getPrivateNodeHandle()));
    ros::NodeHandle raw("~");
    other_.reset(new Other(raw));
    one_.reset(new Both(getNodeHandle()));
    two_.reset(new Both(ros::NodeHandle()));
  }
 private:
  boost::shared_ptr<Worker> worker_;
  boost::shared_ptr<Other> other_;
  boost::shared_ptr<Both> one_, two_;
};
}
PLUGINLIB_EXPORT_CLASS(filt::Filter, nodelet::Nodelet)
"""


def test_a_handle_given_to_another_file_keeps_its_origin(write_tree: Any) -> None:
    # msckf_vio's nodelet hands getPrivateNodeHandle() to ImageProcessor's constructor in
    # another file; a class built on handles of both kinds has neither
    root = write_tree({
        "src/filt/package.xml": PACKAGE, "src/filt/CMakeLists.txt": SPLIT_CMAKE,
        "src/filt/nodelets.xml": PLUGINS, "src/filt/src/filt.cpp": SPLIT_SOURCE,
        "src/filt/src/worker.h": WORKER_H, "src/filt/src/worker.cpp": WORKER_CPP,
        "src/filt/launch/filt.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [filt/launch/filt.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None, jobs=1))
    nodes = {n.name: n for p in model.packages for n in p.nodes}
    origins = {(c.name, c.handle_origin) for c in nodes["filt/filt/Filter"].calls}
    assert origins == {("~worker_out", "nodelet"), ("~other_out", "process"),
                       ("both_out", None)}
    (config,) = model.configurations
    names = _names(config.node("/robot/sensors/filter"))
    assert names == {"~worker_out": "/robot/sensors/filter/worker_out",
                     "~other_out": "/robot/mgr/other_out",
                     "both_out": "/robot/sensors/both_out"}


def _names(instance: Any) -> dict[str, str]:
    return {link.rosname.given: link.rosname.full for link in instance.links}


def test_each_call_says_where_its_handle_comes_from(write_tree: Any) -> None:
    model = _analyse(write_tree)
    (node,) = [n for p in model.packages for n in p.nodes if n.name == "filt/filt/Filter"]
    origins = {(c.kind, c.name): c.handle_origin for c in node.calls}
    assert origins[("publish", "out")] == "nodelet"
    assert origins[("read", "~rate")] == "nodelet"
    assert origins[("publish", "cloud")] == "process"
    assert origins[("read", "~frame")] == "process"
    assert origins[("publish", "member_out")] == "process"  # default-constructed member
    assert origins[("publish", "sub/child_out")] == "nodelet"  # a child of getNodeHandle()
    assert origins[("publish", "~loaded_out")] == "nodelet"  # assigned getPrivateNodeHandle()
    # a constructor given a handle of each kind: its subscription's handle is not known
    assert origins[("subscribe", "chain_in")] is None


def test_a_nodelet_in_a_manager_resolves_constructed_handles_as_the_manager(
        write_tree: Any) -> None:
    model = _analyse(write_tree)
    (config,) = model.configurations
    filt = config.node("/robot/sensors/filter")
    names = _names(filt)
    # the nodelet's own handles: its namespace, its name, its remaps
    assert names["out"] == "/robot/sensors/filtered"
    assert names["~rate"] == "/robot/sensors/filter/rate"
    assert names["sub/child_out"] == "/robot/sensors/sub/child_out"
    assert names["~loaded_out"] == "/robot/sensors/filter/loaded_out"
    # constructed handles: the manager's namespace, private name and remaps
    assert names["cloud"] == "/robot/mgr_cloud"
    assert names["~frame"] == "/robot/mgr/frame"
    assert names["member_out"] == "/robot/member_out"
    # unknown origin: as the nodelet's, as before
    assert names["chain_in"] == "/robot/sensors/chain_in"
    # still the nodelet instance's links; the manager's remap is used, the nodelet's
    # ``cloud`` remap is not
    assert all(link.node is filt for link in config.parameter("/robot/mgr/frame").readers)
    assert config.node("/robot/mgr").remaps_applied == ["/robot/cloud"]
    assert "/robot/sensors/cloud" not in filt.remaps_applied
    said = [d for d in config.diagnostics if d.code == "NODELET_PROCESS_HANDLES"]
    assert [(d.location.line, "/robot/mgr'" in d.message) for d in said] == [(7, True)]


def test_a_standalone_nodelet_is_its_own_process(write_tree: Any) -> None:
    model = _analyse(write_tree)
    (config,) = model.configurations
    names = _names(config.node("/robot/alone"))
    assert names["cloud"] == "/robot/alone_cloud"
    assert names["~frame"] == "/robot/alone/frame"
    assert names["out"] == "/robot/out"


def _nodelet(origin: str | None) -> Node:
    node = Node("filt", "filt/Filter", calls=[
        PrimitiveCall("publish", "cloud", "std_msgs/String", 1, handle_origin=origin,
                      location=Location("filt", "filt/src/filt.cpp", 3, 1))])
    node.kind = "nodelet"
    return node


def _graph(node: Node, manager: bool = True, named: str = "/robot/mgr") -> Configuration:
    decls = [NodeDecl("/robot/mgr", "nodelet", "nodelet", args="manager",
                      namespace="/robot/")] if manager else []
    decls.append(NodeDecl("/robot/sensors/filter", "nodelet", "nodelet",
                          args=f"load filt/Filter {named}", namespace="/robot/sensors/"))
    return build(Configuration("c"), LaunchModel(nodes=decls), Workspace(root="/nowhere"),
                 {node.name: node})


def test_a_call_of_unknown_origin_stays_the_nodelets() -> None:
    # a model saved before the field, or a handle another file gave: as before
    assert [t.name for t in _graph(_nodelet(None)).topics] == ["/robot/sensors/cloud"]
    assert [t.name for t in _graph(_nodelet("nodelet")).topics] == ["/robot/sensors/cloud"]
    assert [t.name for t in _graph(_nodelet("process")).topics] == ["/robot/cloud"]


def test_a_manager_the_configuration_does_not_start_still_names_the_process() -> None:
    config = _graph(_nodelet("process"), manager=False)
    assert [t.name for t in config.topics] == ["/robot/cloud"]
    (said,) = [d for d in config.diagnostics if d.code == "NODELET_PROCESS_HANDLES"]
    assert "no remaps known" in said.message
    # a manager's name not known (an argument nobody set): where it is, neither
    assert [t.name for t in _graph(_nodelet("process"), named="?").topics] == ["/?/cloud"]
    assert [t.name for t in _graph(_nodelet("process"), named="$(arg m)").topics] == [
        "/?/cloud"]


def test_the_origin_reads_back_and_an_older_model_has_none() -> None:
    call = PrimitiveCall("publish", "cloud", handle_origin="process")
    assert call_from_data(to_data(call)).handle_origin == "process"
    data = to_data(PrimitiveCall("publish", "cloud"))
    assert "handle_origin" not in data
    assert call_from_data(data).handle_origin is None
    # a word this version does not know reads back, and places the call as before
    other = call_from_data({**data, "handle_origin": "elsewhere"})
    assert other.handle_origin == "elsewhere"
    assert [t.name for t in _graph(_nodelet("elsewhere")).topics] == ["/robot/sensors/cloud"]
