"""roscpp's three-argument ``ros::param::search(ns, key, result)`` asks the master for
``key`` from the namespace ``ns`` up; given ``n.getNamespace()`` it is
``n.searchParam(key, result)``. The stand-in declared only the two-argument form: the
call was a C++ error, no read was extracted and the node was partial
(CPP_NODE_PARTIAL). kuka-lwr (f9b638a) lwr_controllers'
KinematicChainControllerBase.h:66 searches ``robot_description`` so, then reads the
parameter it found with ``n.getParam(robot_description, xml_string)``, in each of its
13 controllers."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue
from haros_arch.workspace import scan

NODE = """#include <ros/ros.h>
#include <string>
int main(int argc, char** argv) {
  ros::init(argc, argv, "arm_node");
  ros::NodeHandle n("~");
  std::string robot_description, xml, robot_name, frame;
  if (!ros::param::search(n.getNamespace(), "robot_description", robot_description))
    return 1;
  n.getParam(robot_description, xml);
  if (ros::param::search("/cell", "robot_name", robot_name))
    ros::param::get(robot_name, frame);
  ros::spin();
  return 0;
}
"""

LAUNCH = """<launch>
  <param name="robot_description" value="&lt;robot name='r'/&gt;" />
  <param name="cell/robot_name" value="lwr" />
  <node name="arm_node" pkg="arm" type="arm_node" ns="lwr" />
</launch>
"""


def _tree(write_tree):
    return write_tree({
        "src/arm/package.xml": package_xml("arm", "catkin"),
        "src/arm/CMakeLists.txt": (
            "project(arm)\nfind_package(catkin REQUIRED COMPONENTS roscpp)\n"
            "add_executable(arm_node src/arm_node.cpp)\n"),
        "src/arm/src/arm_node.cpp": NODE,
        "src/arm/launch/arm.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [arm/launch/arm.launch]\n",
    })


def test_the_key_is_searched_from_the_namespace_given(write_tree) -> None:
    root = _tree(write_tree)
    source = root / "src/arm/src/arm_node.cpp"
    result = extract_cpp([str(source)], scan([str(root / "src")]), cache_dir=None)
    assert [(c.kind, c.name, c.searched, c.location.line) for c in result.calls] == [
        ("read", "~robot_description", True, 7), ("read", "~robot_description", True, 9),
        ("read", "/cell/robot_name", True, 10), ("read", "/cell/robot_name", True, 11)]
    assert not [d for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED")]


def test_the_node_reads_what_the_search_finds(write_tree) -> None:
    root = _tree(write_tree)
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""}, Options(cache_dir=None))
    config = model.configuration("c")
    (node,) = config.nodes
    assert node.completeness == "complete"
    # found up the tree from /lwr/arm_node: the root's robot_description
    assert [r.node.name for r in config.parameter("/robot_description").readers] == [
        "/lwr/arm_node", "/lwr/arm_node"]
    assert [r.node.name for r in config.parameter("/cell/robot_name").readers] == [
        "/lwr/arm_node", "/lwr/arm_node"]
    rules = {f.rule for f in run_catalogue(model, load(str(root / "project.yaml")))}
    assert not rules & {"parameter-set-not-read", "parameter-read-not-set"}
