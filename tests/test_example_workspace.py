"""The bundled example workspace (what `scripts/demo` runs) gives the graph it shows."""

from __future__ import annotations

import os

import pytest
from conftest import ROOT

from haros_arch.pipeline import analyse
from haros_arch.project import load


@pytest.fixture(scope="module")
def model():
    return analyse(load(str(ROOT / "examples/project.yaml")), {"PATH": os.environ["PATH"]})


def test_both_configurations_and_the_monitor_switch(model):
    robot, without, _rover = model.configurations
    assert [n.name for n in robot.nodes] == ["/robot1/driver", "/robot1/battery",
                                             "/robot1/controller", "/monitor"]
    assert [n.name for n in without.nodes] == ["/robot2/driver", "/robot2/battery",
                                               "/robot2/controller"]


def test_foreach_in_cmake_and_the_python_script_give_all_nodes(model):
    assert sorted(n.name for n in model.nodes) == [
        "demo_robot/battery_monitor.py", "demo_robot/controller", "demo_robot/driver",
        "demo_robot/monitor", "demo_rover/demo_rover::LidarFilter",
        "demo_rover/lidar_filter_node", "demo_rover/safety_stop.py"]


def test_the_python_node_joins_the_graph(model):
    robot = model.configurations[0]
    battery = robot.node("/robot1/battery")
    assert battery is not None and battery.node.language == "python"
    assert sorted((link.kind, link.name) for link in battery.links
                  if link.origin != "action") == [
        ("action-client", "/robot1/dock"), ("client", "/robot1/driver/reset"),
        ("publish", "/robot1/battery/low"), ("read", "/robot1/battery/threshold"),
        ("subscribe", "/robot1/battery/level")]
    low = robot.topic("/robot1/battery/low")
    assert low.publishers[0].latch is True
    assert robot.parameter("/robot1/battery/threshold").value == 0.25


def test_the_planted_mistakes_are_visible(model):
    robot = model.configurations[0]
    cmd_vel = robot.topic("/robot1/cmd_vel")
    assert cmd_vel is not None
    assert cmd_vel.types == ["geometry_msgs/Twist", "geometry_msgs/TwistStamped"]
    assert robot.parameter("/robot_name").readers[0].node.name == "/monitor"
    assert robot.parameter("/monitor/robot_name").readers == []
    scan = robot.topic("/robot1/base_scan")
    assert scan is not None and scan.subscribers[0].rosname.given == "scan"


def test_private_handles_and_conditional_client(model):
    robot = model.configurations[0]
    reset = robot.service("/robot1/driver/reset")
    assert reset is not None
    # ``bool use_reset = false; pnh.getParam("use_reset", use_reset);`` and no launch file
    # sets ~use_reset, so the client rests on the service being there at run time
    client = next(link for link in reset.clients if link.node.name == "/robot1/controller")
    assert [(c.statement, c.text) for c in client.conditions] == [
        ("if", 'use_reset || ros::service::exists("driver/reset", false)')]
    assert robot.parameter("/robot1/driver/port").value == "/dev/ttyUSB0"


def test_the_dock_action_joins_cpp_server_and_python_client(model):
    robot = model.configurations[0]
    (dock,) = robot.actions
    assert (dock.name, dock.types) == ("/robot1/dock", ["demo_robot/Dock"])
    assert [link.node.name for link in dock.servers] == ["/robot1/driver"]
    assert [link.node.name for link in dock.clients] == ["/robot1/battery"]
    goal = robot.topic("/robot1/dock/goal")
    assert goal.types == ["demo_robot/DockActionGoal"] and not goal.is_disconnected


def test_the_ros2_rover_component_and_python_node(model):
    rover = model.configuration("rover")
    assert sorted(n.name for n in rover.nodes) == [
        "/rover/lidar_filter", "/rover/rover_container", "/rover/safety_stop"]
    lidar = rover.node("/rover/lidar_filter")
    assert lidar.ros_version == 2 and lidar.node.kind == "component"
    scan = rover.topic("/rover/scan_filtered")
    assert scan.types == ["sensor_msgs/msg/LaserScan"]
    (publisher,) = scan.publishers
    (subscriber,) = scan.subscribers
    assert publisher.qos["reliability"] == "best_effort"
    assert subscriber.qos["reliability"] == "reliable"
    # the parameter file's value for lidar_filter, the dict's for safety_stop
    assert rover.parameter("/rover/lidar_filter/min_range").value == 0.25
    assert rover.parameter("/rover/safety_stop/stop_distance").value == 0.5
    assert rover.topic("/rover/lidar/scan") is not None  # the launch file's remap
    assert rover.diagnostics == []


def test_a_parameter_set_to_an_unknown_value_leaves_the_name_unknown():
    """fixtures/report_unresolved starts the example robot with /robot_name set from a
    launch argument nobody gives: the monitor reads that value, not the default its code
    names ("robot1"), so its topic is /?/status, with /robot1/status its candidate (it
    was /robot1/status, as if the launch file set nothing). The screenshot of an
    unresolved name (scripts/screenshots.py) is taken from it."""
    fixture = ROOT / "fixtures" / "report_unresolved" / "project.yaml"
    (config,) = analyse(load(str(fixture)), {"PATH": os.environ["PATH"]}).configurations
    name = config.parameter("/robot_name")
    assert name is not None and name.set_by_launch and name.value is None
    monitor = config.node("/monitor")
    assert monitor is not None
    assert [link.name for link in monitor.links if link.kind == "subscribe"] == ["/?/status"]
    status = config.topic("/?/status")
    assert status is not None
    assert [c.name for c in status.candidates] == ["/robot1/status"]
