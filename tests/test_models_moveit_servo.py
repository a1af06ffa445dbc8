"""moveit_servo has an interface model in humble and jazzy: the component a launch file
loads is known by the class the release registers (``moveit_servo::ServoNode``, its
``servo_node`` program), and the Foxy-era class ``moveit_servo::ServoServer``, which no
release of either distribution registers, is said as the model's missing node
(xArm-Developer/xarm_ros2 ef7e1646 on humble, 50b5a579 on jazzy), not as a package
whose interface nobody knows."""

from __future__ import annotations

import pytest
from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

LAUNCH = """\
from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    return LaunchDescription([
        ComposableNodeContainer(
            name='servo_container', namespace='/', package='rclcpp_components',
            executable='component_container',
            composable_node_descriptions=[
                ComposableNode(package='moveit_servo', plugin='{plugin}',
                               name='servo_server'),
            ]),
    ])
"""


def _said(write_tree, distro: str, plugin: str):
    root = write_tree({
        "src/arm/package.xml": package_xml("arm", "ament_python"),
        "src/arm/launch/servo.launch.py": LAUNCH.format(plugin=plugin),
        "project.yaml": (f"project: p\nworkspace: src\ndistro: {distro}\n"
                         "configurations:\n  c: [arm/launch/servo.launch.py]\n"),
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    codes = {d.code for d in config.diagnostics
             if "moveit_servo" in d.message or "ServoServer" in d.message
             or "ServoNode" in d.message}
    servo = [n for n in config.nodes if n.name.endswith("servo_server")]
    return codes, servo, {link.resource.name for link in config.links
                          if link.node in servo}


@pytest.mark.parametrize("distro", ["humble", "jazzy"])
def test_the_old_servo_class_is_a_node_the_model_lacks(write_tree, distro: str) -> None:
    codes, _, _ = _said(write_tree, distro, "moveit_servo::ServoServer")
    assert "MODEL_NODE_MISSING" in codes
    assert "NODE_PACKAGE_UNKNOWN" not in codes


@pytest.mark.parametrize(("distro", "service"), [
    ("humble", "/servo_server/change_drift_dimensions"),  # servo_calcs.cpp of 2.5.9
    ("jazzy", "/servo_server/switch_command_type"),  # servo_node.cpp of 2.12.x
])
def test_the_released_servo_component_takes_the_model(write_tree, distro: str,
                                                      service: str) -> None:
    codes, servo, names = _said(write_tree, distro, "moveit_servo::ServoNode")
    assert not codes & {"MODEL_NODE_MISSING", "NODE_PACKAGE_UNKNOWN", "NODE_NOT_FOUND"}
    (node,) = servo
    assert node.node is not None
    # its interface is the release's: a service each release's servo node offers under
    # its own name
    assert service in names
