"""A ROS 2 main that makes its node in a local (``auto node =
rclcpp::Node::make_shared(...)``) and hands it to a class of a header not found
(moveit2_tutorials' move_group_interface_tutorial.cpp:79,
``moveit::planning_interface::MoveGroupInterface move_group(move_group_node, ...)``,
whose code subscribes, calls actions and reads parameters on that node). The main makes
no other ROS call, so no name is declared and the statement stays an error: the node was
'complete' with no call. The statement passes the local that holds the node: the node is
partial (CPP_NODE_TO_UNKNOWN), as for a parameter of a node type. A local that is no node
(a string) given to the unknown class is no such place."""

from __future__ import annotations

import os
from typing import Any

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

MAIN = """
    #include <memory>
    #include <string>
    #include <rclcpp/rclcpp.hpp>
    #include <vendor/move_group_interface.h>

    int main(int argc, char ** argv) {
      rclcpp::init(argc, argv);
      rclcpp::NodeOptions node_options;
      node_options.automatically_declare_parameters_from_overrides(true);
      auto move_group_node = rclcpp::Node::make_shared("tutorial", node_options);
      std::string group = "panda_arm";
      vendor::planning::MoveGroupInterface move_group(GIVEN, group);
      rclcpp::shutdown();
      return 0;
    }
    """


def _node(write_tree: Any, given: str) -> Any:
    root = write_tree({
        "src/tut/package.xml": package_xml("tut", build_type="ament_cmake"),
        "src/tut/CMakeLists.txt": "project(tut)\nadd_executable(tutorial src/tutorial.cpp)\n",
        "src/tut/src/tutorial.cpp": MAIN.replace("GIVEN", given),
        "project.yaml": "project: p\nworkspace: [src]\nconfigurations: {}\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    return next(n for p in model.packages for n in p.nodes if n.name == "tut/tutorial")


def test_a_local_node_given_to_an_unknown_class_makes_the_node_partial(
        write_tree: Any) -> None:
    node = _node(write_tree, "move_group_node")
    assert node.completeness == "partial", node.completeness_reasons
    assert any("the node (move_group_node) is given to vendor::planning::MoveGroupInterface," in r
               for r in node.completeness_reasons), node.completeness_reasons


def test_a_local_that_is_no_node_given_to_it_is_no_such_place(write_tree: Any) -> None:
    node = _node(write_tree, "group")
    assert node.completeness == "complete", node.completeness_reasons
