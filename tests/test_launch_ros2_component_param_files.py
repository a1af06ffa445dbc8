"""A parameter file with no ``ros__parameters`` at all, given to a composable node:
launch_ros (``to_parameters_list``, humble to rolling) hands the node the whole file,
its mappings joined by dots, where rcl refuses the same file for a node of its own
process. septentrio_gnss_driver's rover.launch.py loads ``config/rover.yaml`` (flat:
``device``, ``serial: {baudrate}`` ...) into a container: that was a
LAUNCH_PARAMS_OUTSIDE error and the driver's parameters were unset."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

LAUNCH = """
import os
from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer, Node
from launch_ros.descriptions import ComposableNode

def generate_launch_description():
    here = os.path.join(os.path.dirname(__file__), '..', 'config')
    return LaunchDescription([
        ComposableNodeContainer(
            name='container', namespace='', package='rclcpp_components',
            executable='component_container',
            composable_node_descriptions=[
                ComposableNode(package='gnss', plugin='gnss::Driver', name='driver',
                               parameters=[os.path.join(here, 'flat.yaml')]),
                ComposableNode(package='gnss', plugin='gnss::Driver', name='sections',
                               parameters=[os.path.join(here, 'sections.yaml')]),
            ]),
        Node(package='gnss', executable='driver_node', name='standalone',
             parameters=[os.path.join(here, 'flat.yaml')]),
    ])
"""

FILES = {
    "src/gnss/package.xml": package_xml("gnss", "ament_cmake"),
    "src/gnss/config/flat.yaml": "device: tcp://10.0.0.1:28784\nserial:\n  baudrate: 921600\n",
    # a file with sections: launch_ros takes those, the value outside is no parameter
    "src/gnss/config/sections.yaml":
        "stray: 1\nsections:\n  ros__parameters:\n    rate: 5\n",
    "src/gnss/launch/driver.launch.py": LAUNCH,
}


def test_a_file_without_sections_is_the_components_parameters(write_tree):
    root = write_tree(FILES)
    model = load(str(root / "src/gnss/launch/driver.launch.py"),
                 scan([str(root / "src")], {}), {}, {})
    values = {p.name: p.value for p in model.params}
    assert values["/driver/device"] == "tcp://10.0.0.1:28784"
    assert values["/driver/serial.baudrate"] == 921600
    assert values["/sections/rate"] == 5
    assert "/sections/stray" not in values
    # the node of its own process gets nothing from the flat file: rcl refuses it
    assert not [name for name in values if name.startswith("/standalone/")]
    outside = [d.message for d in model.diagnostics if d.code == "LAUNCH_PARAMS_OUTSIDE"]
    assert len(outside) == 2, outside
    assert any("flat.yaml" in m for m in outside) and any("sections.yaml" in m
                                                          for m in outside)
    assert {d.location.line for d in model.diagnostics
            if d.code == "LAUNCH_PARAMS_OUTSIDE"} == {15, 18}  # not the first, line 12
