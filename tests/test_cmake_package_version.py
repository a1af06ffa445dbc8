"""catkin's ``catkin_package_xml()`` and ament's ``ament_package_xml()`` set
``<project>_VERSION`` from the package's package.xml; ``catkin_package()``,
``ament_package()``, ``ament_auto_package()`` and ``ament_auto_find_build_dependencies()``
run them when nothing ran them before. Lslidar's ROS 1 driver defines
``-D${PROJECT_NAME}_VERSION="${${PROJECT_NAME}_VERSION}"`` after ``catkin_package()``
and prints the macro in its ``main``: read as a variable never set, the macro was an
unknown value, clang's error in ``main`` made the node partial (``CPP_NODE_PARTIAL``).
"""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.extract.cpp.build_macros import cmake_flags
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import scan

DEFINE = 'add_definitions("-D${PROJECT_NAME}_VERSION=\\"${${PROJECT_NAME}_VERSION}\\"")\n'


def _flags(write_tree, name: str, cmake: str, folder: str | None = None) -> list[str]:
    folder = folder or name
    root = write_tree({
        f"src/{folder}/package.xml": package_xml(folder, "catkin"),
        f"src/{folder}/CMakeLists.txt": cmake + "add_executable(n src/n.cpp)\n",
        f"src/{folder}/src/n.cpp": "int main() { return 0; }\n",
    })
    return cmake_flags(str(root / "src" / folder / "src" / "n.cpp"), scan([str(root / "src")]))


def test_catkin_package_sets_the_version(write_tree) -> None:
    cmake = ("cmake_minimum_required(VERSION 3.0.2)\nproject(ver)\n"
             "find_package(catkin REQUIRED)\ncatkin_package()\n" + DEFINE)
    assert _flags(write_tree, "ver", cmake) == ['-Dver_VERSION="0.1.0"']


def test_before_the_parse_the_version_is_not_known(write_tree) -> None:
    # (a definition whose word reads what is not known and whose name is not written
    # out is left out: ``_definitions``)
    cmake = ("cmake_minimum_required(VERSION 3.0.2)\nproject(ver)\n"
             "find_package(catkin REQUIRED)\n" + DEFINE + "catkin_package()\n")
    assert _flags(write_tree, "ver", cmake) == []


def test_ament_parses_package_xml_once(write_tree) -> None:
    for first in ("ament_package_xml()", "ament_auto_find_build_dependencies()"):
        cmake = ("cmake_minimum_required(VERSION 3.8)\nproject(ver)\n"
                 f"find_package(ament_cmake REQUIRED)\n{first}\n" + DEFINE + "ament_package()\n")
        assert _flags(write_tree, "ver", cmake) == ['-Dver_VERSION="0.1.0"'], first


def test_another_project_name_or_folder_sets_nothing(write_tree) -> None:
    # catkin_package_xml stops the build when project() is not the package's name
    cmake = ("cmake_minimum_required(VERSION 3.0.2)\nproject(other)\n"
             "find_package(catkin REQUIRED)\ncatkin_package()\n" + DEFINE)
    assert _flags(write_tree, "other", cmake, folder="ver") == []
    cmake = ("cmake_minimum_required(VERSION 3.0.2)\nproject(ver)\n"
             "find_package(catkin REQUIRED)\ncatkin_package_xml(DIRECTORY elsewhere)\n"
             + DEFINE)
    assert _flags(write_tree, "ver", cmake) == []


NODE = """
#include <ros/ros.h>
#include <std_msgs/String.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "driver");
  ros::NodeHandle nh;
  ROS_INFO("driver version: %s", driver_VERSION);
  ros::Publisher pub = nh.advertise<std_msgs::String>("points", 10);
  ros::spin();
}
"""


def test_a_node_printing_its_version_is_complete(write_tree) -> None:
    root = write_tree({
        "src/driver/package.xml": package_xml("driver", "catkin").replace(
            "</package>", "<depend>roscpp</depend><depend>std_msgs</depend></package>"),
        "src/driver/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(driver)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)\ncatkin_package()\n"
            + DEFINE + "add_executable(driver_node src/driver_node.cpp)\n"),
        "src/driver/src/driver_node.cpp": NODE,
        "project.yaml": "project: p\nconfigurations: {}\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    node = next(n for p in model.packages for n in p.nodes if n.executable == "driver_node")
    assert [c.name for c in node.calls if c.kind == "publish"] == ["points"]
    assert node.completeness == "complete", node.completeness_reasons
    assert not [d for d in model.diagnostics if d.code == "CPP_NODE_PARTIAL"]
