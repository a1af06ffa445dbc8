"""A ROS 1 nodelet manager's own parameter, and nodelets named by their C++ type."""

from __future__ import annotations

from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Location, Node, PrimitiveCall
from haros_arch.workspace import Workspace


def graph(decls, params=(), nodes=()):
    launch = LaunchModel(nodes=list(decls), params=list(params))
    return build(Configuration("c"), launch, Workspace(root="/nowhere"),
                 {n.name: n for n in nodes})


def test_a_nodelet_manager_reads_its_number_of_worker_threads():
    # nodelet's Loader (loader.cpp advertiseRosApi): server_nh.param("num_worker_threads",
    # n, 0) on the manager's private handle, beside its three services
    config = graph([NodeDecl("/mgr", "nodelet", "nodelet", args="manager")],
                   params=[ParamDecl("/mgr/num_worker_threads", 4, "int")])
    threads = config.parameter("/mgr/num_worker_threads")
    assert [r.node.name for r in threads.readers] == ["/mgr"]
    read = next(link for link in config.links if link.kind == "read")
    assert read.call.has_default and read.type == "int"
    assert config.node("/mgr").is_complete


def test_a_nodelet_named_by_its_cxx_type_gets_its_interface():
    # a plugin description's <class type="vesc_ackermann::AckermannToVescNodelet"> with no
    # name: pluginlib's lookup name is the type, as `nodelet load` gives it (f1tenth's vesc)
    plugin = Node("vesc_ackermann", "vesc_ackermann::AckermannToVescNodelet", calls=[
        PrimitiveCall("subscribe", "ackermann_cmd", "ackermann_msgs/AckermannDriveStamped",
                      1, location=Location("vesc_ackermann", "v/src/a.cpp", 3, 1))])
    plugin.kind = "nodelet"
    config = graph([
        NodeDecl("/mgr", "nodelet", "nodelet", args="manager"),
        NodeDecl("/a2v", "nodelet", "nodelet",
                 args="load vesc_ackermann::AckermannToVescNodelet mgr"),
        NodeDecl("/alone", "nodelet", "nodelet",
                 args="standalone vesc_ackermann::AckermannToVescNodelet"),
    ], nodes=[plugin])
    assert config.node("/a2v").node is plugin
    assert config.node("/alone").node is plugin
    assert sorted(t.name for t in config.topics) == ["/ackermann_cmd"]
    assert config.diagnostics == []


def test_a_nodelet_named_by_one_word_gets_its_interface():
    # PX4-Avoidance's local_planner exports <class name="LocalPlannerNodelet"
    # type="avoidance::LocalPlannerNodelet">, loaded as `load LocalPlannerNodelet mgr`:
    # a lookup name that names no package; the one package exporting it is the one.
    # A word no package exports is a node type not found, said
    plugin = Node("local_planner", "LocalPlannerNodelet", calls=[
        PrimitiveCall("subscribe", "mavros/state", "mavros_msgs/State", 1,
                      location=Location("local_planner", "l/src/n.cpp", 3, 1))])
    plugin.kind = "nodelet"
    where = Location("local_planner", "l/launch/a.launch", 9, 0)
    config = graph([
        NodeDecl("/mgr", "nodelet", "nodelet", args="manager"),
        NodeDecl("/planner", "nodelet", "nodelet", args="load LocalPlannerNodelet mgr"),
        NodeDecl("/other", "nodelet", "nodelet", args="load OtherNodelet mgr",
                 location=where),
    ], nodes=[plugin])
    assert config.node("/planner").node is plugin
    assert sorted(t.name for t in config.topics) == ["/mavros/state"]
    assert config.node("/other").node is None
    assert [(d.code, d.location.line) for d in config.diagnostics] == [("NODE_NOT_FOUND", 9)]
    assert "node type OtherNodelet is not in the workspace" in config.diagnostics[0].message
