"""A Python launch file named ``*.launch`` (CMU's autonomy stacks name every one so:
``system_simulation.launch``, included by ``PythonLaunchDescriptionSource``): launch
loads a file whose extension is not ``.py`` with its front ends first, then with its
Python loader (``get_launch_description_from_any_launch_file``), so ``ros2 launch`` runs
it as Python. It was read as XML only: a false LAUNCH_XML_SYNTAX error and none of its
nodes nor its includes. A file that is neither XML nor a Python launch file stays
LAUNCH_XML_SYNTAX."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch.ros2 import load
from haros_arch.workspace import scan

SYSTEM = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node

def generate_launch_description():
    planner = IncludeLaunchDescription(PythonLaunchDescriptionSource(os.path.join(
        get_package_share_directory('p'), 'launch', 'planner.launch')))
    return LaunchDescription([
        Node(package='p', executable='simulator', name='vehicle_simulator'),
        planner,
    ])
"""

PLANNER = """
from launch import LaunchDescription
from launch_ros.actions import Node

def generate_launch_description():
    return LaunchDescription([Node(package='p', executable='planner', name='far_planner')])
"""


def _load(write_tree, files: dict[str, str], name: str):
    root = write_tree({"src/p/package.xml": package_xml("p", "ament_cmake"),
                       **{f"src/p/launch/{k}": v for k, v in files.items()}})
    workspace = scan([str(root / "src")], {})
    return load(str(root / "src/p/launch" / name), workspace, {}, {})


def test_a_python_launch_file_named_launch_is_read_as_python(write_tree) -> None:
    model = _load(write_tree, {"system.launch": SYSTEM, "planner.launch": PLANNER},
                  "system.launch")
    assert sorted(node.name for node in model.nodes) == ["/far_planner",
                                                          "/vehicle_simulator"]
    assert [d.code for d in model.diagnostics if d.severity == "error"] == []


def test_a_file_neither_xml_nor_a_python_launch_file_is_an_xml_error(write_tree) -> None:
    model = _load(write_tree, {"broken.launch": "import os\nprint('no launch here')\n",
                               "worse.launch": "<launch><node pkg='p'</launch>\n"},
                  "broken.launch")
    assert [d.code for d in model.diagnostics if d.severity == "error"] == [
        "LAUNCH_XML_SYNTAX"]
