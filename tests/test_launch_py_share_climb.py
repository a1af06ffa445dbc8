"""A ROS 2 Python launch file that climbs out of a package's share folder to reach the
workspace's sources (drone_autonomous_landing_on_ugv cdfdd52, ros2_px4_swarming's
launch files: ``os.path.join(get_package_share_directory('ros2_px4_swarming'), '..',
'..', '..', '..', 'src', 'ros2_px4_swarming', 'parameters', 'params.yaml')``; also
written with ``os.path.abspath(...)`` and ``os.pardir``). ROS 2 finds the package in
colcon's install space, ``<ws>/install/<pkg>/share/<pkg>``, four folders below the
workspace, so the path is ``<ws>/src/<pkg>/parameters/params.yaml``. The share folder was
taken as the package's source folder, two below, and the climb left the workspace: the
file "is outside the workspace and installed packages; it is not read", and what it
sets was unknown. A climb that reaches no file stays as it was read."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

LAUNCH = '''import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    params = os.path.join(get_package_share_directory('swarm'), '..', '..', '..', '..',
                          'src', 'swarm', 'parameters', 'params.yaml')
    other = os.path.abspath(os.path.join(get_package_share_directory('swarm'),
                                         os.pardir, os.pardir, os.pardir, os.pardir,
                                         'src/swarm/', 'parameters', 'other.yaml'))
    gone = os.path.join(get_package_share_directory('swarm'), '..', '..', '..', '..',
                        'src', 'swarm', 'parameters', 'gone.yaml')
    return LaunchDescription([
        Node(package='swarm', executable='drone', name='drone', parameters=[params]),
        Node(package='swarm', executable='target', name='target', parameters=[other]),
        Node(package='swarm', executable='gps', name='gps', parameters=[gone]),
    ])
'''

PARAMS = '''/**:
  ros__parameters:
    QUEUE_SIZE: 10
'''

OTHER = '''target:
  ros__parameters:
    RATE: 20.0
'''


def test_a_climb_out_of_the_share_folder_starts_in_the_install_space(write_tree):
    root = write_tree({"ws/src/swarm/package.xml": package_xml("swarm", "ament_python"),
                       "ws/src/swarm/launch/sim.launch.py": LAUNCH,
                       "ws/src/swarm/parameters/params.yaml": PARAMS,
                       "ws/src/swarm/parameters/other.yaml": OTHER})
    ws = scan([str(root / "ws")], {})
    model = load(str(root / "ws/src/swarm/launch/sim.launch.py"), ws, {}, {})
    outside = [d.message for d in model.diagnostics if "outside the workspace" in d.message]
    assert len(outside) == 1 and "gone.yaml" in outside[0], model.diagnostics
    values = {p.name: p.value for p in model.params}
    assert values["/drone/QUEUE_SIZE"] == 10
    assert values["/target/RATE"] == 20.0


CHECKOUT_LAUNCH = '''import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    robot = os.path.join(get_package_share_directory('blackbox'), '../../../../',
                         'src/fleet-asv/asv_setup/config/robots/', 'boat.yaml')
    other = os.path.join(get_package_share_directory('blackbox'), '../../../../',
                         'src/another-repo/asv_setup/config/robots/', 'boat.yaml')
    return LaunchDescription([
        Node(package='blackbox', executable='blackbox_node', name='blackbox_node',
             parameters=[robot]),
        Node(package='blackbox', executable='recorder', name='recorder',
             parameters=[other]),
    ])
'''

BOAT = '''/**:
  ros__parameters:
    physical:
      mass: 120.0
'''


def test_a_climb_into_the_repository_analysed_alone_is_its_checkout(write_tree):
    # vortex-asv's mission/blackbox/launch/blackbox.launch.py:10-15 climbs four folders
    # out of the share folder into ``src/vortex-asv/asv_setup/config/robots/freya.yaml``:
    # the repository, analysed as the folder of that name, is that checkout in src/
    root = write_tree({
        "fleet-asv/mission/blackbox/package.xml": package_xml("blackbox", "ament_python"),
        "fleet-asv/mission/blackbox/launch/blackbox.launch.py": CHECKOUT_LAUNCH,
        "fleet-asv/asv_setup/config/robots/boat.yaml": BOAT})
    ws = scan([str(root / "fleet-asv")], {})
    model = load(str(root / "fleet-asv/mission/blackbox/launch/blackbox.launch.py"), ws,
                 {}, {})
    values = {p.name: p.value for p in model.params}
    assert values["/blackbox_node/physical.mass"] == 120.0
    # the guard: another repository's folder is not this one's
    outside = [d.message for d in model.diagnostics if "outside the workspace" in d.message]
    assert len(outside) == 1 and "another-repo" in outside[0], model.diagnostics
    assert not any(name.startswith("/recorder/physical") for name in values)
