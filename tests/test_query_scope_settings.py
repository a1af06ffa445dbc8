"""A ROS 2 setting for several nodes (``SetParameter`` for every node of its scope, the
``/**`` entries of a parameter file given to several nodes) gives each of them the
value, and each takes it only if it declares it (Autoware's vehicle_info.launch.py sets
the vehicle's dimensions so for every node of autoware.launch.xml, and its planning
launch files give each node the same common.param.yaml). ``parameter-set-not-read``
reports such a setting once when none of those nodes reads it, not once per node that
has no use for it."""

from __future__ import annotations

import textwrap

from conftest import package_xml

from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue
from haros_arch.query.catalogue import UNDECIDED

SETUP = """
    from setuptools import setup
    setup(name="car", packages=["car"],
          entry_points={"console_scripts": ["planner = car.planner:main",
                                            "monitor = car.monitor:main",
                                            "lost = car.lost:main"]})
    """
PLANNER = """
    import rclpy
    def main():
        rclpy.init()
        node = rclpy.create_node("planner")
        node.declare_parameter("wheel_base", 2.7)
        node.declare_parameter("speed", 1.0)
    """
MONITOR = """
    import rclpy
    def main():
        rclpy.init()
        node = rclpy.create_node("monitor")
        node.declare_parameter("period", 1.0)
    """
LOST = """
    import rclpy
    def main():
        rclpy.init()
        node = rclpy.create_node("lost")
        node.declare_parameter(input())
    """
LAUNCH = """
    from launch import LaunchDescription
    from launch.actions import GroupAction
    from launch_ros.actions import Node, SetParameter, SetParametersFromFile

    def generate_launch_description():
        return LaunchDescription([GroupAction([
            SetParameter(name="wheel_base", value=2.7),
            SetParameter(name="wheel_bsae", value=2.7),
            SetParametersFromFile("/WS/src/car/config/common.yaml"),
            Node(package="car", executable="planner", name="planner",
                 parameters=[{"speed": 2.0, "unused": 1}, "/WS/src/car/config/shared.yaml"]),
            Node(package="car", executable="monitor", name="monitor",
                 parameters=["/WS/src/car/config/shared.yaml",
                             "/WS/src/car/config/own.yaml"]),
            %s
        ])])
    """
SHARED = """
    /**:
      ros__parameters:
        speed: 3.0
        period: 2.0
        nobody: 1
    """
OWN = """
    /**:
      ros__parameters:
        lonely: 1
    """
COMMON = """
    /**:
      ros__parameters:
        period: 0.5
        colour: red
    monitor:
      ros__parameters:
        mode: fast
    """


def _findings(write_tree, extra: str = "") -> dict[str, list[tuple[str, ...]]]:
    root = write_tree({
        "src/car/package.xml": package_xml("car", "ament_python"),
        "src/car/setup.py": SETUP,
        "src/car/car/__init__.py": "",
        "src/car/car/planner.py": PLANNER,
        "src/car/car/monitor.py": MONITOR,
        "src/car/car/lost.py": LOST,
        "src/car/config/common.yaml": COMMON,
        "src/car/config/shared.yaml": SHARED,
        "src/car/config/own.yaml": OWN,
        "src/car/launch/car.launch.py": "",
        "project.yaml": "project: p\nconfigurations:\n  c: [car/launch/car.launch.py]\n",
    })
    launch = LAUNCH.replace("/WS", str(root)) % extra
    (root / "src/car/launch/car.launch.py").write_text(textwrap.dedent(launch).lstrip("\n"))
    model = analyse(load(str(root / "project.yaml")), {})
    found: dict[str, list[tuple[str, ...]]] = {}
    for finding in run_catalogue(model):
        if finding.rule.startswith("parameter-set-not-read"):
            found.setdefault(finding.rule, []).append(tuple(finding.entities))
    return found


def test_a_setting_for_the_scope_is_unread_only_when_no_node_there_reads_it(write_tree):
    found = _findings(write_tree)
    assert sorted(found["parameter-set-not-read"]) == [
        # a file given to the monitor alone, and the file's entry for the monitor: the
        # monitor's own
        ("parameter:/monitor/lonely",),
        ("parameter:/monitor/mode",),
        # the /** entry of the scope's file: no node there reads it: once
        ("parameter:/planner/colour",),
        # the /** entry of a file both nodes are given, and neither reads: once
        ("parameter:/planner/nobody",),
        # a node's own parameter, unread: per node, as before
        ("parameter:/planner/unused",),
        # no node of the scope reads it: once, on the first node it reached
        ("parameter:/planner/wheel_bsae",),
    ]
    # wheel_base: the planner reads it, the monitor has no use for it; period: the
    # monitor reads it, the planner does not (from common.yaml and shared.yaml); speed
    # of shared.yaml: the planner reads it: none is reported
    assert UNDECIDED not in "".join(found)


def test_a_node_that_could_read_it_unseen_leaves_the_setting_undecided(write_tree):
    found = _findings(write_tree, 'Node(package="car", executable="lost", name="lost"),')
    unread = found["parameter-set-not-read"]
    assert ("parameter:/planner/wheel_bsae",) not in unread
    assert ("parameter:/planner/colour",) not in unread
    assert ("parameter:/planner/unused",) in unread
    # said once, naming the node whose reads are not all known
    assert found["parameter-set-not-read" + UNDECIDED] == [("node:/lost",)]


ROS1_NODE = """
    #!/usr/bin/env python
    import rospy
    rospy.init_node("%s")
    %s
    """
ROS1_LAUNCH = """
    <launch>
      <node pkg="sim" type="simulator.py" name="simulator">
        <rosparam command="load" file="$(find sim)/params.yaml"/>
      </node>
      <node pkg="sim" type="mux.py" name="mux">
        <rosparam command="load" file="$(find sim)/params.yaml"/>
        <rosparam>{own_unused: 1}</rosparam>
      </node>
      <node pkg="sim" type="mux.py" name="alone">
        <rosparam command="load" file="$(find sim)/alone.yaml"/>
      </node>
    </launch>
    """


def test_a_ros1_parameter_file_loaded_into_several_nodes_is_one_setting(write_tree):
    """f1tenth_simulator loads one params.yaml into each of its five nodes, each reading
    what it needs: every key was reported for each node that does not read it (234
    warnings). Now a key no node reads is reported once, on the first node; one any
    of them reads is not; a file given to one node, and text, stay the node's own."""
    root = write_tree({
        "src/sim/package.xml": package_xml("sim"),
        "src/sim/CMakeLists.txt": ("project(sim)\nfind_package(catkin REQUIRED)\n"
                                   "catkin_package()\ncatkin_install_python(PROGRAMS "
                                   "scripts/simulator.py scripts/mux.py DESTINATION x)\n"),
        "src/sim/scripts/simulator.py": textwrap.dedent(ROS1_NODE % (
            "simulator", "rospy.get_param('~wheelbase')")),
        "src/sim/scripts/mux.py": textwrap.dedent(ROS1_NODE % (
            "mux", "rospy.get_param('~mux_size')")),
        "src/sim/params.yaml": "wheelbase: 0.3\nmux_size: 4\nnobody: 1\n",
        "src/sim/alone.yaml": "wheelbase: 0.3\n",
        "src/sim/launch/sim.launch": textwrap.dedent(ROS1_LAUNCH),
        "project.yaml": "project: p\ndistro: noetic\nconfigurations:\n"
                        "  c: [sim/launch/sim.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {})
    found = sorted(tuple(f.entities) for f in run_catalogue(model)
                   if f.rule == "parameter-set-not-read")
    assert found == [("parameter:/alone/wheelbase",), ("parameter:/mux/own_unused",),
                     ("parameter:/simulator/nobody",)]
