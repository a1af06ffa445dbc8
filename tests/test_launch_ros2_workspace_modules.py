"""ROS 2 Python launch files that import helpers from a Python package a package of the
workspace holds (an ament_python package installs it where launch imports it:
Interbotix's ``from interbotix_xs_modules.xs_launch import
declare_interbotix_xsarm_robot_description_launch_arguments``) read the helper's code,
its own relative imports too, as they read a module of a folder put on ``sys.path``."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

LAUNCH = """
from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration
from arm_modules.arm_launch import declare_arm_arguments, arm_node
import arm_modules.common as common

def generate_launch_description():
    return LaunchDescription(declare_arm_arguments() + [
        arm_node(LaunchConfiguration('robot_name')),
        arm_node(common.SECOND),
    ])
"""

FILES = {
    "src/arm_modules/package.xml": package_xml("arm_modules", "ament_python"),
    "src/arm_modules/setup.py": "from setuptools import setup\nsetup(name='arm_modules')\n",
    "src/arm_modules/arm_modules/__init__.py": "",
    "src/arm_modules/arm_modules/common.py": "MODELS = ('wx200', 'wx250')\nSECOND = 'spare'\n",
    "src/arm_modules/arm_modules/arm_launch/__init__.py":
        "from .arm_launch import declare_arm_arguments, arm_node  # noqa\n",
    "src/arm_modules/arm_modules/arm_launch/arm_launch.py": """
from launch.actions import DeclareLaunchArgument
from launch_ros.actions import Node
from ..common import MODELS

def declare_arm_arguments():
    return [DeclareLaunchArgument('robot_model', default_value=MODELS[1]),
            DeclareLaunchArgument('robot_name', default_value='arm1')]

def arm_node(namespace):
    return Node(package='arm_control', executable='driver', name='driver',
                namespace=namespace)
""",
    "src/bringup/package.xml": package_xml("bringup", "ament_cmake"),
    "src/bringup/launch/arm.launch.py": LAUNCH,
}


def test_helpers_of_a_workspace_python_package_are_read(write_tree):
    root = write_tree(FILES)
    model = load(str(root / "src/bringup/launch/arm.launch.py"), scan([str(root / "src")], {}),
                 {}, {})
    assert sorted(n.name for n in model.nodes) == ["/arm1/driver", "/spare/driver"]
    codes = {d.code for d in model.diagnostics}
    assert not codes & {"LAUNCH_PY_UNSUPPORTED", "LAUNCH_UNKNOWN_VALUE", "LAUNCH_ARG_UNSET"}


# vrx's competition.launch.py: ``import vrx_gz.launch`` then ``vrx_gz.launch.spawn(...)``;
# its launch.py does ``import vrx_gz.bridges`` the same way. Python binds the top
# package, each module of the path an attribute of the one above it.
DOTTED = """
from launch import LaunchDescription
import sim_helpers.spawning
import sim_helpers.deep.names
from sim_helpers import topics

def generate_launch_description():
    return LaunchDescription(sim_helpers.spawning.nodes(sim_helpers.deep.names.NAME)
                             + [topics.relay()])
"""

DOTTED_FILES = {
    "src/sim_helpers/package.xml": package_xml("sim_helpers", "ament_cmake"),
    "src/sim_helpers/src/sim_helpers/__init__.py": "",
    "src/sim_helpers/src/sim_helpers/deep/__init__.py": "",
    "src/sim_helpers/src/sim_helpers/deep/names.py": "NAME = 'boat'\n",
    "src/sim_helpers/src/sim_helpers/topics.py": """
from launch_ros.actions import Node

def relay():
    return Node(package='topic_tools', executable='relay', name='relay')
""",
    "src/sim_helpers/src/sim_helpers/spawning.py": """
from launch_ros.actions import Node
import sim_helpers.topics

def nodes(name):
    return [Node(package='bridge', executable='bridge', name='bridge', namespace=name),
            sim_helpers.topics.relay()]
""",
    "src/sim_helpers/launch/sim.launch.py": DOTTED,
}


def test_a_dotted_import_binds_its_top_package(write_tree):
    root = write_tree(DOTTED_FILES)
    model = load(str(root / "src/sim_helpers/launch/sim.launch.py"),
                 scan([str(root / "src")], {}), {}, {})
    assert sorted(n.name for n in model.nodes) == ["/boat/bridge", "/relay", "/relay"]
    assert not [d for d in model.diagnostics if d.code in (
        "LAUNCH_PY_UNSUPPORTED", "LAUNCH_UNKNOWN_VALUE")]
