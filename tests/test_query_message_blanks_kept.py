"""A finding's message keeps a value filled into it as it is written: a launch file's
``get_package_share_directory('   ')`` (ASV_Loyola_US) was said by the launch reader
with its three blanks, ``(written '   ')``, and ``check``'s text and JSON showed
``(written ' ')``: the catalogue collapsed every run of blanks of the filled message,
where only the template's own layout (a YAML block over several lines) is to be
joined into one line."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue

LAUNCH = """
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    share = get_package_share_directory('   ')
    return LaunchDescription([
        Node(package='ex', executable='x', name='n', parameters=[share + '/a.yaml']),
    ])
"""


def test_a_value_of_blanks_is_kept_in_the_finding(write_tree):
    root = write_tree({
        "src/ex/package.xml": package_xml("ex", "ament_cmake"),
        "src/ex/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(ex)\n",
        "src/ex/launch/ex.launch.py": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [ex/launch/ex.launch.py]\n"})
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    said = [f.message for f in run_catalogue(model) if "written" in f.message]
    assert said and all("(written '   ')" in m for m in said), said

