"""A node whose executable (or package) a launch file names with a value not known
statically (a launch argument with no value) is of unknown type, not a missing one:
NODE_TYPE_UNKNOWN, a warning, and no launch-missing-reference error (survey Z19:
crazyswarm2's crazyflie_examples/launch/launch.py starts ``executable=script``, the
required argument ``script`` given on the command line)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue

LAUNCH = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    script = LaunchConfiguration('script')
    return LaunchDescription([
        DeclareLaunchArgument('script'),
        Node(package='ex', executable=script, name='example'),
        Node(package='ex', executable='missing_node', name='other'),
    ])
"""


def test_an_executable_not_known_is_no_missing_one(write_tree):
    root = write_tree({
        "src/ex/package.xml": package_xml("ex", "ament_cmake"),
        "src/ex/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(ex)\n",
        "src/ex/launch/ex.launch.py": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [ex/launch/ex.launch.py]\n"})
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (config,) = model.configurations
    found = {d.code: d.message for d in config.diagnostics
             if d.code.startswith("NODE_")}
    assert found == {
        "NODE_TYPE_UNKNOWN": "node type ex/? is not known statically; its interface "
                             "is unknown",
        "NODE_NOT_FOUND": "node type ex/missing_node is not in the workspace; its "
                          "interface is unknown; package ex is in the workspace, with "
                          "no program found in its build files"}
    missing = [f.message for f in run_catalogue(model)
               if f.rule == "launch-missing-reference"]
    assert missing == ["node type ex/missing_node is not in the workspace; its "
                       "interface is unknown; package ex is in the workspace, with no "
                       "program found in its build files"]
