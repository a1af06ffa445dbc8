"""``if(EXISTS <path>)`` in a package's CMake where the path lies in a git submodule the
tree does not have checked out (``git clone`` without ``--recursive``): the build that
has the submodule takes the branch, so the test is not decided here, not false.
mrover-ros2 c7572baf makes its five hardware bridge nodes under
``if (EXISTS ${MROVER_EMBEDDED_ROOT_DIR} AND NOT APPLE)``, the folder ``esw/fw/lib`` of
the submodule ``esw/fw``: read as false, the nodes were not built and each launch file
starting one got a launch-missing-reference error."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

GITMODULES = """[submodule "fw"]
\tpath = rov/fw
\turl = https://example.invalid/fw.git
"""

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(rov)
find_package(ament_cmake REQUIRED)
find_package(rclcpp REQUIRED)
set(FW_ROOT "${CMAKE_CURRENT_SOURCE_DIR}/fw/lib")
if (EXISTS ${FW_ROOT} AND NOT APPLE)
  add_executable(bridge src/bridge.cpp)
  ament_target_dependencies(bridge rclcpp)
  install(TARGETS bridge DESTINATION lib/${PROJECT_NAME})
endif()
if (EXISTS "${CMAKE_CURRENT_SOURCE_DIR}/not_there")
  add_executable(ghost src/bridge.cpp)
  install(TARGETS ghost DESTINATION lib/${PROJECT_NAME})
endif()
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
ament_package()
"""

NODE = """#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("bridge");
  auto pub = node->create_publisher<std_msgs::msg::String>("status", 10);
  rclcpp::spin(node);
}
"""

LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="rov", executable="bridge", name="bridge"),
        Node(package="rov", executable="ghost", name="ghost"),
    ])
"""


def _tree(write_tree):
    root = write_tree({
        "src/.gitmodules": GITMODULES,
        "src/rov/package.xml": package_xml("rov", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"),
        "src/rov/CMakeLists.txt": CMAKE,
        "src/rov/src/bridge.cpp": NODE,
        "src/rov/launch/rov.launch.py": LAUNCH,
        "project.yaml": "project: p\ndistro: humble\nworkspace: src\nconfigurations:\n"
                        "  c: [rov/launch/rov.launch.py]\n"})
    os.makedirs(root / "src/rov/fw", exist_ok=True)  # the empty folder git leaves
    return root


def test_exists_in_a_submodule_not_checked_out_is_not_decided(write_tree):
    root = _tree(write_tree)
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    not_found = sorted(d.message.split(" is ")[0] for d in config.diagnostics
                       if d.code == "NODE_NOT_FOUND")
    # the folder outside any submodule is known absent: ghost is never built
    assert not_found == ["node type rov/ghost"]
    (bridge,) = [n for n in model.nodes if n.package == "rov" and n.executable == "bridge"]
    assert [c.text for c in bridge.conditions] == ["EXISTS ${FW_ROOT} AND NOT APPLE"]
    (instance,) = [i for i in config.nodes if i.name == "/bridge"]
    assert instance.node is bridge


# -- a program a ROS 2 package installs that is no node this tool reads ----------------
SCRIPT_CMAKE = """cmake_minimum_required(VERSION 3.8)
project(gui)
find_package(ament_cmake REQUIRED)
install(PROGRAMS scripts/serve.sh DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
ament_package()
"""

SCRIPT_LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="gui", executable="serve.sh", name="serve"),
        Node(package="gui", executable="absent.sh", name="absent"),
    ])
"""


def test_installed_shell_script_is_a_program_not_read(write_tree):
    """mrover-ros2 c7572baf installs ``gui_prod.sh`` with ``install(PROGRAMS ...
    DESTINATION lib/${PROJECT_NAME})`` and its basestation.launch.py starts it as a
    ``Node``: ros2 launch finds it there, so it is not missing (it was a
    launch-missing-reference error); a shell script is not read, so its interface is not
    known (NODE_NOT_READ, as for a ROS 1 script)."""
    root = write_tree({
        "src/gui/package.xml": package_xml("gui", "ament_cmake"),
        "src/gui/CMakeLists.txt": SCRIPT_CMAKE,
        "src/gui/scripts/serve.sh": "#!/bin/bash\nexec python3 server.py\n",
        "src/gui/launch/gui.launch.py": SCRIPT_LAUNCH,
        "project.yaml": "project: p\ndistro: humble\nworkspace: src\nconfigurations:\n"
                        "  c: [gui/launch/gui.launch.py]\n"})
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    said = sorted((d.code, d.message.split(" is ")[0]) for d in config.diagnostics
                  if d.code in ("NODE_NOT_FOUND", "NODE_NOT_READ"))
    assert said == [("NODE_NOT_FOUND", "node type gui/absent.sh"),
                    ("NODE_NOT_READ", "node type gui/serve.sh")]
