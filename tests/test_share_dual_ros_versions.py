"""A package built for ROS 1 and ROS 2 from one folder (carla ros-bridge's): its
package.xml says ``<build_type condition="$ROS_VERSION == 1">catkin`` and ``...== 2">
ament_python``, it keeps a catkin CMakeLists.txt, and its setup.py calls the ROS 2
``setup(data_files=[(os.path.join('share', package_name), glob('launch/*.launch.py'))])``
under ``if ROS_VERSION == 2:`` with ``ROS_VERSION = int(os.environ['ROS_VERSION'])`` and
``package_name`` set in that branch. Its share folder (for a ROS 2 distribution) is
setup.py's: the launch files sit at ``share/<pkg>/<file>``, where the other packages'
launch files include them. The share map was read from the CMakeLists.txt (the
manifest only), and setup.py's module-level ``if`` was skipped: every include of
``get_package_share_directory('bridge') + '/bridge.launch.py'`` was
``LAUNCH_FILE_MISSING``, an error, and the nodes there never seen."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import distro_variables
from haros_arch.share import share_map
from haros_arch.workspace import scan

MANIFEST = package_xml("bridge").replace(
    "</package>", '<export><build_type condition="$ROS_VERSION == 1">catkin</build_type>'
    '<build_type condition="$ROS_VERSION == 2">ament_python</build_type></export>'
    "</package>")
SETUP = """\
import os
from glob import glob
ROS_VERSION = int(os.environ['ROS_VERSION'])

if ROS_VERSION == 1:
    from distutils.core import setup
    from catkin_pkg.python_setup import generate_distutils_setup
    d = generate_distutils_setup(packages=['bridge'], package_dir={'': 'src'})
    setup(**d)
elif ROS_VERSION == 2:
    from setuptools import setup
    package_name = 'bridge'
    setup(
        name=package_name,
        packages=[package_name],
        data_files=[('share/' + package_name, ['package.xml']),
                    (os.path.join('share', package_name), glob('launch/*.launch.py'))],
        entry_points={'console_scripts': ['bridge = bridge.bridge:main']},
        package_dir={'': 'src'},
    )
"""
CMAKE = """\
cmake_minimum_required(VERSION 3.5)
project(bridge)
set(ROS_VERSION $ENV{ROS_VERSION})
if(${ROS_VERSION} EQUAL 1)
  find_package(catkin REQUIRED COMPONENTS rospy)
  catkin_python_setup()
  catkin_package()
  install(DIRECTORY launch/ DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION}/launch)
endif()
"""


def test_a_ros2_ament_python_package_with_a_catkin_cmakelists_installs_by_setup_py(
        write_tree) -> None:
    root = write_tree({"bridge/package.xml": MANIFEST, "bridge/setup.py": SETUP,
                       "bridge/CMakeLists.txt": CMAKE,
                       "bridge/launch/bridge.launch.py": "def generate_launch_description():\n"
                       "    return None\n",
                       "bridge/src/bridge/__init__.py": "",
                       "bridge/src/bridge/bridge.py": "def main():\n    pass\n"})
    workspace = scan([str(root)], {"ROS_DISTRO": "humble", **distro_variables("humble")})
    mapped = {k: workspace.relpath(v)
              for k, v in share_map(workspace.packages["bridge"], workspace).items()}
    assert mapped == {"bridge.launch.py": "bridge/launch/bridge.launch.py",
                      "package.xml": "bridge/package.xml"}


def test_a_variable_the_distribution_does_not_set_decides_no_branch(write_tree) -> None:
    """``CI`` is the builder's shell's: neither branch is known, so neither's files are
    said installed (the analyst's own shell decides nothing)."""
    root = write_tree({"tool/package.xml": package_xml("tool", "ament_python"),
                       "tool/setup.py": "import os\nfrom setuptools import setup\n"
                       "if 'CI' in os.environ:\n    extra = ['ci.yaml']\n"
                       "else:\n    extra = ['local.yaml']\n"
                       "setup(name='tool', data_files=[('share/tool', ['package.xml']),\n"
                       "                               ('share/tool/config', extra)])\n",
                       "tool/ci.yaml": "a: 1\n", "tool/local.yaml": "a: 2\n"})
    workspace = scan([str(root)], {"CI": "1", "ROS_DISTRO": "humble",
                                   **distro_variables("humble")})
    mapped = {k: workspace.relpath(v)
              for k, v in share_map(workspace.packages["tool"], workspace).items()}
    assert mapped == {"package.xml": "tool/package.xml"}
