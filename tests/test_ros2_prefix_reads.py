"""ROS 2 reads of every parameter under a prefix (rclpy's ``get_parameters_by_prefix``,
rclcpp's ``get_parameters(prefix, map)`` and its parameters interface's
``get_parameters_by_prefix``) are read as ROS 1 reads a namespace whole: what the
configuration sets under the prefix is read as part of it (``read_as_part_of``), the
prefix holds their dictionary. They were reads of ``prefix.?``: stretch_ros2's
detect_aruco_markers.py:634 left 52 parameters ``aruco_marker_info.*`` undecided
(parameter-set-not-read-undecided). A prefix not known statically keeps its ``?``."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.extract.python import extract_python
from haros_arch.model import Parameter
from haros_arch.model.load import call_from_data
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import load_catalogue, run_rule
from haros_arch.workspace import scan

CPP_NODE = """
#include <map>
#include <string>
#include <vector>
#include <rclcpp/rclcpp.hpp>
class Markers : public rclcpp::Node
{
public:
  Markers() : rclcpp::Node("markers",
      rclcpp::NodeOptions().automatically_declare_parameters_from_overrides(true))
  {
    std::map<std::string, double> sizes;
    this->get_parameters("marker_sizes", sizes);
    this->get_parameters("scale", sizes);
    std::map<std::string, rclcpp::Parameter> all;
    get_node_parameters_interface()->get_parameters_by_prefix("limits", all);
    std::vector<rclcpp::Parameter> two = get_parameters({"gain", "offset"});
  }
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Markers>());
}
"""

CPP_LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='ex', executable='markers', name='markers',
             parameters=[{'marker_sizes': {'a': 1.0, 'b': {'c': 2.0}},
                          'limits': {'speed': 3.0},
                          'scale': 2.0, 'gain': 1.0, 'offset': 2.0, 'unused': 4}]),
    ])
"""


def _rule(model, rule_id: str) -> list[tuple[list[str], str]]:
    return [(list(f.entities), f.message) for rule in load_catalogue()
            if rule.id == rule_id for f in run_rule(rule, model)]


def test_cpp_prefix_reads_read_what_is_set_under_the_prefix(write_tree) -> None:
    root = write_tree({
        "src/ex/package.xml": package_xml("ex", "ament_cmake"),
        "src/ex/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(ex)\n"
                                 "add_executable(markers src/node.cpp)\n",
        "src/ex/src/node.cpp": CPP_NODE,
        "src/ex/launch/ex.launch.py": CPP_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [ex/launch/ex.launch.py]\n"})
    result = extract_cpp([str(root / "src/ex/src/node.cpp")], scan([str(root / "src")]),
                         cache_dir=None)
    # one read under each prefix, an empty map when nothing is there (no error); the
    # list overload reads each name it is given
    assert [(c.name, c.under, c.has_default) for c in result.calls if c.kind == "read"] == [
        ("marker_sizes.", True, True), ("scale.", True, True), ("limits.", True, True),
        ("gain", False, False), ("offset", False, False)]
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    params = {p.name: p for p in model.configuration("c").parameters}
    sizes = params["/markers/marker_sizes."]
    assert sizes.value == {"a": 1.0, "b.c": 2.0}  # keyed as rclcpp's map is
    assert params["/markers/marker_sizes.b.c"].read_as_part_of is sizes
    assert params["/markers/limits.speed"].read_as_part_of is params["/markers/limits."]
    # only what nothing reads is reported, decided: no '?' read leaves the rest undecided;
    # 'scale' itself is no parameter under 'scale.' (teleop_twist_joy's scale_angular)
    assert [e for e, _ in _rule(model, "parameter-set-not-read")] == [
        ["parameter:/markers/scale"], ["parameter:/markers/unused"]]
    assert _rule(model, "parameter-set-not-read-undecided") == []
    assert _rule(model, "parameter-read-not-set") == []
    assert not any(isinstance(p, Parameter) and p.is_unresolved
                   for p in model.configuration("c").parameters)


PY_NODE = """
import rclpy
from rclpy.node import Node


class Detect(Node):
    def __init__(self, which):
        super().__init__('detect', allow_undeclared_parameters=True,
                         automatically_declare_parameters_from_overrides=True)
        info = self.get_parameters_by_prefix('aruco_marker_info')
        unknown = self.get_parameters_by_prefix(which)
        two = self.get_parameters(['gain', 'offset'])


def main():
    rclpy.init()
    Detect(input())
"""

PY_LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package='talk', executable='detect', name='detect',
        parameters=[{'aruco_marker_info': {'130': {'length_mm': 47.0, 'name': 'base'}},
                     'gain': 1.0, 'unused': 3}])])
"""


def test_python_prefix_reads_read_what_is_set_under_the_prefix(write_tree) -> None:
    root = write_tree({
        "src/talk/package.xml": package_xml("talk", build_type="ament_python"),
        "src/talk/setup.py": "from setuptools import setup\n"
                             "setup(name='talk', packages=['talk'], entry_points="
                             "{'console_scripts': ['detect = talk.detect:main']})\n",
        "src/talk/resource/talk": "",
        "src/talk/talk/__init__.py": "",
        "src/talk/talk/detect.py": PY_NODE,
        "src/talk/launch/detect.launch.py": PY_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [talk/launch/detect.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    (node,) = [n for n in model.nodes if n.name == "talk/detect"]
    # the prefix; a prefix not known: '?'
    assert [(c.name, c.under, c.has_default) for c in node.calls if c.kind == "read"] == [
        ("aruco_marker_info.", True, True), ("?.?", False, True),
        ("gain", False, False), ("offset", False, False)]
    params = {p.name: p for p in model.configuration("c").parameters}
    info = params["/detect/aruco_marker_info."]
    assert info.value == {"130.length_mm": 47.0, "130.name": "base"}
    assert params["/detect/aruco_marker_info.130.name"].read_as_part_of is info
    # what is set under the prefix is read, decided; 'unused' (no '.': not what the
    # unknown prefix's '?.?' may stand for) is not
    assert [e for e, _ in _rule(model, "parameter-set-not-read")] == [
        ["parameter:/detect/unused"]]
    assert _rule(model, "parameter-set-not-read-undecided") == []


def test_an_interface_model_keeps_a_read_under_a_prefix() -> None:
    """The shipped jazzy joint_state_publisher model reads ``zeros`` under its prefix
    (joint_state_publisher.py:384); loaded without the mark it was a read of one
    parameter ``zeros.``, and stretch_ros2's ``zeros.joint_lift`` set but not read."""
    call = call_from_data({"kind": "read", "name": "zeros.", "under": True,
                           "has_default": True, "default": {}})
    assert call.under and call.name == "zeros."
    assert not call_from_data({"kind": "read", "name": "zeros"}).under


def test_python_prefix_read_of_everything_is_the_node_whole(write_tree) -> None:
    """``get_parameters_by_prefix('')`` is every parameter of the node (rclpy adds no
    ``.`` to an empty prefix): a read of its ``~`` whole, as rclcpp's
    ``get_parameter_overrides()``; it was a read of ``?``."""
    root = write_tree({
        "src/talk/package.xml": package_xml("talk", build_type="ament_python"),
        "src/talk/talk/node.py": "import rclpy\n"
                                 "node = rclpy.create_node('n')\n"
                                 "every = node.get_parameters_by_prefix('')\n"})
    calls = extract_python([str(root / "src/talk/talk/node.py")], scan([str(root)]),
                           package="talk").calls
    assert [(c.kind, c.name, c.under) for c in calls] == [("read", "~", False)]


LIST_NODE = """
#include <string>
#include <rclcpp/rclcpp.hpp>
class Dummy : public rclcpp::Node
{
public:
  Dummy() : rclcpp::Node("dummy",
      rclcpp::NodeOptions().automatically_declare_parameters_from_overrides(true))
  {
    const auto names = this->list_parameters({"required_diags"}, 3).names;
    for (const auto & name : names) {
      std::string status;
      this->get_parameter_or(name + ".status", status, std::string("OK"));
    }
  }
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Dummy>());
}
"""

LIST_LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='ex', executable='dummy', name='dummy',
             parameters=[{'required_diags': {'localization': 'ekf', 'map': {'status': 'OK'}},
                          'unused': 4}]),
    ])
"""


def test_cpp_list_parameters_reads_what_is_set_under_each_prefix(write_tree) -> None:
    """``list_parameters({prefix}, depth)`` gives the names the node has under the prefix,
    which the code then reads by them: a read of the prefix's namespace whole, as
    ``get_parameters(prefix, map)`` (Autoware's dummy_diag_publisher lists
    ``required_diags``: 7 false "set but never read")."""
    root = write_tree({
        "src/ex/package.xml": package_xml("ex", "ament_cmake"),
        "src/ex/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(ex)\n"
                                 "add_executable(dummy src/node.cpp)\n",
        "src/ex/src/node.cpp": LIST_NODE,
        "src/ex/launch/ex.launch.py": LIST_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [ex/launch/ex.launch.py]\n"})
    result = extract_cpp([str(root / "src/ex/src/node.cpp")], scan([str(root / "src")]),
                         cache_dir=None)
    assert ("required_diags.", True) in [(c.name, c.under) for c in result.calls
                                         if c.kind == "read"]
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    assert [e for e, _ in _rule(model, "parameter-set-not-read")] == [
        ["parameter:/dummy/unused"]]
