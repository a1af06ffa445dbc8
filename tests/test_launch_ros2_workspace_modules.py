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


# py_trees_ros_tutorials 15c9060: the package's __init__.py imports each tutorial with
# ``from . import one``; a tutorial says ``from . import mock`` and builds its launch
# description from ``mock.launch.generate_launch_nodes()``, while mock/__init__.py says
# ``from . import launch``. Python hands the package, still being initialised, to each
# submodule that imports it again: no cycle, and the mock robot's nodes are launched.
PARTIAL_PACKAGE = {
    "src/tutorials/package.xml": package_xml("tutorials", "ament_python"),
    "src/tutorials/setup.py": "from setuptools import setup\nsetup(name='tutorials')\n",
    "src/tutorials/tutorials/__init__.py":
        "from . import behaviours\nfrom . import mock\nfrom . import one\n",
    "src/tutorials/tutorials/behaviours.py": "TOPIC = '/led_strip/command'\n",
    "src/tutorials/tutorials/mock/__init__.py": "from . import launch\n",
    "src/tutorials/tutorials/mock/launch.py": """
import launch
import launch_ros.actions

def generate_launch_nodes():
    return [launch_ros.actions.Node(package='tutorials', executable='mock-' + name,
                                    name=name) for name in ('battery', 'dashboard')]
""",
    "src/tutorials/tutorials/one.py": """
import launch
import launch_ros
from . import behaviours
from . import mock
from . import later

def generate_launch_description():
    return launch.LaunchDescription(mock.launch.generate_launch_nodes() + [
        launch_ros.actions.Node(package='tutorials', executable='tree-one', name='tree',
                                remappings=[('led', behaviours.TOPIC)])])
""",
    "src/tutorials/tutorials/later.py": "from tutorials.one import NOT_YET\n",
    "src/tutorials/launch/one_launch.py":
        "import tutorials.one as tutorial\n\n"
        "def generate_launch_description():\n"
        "    return tutorial.generate_launch_description()\n",
}


def test_a_package_imported_again_while_it_is_read_is_no_cycle(write_tree):
    root = write_tree(PARTIAL_PACKAGE)
    model = load(str(root / "src/tutorials/launch/one_launch.py"),
                 scan([str(root / "src")], {}), {}, {})
    assert [n.name for n in model.nodes] == ["/battery", "/dashboard", "/tree"]
    messages = [d.message for d in model.diagnostics]
    assert not any("imports itself" in m for m in messages), messages
    # a name the module being read has not bound yet is not there, as at run time
    assert any("NOT_YET is not defined in tutorials.one as read here" in m
               for m in messages), messages
