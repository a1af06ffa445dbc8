"""A robot-wide parameter file whose ``/**`` entries the launch files of several
configurations give their nodes, each node declaring its own few keys of it: a key is
read where any of those nodes reads it, in any configuration. vortex-asv's freya.yaml
goes to blackbox_node (blackbox.launch.py), PSM_publisher (internal_status_launch.py)
and the nodes of asv_setup's three launch files; blackbox_node.py:107-112 reads only
``blackbox.data_logging_rate``, and parameter-set-not-read said each of the other 34
keys in each configuration (148 warnings), keys that thrust_allocator, the hybridpath
controller and the others read. A key no node of any configuration reads is still said
(12 of freya.yaml's: ``physical.mass_kg``, ``computer``, ...). blackbox.launch.py names
the file by a climb out of its share folder, asv_setup's launch files by asv_setup's
share folder: one file, one setting."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load as load_project
from haros_arch.query.catalogue import load_catalogue, run_rule

SETUP = """
    from setuptools import setup
    setup(name="boat", packages=["boat"],
          entry_points={"console_scripts": ["logger = boat.logger:main",
                                            "pilot = boat.pilot:main"]})
    """
LOGGER = """
    import rclpy
    def main():
        rclpy.init()
        node = rclpy.create_node("logger")
        node.declare_parameter("logger.rate", 1.0)
    """
PILOT = """
    import rclpy
    def main():
        rclpy.init()
        node = rclpy.create_node("pilot")
        node.declare_parameter("physical.mass", 1.0)
    """
ROBOT = """
    /**:
      ros__parameters:
        logger:
          rate: 2.0
        physical:
          mass: 40.0
          spare: 0
    """
# the logger's launch names the file by a climb out of its own share folder
LOGGING = """
    import os
    from ament_index_python.packages import get_package_share_directory
    from launch import LaunchDescription
    from launch_ros.actions import Node

    def generate_launch_description():
        config = os.path.join(get_package_share_directory("boat"), "launch", "..",
                              "config", "robot.yaml")
        return LaunchDescription([
            Node(package="boat", executable="logger", name="logger", parameters=[config]),
        ])
    """
PILOTING = """
    import os
    from ament_index_python.packages import get_package_share_directory
    from launch import LaunchDescription
    from launch_ros.actions import Node

    def generate_launch_description():
        config = os.path.join(get_package_share_directory("boat"), "config", "robot.yaml")
        return LaunchDescription([
            Node(package="boat", executable="pilot", name="pilot", parameters=[config]),
        ])
    """
SETUP_CFG = "[install]\ninstall_scripts=$base/lib/boat\n"


def test_a_key_another_configuration_reads_is_read(write_tree) -> None:
    root = write_tree({
        "src/boat/package.xml": package_xml("boat", "ament_python"),
        "src/boat/setup.py": SETUP,
        "src/boat/setup.cfg": SETUP_CFG,
        "src/boat/boat/__init__.py": "",
        "src/boat/boat/logger.py": LOGGER,
        "src/boat/boat/pilot.py": PILOT,
        "src/boat/config/robot.yaml": ROBOT,
        "src/boat/launch/logging.launch.py": LOGGING,
        "src/boat/launch/piloting.launch.py": PILOTING,
        "project.yaml": ("project: p\nconfigurations:\n"
                         "  logging: [boat/launch/logging.launch.py]\n"
                         "  piloting: [boat/launch/piloting.launch.py]\n")})
    model = analyse(load_project(str(root / "project.yaml")),
                    {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    rule = next(r for r in load_catalogue() if r.id == "parameter-set-not-read")
    found = sorted((f.configurations[0] if f.configurations else "", f.message.split()[0])
                   for f in run_rule(rule, model) if f.rule == "parameter-set-not-read")
    # physical.spare is read by no node anywhere: said in each configuration; the
    # logger's rate and the pilot's mass are read by the other configuration's node
    assert found == [("logging", "/logger/physical.spare"),
                     ("piloting", "/pilot/physical.spare")]
