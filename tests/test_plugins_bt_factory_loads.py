"""A program that registers the behavior tree node classes of libraries it opens by name
(BehaviorTree.CPP's ``factory.registerFromPlugin(loader.getOSName("lib"))``) and builds a
tree from them makes the tree nodes' calls on its node, which are not in its code: each
instance of it is partial (unknown is not empty), unless it is a tree host of the table
whose trees are read. book_ros2's patrolling_main was complete with no call at all, and
the remap of ``output_vel``, the topic its Patrol tree node publishes, was said unused."""

from __future__ import annotations

import os
from typing import Any

from conftest import package_xml

from haros_arch.extract.cpp import plugin_loads
from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl
from haros_arch.model import Configuration, Node
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue
from haros_arch.workspace import scan

MAIN = """
#include <string>
#include "behaviortree_cpp_v3/bt_factory.h"
#include "behaviortree_cpp_v3/utils/shared_library.h"
#include "rclcpp/rclcpp.hpp"

int main(int argc, char * argv[])
{
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("patrolling_node");
  BT::BehaviorTreeFactory factory;
  BT::SharedLibrary loader;
  factory.registerFromPlugin(loader.getOSName("patrol_bt_node"));
  // factory.registerFromPlugin(loader.getOSName("old_bt_node"));
  auto blackboard = BT::Blackboard::create();
  blackboard->set("node", node);
  BT::Tree tree = factory.createTreeFromFile("/tmp/patrolling.xml", blackboard);
  rclcpp::spin_some(node);
  return 0;
}
"""

LAUNCH = """
<launch>
  <node pkg="patrol" exec="patrolling_main" name="patrolling_node">
    <remap from="output_vel" to="/cmd_vel"/>
  </node>
</launch>
"""


def test_the_sites_that_register_tree_node_libraries_are_found(tmp_path: Any) -> None:
    text = MAIN + "void f(BT::BehaviorTreeFactory * f) { f->registerFromPlugin(name); }\n"
    found = plugin_loads(str(tmp_path / "main.cpp"), text, scan([str(tmp_path)]))
    assert [(d.code, d.location.line) for d in found] == [
        ("CPP_PLUGINS_LOADED", 13), ("CPP_PLUGINS_LOADED", 21)]
    assert found[0].message == ('factory.registerFromPlugin(loader.getOSName("patrol_bt_node"));'
                                ": loads plugin classes through BehaviorTree.CPP")


def test_a_program_that_registers_tree_nodes_by_name_is_partial(write_tree: Any) -> None:
    root = write_tree({
        "src/patrol/package.xml": package_xml("patrol", build_type="ament_cmake"),
        "src/patrol/CMakeLists.txt":
            "project(patrol)\nadd_executable(patrolling_main src/patrolling_main.cpp)\n"
            "install(TARGETS patrolling_main DESTINATION lib/${PROJECT_NAME})\n",
        "src/patrol/src/patrolling_main.cpp": MAIN,
        "src/patrol/launch/patrol.launch.xml": LAUNCH,
        "project.yaml": "project: p\ndistro: jazzy\n"
                        "configurations:\n  c: [patrol/launch/patrol.launch.xml]\n",
    })
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    instance = next(n for n in model.configurations[0].nodes
                    if n.name == "/patrolling_node")
    assert instance.completeness == "partial"
    # (the file as written: its first line is the include)
    assert instance.completeness_reasons == [
        "patrol/src/patrolling_main.cpp:12: loads plugin classes by name whose calls are "
        "not known here"]
    # the remap may rename what a tree node uses: not said unused
    rules = {finding.rule for finding in run_catalogue(model, project)}
    assert "remap-unused" not in rules


def test_a_tree_host_that_registers_its_libraries_is_not_made_partial_by_it(
        tmp_path: Any) -> None:
    # PlanSys2's bt_action_node registers the libraries of its ``plugins`` parameter so;
    # its trees are read instead (plugins.behavior_trees)
    node = Node("plansys2_bt_actions", "bt_action_node",
                plugin_loads=["plansys2_bt_actions/src/BTAction.cpp:60"])
    decl = NodeDecl("/move", "plansys2_bt_actions", "bt_action_node", ros_version=2)
    config = build(Configuration("c"), LaunchModel(nodes=[decl]), scan([str(tmp_path)]),
                   {node.name: node})
    assert config.node("/move").completeness_reasons == [
        "behavior tree bt_xml_file not set: the tree is not known"]
    # another program that loads so is partial by it
    other = Node("patrol", "patrolling_main",
                 plugin_loads=["patrol/src/patrolling_main.cpp:13"])
    decl = NodeDecl("/patrolling_node", "patrol", "patrolling_main", ros_version=2)
    config = build(Configuration("c"), LaunchModel(nodes=[decl]), scan([str(tmp_path)]),
                   {other.name: other})
    assert config.node("/patrolling_node").completeness_reasons == [
        "patrol/src/patrolling_main.cpp:13: loads plugin classes by name whose calls are "
        "not known here"]
