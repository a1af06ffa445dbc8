"""A file in a git submodule that is not checked out (its folder empty or missing, as a
clone without --recursive leaves it) is not a missing file: the launch files and build
files name what is elsewhere. microstrain_inertial ad94c84's driver compiles and
configures from its microstrain_inertial_driver_common submodule: a clone of the
repository alone gave a LAUNCH_BAD_VALUE error ("file does not exist") for its
params.yml and twelve CMAKE_SOURCE_MISSING warnings. Now each says the submodule, where
.gitmodules declares it and how to check it out, what it would set or start stays
unknown, and the node whose sources are there is partial."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

GITMODULES = """[submodule "drv/common"]
\tpath = drv/common
\turl = https://example.invalid/common.git
"""

CMAKE = """cmake_minimum_required(VERSION 3.5)
project(drv)
find_package(catkin REQUIRED COMPONENTS roscpp)
catkin_package()
add_library(drv_common common/src/node_common.cpp common/src/config.cpp)
add_executable(drv_node src/drv_node.cpp)
target_link_libraries(drv_node drv_common)
add_executable(other_node src/other.cpp src/gone.cpp)
"""

NODE = """#include <ros/ros.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "drv");
  ros::NodeHandle nh;
  ros::Publisher p = nh.advertise<std_msgs::String>("status", 1);
  ros::spin();
}
"""

LAUNCH = """<launch>
  <node pkg="drv" type="drv_node" name="drv">
    <rosparam file="$(find drv)/common/config/params.yml" command="load"/>
    <rosparam file="$(find drv)/config/absent.yml" command="load"/>
  </node>
  <include file="$(find drv)/common/launch/extra.launch"/>
</launch>
"""


def _tree(write_tree, checked_out: bool = False):
    files = {
        "src/.gitmodules": GITMODULES,
        "src/drv/package.xml": package_xml("drv").replace(
            "</package>", "<depend>roscpp</depend></package>"),
        "src/drv/CMakeLists.txt": CMAKE,
        "src/drv/src/drv_node.cpp": NODE,
        "src/drv/src/other.cpp": "int main() { return 0; }\n",
        "src/drv/launch/drv.launch": LAUNCH,
        "project.yaml": "project: p\ndistro: noetic\nworkspace: src\nconfigurations:\n"
                        "  c: [drv/launch/drv.launch]\n"}
    if checked_out:
        files["src/drv/common/README.md"] = "checked out, but without the files named\n"
    root = write_tree(files)
    os.makedirs(root / "src/drv/common", exist_ok=True)  # the empty folder git leaves
    return root


def _said(root):
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    every = [*model.diagnostics, *config.diagnostics]
    return model, [(d.code, d.location.line, d.message) for d in every]


def test_files_in_a_submodule_not_checked_out_are_unknown_not_missing(write_tree):
    model, said = _said(_tree(write_tree))
    codes = [(code, line) for code, line, _ in said]
    # the file outside the submodule is still missing, as roslaunch finds it
    assert ("LAUNCH_BAD_VALUE", 4) in codes
    assert [m for c, _l, m in said if c == "LAUNCH_BAD_VALUE"] == [
        "file does not exist: drv/config/absent.yml"]
    assert "LAUNCH_FILE_MISSING" not in {c for c, _l in codes}
    unknown = sorted((line, m) for c, line, m in said if c == "LAUNCH_UNKNOWN_VALUE")
    assert unknown == [
        (3, "drv/common/config/params.yml lies in the git submodule drv/common (declared "
            "at .gitmodules:2), which is not checked out here (git submodule update "
            "--init); it is not read; what depends on it keeps '?'"),
        (6, "drv/common/launch/extra.launch lies in the git submodule drv/common "
            "(declared at .gitmodules:2), which is not checked out here (git submodule "
            "update --init); it is not read; what depends on it keeps '?'")]
    builds = sorted((c, m) for c, _l, m in said if c.startswith("CMAKE_SOURCE"))
    assert builds == [
        ("CMAKE_SOURCE_IN_SUBMODULE", "sources of target drv_common lie in the git "
         "submodule drv/common (declared at .gitmodules:2), which is not checked out here "
         "(git submodule update --init); their code is not read"),
        ("CMAKE_SOURCE_MISSING", "source file drv/src/gone.cpp of target other_node does "
         "not exist")]
    nodes = {n.executable: n for n in model.nodes if n.package == "drv"}
    assert nodes["drv_node"].completeness == "partial"
    assert nodes["drv_node"].completeness_reasons[0] == (
        "drv/CMakeLists.txt:5: sources in the git submodule drv/common, not checked out, "
        "are not read")
    assert nodes["other_node"].completeness == "complete"


def test_a_checked_out_submodule_lacking_a_file_misses_it(write_tree):
    _model, said = _said(_tree(write_tree, checked_out=True))
    codes = {c for c, _l, _m in said}
    assert "LAUNCH_FILE_MISSING" in codes and "CMAKE_SOURCE_IN_SUBMODULE" not in codes
    assert [m for c, _l, m in said if c == "LAUNCH_BAD_VALUE"] == [
        "file does not exist: drv/common/config/params.yml",
        "file does not exist: drv/config/absent.yml"]


LAUNCH_PY = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node


def generate_launch_description():
    share = get_package_share_directory('drv2')
    return LaunchDescription([
        Node(package='drv2', executable='drv2_node', name='drv2',
             parameters=[os.path.join(share, 'common', 'config', 'params.yaml')]),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            os.path.join(share, 'common', 'launch', 'extra.launch.py'))),
    ])
"""


def test_ros2_includes_and_parameter_files_in_a_submodule(write_tree):
    root = write_tree({
        "src/.gitmodules": "[submodule \"c\"]\n  path = drv2/common\n",
        "src/drv2/package.xml": package_xml("drv2", "ament_cmake"),
        "src/drv2/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(drv2)\n"
                                   "install(DIRECTORY launch common DESTINATION share/"
                                   "${PROJECT_NAME})\n",
        "src/drv2/launch/drv2.launch.py": LAUNCH_PY,
        "project.yaml": "project: p\ndistro: jazzy\nworkspace: src\nconfigurations:\n"
                        "  c: [drv2/launch/drv2.launch.py]\n"})
    _model, said = _said(root)
    codes = {c for c, _l, _m in said}
    assert "LAUNCH_FILE_MISSING" not in codes and "LAUNCH_PARAM_FILE" not in codes
    unknown = sorted(m.split(" lies in ")[0] for c, _l, m in said
                     if c == "LAUNCH_UNKNOWN_VALUE" and "git submodule drv2/common" in m)
    assert unknown == ["drv2/common/config/params.yaml", "drv2/common/launch/extra.launch.py"]
