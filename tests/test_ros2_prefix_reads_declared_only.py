"""A ROS 2 node that does not declare the overrides it is given
(``automatically_declare_parameters_from_overrides``, false by default in rclpy and
rclcpp) has only the parameters it declares: its read of what it has under a prefix
(rclpy's ``get_parameters_by_prefix``, rclcpp's ``get_parameters(prefix, map)``) gets
those, never a parameter the configuration sets beside them. Every parameter set on such
a node was taken as read by the prefix read: bitbots_main 4702704's vision node reads
``get_parameters_by_prefix("")`` and declares neither ``vision_publish_debug_image`` nor
``vision_publish_field_mask_image``, which its launch file sets (missed)."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.extract.overrides import may_declare
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import load_catalogue, run_rule

PY_NODE = """
import rclpy
from rclpy.node import Node


class Vision(Node):
    def __init__(self):
        super().__init__('vision'{options})
        self.declare_parameter('debug_image_active', False)
        self.declare_parameter('ball.threshold', 0.5)
        everything = self.get_parameters_by_prefix('')
        ball = self.get_parameters_by_prefix('ball')


def main():
    rclpy.init()
    rclpy.spin(Vision())
"""

PY_LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package='vis', executable='vision', name='vision',
        parameters=[{'debug_image_active': True, 'publish_debug_image': True,
                     'ball': {'threshold': 0.7, 'size': 3}}])])
"""


def _rule(model, rule_id: str) -> list[list[str]]:
    return [list(f.entities) for rule in load_catalogue()
            if rule.id == rule_id for f in run_rule(rule, model)]


def _python_tree(write_tree, options: str, extra: dict[str, str] | None = None):
    root = write_tree({
        "src/vis/package.xml": package_xml("vis", build_type="ament_python"),
        "src/vis/setup.py": "from setuptools import setup\n"
                            "setup(name='vis', packages=['vis'], entry_points="
                            "{'console_scripts': ['vision = vis.vision:main']})\n",
        "src/vis/resource/vis": "",
        "src/vis/vis/__init__.py": "",
        "src/vis/vis/vision.py": PY_NODE.replace("{options}", options),
        "src/vis/launch/vision.launch.py": PY_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [vis/launch/vision.launch.py]\n",
        **(extra or {})})
    return analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                   Options(cache_dir=None))


def test_a_node_without_automatic_declarations_gets_only_what_it_declares(write_tree):
    model = _python_tree(write_tree, "")
    (node,) = [n for n in model.nodes if n.name == "vis/vision"]
    assert [(c.name, c.declared_only) for c in node.calls if c.kind == "read"] == [
        ("~", True), ("ball.", True)]
    params = {p.name: p for p in model.configuration("c").parameters}
    assert params["/vision/ball."].value == {"threshold": 0.7}
    # what the node declares is read by its declaration; the rest by nothing
    assert _rule(model, "parameter-set-not-read") == [
        ["parameter:/vision/publish_debug_image"], ["parameter:/vision/ball.size"]]


def test_a_node_that_declares_its_overrides_reads_them_by_prefix(write_tree):
    model = _python_tree(write_tree,
                         ", automatically_declare_parameters_from_overrides=True")
    (node,) = [n for n in model.nodes if n.name == "vis/vision"]
    assert not any(c.declared_only for c in node.calls)
    assert _rule(model, "parameter-set-not-read") == []


def test_a_node_of_options_not_known_keeps_every_parameter_read(write_tree):
    """The option given a value not known statically, or turned on in another file of
    the package (a module that builds the node's keywords), may declare them."""
    model = _python_tree(write_tree, ", **options.KEYWORDS", {
        "src/vis/vis/options.py": "import os\nKEYWORDS = {'automatically_declare_"
                                  "parameters_from_overrides': os.environ.get('A') == '1'}\n"})
    assert _rule(model, "parameter-set-not-read") == []


def test_a_declaration_of_a_name_not_known_leaves_the_rest_undecided(write_tree):
    """bitbots_main's vision declares its parameters from a generator's cache
    (``node.declare_parameter(*param)``): any parameter set on it may be one of them."""
    model = _python_tree(write_tree, ")\n        for param in load():\n"
                                     "            self.declare_parameter(*param")
    (said,) = [f.message for rule in load_catalogue() if rule.id == "parameter-set-not-read"
               for f in run_rule(rule, model)]
    assert said.startswith("2 possible finding(s) not reported (first: parameter "
                           "/vision/publish_debug_image)")


CPP_NODE = """
#include <map>
#include <string>
#include <rclcpp/rclcpp.hpp>
class Limits : public rclcpp::Node
{
public:
  explicit Limits(const rclcpp::NodeOptions & options) : rclcpp::Node("limits", options)
  {
    declare_parameter("limits.speed", 1.0);
    std::map<std::string, double> all;
    get_parameters("limits", all);
  }
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::NodeOptions options;
  // options.automatically_declare_parameters_from_overrides(true);
  rclcpp::spin(std::make_shared<Limits>(options{more}));
}
"""

CPP_LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='ex', executable='limits', name='limits',
             parameters=[{'limits': {'speed': 3.0, 'accel': 2.0}}]),
    ])
"""


def _cpp_model(write_tree, more: str):
    root = write_tree({
        "src/ex/package.xml": package_xml("ex", "ament_cmake"),
        "src/ex/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(ex)\n"
                                 "add_executable(limits src/node.cpp)\n",
        "src/ex/src/node.cpp": CPP_NODE.replace("{more}", more),
        "src/ex/launch/ex.launch.py": CPP_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [ex/launch/ex.launch.py]\n"})
    return analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                   Options(cache_dir=None))


def test_cpp_prefix_read_of_a_node_without_automatic_declarations(write_tree):
    """The option in a comment turns nothing on."""
    model = _cpp_model(write_tree, "")
    assert _rule(model, "parameter-set-not-read") == [["parameter:/limits/limits.accel"]]


def test_cpp_node_options_that_declare_the_overrides(write_tree):
    model = _cpp_model(write_tree,
                       ".automatically_declare_parameters_from_overrides(true)")
    assert _rule(model, "parameter-set-not-read") == []


def test_the_option_written_in_code():
    assert may_declare("rclcpp::NodeOptions().automatically_declare_parameters_from_"
                       "overrides(true)")
    assert may_declare("options.automatically_declare_parameters_from_overrides(flag);")
    assert may_declare("Node('n', automatically_declare_parameters_from_overrides=True)")
    assert not may_declare("Node('n', automatically_declare_parameters_from_overrides="
                           "False)")
    assert not may_declare("o.automatically_declare_parameters_from_overrides( false )")
